// IK against a peer in the same run (docs/performance-ik-kdl.md, "Against Orocos KDL"): our solvers and,
// when liborocos-kdl-dev is installed, KDL's Levenberg-Marquardt solver ChainIkSolverPos_LMA on the
// same chains and the same goals.
//
// Chains: 10, 100 and 1,000 ball joints along +x, total length 2 m, every DOF limited to ±120°. Our
// ball joint is R = Rx(θ₀)·Ry(θ₁)·Rz(θ₂) (skeleton.h); in KDL it is three segments with revolute
// joints RotX, RotY and RotZ, the bone (L, 0, 0) on the last, so both chains have the same 3n DOFs in
// the same order (checked at set-up: KDL's forward kinematics of every goal pose matches ours).
// Goals: FK of random poses, every DOF uniform in ±120° (seed 1). Every solve starts from the
// straight pose (all DOFs 0), position only, tolerance 1e-3 m, one thread, iteration cap 500 (KDL's
// default maxiter). KDL: weights L = (1, 1, 1, 0, 0, 0) (position only); its eps applies to the
// weighted error norm, i.e. the position error in metres, the same test as ours. KDL's solver has no
// joint limits; ours clamp to ±120° (SolveOptions' defaults: the methods as published).
// Time: microseconds per solve (CPU time); counters: iterations per solve and success rate.
//
//   cmake --build build/release -j2 --target pba_ik_kdl_bench && build/release/bench/pba_ik_kdl_bench
#include <random>
#include <vector>

#include <benchmark/benchmark.h>

#include "physics/ik/builders.h"
#include "physics/ik/solver.h"

#ifdef PBA_HAVE_KDL
#include <kdl/chain.hpp>
#include <kdl/chainfksolverpos_recursive.hpp>
#include <kdl/chainiksolverpos_lma.hpp>
#endif

namespace {
using namespace pba;
using namespace pba::ik;

constexpr Real kTolerance = 1e-3;  // [m]
constexpr int kIterationCap = 500;

// The chain and its goals for one size (built once per size and shared by every solver).
struct Problem {
  Rig rig;
  std::vector<Pose> poses;  // the random poses the goals come from
  std::vector<Vec3> goals;  // [m] tip positions of those poses
};

const Problem& problem(int links) {
  static std::vector<std::pair<int, Problem>> cache;
  for (const auto& [n, p] : cache)
    if (n == links) return p;
  ChainDesc d;
  d.links = links;
  d.joint = JointType::Ball;
  d.totalLength = 2.0;
  d.limit = degToRad(120.0);
  Problem p{buildIkChain(d).value(), {}, {}};
  std::mt19937_64 rng(1);
  const int count = links <= 10 ? 1000 : links <= 100 ? 100 : 20;
  for (int i = 0; i < count; ++i) {
    p.poses.push_back(randomPose(p.rig.skeleton, rng));
    std::vector<Effector> e = p.rig.effectors;
    setGoalsFromPose(p.rig.skeleton, p.poses.back(), e);
    p.goals.push_back(e[0].targetPosition);
  }
  cache.emplace_back(links, std::move(p));
  return cache.back().second;
}

// maxErrorStep 0: Buss's D_max = the mean bone length (the default: 2 m / links, so DLS and SDLS need
// O(links) steps to cross the workspace); otherwise that clamp [m] at every size.
void ours(benchmark::State& state, SolverKind kind, Real maxErrorStep = 0.0) {
  const Problem& p = problem(static_cast<int>(state.range(0)));
  SolveOptions o;
  o.solver = kind;
  o.tolerance = kTolerance;
  o.maxIterations = kIterationCap;
  o.maxErrorStep = maxErrorStep;
  std::vector<Effector> effectors = p.rig.effectors;
  long iterations = 0, solves = 0, successes = 0;
  size_t next = 0;
  SolveWorkspace workspace;
  for (auto _ : state) {
    effectors[0].targetPosition = p.goals[next];
    Pose pose = p.rig.skeleton.restPose();
    const SolveResult r = solve(p.rig.skeleton, pose, effectors, o, workspace);
    benchmark::DoNotOptimize(pose.dofs.data());
    next = (next + 1) % p.goals.size();
    iterations += r.iterations;
    successes += r.status == SolveStatus::Success;
    ++solves;
  }
  state.counters["iterations"] = solves ? double(iterations) / double(solves) : 0.0;
  state.counters["success"] = solves ? double(successes) / double(solves) : 0.0;
}

#define PBA_IK_OURS_CLAMP(name, kind, clamp)               \
  void name(benchmark::State& s) { ours(s, kind, clamp); } \
  BENCHMARK(name)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond)->MinTime(0.3)
