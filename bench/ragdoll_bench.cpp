// Ragdoll benchmarks (issue 10, docs/performance-ragdoll.md), one thread, thread CPU time:
//  * the Ragdoll paper's performance tests with both methods, in the paper's unit (percent of real
//    time: CPU time / simulated time) and ms per step: time step (3 bones, 1 hinge + 1 ball, 10 s
//    simulated, dt 0.001–0.1), number of bones (chains of 3–120 bones, 2 joints per 3 bones, dt 0.01,
//    5 iterations), iterations (particle method, 9 boxes, dt 0.01, 1–40) and memory against boxes
//    (2–4,096 free boxes: the bytes each method keeps per box, counted from its arrays);
//  * many ragdolls: 136 of the paper's 16-bone humans (Bullet's ragdoll benchmark count) dropped on the
//    ground, ms per step at dt 1/60 over 10 s, against Debian's Bullet 3.24 in double precision
//    (pkg-config bullet-float64) with the same boxes, masses and joints (cone-twist for limited balls,
//    hinges with limits) in the same run, every body kept awake on both sides; and 1,000 particle humans.
// Run: build/release/bench/pba_ragdoll_bench
#include <ctime>
#include <memory>
#include <vector>

#include <benchmark/benchmark.h>

#include "physics/ragdoll/builders.h"
#include "physics/ragdoll/constraint_ragdoll.h"
#include "physics/ragdoll/particle_ragdoll.h"

#ifdef PBA_HAVE_BULLET
#include <btBulletDynamicsCommon.h>
#endif

#include "thread_cpu_time.h"
#include "timed_once.h"

