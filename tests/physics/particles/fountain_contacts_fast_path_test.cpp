// PART-5's fast path in the fountain (framework/physics/particles/fountain_contacts.h) against the scalar
// route it replaces, on random particles around random obstacles and materials and on a settled fountain
// pool. Each lane of the fast path does resolveContact's and PART-5's IEEE operations in their order and
// keeps the bits of whatever a branch would have skipped, so positions, velocities and counts must agree
// to the bit. In the hand-out the fast path runs the scalar route and this holds trivially.
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "physics/particles/emitter.h"
#include "physics/particles/fountain_contacts.h"
#include "physics/particles/kernels.h"
#include "support/same_bits.h"

namespace pba::particles {
namespace {

struct ContactInput {
  std::vector<Vec3> x, v;
  std::vector<std::uint32_t> flagged;
  std::vector<PlaneReach> planes;
  std::vector<SphereReach> spheres;
  ContactMaterial material;
  ContactStep step{Vec3(0.0, -kStandardGravity, 0.0), 1.0 / 120.0};
  FountainObstacles obstacles() const { return {planes, spheres, material, step}; }
};

SphereReach sphereReach(const Vec3& center, Real radius, Real particleRadius) {
  const Real surface = radius + particleRadius, reach = surface + kContactSlop;
  return {center, surface, reach * reach};
}

/// Runs both routes on copies of the input, `passes` times over (the second pass sees the first's
/// projections and responses), and expects the same bits; returns the scalar route's counts.
FountainContactCounts expectSameContacts(const ContactInput& in, int passes) {
  std::vector<Vec3> xScalar = in.x, vScalar = in.v, xFast = in.x, vFast = in.v;
  FountainContactCounts scalar, fast;
  for (int pass = 0; pass < passes; ++pass) {
    const FountainContactCounts s = resolveFountainContactsScalar(xScalar, vScalar, in.flagged, in.obstacles());
    const FountainContactCounts f = resolveFountainContactsFast(xFast, vFast, in.flagged, in.obstacles());
    scalar.contacts += s.contacts;
    scalar.heldBySafetyNet += s.heldBySafetyNet;
    fast.contacts += f.contacts;
    fast.heldBySafetyNet += f.heldBySafetyNet;
  }
  EXPECT_EQ(scalar.contacts, fast.contacts);
  EXPECT_EQ(scalar.heldBySafetyNet, fast.heldBySafetyNet);
  EXPECT_TRUE(test::sameBits(xScalar, xFast, " position"));
  EXPECT_TRUE(test::sameBits(vScalar, vFast, " velocity"));
  return scalar;
}

TEST(FountainContactsFastPath, MatchesTheScalarRouteToTheBitOnRandomContacts) {
  std::mt19937_64 rng(20261205);
  std::uniform_real_distribution<Real> u(-1.0, 1.0), unit(0.0, 1.0);
  std::size_t contacts = 0, flaggedTotal = 0;
  for (int trial = 0; trial < 60; ++trial) {
    ContactInput in;
    const Real radius = 0.02;
    in.planes.push_back({Vec3(0.0, 1.0, 0.0), radius});  // the ground
    if (trial % 3 == 1) {                                // a slope (its normal not along gravity)
      const Vec3 n = glm::normalize(Vec3(0.3, 1.0, -0.2));
      in.planes.push_back({n, glm::dot(n, Vec3(0.0, 0.3, 0.0)) + radius});
    }
    for (int s = 0; s < trial % 4; ++s) {
      in.spheres.push_back(
          sphereReach(Vec3(0.8 * u(rng), 0.4 + 0.3 * u(rng), 0.8 * u(rng)), 0.3 + 0.2 * unit(rng), radius));
    }
    in.material = {unit(rng), 1.2 * unit(rng), 0.8 * unit(rng), 0.3 * unit(rng)};
    if (trial % 5 == 0) in.material.restingSpeed = 0.0;
    const std::size_t n = 1 + static_cast<std::size_t>(trial) * 7 % 41;  // odd and even counts
    for (std::size_t i = 0; i < n; ++i) {
      Vec3 x(u(rng), radius + 0.05 * u(rng), u(rng));  // around the ground: above, touching, below
      if (!in.spheres.empty() && i % 3 == 0) {         // on a sphere's surface, a little in or out
        const SphereReach& s = in.spheres[i % in.spheres.size()];
        x = s.center + (s.surface + 0.01 * u(rng)) * glm::normalize(Vec3(u(rng), u(rng), u(rng)));
      }
      if (i % 11 == 5 && !in.spheres.empty()) x = in.spheres[0].center;                      // at a centre: no normal
      Vec3 v = 3.0 * Vec3(u(rng), u(rng), u(rng));                                           // impacts and departures
      if (i % 4 == 1) v = Vec3(0.3 * u(rng), -kStandardGravity * in.step.dt, 0.3 * u(rng));  // resting
      if (i % 4 == 2) v = Vec3(0.02 * u(rng), -0.5 * unit(rng), 0.02 * u(rng));              // sticking
      if (i % 8 == 3) v = Vec3(0.0, v.y, 0.0);  // no tangential speed on the ground, arriving or leaving
      in.x.push_back(x);
      in.v.push_back(v);
      if (unit(rng) < 0.8) in.flagged.push_back(static_cast<std::uint32_t>(i));
    }
    flaggedTotal += in.flagged.size();
    contacts += expectSameContacts(in, 2).contacts;
  }
  EXPECT_GT(contacts, flaggedTotal / 4);  // the inputs reach the contact model, not only its early exits
}

TEST(FountainContactsFastPath, MatchesTheScalarRouteToTheBitOnASettledFountain) {
  // The benchmark's fountain (bench/particles_bench.cpp) at 4,000 particles after 4 s: a jet, impacts on
  // three spheres and a resting layer on the ground that sticks and slides.
  const std::size_t n = 4000;
  EmitterDesc ed{Vec3(0.0, 0.1, 0.0), kUp, 0.0, 3.0, 0.3, degToRad(12.0), 8.0, 0.1, 0.01, n, colors::kBlue,
                 colors::kOrange};
  ed.rate = static_cast<Real>(n) / (ed.lifetime * (1.0 - ed.lifetimeJitter));
  Emitter emitter(ed, 1);
  Particles p;
  const std::vector<PlaneObstacle> planes{PlaneObstacle{}};
  const std::vector<SphereObstacle> spheres{
      {Vec3(1.2, 1.0, 0.0), 0.6}, {Vec3(-0.8, 0.5, 1.0), 0.5}, {Vec3(0.2, 0.4, -1.3), 0.4}};
  FusedFountainDesc f;
  f.dragRate = 0.005 / ed.particleMass;
  f.wind = Vec3(2.0, 0.0, 0.0);
  f.vortexStrength = 3.0;
  f.planes = planes;
  f.spheres = spheres;
  f.material = ContactMaterial{0.4, 0.3, 0.2, 0.1};
  f.radius = 0.02;
  const Real h = 1.0 / 120.0;
  for (int step = 0; step < 480; ++step) {
    stepFountain(p, f, h);
    emitter.spawn(p, h);
  }
  ContactInput in;
  in.x = p.position;
  in.v = p.velocity;
  for (std::size_t i = 0; i < p.size(); ++i) {  // every particle flagged, moved by one Euler step under gravity
    in.flagged.push_back(static_cast<std::uint32_t>(i));
    in.v[i] += h * f.gravity;
    in.x[i] += h * in.v[i];
  }
  in.planes.push_back({kUp, f.radius});
  for (const SphereObstacle& s : spheres) in.spheres.push_back(sphereReach(s.center, s.radius, f.radius));
  in.material = f.material;
  in.step = {f.gravity, h};
  const FountainContactCounts counts = expectSameContacts(in, 1);
  EXPECT_GT(counts.contacts, p.size() / 10);  // the resting layer, at least (a quarter of the pool)
}

}  // namespace
}  // namespace pba::particles
