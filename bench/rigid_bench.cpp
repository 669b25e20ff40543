// Rigid-body benchmarks (issue 9, docs/performance-rigid.md), one thread:
//  * scenes against Debian's Bullet 3.24 in double precision (pkg-config bullet-float64), when present,
//    in the same run: Bullet's "3000 boxes" (bench-boxes) and "1000 stack" (pyramid, three walls and a
//    tower: 1,076 boxes). Same bodies, same dt (1/60 s), no sleeping on either side, 600 steps (10 s)
//    from the start; thread CPU ms per step and µs per body-step (the manual time). Ours twice: the soft step (4 substeps × 1
//    iteration + 1 relax) and one substep of 10 Baumgarte iterations, Bullet's own count.
//  * broad phase: pairs per millisecond for 10⁴ and 10⁵ moving spheres: tree, sweep and prune, and
//    brute force (10⁴ only).
// Run: build/release/bench/pba_rigid_bench
#include <ctime>
#include <random>
#include <vector>

#include <benchmark/benchmark.h>

#include "physics/collision/broad_phase.h"
#include "physics/rigid/builders.h"

#ifdef PBA_HAVE_BULLET
#include <btBulletDynamicsCommon.h>
#endif

#include "thread_cpu_time.h"
#include "timed_once.h"