namespace {
using namespace pba;
using namespace pba::ragdoll;
using benchmark::internal::Benchmark;

void report(benchmark::State& state, double seconds, int steps, Real dt) {
  state.SetIterationTime(seconds / steps);
  state.counters["ms_per_step"] = 1e3 * seconds / steps;
  state.counters["percent_real_time"] = 100.0 * seconds / (steps * dt);
}

enum class Method { Particle, Constraint };

template <typename Step>
double timeSteps(int steps, Step&& step) {
  const double t0 = bench::threadCpuSeconds();
  for (int i = 0; i < steps; ++i) step();
  return bench::threadCpuSeconds() - t0;
}

// Particle method: `sweeps` stick sweeps per iteration; the paper's tests run its published form
// (Jakobsen: one), the many-humans rows the lab's default (ParticleSettings::stickSweeps, 3).
constexpr int kPublishedSweeps = 1;
void run(benchmark::State& state, const RagdollDesc& desc, Method method, Real dt, Real seconds, int iterations = 5,
         int sweeps = kPublishedSweeps) {
  const int steps = static_cast<int>(seconds / dt + 0.5);
  for (auto _ : state) {
    double t = 0.0;
    if (method == Method::Particle) {
      ParticleSettings s;
      s.iterations = iterations;
      s.stickSweeps = sweeps;
      ParticleRagdoll r = ParticleRagdoll::build(desc, s).value();
      t = timeSteps(steps, [&] { r.step(dt); });
    } else {
      ConstraintSettings s;
      s.world.sleeping = false;
      ConstraintRagdoll r = ConstraintRagdoll::build(desc, s).value();
      t = timeSteps(steps, [&] { r.step(dt); });
    }
    report(state, t, steps, dt);
    state.counters["bones"] = static_cast<double>(desc.bones.size());
  }
}

// The paper's figure: groups of three boxes joined by a hinge and a ball, end to end (2 joints per 3 bones).
RagdollDesc paperChain(int bones) {
  ChainDesc c;
  c.links = bones;
  c.fixedTop = false;
  c.start = Vec3(0.0, 1.0, 0.0);
  RagdollDesc d = buildChain(c);
  d.joints.clear();
  for (int i = 1; i < bones; ++i) {
    if (i % 3 == 0) continue;  // a new group of three starts here
    JointDesc j;
    j.kind = i % 3 == 1 ? JointKind::Hinge : JointKind::Ball;
    j.boneA = i - 1, j.boneB = i;
    j.anchor = 0.5 * (d.bones[i - 1].center + d.bones[i].center);
    j.axis = j.kind == JointKind::Hinge ? Vec3(0.0, 0.0, 1.0) : Vec3(1.0, 0.0, 0.0);
    d.joints.push_back(j);
  }
  return d;
}

void BM_TimeStep(benchmark::State& state, Method m) {
  run(state, paperChain(3), m, 1.0 / static_cast<Real>(state.range(0)), 10.0);
}
// Steps per second, the same rows for both methods.
void stepRates(Benchmark* b) { bench::timedOnce(b, {1000, 200, 100, 20, 10}, benchmark::kMicrosecond); }
BENCHMARK_CAPTURE(BM_TimeStep, particle, Method::Particle)->Apply(stepRates);
BENCHMARK_CAPTURE(BM_TimeStep, constraint, Method::Constraint)->Apply(stepRates);

void BM_Bones(benchmark::State& state, Method m, int sweeps) {
  run(state, paperChain(static_cast<int>(state.range(0))), m, 0.01, 10.0, 5, sweeps);
}
// Bones in the chain, the same rows for both methods.
void boneCounts(Benchmark* b) { bench::timedOnce(b, {3, 15, 30, 60, 120}, benchmark::kMicrosecond); }
BENCHMARK_CAPTURE(BM_Bones, particle, Method::Particle, kPublishedSweeps)->Apply(boneCounts);
BENCHMARK_CAPTURE(BM_Bones, particle_3_sweeps, Method::Particle, 3)->Apply([](Benchmark* b) {
  bench::timedOnce(b, {120}, benchmark::kMicrosecond);
});
BENCHMARK_CAPTURE(BM_Bones, constraint, Method::Constraint, kPublishedSweeps)->Apply(boneCounts);

void BM_Iterations(benchmark::State& state) {
  run(state, paperChain(9), Method::Particle, 0.01, 10.0, static_cast<int>(state.range(0)));
}
BENCHMARK(BM_Iterations)->Apply([](Benchmark* b) { bench::timedOnce(b, {1, 5, 10, 20, 40}, benchmark::kMicrosecond); });

// Memory: free boxes in a row; bytes per box from each method's arrays.
void BM_Memory(benchmark::State& state) {
  const auto n = static_cast<int>(state.range(0));
  RagdollDesc d;
  for (int i = 0; i < n; ++i) {
    BoneDesc b;
    b.center = Vec3(0.3 * i, 0.5, 0.0);
    d.bones.push_back(b);
  }
  for (auto _ : state) {
    const ParticleRagdoll p = ParticleRagdoll::build(d).value();
    const ConstraintRagdoll c = ConstraintRagdoll::build(d).value();
    state.counters["particle_bytes"] = static_cast<double>(p.memoryBytes());
    state.counters["constraint_bytes"] = static_cast<double>(c.memoryBytes());
    state.counters["boxes"] = n;
  }
}
BENCHMARK(BM_Memory)->Arg(2)->Arg(16)->Arg(128)->Arg(1024)->Arg(4096)->Iterations(1);

// Many humans on a grid, lying face down, dropped from 0.6 m.
RagdollDesc humans(int count) {
  RagdollDesc d;
  const int columns = 17;
  for (int k = 0; k < count; ++k) {
    HumanDesc h;
    h.position = Vec3(2.2 * (k % columns), 0.6, 2.4 * (k / columns));
    h.orientation = glm::angleAxis(degToRad(80.0), Vec3(1.0, 0.0, 0.0));
    append(d, buildHumanRagdoll(h));
  }
  return d;
}

// The labels say what each many-humans row times, so that rows of different benchmarks are compared only
// where they time the same thing (docs/performance-ragdoll.md, "Why two benchmarks disagreed").
void BM_Humans(benchmark::State& state, Method m, int iterations) {
  run(state, humans(static_cast<int>(state.range(0))), m, 1.0 / 60.0, 10.0, iterations, ParticleSettings{}.stickSweeps);
  state.SetLabel("all awake, 600 steps, run alone");
}
// One human and the 136 of the Bullet comparison (BM_BulletHumans has the same rows).
void humanCounts(Benchmark* b) { bench::timedOnce(b, {1, 136}); }
BENCHMARK_CAPTURE(BM_Humans, particle_20_iterations, Method::Particle, 20)->Apply(humanCounts);
BENCHMARK_CAPTURE(BM_Humans, particle_5_iterations, Method::Particle, 5)->Apply([](Benchmark* b) {
  bench::timedOnce(b, {136, 1000});
});
BENCHMARK_CAPTURE(BM_Humans, constraint, Method::Constraint, 0)->Apply(humanCounts);

#ifdef PBA_HAVE_BULLET
btVector3 bt(const Vec3& v) { return btVector3(v.x, v.y, v.z); }
btQuaternion bt(const Quat& q) { return btQuaternion(q.x, q.y, q.z, q.w); }

// A frame at `anchor` whose x axis is `axis` (both world), expressed in the body's frame.
btTransform jointFrame(const btRigidBody& body, const Vec3& anchor, const Vec3& axis) {
  const btTransform inverse = body.getWorldTransform().inverse();
  const btVector3 x = (inverse.getBasis() * bt(axis)).normalized();
  const btVector3 helper = std::abs(x.x()) < 0.9 ? btVector3(1, 0, 0) : btVector3(0, 1, 0);
  const btVector3 y = x.cross(helper).normalized(), z = x.cross(y);
  btMatrix3x3 basis(x.x(), y.x(), z.x(), x.y(), y.y(), z.y(), x.z(), y.z(), z.z());
  return btTransform(basis, inverse * bt(anchor));
}

// Bullet's defaults (btDbvtBroadphase, sequential impulses, 10 iterations), the same boxes, masses and
// joints: btConeTwistConstraint for limited balls (swing spans = the cone, twist ±170°),
// btPoint2PointConstraint for free balls, btHingeConstraint with the limits; jointed pairs do not collide.
class BulletRagdolls {
 public:
  explicit BulletRagdolls(const RagdollDesc& d)
      : dispatcher_(&configuration_),
        world_(&dispatcher_, &broadphase_, &solver_, &configuration_),
        groundBody_(btRigidBody::btRigidBodyConstructionInfo(0.0, nullptr, &ground_)) {
    world_.setGravity(btVector3(0, -kStandardGravity, 0));
    groundBody_.setFriction(d.friction);
    world_.addRigidBody(&groundBody_);
    for (const BoneDesc& b : d.bones) {
      shapes_.push_back(std::make_unique<btBoxShape>(bt(b.halfExtents)));
      btVector3 inertia;
      shapes_.back()->calculateLocalInertia(b.mass, inertia);
      btRigidBody::btRigidBodyConstructionInfo info(b.mass, nullptr, shapes_.back().get(), inertia);
      info.m_startWorldTransform = btTransform(bt(b.orientation), bt(b.center));
      info.m_friction = d.friction;
      bodies_.push_back(std::make_unique<btRigidBody>(info));
      bodies_.back()->setActivationState(DISABLE_DEACTIVATION);
      world_.addRigidBody(bodies_.back().get());
    }
    for (const JointDesc& j : d.joints) {
      btRigidBody& a = *bodies_[j.boneA];
      btRigidBody& b = *bodies_[j.boneB];
      const btTransform fa = jointFrame(a, j.anchor, j.axis), fb = jointFrame(b, j.anchor, j.axis);
      if (j.kind == JointKind::Hinge) {
        auto h = std::make_unique<btHingeConstraint>(a, b, fa.getOrigin(), fb.getOrigin(), fa.getBasis().getColumn(0),
                                                     fb.getBasis().getColumn(0));
        if (j.limited) h->setLimit(j.lower, j.upper);
        joints_.push_back(std::move(h));
      } else if (j.limited) {
        auto c = std::make_unique<btConeTwistConstraint>(a, b, fa, fb);
        c->setLimit(j.coneAngle, j.coneAngle, degToRad(170.0));
        joints_.push_back(std::move(c));
      } else {
        joints_.push_back(std::make_unique<btPoint2PointConstraint>(a, b, fa.getOrigin(), fb.getOrigin()));
      }
      world_.addConstraint(joints_.back().get(), true);
    }
  }
  BulletRagdolls(const BulletRagdolls&) = delete;
  BulletRagdolls& operator=(const BulletRagdolls&) = delete;
  ~BulletRagdolls() {
    for (auto& j : joints_) world_.removeConstraint(j.get());
    for (auto& b : bodies_) world_.removeRigidBody(b.get());
    world_.removeRigidBody(&groundBody_);
  }
  void step(Real dt) { world_.stepSimulation(dt, 0); }

