// Scratch memory is explicit (docs/architecture.md, "Physics library conventions"): a rigid world, an
// IK solve and a particle sweep keep their scratch in objects their caller owns, so two of each run on
// two threads at once exactly as they run one after the other. Each pair also shares what may be
// shared, read-only: the worlds one triangle-mesh floor (its tree is queried by both) and one hull,
// the solves one skeleton. The reference is the same work done sequentially; the comparison is bit for
// bit. Under the ASan preset the test also checks that nothing is freed or overrun while shared.
#include <array>
#include <cstdint>
#include <cstring>
#include <functional>
#include <random>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "physics/collision/shapes.h"
#include "physics/ik/builders.h"
#include "physics/ik/solver.h"
#include "physics/particles/spatial_hash.h"
#include "physics/rigid/builders.h"
#include "physics/rigid/world.h"

namespace pba {
namespace {

// The bits of every number, in order: equal fingerprints are the same results bit for bit.
using Fingerprint = std::vector<std::uint64_t>;
void append(Fingerprint& f, Real x) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &x, sizeof bits);
  f.push_back(bits);
}
void append(Fingerprint& f, const Vec3& v) {
  for (int i = 0; i < 3; ++i) append(f, v[i]);
}

// Runs work(0) and work(1) on two threads started together; returns their results.
std::vector<Fingerprint> onTwoThreads(const std::function<Fingerprint(int)>& work) {
  std::vector<Fingerprint> out(2);
  std::thread first([&] { out[0] = work(0); });
  std::thread second([&] { out[1] = work(1); });
  first.join();
  second.join();
  return out;
}

void expectSameConcurrently(const std::function<Fingerprint(int)>& work) {
#if defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__)
  GTEST_SKIP() << "the browser build has no threads (it is built without -pthread)";
#endif
  const Fingerprint alone0 = work(0), alone1 = work(1);
  ASSERT_NE(alone0, alone1) << "the two runs must differ, or a swap of their results would go unseen";
  const std::vector<Fingerprint> together = onTwoThreads(work);
  EXPECT_EQ(together[0], alone0);
  EXPECT_EQ(together[1], alone1);
}

// A floor of 2 × 8 × 8 triangles (a mesh: its bounding-volume tree is queried every step).
collision::Shape meshFloor() {
  std::vector<Vec3> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  constexpr int n = 8;
  for (int i = 0; i <= n; ++i)
    for (int k = 0; k <= n; ++k) vertices.emplace_back(-4.0 + i, 0.05 * ((i + k) % 2), -4.0 + k);
  for (std::uint32_t i = 0; i < n; ++i)
    for (std::uint32_t k = 0; k < n; ++k) {
      const std::uint32_t a = i * (n + 1) + k, b = a + n + 1;
      triangles.push_back({a, a + 1, b});
      triangles.push_back({b, a + 1, b + 1});
    }
  return collision::makeMesh(collision::buildTriangleMesh(std::move(vertices), std::move(triangles)).value());
}

// A world of boxes, hulls, spheres and capsules dropped on a shared mesh floor over a plane, and a fast
// sphere fired at the plane (time of impact); the poses of every body after each step, and what a ray
// cast down through the pile meets.
Fingerprint stepWorld(const collision::Shape& floor, const collision::Shape& hull, unsigned seed) {
  rigid::World world;
  rigid::addGround(world);
  rigid::BodyDesc ground;
  ground.type = rigid::BodyType::Static;
  ground.shape = floor;
  ground.position = Vec3(0.0, 0.2, 0.0);
  world.addBody(ground).value();
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  const collision::Shape shapes[] = {collision::makeBox(Vec3(0.2, 0.15, 0.1)).value(), hull,
                                     collision::makeSphere(0.15).value(), collision::makeCapsule(0.15, 0.1).value()};
  for (int i = 0; i < 24; ++i) {
    rigid::BodyDesc b;
    b.shape = shapes[i % 4];
    b.position = Vec3(1.5 * u(rng), 0.8 + 0.35 * i, 1.5 * u(rng));
    b.orientation = glm::normalize(Quat(1.0, u(rng), u(rng), u(rng)));
    b.angularVelocity = Vec3(u(rng), u(rng), u(rng));
    world.addBody(b).value();
  }
  rigid::BodyDesc shot;
  shot.shape = collision::makeSphere(0.05).value();
  shot.position = Vec3(0.5 * u(rng), 3.0, 0.5 * u(rng));
  shot.linearVelocity = Vec3(0.0, -60.0, 0.0);
  shot.bullet = true;
  world.addBody(shot).value();
  Fingerprint f;
  for (int s = 0; s < 60; ++s) {
    world.step(1.0 / 60.0);
    for (const rigid::Body& b : world.bodies()) {
      append(f, b.position);
      append(f, Vec3(b.orientation.x, b.orientation.y, b.orientation.z));
    }
    // A query between steps: the tree of the broad phase, then the floor's.
    for (const rigid::WorldRayHit& h : world.rayCastAll({Vec3(0.1 * s - 3.0, 5.0, 0.3), Vec3(0.0, -1.0, 0.0)}, 10.0))
      append(f, h.hit.t);
  }
  return f;
}