namespace {
using namespace pba;

// The scene rows: each runs once, timed by its body (bench/timed_once.h).
void runOnce(benchmark::internal::Benchmark* b) { bench::timedOnce(b, {}); }

constexpr Real kDt = 1.0 / 60.0;
constexpr int kSteps = 600;

enum class Scene { Boxes3000, Stack1000 };
std::vector<rigid::BodyDesc> sceneBodies(Scene s) {
  return s == Scene::Boxes3000 ? rigid::benchBoxes() : rigid::benchStack1000();
}

void report(benchmark::State& state, double seconds, std::size_t bodies) {
  const double msPerStep = 1e3 * seconds / kSteps;
  state.SetIterationTime(seconds / kSteps);
  state.counters["ms_per_step"] = msPerStep;
  state.counters["us_per_body_step"] = 1e3 * msPerStep / static_cast<double>(bodies);
  state.counters["bodies"] = static_cast<double>(bodies);
}

void BM_Ours(benchmark::State& state, Scene scene, bool classic) {
  const std::vector<rigid::BodyDesc> bodies = sceneBodies(scene);
  for (auto _ : state) {
    rigid::WorldSettings s;
    s.sleeping = false;
    if (classic) {
      s.substeps = 1;
      s.iterations = 10;
      s.relaxIterations = 0;
      s.positionCorrection = rigid::PositionCorrection::Baumgarte;
    }
    rigid::World world(s);
    rigid::addGround(world, 0.5);
    rigid::addAll(world, bodies);
    const double t0 = bench::threadCpuSeconds();
    for (int i = 0; i < kSteps; ++i) world.step(kDt);
    report(state, bench::threadCpuSeconds() - t0, bodies.size());
    state.counters["solver_iterations"] = world.stats().solverIterations;
  }
}
BENCHMARK_CAPTURE(BM_Ours, boxes3000_soft_step, Scene::Boxes3000, false)->Apply(runOnce);
BENCHMARK_CAPTURE(BM_Ours, boxes3000_baumgarte_10, Scene::Boxes3000, true)->Apply(runOnce);
BENCHMARK_CAPTURE(BM_Ours, stack1000_soft_step, Scene::Stack1000, false)->Apply(runOnce);
BENCHMARK_CAPTURE(BM_Ours, stack1000_baumgarte_10, Scene::Stack1000, true)->Apply(runOnce);

#ifdef PBA_HAVE_BULLET
// Bullet's own defaults (btDbvtBroadphase, sequential impulses, 10 iterations, split impulse for
// penetrations), every body kept awake; boxes with Bullet's default collision margin.
void BM_Bullet(benchmark::State& state, Scene scene) {
  const std::vector<rigid::BodyDesc> bodies = sceneBodies(scene);
  for (auto _ : state) {
    btDefaultCollisionConfiguration configuration;
    btCollisionDispatcher dispatcher(&configuration);
    btDbvtBroadphase broadphase;
    btSequentialImpulseConstraintSolver solver;
    btDiscreteDynamicsWorld world(&dispatcher, &broadphase, &solver, &configuration);
    world.setGravity(btVector3(0, -kStandardGravity, 0));
    world.getSolverInfo().m_numIterations = 10;
    btStaticPlaneShape ground(btVector3(0, 1, 0), 0);
    btRigidBody groundBody(btRigidBody::btRigidBodyConstructionInfo(0.0, nullptr, &ground));
    groundBody.setFriction(0.5);
    world.addRigidBody(&groundBody);
    btBoxShape cube(btVector3(1, 1, 1));
    std::vector<std::unique_ptr<btRigidBody>> rigid;
    btVector3 inertia;
    for (const rigid::BodyDesc& d : bodies) {
      const Vec3& h = d.shape.halfExtents;
      btBoxShape* shape = &cube;
      if (h != Vec3(1.0)) return state.SkipWithError("bench scenes use unit cubes");
      shape->calculateLocalInertia(d.mass, inertia);
      btRigidBody::btRigidBodyConstructionInfo info(d.mass, nullptr, shape, inertia);
      info.m_startWorldTransform.setOrigin(btVector3(d.position.x, d.position.y, d.position.z));
      info.m_startWorldTransform.setRotation(
          btQuaternion(d.orientation.x, d.orientation.y, d.orientation.z, d.orientation.w));
      info.m_friction = d.friction;
      rigid.push_back(std::make_unique<btRigidBody>(info));
      rigid.back()->setActivationState(DISABLE_DEACTIVATION);
      world.addRigidBody(rigid.back().get());
    }
    const double t0 = bench::threadCpuSeconds();
    for (int i = 0; i < kSteps; ++i) world.stepSimulation(kDt, 0);
    report(state, bench::threadCpuSeconds() - t0, bodies.size());
    for (auto& b : rigid) world.removeRigidBody(b.get());
    world.removeRigidBody(&groundBody);
  }
  state.SetLabel("Bullet double precision, all awake");
}
BENCHMARK_CAPTURE(BM_Bullet, boxes3000, Scene::Boxes3000)->Apply(runOnce);
BENCHMARK_CAPTURE(BM_Bullet, stack1000, Scene::Stack1000)->Apply(runOnce);
#endif

// Broad phase: n spheres of radius 0.5 in a cube at density ~0.1, each moving a little every step; one
// iteration = move every proxy + find every pair.
void BM_BroadPhase(benchmark::State& state, collision::BroadPhaseKind kind) {
  const auto n = static_cast<int>(state.range(0));
  const Real side = std::cbrt(static_cast<Real>(n) / 0.1);
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<Real> u(0.0, side), step(-0.05, 0.05);
  std::vector<Vec3> x(n);
  collision::BroadPhase bp(kind, 0.1);
  std::vector<int> proxy(n);
  for (int i = 0; i < n; ++i) {
    x[i] = Vec3(u(rng), u(rng), u(rng));
    proxy[i] = bp.add({x[i] - Vec3(0.5), x[i] + Vec3(0.5)}, i, false);
  }
  std::vector<std::pair<int, int>> pairs;
  std::size_t total = 0;
  for (auto _ : state) {
    for (int i = 0; i < n; ++i) {
      x[i] += Vec3(step(rng), step(rng), step(rng));
      bp.move(proxy[i], {x[i] - Vec3(0.5), x[i] + Vec3(0.5)});
    }
    bp.findPairs(pairs);
    total += pairs.size();
    benchmark::DoNotOptimize(pairs.data());
  }
  state.counters["pairs"] = static_cast<double>(pairs.size());
  state.counters["pairs_per_ms"] = benchmark::Counter(static_cast<double>(total) / 1e3, benchmark::Counter::kIsRate);
}
BENCHMARK_CAPTURE(BM_BroadPhase, tree, collision::BroadPhaseKind::Tree)
    ->Arg(10000)
    ->Arg(100000)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_BroadPhase, sap, collision::BroadPhaseKind::SweepAndPrune)
    ->Arg(10000)
    ->Arg(100000)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_BroadPhase, brute_force, collision::BroadPhaseKind::BruteForce)
    ->Arg(10000)
    ->Unit(benchmark::kMillisecond);

}  // namespace
BENCHMARK_MAIN();
