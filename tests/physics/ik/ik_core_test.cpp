// Tests of the IK library that use no exercise code: skeleton and forward kinematics, rotations,
// linear algebra, the two-bone geometry, builders and input validation.
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <string>

#include <gtest/gtest.h>
#include <Eigen/SVD>

#include "physics/ik/analytic.h"
#include "physics/ik/builders.h"
#include "physics/ik/linalg.h"
#include "physics/ik/solver.h"
#include "physics/ik/solver_internal.h"
#include "support/expect_helpers.h"

namespace pba::ik {
namespace {

TEST(IkSkeleton, ForwardKinematicsOfAPlanarChainMatchesTrigonometry) {
  ChainDesc d;
  d.links = 3;
  d.totalLength = 3.0;
  Rig rig = buildIkChain(d).value();
  Pose pose = rig.skeleton.restPose();
  pose.dofs = {0.3, -0.5, 1.1};
  const std::vector<Frame> frames = forwardKinematics(rig.skeleton, pose);
  // Reference: tip = Σ L (cos Θᵢ, sin Θᵢ) with Θᵢ the cumulative angle (CMU asst4, "Character").
  Vec3 expected(0.0);
  Real cumulative = 0.0;
  for (Real a : pose.dofs) {
    cumulative += a;
    expected += Vec3(std::cos(cumulative), std::sin(cumulative), 0.0);
  }
  // A few roundings per link: 1e-14 m.
  EXPECT_VEC3_NEAR(effectorPosition(rig.effectors[0], frames), expected, 1e-14);
}

TEST(IkSkeleton, EulerXYZRoundTripsAndRotationVectorsRoundTrip) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<Real> u(-1.5, 1.5);
  for (int i = 0; i < 1000; ++i) {
    const Vec3 e(u(rng) * 2.0, u(rng), u(rng) * 2.0);
    const Vec3 back = eulerXYZFromQuat(quatFromEulerXYZ(e));
    EXPECT_VEC3_NEAR(back, e, 1e-9);
    const Vec3 r(u(rng), u(rng), u(rng));
    EXPECT_VEC3_NEAR(rotationVector(quatFromRotationVector(r)), r, 1e-12);
  }
  EXPECT_VEC3_NEAR(rotationVector(Quat(1, 0, 0, 0)), Vec3(0.0), 0.0);
}

TEST(IkSkeleton, ShortestArcHandlesParallelOppositeAndZeroVectors) {
  const Vec3 x(1, 0, 0);
  EXPECT_VEC3_NEAR(shortestArc(x, Vec3(0, 2, 0)) * x, Vec3(0, 1, 0), 1e-15);
  EXPECT_VEC3_NEAR(shortestArc(x, Vec3(-3, 0, 0)) * x, Vec3(-1, 0, 0), 1e-15);
  EXPECT_VEC3_NEAR(shortestArc(x, Vec3(0.0)) * x, x, 0.0);
}

TEST(IkSkeleton, AddRejectsBadParentsAxesAndLimitsNamingTheField) {
  Skeleton s;
  Joint j;
  j.parent = 3;
  Result<int> r = s.add(j);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().find("parent"), std::string::npos);
  j.parent = -1;
  j.axis = Vec3(0.0);
  EXPECT_NE(s.add(j).error().find("axis"), std::string::npos);
  j.axis = Vec3(0, 0, 1);
  j.lo[0] = 1.0;
  j.hi[0] = -1.0;
  EXPECT_NE(s.add(j).error().find("limits"), std::string::npos);
}

