// Particles benchmarks (issue 4, docs/architecture.md §8): particle updates per second per core of the fused
// gravity + drag + plane kernel at 10⁴ and 10⁶ particles beside a STREAM-like triad (the memory
// bandwidth limit, measured in the same run); cost per particle of spatial-hash pair collisions at 10⁵,
// per sweep and through a neighbour list; one fountain pool step at 10⁵ and 10⁶, and the same with parts
// of the scene taken away (where its time goes), beside one call of PART-5 on a resting particle; ns per
// degree of freedom per step of every integrator on a large oscillator system.
// Run: build/release/bench/pba_particles_bench (see docs/performance-particles.md).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <random>
#include <string>
#include <vector>

#include "physics/ode/integrators.h"
#include "physics/ode/oscillator.h"
#include "physics/particles/emitter.h"
#include "physics/particles/kernels.h"
#include "physics/particles/spatial_hash.h"
#include "roofline.h"
#include "thread_cpu_time.h"

namespace {
using namespace pba;

// STREAM triad a = b + s·c over doubles: 24 bytes moved per element (two reads, one write).
void BM_StreamTriad(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  std::vector<double> a(n, 0.0), b(n, 1.0), c(n, 2.0);
  for (auto _ : state) bench::triad(a, b, c, 3.0);
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * n * 24));
}
BENCHMARK(BM_StreamTriad)->Arg(1 << 22)->Arg(1 << 25);

// Fused particle update: reads and writes x and v, 96 bytes per particle.
void BM_ParticlesGravityDragPlane(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<Real> u(0.0, 10.0);
  std::vector<Vec3> x(n), v(n, Vec3(0.0));
  for (Vec3& p : x) p = Vec3(u(rng), u(rng), u(rng));
  particles::FusedStepDesc desc;
  desc.dragRate = 0.1;
  desc.radius = 0.01;
  // A tiny step keeps the particles in the same regime however many iterations run (a few in contact,
  // most in flight); with 1e-3 the small case would run long enough for everything to land and rest.
  for (auto _ : state) {
    particles::stepGravityDragPlane(x, v, desc, 1e-5);
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * n));
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * n * 96));
}
BENCHMARK(BM_ParticlesGravityDragPlane)->Arg(10000)->Arg(1000000)->Arg(4000000);

// Spatial hash build + one sweep of pair collisions, random particles at a granular density.
constexpr Real kCloudRadius = 0.01;  // [m] particle radius of the pair-collision benchmarks

/// n particles of radius kCloudRadius at random in a cube sized for a volume fraction of ≈ 0.13.
particles::Particles randomCloud(std::size_t n) {
  const Real side = std::cbrt(static_cast<Real>(n)) * 2.5 * kCloudRadius;
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<Real> u(0.0, side);
  particles::Particles p;
  for (std::size_t i = 0; i < n; ++i) p.add(Vec3(u(rng), u(rng), u(rng)), Vec3(0.0), 1.0);
  return p;
}

void BM_SpatialHashCollisions(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const Real radius = kCloudRadius;
  const particles::Particles start = randomCloud(n);
  particles::Particles p = start;
  particles::SpatialHash hash;
  for (auto _ : state) {
    state.PauseTiming();
    p = start;
    state.ResumeTiming();
    benchmark::DoNotOptimize(particles::collideParticlePairs(p, radius, 0.2, hash));
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * n));
}
BENCHMARK(BM_SpatialHashCollisions)->Arg(100000)->Unit(benchmark::kMillisecond);

// The same particles through a Verlet neighbour list: one list build (hash build + one query per
// particle, skin = radius) and the granular scene's three sweeps over the pairs.
void BM_NeighbourListBuildAndThreeSweeps(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const Real radius = kCloudRadius;
  const particles::Particles start = randomCloud(n);
  particles::Particles p = start;
  particles::SpatialHash hash;
  particles::NeighbourList list;
  for (auto _ : state) {
    state.PauseTiming();
    p = start;
    list.invalidate();
    state.ResumeTiming();
    list.update(p.position, 2.0 * radius, radius, hash);
    for (int sweep = 0; sweep < 3; ++sweep) {
      benchmark::DoNotOptimize(particles::collideParticlePairs(p, radius, 0.2, list.pairs()));
    }
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * n));
}
BENCHMARK(BM_NeighbourListBuildAndThreeSweeps)->Arg(100000)->Unit(benchmark::kMillisecond);