TEST(TwoThreads, RigidWorldsStepAtOnceAsOneAfterTheOther) {
  const collision::Shape floor = meshFloor();
  const collision::Shape hull =
      collision::makeHull({{0.2, 0.0, 0.0}, {-0.1, 0.17, 0.0}, {-0.1, -0.17, 0.0}, {0.0, 0.0, 0.25}, {0.0, 0.05, -0.2}})
          .value();
  expectSameConcurrently([&](int run) { return stepWorld(floor, hull, 7u + static_cast<unsigned>(run)); });
}

// Solves toward random reachable goals, each from the last pose, with one workspace for the run; the
// poses and residuals after each solve.
Fingerprint solveMany(const ik::Rig& rig, ik::SolverKind kind, unsigned seed) {
  std::mt19937_64 rng(seed);
  ik::SolveOptions o;
  o.solver = kind;
  o.maxIterations = 60;
  o.restarts = 2;
  ik::SolveWorkspace workspace;
  ik::Pose pose = rig.skeleton.restPose();
  std::vector<ik::Effector> effectors = rig.effectors;
  Fingerprint f;
  for (int i = 0; i < 12; ++i) {
    ik::setGoalsFromPose(rig.skeleton, ik::randomPose(rig.skeleton, rng), effectors);
    const ik::SolveResult r = ik::solve(rig.skeleton, pose, effectors, o, workspace);
    for (Real d : pose.dofs) append(f, d);
    append(f, r.positionResidual);
    append(f, static_cast<Real>(r.iterations));
  }
  return f;
}

TEST(TwoThreads, IkSolvesRunAtOnceAsOneAfterTheOther) {
  ik::ChainDesc d;
  d.links = 12;
  d.joint = ik::JointType::Ball;
  const ik::Rig rig = ik::buildIkChain(d).value();
  for (ik::SolverKind kind : {ik::SolverKind::SelectivelyDamped, ik::SolverKind::DampedLeastSquares,
                              ik::SolverKind::Ccd, ik::SolverKind::Fabrik}) {
    SCOPED_TRACE(ik::solverName(kind));
    expectSameConcurrently([&](int run) { return solveMany(rig, kind, 3u + static_cast<unsigned>(run)); });
  }
}

// Random particles in a box, collided pairwise through a spatial hash for a few sweeps.
Fingerprint collideParticles(unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<Real> u(-0.5, 0.5);
  particles::Particles p;
  for (int i = 0; i < 400; ++i) {
    const Vec3 x(u(rng), u(rng), u(rng));
    p.add(x, Vec3(u(rng), u(rng), u(rng)), 1.0);
  }
  particles::SpatialHash hash;
  Fingerprint f;
  for (int sweep = 0; sweep < 5; ++sweep) {
    const particles::PairCollisionStats s = particles::collideParticlePairs(p, 0.03, 0.5, hash);
    append(f, static_cast<Real>(s.contacts));
    for (const Vec3& x : p.position) append(f, x);
  }
  return f;
}

TEST(TwoThreads, ParticleSweepsRunAtOnceAsOneAfterTheOther) {
  expectSameConcurrently([](int run) { return collideParticles(11u + static_cast<unsigned>(run)); });
}

}  // namespace
}  // namespace pba