// Non-finite values never reach a comparison (the test main traps invalid operations): each is
// reported with the field that holds it.
TEST(IkSkeleton, AddRejectsNonFiniteValuesNamingTheField) {
  const Real nan = std::numeric_limits<Real>::quiet_NaN();
  const std::vector<std::pair<const char*, std::function<void(Joint&)>>> cases = {
      {"offset", [nan](Joint& j) { j.offset.y = nan; }},
      {"axis", [nan](Joint& j) { j.axis.x = nan; }},
      {"restRotation", [nan](Joint& j) { j.restRotation.w = nan; }},
      {"limits[0]", [nan](Joint& j) { j.lo[0] = nan; }},
      {"weight[0]", [nan](Joint& j) { j.weight[0] = nan; }},
      {"maxRotation", [nan](Joint& j) { j.type = JointType::Free, j.maxRotation = nan; }},
  };
  for (const auto& [field, spoil] : cases) {
    Skeleton s;
    Joint j;
    spoil(j);
    const Result<int> r = s.add(j);
    ASSERT_FALSE(r.ok()) << field;
    EXPECT_NE(r.error().find(std::string(".") + field + ":"), std::string::npos) << r.error();
  }
  Rig rig = buildIkChain(ChainDesc{}).value();
  for (int k = 0; k < 3; ++k) {
    std::vector<Effector> effectors = rig.effectors;
    const char* field = k == 0   ? "effectors[0].weight"
                        : k == 1 ? "effectors[0].targetPosition"
                                 : "effectors[0].targetOrientation";
    if (k == 0) effectors[0].weight = nan;
    if (k == 1) effectors[0].targetPosition.z = nan;
    if (k == 2) effectors[0].kind = EffectorKind::PositionOrientation, effectors[0].targetOrientation.x = nan;
    Pose pose = rig.skeleton.restPose();
    const SolveResult r = solve(rig.skeleton, pose, effectors, SolveOptions{});
    EXPECT_EQ(r.status, SolveStatus::InvalidInput) << field;
    EXPECT_EQ(r.message.rfind(field, 0), 0u) << r.message;
  }
}

TEST(IkLinalg, SvdReconstructsAWideMatrixWithOrthonormalFactors) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  Matrix J(6, 17);
  for (Real& x : J.data) x = u(rng);
  const Svd d = svd(J);
  ASSERT_EQ(d.sigma.size(), 6u);
  for (int r = 0; r < J.rows; ++r)
    for (int c = 0; c < J.cols; ++c) {
      Real sum = 0.0;
      for (size_t i = 0; i < d.sigma.size(); ++i)
        sum += d.sigma[i] * d.u[i][static_cast<size_t>(r)] * d.v[i][static_cast<size_t>(c)];
      EXPECT_NEAR(sum, J(r, c), 1e-12);
    }
  for (size_t i = 0; i < 6; ++i)
    for (size_t k = 0; k < 6; ++k) EXPECT_NEAR(dot(d.v[i], d.v[k]), i == k ? 1.0 : 0.0, 1e-12);
  for (size_t i = 1; i < 6; ++i) EXPECT_GE(d.sigma[i - 1], d.sigma[i]);
}

// The one-sided Jacobi SVD of wide matrices against Eigen's two-sided JacobiSVD (the reference): the
// same singular values to 1e-13 relative to σ_max, at IK's shapes (3 or 6 rows, up to 3,000 columns),
// at scales 1e-6 to 1e6, with a dependent, a zero or a negligible row (σ exactly 0, no floating-point trap);
// orthonormal u and v; and J rebuilt from the factors.
TEST(IkLinalg, WideSvdMatchesEigensSingularValuesWithOrthonormalFactors) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  const int shapes[][2] = {{3, 3}, {3, 4}, {3, 30}, {6, 30}, {3, 300}, {6, 3000}, {9, 12}};
  for (const auto& shape : shapes) {
    for (const Real scale : {1e-6, 1.0, 1e6}) {
      // Full rank; row 1 = 2 × row 0; the last row zero; the last row 1e-160 of the others (its σ under
      // the rank threshold, and a rotation against it would square a ratio of 1e160).
      for (const int mode : {0, 1, 2, 3}) {
        const bool deficient = mode != 0;
        Matrix J(shape[0], shape[1]);
        for (Real& x : J.data) x = scale * u(rng);
        for (int c = 0; c < J.cols; ++c) {
          if (mode == 1) J(1, c) = 2.0 * J(0, c);
          if (mode == 2) J(J.rows - 1, c) = 0.0;
          if (mode == 3) J(J.rows - 1, c) *= 1e-160;
        }
        const std::string what = std::to_string(J.rows) + "x" + std::to_string(J.cols) + " scale " +
                                 std::to_string(scale) + " mode " + std::to_string(mode);
        Eigen::MatrixXd E(J.rows, J.cols);
        for (int r = 0; r < J.rows; ++r)
          for (int c = 0; c < J.cols; ++c) E(r, c) = J(r, c);
        const Eigen::VectorXd reference = Eigen::JacobiSVD<Eigen::MatrixXd>(E).singularValues();
        const Svd d = svd(J);
        ASSERT_EQ(d.sigma.size(), static_cast<size_t>(J.rows)) << what;
        const Real sigmaMax = reference(0);
        for (size_t i = 0; i < d.sigma.size(); ++i) {
          EXPECT_NEAR(d.sigma[i], reference(static_cast<Eigen::Index>(i)), 1e-13 * sigmaMax) << what << " σ" << i;
          EXPECT_NEAR(dot(d.u[i], d.u[i]), 1.0, 1e-13) << what;
          for (size_t k = 0; k < i; ++k) {
            EXPECT_NEAR(dot(d.u[i], d.u[k]), 0.0, 1e-13) << what;
            if (!d.v[i].empty() && !d.v[k].empty()) {
              EXPECT_NEAR(dot(d.v[i], d.v[k]), 0.0, 1e-12) << what;
            }
          }
          if (!d.v[i].empty()) {
            EXPECT_NEAR(dot(d.v[i], d.v[i]), 1.0, 1e-12) << what;
          }
        }
        EXPECT_EQ(d.sigma.back() == 0.0, deficient) << what;
        for (int r = 0; r < J.rows; ++r)
          for (int c = 0; c < J.cols; c += 7) {
            Real sum = 0.0;
            for (size_t i = 0; i < d.sigma.size(); ++i)
              if (!d.v[i].empty()) sum += d.sigma[i] * d.u[i][static_cast<size_t>(r)] * d.v[i][static_cast<size_t>(c)];
            EXPECT_NEAR(sum, J(r, c), 1e-12 * sigmaMax) << what;
          }
      }
    }
  }
}