// One step of the fountain's pool (particles::stepFountain + Emitter::spawn) with the lab's fountain
// settings, after 6 s of filling so that the pool is full and in steady state (about a quarter of it
// resting on the ground; counter contact_share). The lab takes two such steps per displayed frame.
// BM_FountainParts runs the same pool with parts of the scene taken away, to show what the step is made
// of (docs/performance-particles.md, "Where the fountain's time goes"). Variant (first argument):
//   0 the lab's scene, 1 no spheres, 2 no obstacles at all (no contact ever: motion, ageing, removal,
//   sums), 3 no spheres and static friction 100 (every resting particle sticks: PART-5's cheap branch),
//   4 the spheres lifted 100 m out of reach (their tests without their contacts).
constexpr Real kFountainStep = 1.0 / 120.0;  // [s] the lab's physics step
enum FountainVariant { kWholeScene, kNoSpheres, kNoObstacles, kNoSpheresAllStick, kSpheresOutOfReach };
void fountainPoolSteps(benchmark::State& state, std::size_t n, int variant) {
  particles::EmitterDesc ed{Vec3(0.0, 0.1, 0.0), kUp, 0.0, 3.0, 0.3, degToRad(12.0), 8.0, 0.1, 0.01, n, colors::kBlue,
                            colors::kOrange};
  ed.rate = static_cast<Real>(n) / (ed.lifetime * (1.0 - ed.lifetimeJitter));  // the scene's keep_full
  particles::Emitter emitter(ed, 1);
  particles::Particles p;
  p.reserve(n);
  std::vector<particles::PlaneObstacle> planes{particles::PlaneObstacle{}};
  std::vector<particles::SphereObstacle> spheres{
      {Vec3(1.2, 1.0, 0.0), 0.6}, {Vec3(-0.8, 0.5, 1.0), 0.5}, {Vec3(0.2, 0.4, -1.3), 0.4}};
  if (variant == kNoSpheres || variant == kNoSpheresAllStick || variant == kNoObstacles) spheres.clear();
  if (variant == kNoObstacles) planes.clear();
  if (variant == kSpheresOutOfReach) {
    for (particles::SphereObstacle& sphere : spheres) sphere.center.y += 100.0;
  }
  particles::FusedFountainDesc f;
  f.dragRate = 0.005 / ed.particleMass;
  f.wind = Vec3(2.0, 0.0, 0.0);
  f.vortexStrength = 3.0;
  f.vortexCore = 0.5;
  f.planes = planes;
  f.spheres = spheres;
  f.material = particles::ContactMaterial{0.4, variant == kNoSpheresAllStick ? 100.0 : 0.3, 0.2, 0.1};
  f.radius = 0.02;
  const Real h = kFountainStep;
  for (int s = 0; s < 720; ++s) {
    particles::stepFountain(p, f, h);
    emitter.spawn(p, h);
  }
  // The memory floor of one particle update, measured in this run just before the timed steps (roofline.h):
  // an update reads x, v, age and lifetime and writes x, v and age (kFountainBytesPerUpdate), at the
  // triad's bandwidth over three arrays as large as the pool's (x, v, inverse mass, age, lifetime and
  // colour: 88 bytes a particle), so that both live in the same level of the memory hierarchy.
  constexpr double kFountainBytesPerUpdate = 120.0, kPoolBytesPerParticle = 88.0;
  const bench::Roofline roofline =
      bench::measureRoofline(static_cast<std::size_t>(static_cast<double>(n) * kPoolBytesPerParticle / 24.0));
  std::size_t contacts = 0;
  const double start = bench::threadCpuSeconds();
  for (auto _ : state) {
    contacts += particles::stepFountain(p, f, h).contacts;
    emitter.spawn(p, h);
  }
  const auto updates = static_cast<std::int64_t>(state.iterations() * n);
  const double nsPerUpdate =
      1e9 * (bench::threadCpuSeconds() - start) / static_cast<double>(std::max<std::int64_t>(1, updates));
  state.SetItemsProcessed(updates);
  state.counters["contact_share"] =
      static_cast<double>(contacts) / static_cast<double>(std::max<std::int64_t>(1, updates));
  state.counters["floor_ns"] = kFountainBytesPerUpdate / roofline.bytesPerNs;
  state.counters["times_floor"] = nsPerUpdate / (kFountainBytesPerUpdate / roofline.bytesPerNs);
  state.counters["roof_GBps"] = roofline.bytesPerNs;
}
void BM_FountainPoolStep(benchmark::State& state) {
  fountainPoolSteps(state, static_cast<std::size_t>(state.range(0)), kWholeScene);
}
BENCHMARK(BM_FountainPoolStep)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);
void BM_FountainParts(benchmark::State& state) {
  fountainPoolSteps(state, static_cast<std::size_t>(state.range(1)), static_cast<int>(state.range(0)));
}
BENCHMARK(BM_FountainParts)
    ->ArgsProduct({{kNoSpheres, kNoObstacles, kNoSpheresAllStick, kSpheresOutOfReach}, {100000, 1000000}})
    ->Unit(benchmark::kMillisecond);