 private:
  btDefaultCollisionConfiguration configuration_;
  btCollisionDispatcher dispatcher_;
  btDbvtBroadphase broadphase_;
  btSequentialImpulseConstraintSolver solver_;
  btDiscreteDynamicsWorld world_;
  btStaticPlaneShape ground_{btVector3(0, 1, 0), 0};
  btRigidBody groundBody_;
  std::vector<std::unique_ptr<btBoxShape>> shapes_;
  std::vector<std::unique_ptr<btRigidBody>> bodies_;
  std::vector<std::unique_ptr<btTypedConstraint>> joints_;
};

void BM_BulletHumans(benchmark::State& state) {
  const RagdollDesc d = humans(static_cast<int>(state.range(0)));
  const Real dt = 1.0 / 60.0;
  const int steps = 600;
  for (auto _ : state) {
    BulletRagdolls bullet(d);
    const double t = timeSteps(steps, [&] { bullet.step(dt); });
    report(state, t, steps, dt);
    state.counters["bones"] = static_cast<double>(d.bones.size());
  }
  state.SetLabel("Bullet double precision, all awake, 600 steps, run alone");
}
BENCHMARK(BM_BulletHumans)->Apply(humanCounts);

// The same two simulations stepped in alternation, 20 steps of one then 20 of the other, 600 steps each,
// so that a change of the machine's load during the run falls on both alike (on this shared machine,
// back-to-back runs of the two moved by ±15 %). Time: ours; counters: both and their ratio.
void BM_HumansAgainstBullet(benchmark::State& state) {
  const RagdollDesc d = humans(static_cast<int>(state.range(0)));
  const Real dt = 1.0 / 60.0;
  constexpr int kSteps = 600, kBlock = 20;
  for (auto _ : state) {
    ConstraintSettings s;
    s.world.sleeping = false;
    ConstraintRagdoll ours = ConstraintRagdoll::build(d, s).value();
    BulletRagdolls bullet(d);
    double oursSeconds = 0.0, bulletSeconds = 0.0;
    for (int done = 0; done < kSteps; done += kBlock) {
      oursSeconds += timeSteps(kBlock, [&] { ours.step(dt); });
      bulletSeconds += timeSteps(kBlock, [&] { bullet.step(dt); });
    }
    report(state, oursSeconds, kSteps, dt);
    state.counters["bullet_ms_per_step"] = 1e3 * bulletSeconds / kSteps;
    state.counters["ours_over_bullet"] = oursSeconds / bulletSeconds;
  }
  state.SetLabel("Bullet double precision, all awake, 600 steps, alternated by 20");
}
BENCHMARK(BM_HumansAgainstBullet)->Apply([](Benchmark* b) { bench::timedOnce(b, {136}); });
#endif

}  // namespace
BENCHMARK_MAIN();