TEST(IkLinalg, SvdOfARankDeficientMatrixReportsZeroSingularValues) {
  Matrix J(3, 4);  // two equal rows: rank 2
  const Real rows[3][4] = {{1, 2, 3, 4}, {1, 2, 3, 4}, {0, 1, 0, 1}};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) J(r, c) = rows[r][c];
  const Svd d = svd(J);
  EXPECT_EQ(d.sigma[2], 0.0);
  EXPECT_TRUE(d.v[2].empty());
}

TEST(IkLinalg, CholeskySolvesASymmetricPositiveDefiniteSystemAndRejectsASingularOne) {
  Matrix A(2, 2);
  A(0, 0) = 4;
  A(0, 1) = A(1, 0) = 1;
  A(1, 1) = 3;
  std::vector<Real> x;
  ASSERT_TRUE(solveSpd(A, {1, 2}, x));
  EXPECT_NEAR(4 * x[0] + x[1], 1.0, 1e-15);
  EXPECT_NEAR(x[0] + 3 * x[1], 2.0, 1e-15);
  Matrix S(2, 2);
  S(0, 0) = S(0, 1) = S(1, 0) = S(1, 1) = 1.0;
  EXPECT_FALSE(solveSpd(S, {1, 2}, x));
}

// A singular J Jᵀ (λ = 0, two equal rows of J; or a row that is a combination of the others) rounds
// to a tiny positive pivot, never to an exact zero: the relative pivot test must report it, at
// every scale of J. With damping λ² I added the same matrix solves, to 1e-12 relative.
TEST(IkLinalg, SolveSpdReportsASingularGramMatrixWithoutDampingAtAnyScale) {
  std::mt19937_64 rng(6);
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  for (Real scale : {1e-6, 1.0, 1e6})
    for (int trial = 0; trial < 20; ++trial) {
      Matrix J(3, 7);
      for (int c = 0; c < 7; ++c) {
        J(0, c) = scale * u(rng);
        J(1, c) = scale * u(rng);
        J(2, c) = trial % 2 ? J(0, c) : 0.3 * J(0, c) - 1.7 * J(1, c);  // rank 2
      }
      std::vector<Real> x;
      EXPECT_FALSE(solveSpd(gram(J), {1.0, 2.0, 3.0}, x)) << "scale " << scale << " trial " << trial;
      Matrix A = gram(J);
      const Real lambda2 = 1e-2 * scale * scale;
      for (int i = 0; i < 3; ++i) A(i, i) += lambda2;
      const std::vector<Real> b = {1.0, 2.0, 3.0};
      ASSERT_TRUE(solveSpd(A, b, x)) << "scale " << scale;
      for (int r = 0; r < 3; ++r) {
        Real Ax = 0.0, size = 0.0;
        for (int c = 0; c < 3; ++c) Ax += A(r, c) * x[size_t(c)], size += std::abs(A(r, c) * x[size_t(c)]);
        EXPECT_NEAR(Ax, b[size_t(r)], 1e-12 * (size + 1.0));
      }
    }
  Matrix zero(2, 2);
  std::vector<Real> x;
  EXPECT_FALSE(solveSpd(zero, {1.0, 1.0}, x));
}