// One call of PART-5 (particles::contactVelocity) on a resting particle's velocity (inward g·h, the
// fountain's material with restitution 0), over 333,000 particles (a third of the pool at 10⁶): the part
// of a ground contact that is the student's scalar function. Argument: 0 every particle sticks (small
// tangential speed), 1 every one slides, 2 a random half of each, which defeats branch prediction.
void BM_ContactVelocityResting(benchmark::State& state) {
  const std::size_t n = 333000;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  std::vector<Vec3> v(n), out(n);
  for (Vec3& x : v) {
    const Real tangential = state.range(0) == 0 ? 0.01 : state.range(0) == 1 ? 0.3 : (u(rng) > 0.0 ? 0.01 : 0.3);
    x = Vec3(tangential * u(rng), -kStandardGravity * kFountainStep, tangential * u(rng));
  }
  const particles::ContactMaterial resting{0.0, 0.3, 0.2, 0.1};
  for (auto _ : state) {
    for (std::size_t i = 0; i < n; ++i) out[i] = particles::contactVelocity(v[i], kUp, resting);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * n));
}
BENCHMARK(BM_ContactVelocityResting)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);

// ns per DOF-step of each integrator on 10⁵ independent oscillators (force evaluation included), and its
// ratio to the roofline floor of that method (roofline.h) measured in the same run. The floor is one
// fused loop over the coordinates of ẍ = −(k/m) x with k/m folded into one constant: the state read and
// written once (q and v, 32 B; position Verlet also reads and writes its q(t − h), 40 B) and the
// method's arithmetic per coordinate (each + and × one flop, the acceleration one flop):
//   euler, symplectic Euler    a; q and v updated (2 + 2)                                   5 flops
//   midpoint                   a; half-step q, v (4); a there; full-step q, v (4)           10
//   rk4                        4 a; three stage states (12); the weighted sums (2 × 7)       30
//   position Verlet            a; 2q − q₋ + h²a (4); v = (q' − q)/h + (h/2) a (4)            9
//   velocity Verlet            a; half kick (2); drift (2); a again; half kick (2)           8
//   implicit Euler             one Newton step is exact on this linear system:
//                              Δv = −(hk/(m + h²k)) (q + h v) (3); v and q updated (1 + 2)   6
//   adaptive (DOPRI5, FSAL)    6 a; the six stage sums Σ_{i=2..7} (i − 1) multiply-adds for q
//                              and v (84); the error estimate, 6 terms for q and v (24); its
//                              scaled norm (12)                                            126
// The generic implementations pay for what the fused loop does not: every stage stored to memory, one
// pass per vector operation, the derivative's copy of v, the state copied out and back for a system
// that does not lend its storage (the oscillator does), and CG for implicit Euler.
constexpr int kOscillators = 100000;
struct FusedCost {
  double bytes, flops;
};
FusedCost fusedCost(ode::IntegratorKind kind) {
  switch (kind) {
    case ode::IntegratorKind::Euler:
    case ode::IntegratorKind::SymplecticEuler:
      return {32, 5};
    case ode::IntegratorKind::Midpoint:
      return {32, 10};
    case ode::IntegratorKind::Rk4:
      return {32, 30};
    case ode::IntegratorKind::Verlet:
      return {40, 9};
    case ode::IntegratorKind::VelocityVerlet:
      return {32, 8};
    case ode::IntegratorKind::ImplicitEuler:
      return {32, 6};
    case ode::IntegratorKind::Adaptive:
      return {32, 126};
  }
  return {32, 5};
}
// The triad over three arrays as large as the oscillators' state (q and v: 2 doubles per coordinate),
// measured by each integrator's benchmark just before it times the method (≈ 20 ms): on a shared
// machine the load changes within a run, and a roof measured once at the start made the ratios of the
// later rows swing by up to 1.8× (both roofs fell together when another job took the core).
bench::Roofline oscillatorRoofline() { return bench::measureRoofline(2 * kOscillators); }

