// Unit tests of the IK exercises' functions in isolation (suite names carry the tag: IK_1_… IK_8_…).
// Expected values come from independent references computed here (rotations applied by glm, angles
// by acos, finite differences, the SVD formula of the damped step with Eigen's SVD).
#include <cmath>
#include <random>

#include <gtest/gtest.h>
#include <Eigen/SVD>

#include "physics/ik/builders.h"
#include "physics/ik/exercises.h"
#include "physics/ik/jacobian.h"
#include "support/expect_helpers.h"

namespace pba::ik {
namespace {

Vec3 randomVec(std::mt19937_64& rng, Real scale = 1.0) {
  std::uniform_real_distribution<Real> u(-scale, scale);
  return Vec3(u(rng), u(rng), u(rng));
}

TEST(IK_1_AnalyticSingleJoint, TurnsTheBoneOntoTheTargetDirection) {
  std::mt19937_64 rng(1);
  for (int i = 0; i < 1000; ++i) {
    const Vec3 b = randomVec(rng), t = randomVec(rng);
    const AxisAngle r = analyticSingleJoint(b, t);
    EXPECT_NEAR(glm::length(r.axis), 1.0, 1e-12);
    // Rotating b by the answer points it along t: 1e-12 (unit vectors, a few roundings).
    EXPECT_VEC3_NEAR(glm::angleAxis(r.angle, r.axis) * glm::normalize(b), glm::normalize(t), 1e-12);
    // The shortest such rotation: its axis is normal to both, its angle the one between them
    // (acos of the normalised dot product, accurate away from 0 and π: 1e-9 rad).
    EXPECT_NEAR(glm::dot(r.axis, glm::normalize(b)), 0.0, 1e-12);
    EXPECT_NEAR(glm::dot(r.axis, glm::normalize(t)), 0.0, 1e-12);
    EXPECT_NEAR(r.angle, std::acos(glm::dot(glm::normalize(b), glm::normalize(t))), 1e-9);
  }
}

TEST(IK_1_AnalyticSingleJoint, ParallelOppositeAndZeroDirectionsAreSafe) {
  const Vec3 x(1, 0, 0);
  EXPECT_NEAR(analyticSingleJoint(x, 2.0 * x).angle, 0.0, 1e-15);
  const AxisAngle opposite = analyticSingleJoint(x, -x);
  EXPECT_NEAR(opposite.angle, kPi, 1e-15);
  EXPECT_NEAR(glm::dot(opposite.axis, x), 0.0, 1e-15);
  EXPECT_VEC3_NEAR(glm::angleAxis(opposite.angle, opposite.axis) * x, -x, 1e-15);
  EXPECT_EQ(analyticSingleJoint(Vec3(0.0), x).angle, 0.0);
  EXPECT_EQ(analyticSingleJoint(x, Vec3(0.0)).angle, 0.0);
}

TEST(IK_2_CcdJointUpdate, RotatesTheEffectorOntoTheRayToTheTarget) {
  std::mt19937_64 rng(2);
  for (int i = 0; i < 1000; ++i) {
    const Vec3 p = randomVec(rng), e = p + randomVec(rng), t = p + randomVec(rng, 3.0);
    const Quat q = ccdJointUpdate(p, e, t);
    const Vec3 moved = p + q * (e - p);
    // Same distance from the pivot, and on the ray pivot → target.
    EXPECT_NEAR(glm::length(moved - p), glm::length(e - p), 1e-12);
    EXPECT_VEC3_NEAR(glm::normalize(moved - p), glm::normalize(t - p), 1e-12);
    // The shortest arc: a unit quaternion turning about V1 × V2 by the angle between V1 and V2
    // (acos of the normalised dot product: 1e-9 rad), not a rotation with a twist added.
    EXPECT_NEAR(glm::length(glm::dvec4(q.w, q.x, q.y, q.z)), 1.0, 1e-12);
    const Vec3 n1 = glm::normalize(e - p), n2 = glm::normalize(t - p);
    EXPECT_VEC3_NEAR(rotationVector(q), std::acos(glm::dot(n1, n2)) * glm::normalize(glm::cross(n1, n2)), 1e-9);
  }
}

TEST(IK_2_CcdJointUpdate, DegenerateCasesGiveUnitQuaternions) {
  const Vec3 p(0.0), x(1, 0, 0);
  for (const Quat& q :
       {ccdJointUpdate(p, p, x), ccdJointUpdate(p, x, p), ccdJointUpdate(p, x, 3.0 * x), ccdJointUpdate(p, x, -x)}) {
    EXPECT_NEAR(glm::length(glm::dvec4(q.w, q.x, q.y, q.z)), 1.0, 1e-15);
  }
  EXPECT_VEC3_NEAR(ccdJointUpdate(p, x, -2.0 * x) * x, -x, 1e-15);
}

// Closed forms by geometry: a point 2 m from a z hinge moves at 2 m/s per rad along +y (right-hand
// rule); a prismatic DOF moves every point at 1 m/s along its axis; a ball joint at zero angles turns
// about R_pre's x, y and z.
TEST(IK_3_JacobianColumn, GivesTheCircleVelocityOfEachDofType) {
  Joint hinge;
  hinge.type = JointType::Hinge;
  hinge.axis = Vec3(0, 0, 1);
  const Frame atX{Vec3(1, 0, 0), Quat(1, 0, 0, 0), Quat(1, 0, 0, 0)};
  const JointColumns h = jointJacobianColumns(hinge, Pose{}, atX, Vec3(3, 0, 0));
  EXPECT_VEC3_NEAR(h.column[0], Vec3(0, 2, 0), 1e-15);
  EXPECT_VEC3_NEAR(h.axis[0], Vec3(0, 0, 1), 1e-15);
  // The same hinge with its frame turned a quarter turn about x: the axis is world −y.
  const Frame turned{Vec3(0.0), glm::angleAxis(0.5 * kPi, Vec3(1, 0, 0)), glm::angleAxis(0.5 * kPi, Vec3(1, 0, 0))};
  const JointColumns t = jointJacobianColumns(hinge, Pose{}, turned, Vec3(1, 0, 0));
  EXPECT_VEC3_NEAR(t.axis[0], Vec3(0, -1, 0), 1e-15);
  EXPECT_VEC3_NEAR(t.column[0], Vec3(0, 0, 1), 1e-15);
  Joint slider = hinge;
  slider.type = JointType::Prismatic;
  const JointColumns p = jointJacobianColumns(slider, Pose{}, turned, Vec3(5, 4, 3));
  EXPECT_VEC3_NEAR(p.column[0], Vec3(0, -1, 0), 1e-15);
  Skeleton s;
  Joint ball;
  ball.type = JointType::Ball;
  ASSERT_TRUE(s.add(ball).ok());
  const Pose rest = s.restPose();
  const JointColumns b = jointJacobianColumns(s.joint(0), rest, Frame{}, Vec3(0, 1, 0));
  EXPECT_VEC3_NEAR(b.column[0], Vec3(0, 0, 1), 1e-15);   // x̂ × ŷ
  EXPECT_VEC3_NEAR(b.column[1], Vec3(0.0), 1e-15);       // on the y axis
  EXPECT_VEC3_NEAR(b.column[2], Vec3(-1, 0, 0), 1e-15);  // ẑ × ŷ
}

// Every DOF type on one tree, with a position and a 6-DOF effector: analytic J vs central finite
// differences. With h = 1e-6 the truncation error is O(h²) ≈ 1e-12 and rounding ≈ 1e-16/h = 1e-10.
TEST(IK_3_JacobianColumn, MatchesCentralFiniteDifferencesForEveryDofType) {
  for (JointType type : {JointType::Hinge, JointType::Ball, JointType::Free, JointType::Prismatic}) {
    Skeleton s;
    Joint root;
    root.type = JointType::Ball;
    root.offset = Vec3(0.1, 0.2, 0.3);
    ASSERT_TRUE(s.add(root).ok());
    Joint j;
    j.parent = 0;
    j.offset = Vec3(0.5, 0.1, 0.0);
    j.type = type;
    j.axis = glm::normalize(Vec3(0.3, 1.0, -0.4));
    j.restRotation = glm::angleAxis(0.4, glm::normalize(Vec3(1, 1, 0)));
    ASSERT_TRUE(s.add(j).ok());
    Joint tip;
    tip.parent = 1;
    tip.offset = Vec3(0.4, 0.0, 0.1);
    tip.type = JointType::Hinge;
    ASSERT_TRUE(s.add(tip).ok());
    std::mt19937_64 rng(11);
    for (int trial = 0; trial < 20; ++trial) {
      Pose pose = randomPose(s, rng);
      std::vector<Effector> effectors(2);
      effectors[0].joint = 2;
      effectors[0].localOffset = Vec3(0.3, 0.0, 0.0);
      effectors[0].kind = EffectorKind::PositionOrientation;
      effectors[0].targetPosition = Vec3(1, 1, 1);
      effectors[0].targetOrientation = glm::angleAxis(1.0, Vec3(0, 1, 0));
      effectors[1].joint = 1;
      effectors[1].localOffset = Vec3(0.1, 0.2, 0.0);
      effectors[1].targetPosition = Vec3(-1, 0.5, 0.2);
      const std::vector<Frame> frames = forwardKinematics(s, pose);
      const Real scale = 0.7;
      const JacobianLayout L = planJacobian(s, pose, effectors, frames, scale);
      const Matrix J = jacobian(s, pose, effectors, frames, L, scale);
      const Matrix N = numericalJacobian(s, pose, effectors, L, scale, 1e-6);
      Real worst = 0.0;
      for (size_t i = 0; i < J.data.size(); ++i) worst = std::max(worst, std::abs(J.data[i] - N.data[i]));
      EXPECT_LT(worst, 1e-6) << jointTypeName(type) << " trial " << trial;
    }
  }
}

TEST(IK_4_DampedLeastSquaresStep, EqualsTheSingularValueFormula) {
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  for (Real lambda : {0.0, 0.1, 1.0}) {
    Matrix J(3, 7);
    for (Real& x : J.data) x = u(rng);
    const std::vector<Real> e = {u(rng), u(rng), u(rng)};
    const std::vector<Real> step = dampedLeastSquaresStep(J, e, lambda);
    // Reference: Σ σ/(σ² + λ²) (u·e) v from Eigen's SVD of J (not the normal equations the step solves).
    Eigen::MatrixXd Je(3, 7);
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 7; ++c) Je(r, c) = J(r, c);
    const Eigen::JacobiSVD<Eigen::MatrixXd> d(Je, Eigen::ComputeThinU | Eigen::ComputeThinV);
    const Eigen::Vector3d ee(e[0], e[1], e[2]);
    Eigen::VectorXd expected = Eigen::VectorXd::Zero(7);
    for (int i = 0; i < 3; ++i) {
      const Real s = d.singularValues()(i);
      expected += s / (s * s + lambda * lambda) * d.matrixU().col(i).dot(ee) * d.matrixV().col(i);
    }
    ASSERT_EQ(step.size(), 7u);
    for (size_t k = 0; k < 7; ++k) EXPECT_NEAR(step[k], expected(Eigen::Index(k)), 1e-10) << "lambda " << lambda;
  }
}

TEST(IK_4_DampedLeastSquaresStep, IsFiniteForASingularJacobian) {
  Matrix J(3, 2);  // both columns equal: J Jᵀ singular; the damping keeps the solve well posed
  J(0, 0) = J(0, 1) = 1.0;
  const std::vector<Real> step = dampedLeastSquaresStep(J, {1.0, 1.0, 0.0}, 0.1);
  ASSERT_EQ(step.size(), 2u);
  EXPECT_TRUE(isFinite(step[0]) && isFinite(step[1]));
  EXPECT_NEAR(step[0], step[1], 1e-15);
  // Independent reference by hand: J Jᵀ = diag(2, 0, 0), so (J Jᵀ + λ² I)⁻¹ e = (1/2.01, 1/0.01, 0)
  // and Jᵀ of that is (1/2.01, 1/2.01). Equivalently σ = √2, u = x, v = (1, 1)/√2 in the SVD formula.
  EXPECT_NEAR(step[0], 1.0 / 2.01, 1e-12);
  EXPECT_NEAR(step[1], 1.0 / 2.01, 1e-12);
  // λ = 0 on the same J: J Jᵀ is singular and no step is defined; step (3) returns zeros.
  for (Real x : dampedLeastSquaresStep(J, {1.0, 1.0, 0.0}, 0.0)) EXPECT_EQ(x, 0.0);
}

// IK-7 against Eigen: the direction is Jᵀ r (Eigen's product), and α minimises the linearised error
// φ(α) = |r − α J d|² along it: φ is a parabola, so its central difference at α vanishes and every other
// α on either side gives a larger φ.
TEST(IK_7_JacobianTransposeStep, IsSteepestDescentWithTheBestLengthAlongIt) {
  std::mt19937_64 rng(77);
  std::normal_distribution<Real> n(0.0, 1.0);
  for (int trial = 0; trial < 50; ++trial) {
    const int rows = 3 + trial % 4, cols = 2 + trial % 7;
    Matrix J(rows, cols);
    Eigen::MatrixXd je(rows, cols);
    for (int r = 0; r < rows; ++r)
      for (int c = 0; c < cols; ++c) je(r, c) = J(r, c) = n(rng);
    std::vector<Real> error(static_cast<size_t>(rows));
    Eigen::VectorXd re(rows);
    for (int r = 0; r < rows; ++r) re(r) = error[static_cast<size_t>(r)] = n(rng);
    const TransposeStep t = jacobianTransposeStep(J, error);
    const Eigen::VectorXd d = je.transpose() * re;
    ASSERT_EQ(t.direction.size(), static_cast<size_t>(cols));
    for (int c = 0; c < cols; ++c) EXPECT_NEAR(t.direction[static_cast<size_t>(c)], d(c), 1e-12);
    auto phi = [&](Real a) { return (re - a * (je * d)).squaredNorm(); };
    EXPECT_GT(t.alpha, 0.0);
    const Real da = 1e-4 * t.alpha;
    EXPECT_NEAR((phi(t.alpha + da) - phi(t.alpha - da)) / (2.0 * da), 0.0, 1e-8 * (1.0 + phi(0.0)));
    EXPECT_LT(phi(t.alpha), phi(0.9 * t.alpha));
    EXPECT_LT(phi(t.alpha), phi(1.1 * t.alpha));
  }
}

TEST(IK_7_JacobianTransposeStep, IdentityGivesTheErrorAndAStationaryPointGivesNoLength) {
  Matrix I(3, 3);
  for (int k = 0; k < 3; ++k) I(k, k) = 1.0;
  const TransposeStep t = jacobianTransposeStep(I, {0.3, -0.2, 0.5});
  EXPECT_NEAR(t.alpha, 1.0, 1e-15);
  EXPECT_NEAR(t.direction[1], -0.2, 1e-15);
  // r orthogonal to every column: no descent direction, α = 0 (the solver stops).
  Matrix J(3, 2);
  J(0, 0) = 1.0;
  J(1, 1) = 2.0;
  const TransposeStep s = jacobianTransposeStep(J, {0.0, 0.0, 1.0});
  EXPECT_EQ(s.alpha, 0.0);
  for (Real x : s.direction) EXPECT_EQ(x, 0.0);
}

TEST(IK_5_FabrikPasses, KeepTheSegmentLengthsAndPinTheEnds) {
  std::mt19937_64 rng(5);
  std::vector<Vec3> points = {Vec3(0.0)};
  std::vector<Real> lengths;
  for (int i = 0; i < 8; ++i) {
    points.push_back(points.back() + randomVec(rng, 0.5));
    lengths.push_back(glm::length(points.back() - points[points.size() - 2]));
  }
  const Vec3 target(0.7, 0.4, -0.2);
  fabrikBackward(points, lengths, target);
  EXPECT_VEC3_NEAR(points.back(), target, 0.0);
  for (size_t i = 0; i < lengths.size(); ++i) EXPECT_NEAR(glm::length(points[i + 1] - points[i]), lengths[i], 1e-12);
  fabrikForward(points, lengths, Vec3(0.0));
  EXPECT_VEC3_NEAR(points.front(), Vec3(0.0), 0.0);
  for (size_t i = 0; i < lengths.size(); ++i) EXPECT_NEAR(glm::length(points[i + 1] - points[i]), lengths[i], 1e-12);
}

TEST(IK_5_FabrikPasses, ConvergeOnAReachableTargetAndCoincidentPointsStayFinite) {
  std::vector<Vec3> points = {Vec3(0.0), Vec3(1, 0, 0), Vec3(2, 0, 0), Vec3(3, 0, 0)};
  const std::vector<Real> lengths = {1, 1, 1};
  const Vec3 target(1.0, 1.5, 0.5);
  for (int it = 0; it < 100; ++it) {
    fabrikBackward(points, lengths, target);
    fabrikForward(points, lengths, Vec3(0.0));
  }
  EXPECT_LT(glm::length(points.back() - target), 1e-6);
  std::vector<Vec3> same(4, Vec3(0.0));
  fabrikBackward(same, lengths, Vec3(0.0));
  fabrikForward(same, lengths, Vec3(0.0));
  for (const Vec3& p : same) EXPECT_TRUE(isFinite(p));
}

TEST(IK_6_JointLimitClamping, ClampsScalarDofsAndFreeJointAngles) {
  Skeleton s;
  Joint ball;
  ball.type = JointType::Ball;
  for (int k = 0; k < 3; ++k) {
    ball.lo[k] = -0.5;
    ball.hi[k] = 0.25;
  }
  ASSERT_TRUE(s.add(ball).ok());
  Joint free;
  free.parent = 0;
  free.type = JointType::Free;
  free.maxRotation = 0.3;
  ASSERT_TRUE(s.add(free).ok());
  Pose p = s.restPose();
  p.dofs = {-2.0, 0.1, 3.0};
  p.rotations[1] = glm::angleAxis(1.2, glm::normalize(Vec3(1, 2, 3)));
  clampJointToLimits(s, p, 0);
  clampJointToLimits(s, p, 1);
  EXPECT_EQ(p.dofs[0], -0.5);
  EXPECT_EQ(p.dofs[1], 0.1);
  EXPECT_EQ(p.dofs[2], 0.25);
  EXPECT_VEC3_NEAR(rotationVector(p.rotations[1]), 0.3 * glm::normalize(Vec3(1, 2, 3)), 1e-12);
  EXPECT_LE(limitViolation(s, p), 1e-12);
}

// IK-8 on a Jacobian whose singular triples are known in closed form: two unit-speed DOFs moving one
// effector in directions an angle t apart, j₁ = (1, 0, 0), j₂ = (cos t, sin t, 0), so ρ = (1, 1).
// JᵀJ = [[1, c], [c, 1]]: σ² = 1 ± c along v = (1, ±1)/√2, u = J v / σ. Then N = |u| = 1 and
// M = √2 / σ, so γ = γ_max σ/√2: cos(t/2) γ_max for the stiff direction and sin(t/2) γ_max for the
// nearly singular one (it asks the joints to swing far apart for a small effector motion).
TEST(IK_8_SelectiveDampingLimit, ScalesGammaMaxByTheRatioOfAskedToProducedMotion) {
  const Real gammaMax = 0.7;
  for (Real t : {0.05, 0.4, 1.0, 2.0, 3.0}) {
    const Real c = std::cos(t), s = std::sin(t);
    const std::vector<Real> rho{1.0, 1.0};
    for (Real sign : {1.0, -1.0}) {
      const Real sigma = std::sqrt(1.0 + sign * c);
      const std::vector<Real> v{1.0 / std::sqrt(2.0), sign / std::sqrt(2.0)};
      const std::vector<Real> u{(v[0] + v[1] * c) / sigma, v[1] * s / sigma, 0.0};
      const Real expected = (sign > 0.0 ? std::cos(0.5 * t) : std::sin(0.5 * t)) * gammaMax;
      EXPECT_NEAR(selectiveDampingLimit(u, v, sigma, rho, gammaMax), expected, 1e-12) << "t " << t << " sign " << sign;
    }
  }
}

TEST(IK_8_SelectiveDampingLimit, GivesGammaMaxWhenTheJointsMoveNoMoreThanAsked) {
  // One hinge moving one effector at 2 m: J = (0, 2, 0)ᵀ, σ = 2, u = (0, 1, 0), v = (1), ρ = 2.
  EXPECT_NEAR(selectiveDampingLimit({0.0, 1.0, 0.0}, {1.0}, 2.0, {2.0}, 0.5), 0.5, 1e-15);
  // The same hinge moving two effectors, at 1 m and 3 m: σ = √10, ρ = 4; the motion asked (sum of the
  // two blocks of u) equals the motion produced, so still γ_max.
  const Real sigma = std::sqrt(10.0);
  EXPECT_NEAR(selectiveDampingLimit({0.0, 1.0 / sigma, 0.0, 0.0, 3.0 / sigma, 0.0}, {1.0}, sigma, {4.0}, 0.5), 0.5,
              1e-14);
  // A DOF that swings the effector 10 times farther than its share asks: a tenth of γ_max. u has two
  // blocks of length 1/√2 each (N = √2); v = (1), ρ = 10√2, σ = 1: M = 10√2.
  const Real h = 1.0 / std::sqrt(2.0);
  EXPECT_NEAR(selectiveDampingLimit({h, 0.0, 0.0, 0.0, h, 0.0}, {1.0}, 1.0, {10.0 * std::sqrt(2.0)}, 0.5), 0.05, 1e-14);
  // Scaling J by k scales σ and ρ alike and leaves γ unchanged.
  EXPECT_NEAR(selectiveDampingLimit({h, 0.0, 0.0, 0.0, h, 0.0}, {1.0}, 7.0, {70.0 * std::sqrt(2.0)}, 0.5), 0.05, 1e-14);
}

}  // namespace
}  // namespace pba::ik