TEST(IkTwoBone, GeometryPutsTheWristOnTheTargetAndTheElbowInThePolePlane) {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  const Real a = 0.9, b = 0.7;
  for (int i = 0; i < 1000; ++i) {
    const Vec3 s(u(rng), u(rng), u(rng)), t = s + Vec3(u(rng), u(rng), u(rng)), pole(u(rng) * 3, u(rng) * 3, 2.0);
    const TwoBonePose p = twoBoneGeometry(s, a, b, t, pole);
    const Real d = glm::length(t - s);
    if (d > a + b || d < a - b) {
      EXPECT_FALSE(p.reachable);
      continue;
    }
    // Law of cosines is exact up to rounding: 1e-12 m.
    EXPECT_VEC3_NEAR(p.wrist, t, 1e-12);
    EXPECT_NEAR(glm::length(p.elbow - s), a, 1e-12);
    EXPECT_NEAR(glm::length(p.wrist - p.elbow), b, 1e-12);
    const Vec3 normal = glm::cross(t - s, pole - s);
    if (glm::length(normal) > 1e-6) {
      EXPECT_NEAR(glm::dot(p.elbow - s, normal / glm::length(normal)), 0.0, 1e-12);
    }
  }
}

TEST(IkBuilders, RejectBadDescriptionsAndBuildTheDocumentedShapes) {
  ChainDesc d;
  d.links = 0;
  EXPECT_NE(buildIkChain(d).error().find("links"), std::string::npos);
  d.links = 1000;
  const Rig chain = buildIkChain(d).value();
  EXPECT_EQ(chain.skeleton.jointCount(), 1000);
  EXPECT_NEAR(reach(chain.skeleton, 0, chain.effectors[0]), d.totalLength, 1e-9);
  EXPECT_EQ(buildHand().value().effectors.size(), 5u);
  EXPECT_EQ(buildDoubleY().value().effectors.size(), 4u);
}

TEST(IkSolve, InvalidInputsGiveAClearStatusAndMessage) {
  Rig rig = buildIkChain(ChainDesc{}).value();
  Pose pose = rig.skeleton.restPose();
  pose.dofs.pop_back();
  SolveResult r = solve(rig.skeleton, pose, rig.effectors, SolveOptions{});
  EXPECT_EQ(r.status, SolveStatus::InvalidInput);
  EXPECT_NE(r.message.find("pose.dofs"), std::string::npos);
  pose = rig.skeleton.restPose();
  rig.effectors[0].joint = 99;
  r = solve(rig.skeleton, pose, rig.effectors, SolveOptions{});
  EXPECT_EQ(r.status, SolveStatus::InvalidInput);
  EXPECT_NE(r.message.find("effectors[0].joint"), std::string::npos);
}

TEST(IkSolve, AnalyticSolverRefusesLongChainsWithNotApplicable) {
  Rig rig = buildIkChain(ChainDesc{}).value();
  Pose pose = rig.skeleton.restPose();
  SolveOptions o;
  o.solver = SolverKind::Analytic;
  const SolveResult r = solve(rig.skeleton, pose, rig.effectors, o);
  EXPECT_EQ(r.status, SolveStatus::NotApplicable);
  EXPECT_FALSE(r.message.empty());
}

// One table drives every name: the short names round-trip, the table lists the methods in
// SolverKind order without a gap, and the lists the lab's menus read match their enums' order.
TEST(IkSolverNames, RoundTripEverySolverAndListThemInOrder) {
  const std::vector<std::string> names = solverNames();
  ASSERT_EQ(names.size(), solverTable().size());
  for (size_t k = 0; k < names.size(); ++k) {
    EXPECT_EQ(static_cast<size_t>(solverTable()[k].value), k);
    SolverKind kind{};
    ASSERT_TRUE(solverFromName(names[k], &kind)) << names[k];
    EXPECT_EQ(static_cast<size_t>(kind), k);
    EXPECT_EQ(names[k], solverName(kind));
    EXPECT_FALSE(std::string(solverLongName(kind)).empty());
  }
  SolverKind kind{};
  EXPECT_FALSE(solverFromName("newton", &kind));
  EXPECT_EQ(lineSearchNames().size(), 3u);
  EXPECT_STREQ(lineSearchName(LineSearch::GoldenSection), "golden");
  EXPECT_EQ(jacobianLimitModeNames()[static_cast<size_t>(JacobianLimitMode::ZeroColumns)], "zero_columns");
  EXPECT_EQ(jacobianSourceNames()[static_cast<size_t>(JacobianSource::CentralDifferences)], "differences");
}