void BM_Integrator(benchmark::State& state) {
  const auto kind = static_cast<ode::IntegratorKind>(state.range(0));
  const bench::Roofline roofline = oscillatorRoofline();
  ode::OscillatorDesc desc;
  desc.copies = kOscillators;
  ode::HarmonicOscillator osc(desc);
  ode::Integrator integrator(kind);
  (void)integrator.setAdaptiveSettings({.tolerance = 1e-6});  // valid: a constant
  // Two figures per method: the mean CPU time over all steps (times_floor), and the best single step
  // (best_times_floor), which is measured the way the roofline is (the best of many short passes), so
  // that a load that comes and goes during the run does not favour one side of the ratio.
  const double start = bench::threadCpuSeconds();
  double bestSeconds = 1e300;
  for (auto _ : state) {
    const auto stepStart = std::chrono::steady_clock::now();
    integrator.step(osc, 1e-3);
    bestSeconds =
        std::min(bestSeconds, std::chrono::duration<double>(std::chrono::steady_clock::now() - stepStart).count());
  }
  const double dofSteps = static_cast<double>(state.iterations()) * desc.copies;
  const double nsPerDofStep = 1e9 * (bench::threadCpuSeconds() - start) / dofSteps;
  const double bestNsPerDofStep = 1e9 * bestSeconds / desc.copies;
  const FusedCost cost = fusedCost(kind);
  const double floorNs = roofline.floorNs(cost.bytes, cost.flops);
  // The label carries the ratios into ./pba bench's table (no commas: the table is read from CSV).
  char label[200];
  std::snprintf(label, sizeof label, "%s: floor %.2f ns/DOF-step (%s-bound) measured %.1fx the floor (best step %.1fx)",
                std::string(ode::integratorName(kind)).c_str(), floorNs,
                roofline.memoryBound(cost.bytes, cost.flops) ? "memory" : "arithmetic", nsPerDofStep / floorNs,
                bestNsPerDofStep / floorNs);
  state.SetLabel(label);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * desc.copies));
  state.counters["floor_ns"] = floorNs;
  state.counters["times_floor"] = nsPerDofStep / floorNs;
  state.counters["best_ns"] = bestNsPerDofStep;
  state.counters["best_times_floor"] = bestNsPerDofStep / floorNs;
  state.counters["roof_GBps"] = roofline.bytesPerNs;
  state.counters["roof_GFLOPs"] = roofline.flopsPerNs;
}
BENCHMARK(BM_Integrator)->DenseRange(0, 7);

}  // namespace

BENCHMARK_MAIN();