#define PBA_IK_OURS(name, kind) PBA_IK_OURS_CLAMP(name, kind, 0.0)

PBA_IK_OURS(BM_Ours_Dls, SolverKind::DampedLeastSquares);
PBA_IK_OURS(BM_Ours_Sdls, SolverKind::SelectivelyDamped);
PBA_IK_OURS(BM_Ours_Lbfgs, SolverKind::Lbfgs);
PBA_IK_OURS(BM_Ours_Fabrik, SolverKind::Fabrik);
PBA_IK_OURS(BM_Ours_Ccd, SolverKind::Ccd);
// The same methods with Buss's clamp D_max = 0.2 m (a tenth of the reach) at every size: an option of
// SolveOptions (maxErrorStep), not the default.
PBA_IK_OURS_CLAMP(BM_Ours_Dls_Dmax20cm, SolverKind::DampedLeastSquares, 0.2);
PBA_IK_OURS_CLAMP(BM_Ours_Sdls_Dmax20cm, SolverKind::SelectivelyDamped, 0.2);

#ifdef PBA_HAVE_KDL
// The same chain in KDL: per ball joint, revolute joints about x, y and z at one point, then the bone.
KDL::Chain kdlChain(const Skeleton& s, Real boneLength) {
  KDL::Chain chain;
  for (int j = 0; j < s.jointCount(); ++j) {
    chain.addSegment(KDL::Segment(KDL::Joint(KDL::Joint::RotX)));
    chain.addSegment(KDL::Segment(KDL::Joint(KDL::Joint::RotY)));
    chain.addSegment(KDL::Segment(KDL::Joint(KDL::Joint::RotZ), KDL::Frame(KDL::Vector(boneLength, 0.0, 0.0))));
  }
  return chain;
}

void kdlLma(benchmark::State& state) {
  const int links = static_cast<int>(state.range(0));
  const Problem& p = problem(links);
  const KDL::Chain chain = kdlChain(p.rig.skeleton, 2.0 / links);
  const unsigned n = chain.getNrOfJoints();
  // Set-up check: KDL's FK of each goal pose lands on our goal (same chain, same DOF order).
  KDL::ChainFkSolverPos_recursive fk(chain);
  for (size_t i = 0; i < p.poses.size(); ++i) {
    KDL::JntArray q(n);
    for (unsigned k = 0; k < n; ++k) q(k) = p.poses[i].dofs[k];
    KDL::Frame tip;
    fk.JntToCart(q, tip);
    const Vec3 d = Vec3(tip.p.x(), tip.p.y(), tip.p.z()) - p.goals[i];
    if (glm::length(d) > 1e-9) {
      state.SkipWithError("KDL chain differs from ours (forward kinematics)");
      return;
    }
  }
  Eigen::Matrix<double, 6, 1> L;
  L << 1.0, 1.0, 1.0, 0.0, 0.0, 0.0;
  KDL::ChainIkSolverPos_LMA solver(chain, L, kTolerance, kIterationCap);
  KDL::JntArray straight(n), out(n);
  long iterations = 0, solves = 0, successes = 0;
  size_t next = 0;
  for (auto _ : state) {
    const Vec3& g = p.goals[next];
    const int rc = solver.CartToJnt(straight, KDL::Frame(KDL::Vector(g.x, g.y, g.z)), out);
    benchmark::DoNotOptimize(out.data.data());
    next = (next + 1) % p.goals.size();
    iterations += solver.lastNrOfIter;
    successes += rc == KDL::SolverI::E_NOERROR;
    ++solves;
  }
  state.counters["iterations"] = solves ? double(iterations) / double(solves) : 0.0;
  state.counters["success"] = solves ? double(successes) / double(solves) : 0.0;
}
BENCHMARK(kdlLma)->Name("BM_Kdl_Lma")->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond)->MinTime(0.3);
#endif

}  // namespace

BENCHMARK_MAIN();