// Every setting of SolveOptions at its boundary: the value just outside the valid range (zero
// iteration caps, negative damping, tolerance ≤ 0, non-finite values, enum values out of range)
// gives InvalidInput with a message naming the field; the value on the boundary is accepted.
TEST(IkSolveOptions, EveryFieldIsValidatedAtItsBoundaryNamingTheField) {
  const Real nan = std::numeric_limits<Real>::quiet_NaN(), inf = std::numeric_limits<Real>::infinity();
  struct Case {
    const char* field;
    std::function<void(SolveOptions&)> bad;
    std::function<void(SolveOptions&)> edge;  // valid boundary value (nullptr: none to try)
  };
  const std::vector<Case> cases = {
      {"options.solver", [](SolveOptions& o) { o.solver = static_cast<SolverKind>(99); }, nullptr},
      {"options.tolerance", [](SolveOptions& o) { o.tolerance = 0.0; }, [](SolveOptions& o) { o.tolerance = 1e-300; }},
      {"options.tolerance", [nan](SolveOptions& o) { o.tolerance = nan; }, nullptr},
      {"options.angleTolerance", [](SolveOptions& o) { o.angleTolerance = -1e-3; }, nullptr},
      {"options.angleTolerance", [inf](SolveOptions& o) { o.angleTolerance = inf; }, nullptr},
      {"options.maxIterations", [](SolveOptions& o) { o.maxIterations = 0; },
       [](SolveOptions& o) { o.maxIterations = 1; }},
      {"options.maxSeconds", [](SolveOptions& o) { o.maxSeconds = -1e-9; },
       [](SolveOptions& o) { o.maxSeconds = 0.0; }},
      {"options.maxSeconds", [nan](SolveOptions& o) { o.maxSeconds = nan; }, nullptr},
      {"options.stallIterations", [](SolveOptions& o) { o.stallIterations = -1; },
       [](SolveOptions& o) { o.stallIterations = 0; }},
      {"options.stallRatio", [](SolveOptions& o) { o.stallRatio = 1.0; }, [](SolveOptions& o) { o.stallRatio = 0.0; }},
      {"options.stallRatio", [](SolveOptions& o) { o.stallRatio = -0.1; }, nullptr},
      {"options.limitMode", [](SolveOptions& o) { o.limitMode = static_cast<JacobianLimitMode>(7); }, nullptr},
      {"options.jacobian", [](SolveOptions& o) { o.jacobian = static_cast<JacobianSource>(-1); }, nullptr},
      {"options.damping", [](SolveOptions& o) { o.damping = -1e-9; }, [](SolveOptions& o) { o.damping = 0.0; }},
      {"options.damping", [inf](SolveOptions& o) { o.damping = inf; }, nullptr},
      {"options.singularCutoff", [](SolveOptions& o) { o.singularCutoff = 1.0; },
       [](SolveOptions& o) { o.singularCutoff = 0.0; }},
      {"options.singularCutoff", [nan](SolveOptions& o) { o.singularCutoff = nan; }, nullptr},
      {"options.maxErrorStep", [](SolveOptions& o) { o.maxErrorStep = -0.1; },
       [](SolveOptions& o) { o.maxErrorStep = 0.0; }},
      {"options.maxJointStep", [](SolveOptions& o) { o.maxJointStep = -0.1; },
       [](SolveOptions& o) { o.maxJointStep = 0.0; }},
      {"options.maxJointStep", [nan](SolveOptions& o) { o.maxJointStep = nan; }, nullptr},
      {"options.orientationScale", [](SolveOptions& o) { o.orientationScale = -1.0; },
       [](SolveOptions& o) { o.orientationScale = 0.0; }},
      {"options.polePoint", [nan](SolveOptions& o) { o.polePoint = Vec3(0.0, nan, 0.0); }, nullptr},
      {"options.lineSearch", [](SolveOptions& o) { o.lineSearch = static_cast<LineSearch>(3); }, nullptr},
      {"options.gradientStep", [](SolveOptions& o) { o.gradientStep = 0.0; }, nullptr},
      {"options.lineSearchMaxStep", [](SolveOptions& o) { o.lineSearchMaxStep = 0.0; }, nullptr},
      {"options.lbfgsMemory", [](SolveOptions& o) { o.lbfgsMemory = 0; }, [](SolveOptions& o) { o.lbfgsMemory = 1; }},
      {"options.restarts", [](SolveOptions& o) { o.restarts = -1; }, [](SolveOptions& o) { o.restarts = 0; }},
      {"options.ccdMaxTurn", [](SolveOptions& o) { o.ccdMaxTurn = -0.01; },
       [](SolveOptions& o) { o.ccdMaxTurn = 0.0; }},
      {"options.ccdMaxTurn", [nan](SolveOptions& o) { o.ccdMaxTurn = nan; }, nullptr},
  };
  ChainDesc d;
  d.links = 2;
  const Rig rig = buildIkChain(d).value();
  for (const Case& c : cases) {
    SolveOptions o;
    c.bad(o);
    Pose pose = rig.skeleton.restPose();
    const SolveResult r = solve(rig.skeleton, pose, rig.effectors, o);
    EXPECT_EQ(r.status, SolveStatus::InvalidInput) << c.field;
    EXPECT_EQ(r.message.rfind(std::string(c.field) + ":", 0), 0u) << c.field << " → " << r.message;
    EXPECT_EQ(pose.dofs, rig.skeleton.restPose().dofs) << "an invalid solve leaves the pose alone";
    if (!c.edge) continue;
    SolveOptions edge;
    c.edge(edge);
    EXPECT_TRUE(validate(edge).ok()) << c.field << ": " << validate(edge).error();
  }
  EXPECT_TRUE(validate(SolveOptions{}).ok());
}

