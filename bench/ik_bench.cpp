// IK kernels (docs/performance-ik.md): microseconds per solve and iterations per solver on chains of
// 10 links (2,000 random reachable targets, cycled), 100 and 1,000 links; tolerance 1e-4 m, solves
// from the rest pose, SolveOptions' defaults: the methods as published (no restarts, no step clamp,
// no line search of the Jacobian methods; gradient descent with its golden-section search).
// Counters: iterations per solve and success rate (without restarts).
#include <random>
#include <vector>

#include <benchmark/benchmark.h>

#include "physics/ik/builders.h"
#include "physics/ik/solver.h"

namespace {
using namespace pba;
using namespace pba::ik;

// limit 0: ±120° for 10 links, ±30° per DOF for 100 and 1,000 links; otherwise the given limit
// (kPi: unconstrained ball joints, the setting of the FABRIK paper's Table 1).
// ccdMaxTurn > 0: CCD with SolveOptions::ccdMaxTurn (ours; 0 = CCD as published).
void solveChain(benchmark::State& state, SolverKind kind, JointType joint, Real limit = 0.0, Real ccdMaxTurn = 0.0) {
  ChainDesc d;
  d.links = static_cast<int>(state.range(0));
  d.joint = joint;
  d.limit = limit > 0.0 ? limit : d.links >= 100 ? degToRad(30.0) : degToRad(120.0);
  const Rig rig = buildIkChain(d).value();
  std::mt19937_64 rng(1);
  std::vector<std::vector<Effector>> goals;
  const int count = d.links <= 10 ? 2000 : 50;
  for (int i = 0; i < count; ++i) {
    std::vector<Effector> e = rig.effectors;
    setGoalsFromPose(rig.skeleton, randomPose(rig.skeleton, rng), e);
    goals.push_back(std::move(e));
  }
  SolveOptions o;
  o.solver = kind;
  o.maxIterations = d.links <= 10 ? 1000 : 200;
  o.ccdMaxTurn = ccdMaxTurn;
  long iterations = 0, solves = 0, successes = 0;
  size_t next = 0;
  SolveWorkspace workspace;
  for (auto _ : state) {
    Pose pose = rig.skeleton.restPose();
    const SolveResult r = solve(rig.skeleton, pose, goals[next], o, workspace);
    benchmark::DoNotOptimize(pose.dofs.data());
    next = (next + 1) % goals.size();
    iterations += r.iterations;
    successes += r.status == SolveStatus::Success;
    ++solves;
  }
  state.counters["iterations"] = solves ? double(iterations) / double(solves) : 0.0;
  state.counters["success"] = solves ? double(successes) / double(solves) : 0.0;
}

#define PBA_IK_BENCH_LIMIT(name, kind, joint, limit)                    \
  void name(benchmark::State& s) { solveChain(s, kind, joint, limit); } \
  BENCHMARK(name)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond)->MinTime(0.5)
#define PBA_IK_BENCH(name, kind, joint) PBA_IK_BENCH_LIMIT(name, kind, joint, 0.0)

PBA_IK_BENCH(BM_Ccd_Ball, SolverKind::Ccd, JointType::Ball);
PBA_IK_BENCH(BM_Fabrik_Ball, SolverKind::Fabrik, JointType::Ball);
PBA_IK_BENCH(BM_JacobianTranspose_Ball, SolverKind::JacobianTranspose, JointType::Ball);
PBA_IK_BENCH(BM_PseudoInverse_Ball, SolverKind::PseudoInverse, JointType::Ball);
PBA_IK_BENCH(BM_Dls_Ball, SolverKind::DampedLeastSquares, JointType::Ball);
PBA_IK_BENCH(BM_Sdls_Ball, SolverKind::SelectivelyDamped, JointType::Ball);
PBA_IK_BENCH(BM_Gradient_Ball, SolverKind::GradientDescent, JointType::Ball);  // golden-section line search
PBA_IK_BENCH(BM_Lbfgs_Ball, SolverKind::Lbfgs, JointType::Ball);
PBA_IK_BENCH(BM_Ccd_Hinge, SolverKind::Ccd, JointType::Hinge);
// The departure of ours for long limited chains (docs/performance-ik-ccd.md, "CCD on 1,000 limited
// hinges"): every joint turns by at most 0.02 rad (≈ 1.15°) per pass.
void BM_Ccd_HingeMaxTurn(benchmark::State& s) { solveChain(s, SolverKind::Ccd, JointType::Hinge, 0.0, 0.02); }
BENCHMARK(BM_Ccd_HingeMaxTurn)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond)->MinTime(0.5);
PBA_IK_BENCH(BM_Fabrik_Hinge, SolverKind::Fabrik, JointType::Hinge);
PBA_IK_BENCH(BM_Dls_Hinge, SolverKind::DampedLeastSquares, JointType::Hinge);
PBA_IK_BENCH_LIMIT(BM_Ccd_BallFree, SolverKind::Ccd, JointType::Ball, kPi);
PBA_IK_BENCH_LIMIT(BM_Fabrik_BallFree, SolverKind::Fabrik, JointType::Ball, kPi);
PBA_IK_BENCH_LIMIT(BM_Dls_BallFree, SolverKind::DampedLeastSquares, JointType::Ball, kPi);
PBA_IK_BENCH_LIMIT(BM_JacobianTranspose_BallFree, SolverKind::JacobianTranspose, JointType::Ball, kPi);

}  // namespace

BENCHMARK_MAIN();