// Horn's fit (FABRIK's sub-bases): exact for a rotated point set; with the points leaving a rotation
// free (one point, or coincident points) the member of the optimal family nearest the reference.
TEST(IkInternals, FitRotationRecoversARotationAndOtherwisePrefersTheReference) {
  std::mt19937_64 rng(1);
  std::normal_distribution<Real> n;
  for (int t = 0; t < 50; ++t) {
    const Quat q = glm::normalize(Quat(n(rng), n(rng), n(rng), n(rng)));
    std::vector<Vec3> from, to;
    const std::vector<Real> w(4, 1.0);
    for (int i = 0; i < 4; ++i) {
      from.emplace_back(n(rng), n(rng), n(rng));
      to.push_back(q * from.back());
    }
    const Quat fit = detail::fitRotation(from, to, w, Quat(1, 0, 0, 0));
    for (int i = 0; i < 4; ++i) EXPECT_VEC3_NEAR(fit * from[size_t(i)], to[size_t(i)], 1e-12);
    // One point (twice, as coincident branch joints): the shortest arc from the reference.
    const Quat reference = glm::normalize(Quat(n(rng), n(rng), n(rng), n(rng)));
    const std::vector<Vec3> one{from[0], from[0]}, target{to[0], to[0]};
    const Quat single = detail::fitRotation(one, target, {1.0, 1.0}, reference);
    const Quat expected = shortestArc(reference * from[0], to[0]) * reference;
    EXPECT_VEC3_NEAR(single * from[0], to[0], 1e-12);
    EXPECT_NEAR(std::abs(glm::dot(single, expected)), 1.0, 1e-12);
  }
}

// A ball joint limited to ±120° admits rotations with |b| > 90° only in the second XYZ Euler
// representation (a + π, π − b, c + π): the one to clamp is the one inside the limits.
TEST(IkInternals, EulerWithinLimitsPicksTheRepresentationTheLimitsAdmit) {
  Joint joint;
  joint.type = JointType::Ball;
  for (int k = 0; k < 3; ++k) joint.lo[k] = -degToRad(120.0), joint.hi[k] = degToRad(120.0);
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<Real> u(-degToRad(120.0), degToRad(120.0));
  for (int t = 0; t < 1000; ++t) {
    const Vec3 e(u(rng), u(rng), u(rng));
    const Quat q = quatFromEulerXYZ(e);
    bool inside = false;
    const Vec3 got = detail::eulerWithinLimits(joint, q, &inside);
    EXPECT_TRUE(inside) << e.x << " " << e.y << " " << e.z;
    for (int k = 0; k < 3; ++k) EXPECT_LE(std::abs(got[k]), degToRad(120.0) + 1e-12);
    EXPECT_NEAR(std::abs(glm::dot(quatFromEulerXYZ(got), q)), 1.0, 1e-12);
  }
  // Outside the limits either way: reported, and the representation that clamping moves least.
  bool inside = true;
  detail::eulerWithinLimits(joint, glm::angleAxis(kPi, Vec3(0, 0, 1)) * glm::angleAxis(0.9 * kPi, Vec3(1, 0, 0)),
                            &inside);
  EXPECT_FALSE(inside);
}

}  // namespace
}  // namespace pba::ik
