#include "physics/cloth/implicit.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "physics/exercises/not_implemented.h"

namespace pba::cloth {
namespace {

constexpr Real kContactTolerance = 1e-4;  // [m] a particle this close beyond the margin counts as touching
constexpr Real kStuckSlip = 1e-9;         // [m] tangential motion over a step below which friction held it

/// Colours the particles so that no spring joins two of one colour (for the probed preconditioner).
void refreshColouring(const Cloth& cloth, ImplicitWorkspace& w) {
  if (w.colouredSprings == cloth.springs.size() && w.colour.size() == cloth.size()) return;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  pairs.reserve(cloth.springs.size());
  for (const Link& s : cloth.springs) pairs.emplace_back(s.i, s.j);
  w.colour = colourParticles(cloth.size(), pairs, &w.colours);
  w.colouredSprings = cloth.springs.size();
}

/// Filter and prescribed velocities: pins fixed at their velocity; a particle that touches a collider and
/// moves into it, or that would reach it within the step, constrained along the collider's normal so that
/// it ends the step on the surface plus the margin, no further:
///  - touching or inside (gap ≤ tolerance) and approaching: the collider's normal velocity plus the depth
///    over h, the position alteration y of B&W §6 (the particle is moved out inside the solve, so its
///    springs see the move; the depth's share is taken off the velocity after the solve);
///  - outside but reaching the surface within the step at its present velocity: the normal velocity that
///    closes the gap in h exactly (a speculative contact, our addition: without it the collider projection
///    after the step moves particles by up to h·v against springs the solve never saw, which stiff cloth
///    turns into energy).
/// A touching particle that stuck at the last step (static friction) is fixed to the collider's motion in
/// all three directions, inside the solve, so that its neighbours' springs see it hold.
std::size_t buildFilter(const Cloth& cloth, std::span<const Collider> colliders, const ImplicitSettings& settings,
                        Real h, ImplicitWorkspace& w) {
  const std::size_t n = cloth.size();
  w.filter.assign(n, ParticleFilter{});
  w.z.assign(n, Vec3(0.0));
  w.correction.assign(n, 0.0);
  w.contact.assign(n, -1);
  w.released.resize(n, 0);
  w.sticking.resize(n, 0);
  for (const Pin& p : cloth.pins) {
    w.filter[p.particle].kind = ParticleFilter::Kind::Fixed;
    w.z[p.particle] = (p.target - cloth.position[p.particle]) / h;
  }
  std::size_t contacts = 0;
  if (!settings.contactConstraints) return contacts;
  const Real margin = 0.5 * cloth.material.thickness;
  for (std::size_t i = 0; i < n; ++i) {
    const bool stuck = std::exchange(w.sticking[i], 0) != 0;
    if (w.filter[i].kind != ParticleFilter::Kind::Free) continue;
    if (std::exchange(w.released[i], 0) != 0) continue;
    for (std::size_t k = 0; k < colliders.size(); ++k) {
      const Collider& c = colliders[k];
      const SurfacePoint s = closestSurface(c, cloth.position[i]);
      const Real gap = s.distance - margin;                                      // < 0: inside
      const Real approach = glm::dot(cloth.velocity[i] - c.velocity, s.normal);  // < 0: towards the surface
      const bool touching = gap <= kContactTolerance && approach <= 0.0;
      const bool reaching = settings.speculativeContacts && gap > kContactTolerance && gap + h * approach < 0.0;
      if (!touching && !reaching) continue;
      const Real depth = touching ? std::max(0.0, -gap) : 0.0;
      const Real normalSpeed = glm::dot(c.velocity, s.normal) + (reaching ? -gap / h : depth / h);
      if (touching && stuck && settings.staticFriction) {
        w.filter[i] = {ParticleFilter::Kind::Fixed, s.normal, Vec3(0.0)};
        w.z[i] = c.velocity + (normalSpeed - glm::dot(c.velocity, s.normal)) * s.normal;
      } else {
        w.filter[i] = {ParticleFilter::Kind::OneDirection, s.normal, Vec3(0.0)};
        w.z[i] = normalSpeed * s.normal;
      }
      w.correction[i] = depth / h;
      w.contact[i] = static_cast<int>(k);
      ++contacts;
      break;
    }
  }
  return contacts;
}

/// After the solve: the constraint impulse of each contact is r = A v₁ − b. One that pulls (r·n < 0) is
/// released for the next step (B&W §5.3). A stuck particle (fixed in all directions) keeps sticking while
/// its tangential impulse stays within the friction cone, |r_t| ≤ μ r·n, and slides from the next step
/// on otherwise. A sliding one has its tangential velocity change bounded by μ × (r·n) / m, which is
/// CLOTH-4's friction: the particle ends at x₁ = x₀ + h v₁ on the surface; placed the depth h (r·n)/m
/// below it (the depth whose projection gives this impulse), the projection onto the sphere tangent at x₁
/// pushes it back to x₁ and takes the friction off its motion relative to the collider. When that stops
/// its motion relative to the collider, it sticks at the next step.
void contactFriction(const Cloth& cloth, std::span<const Collider> colliders, const ParticleOperator& A, Real h,
                     ImplicitWorkspace& w) {
  w.probeOut.resize(cloth.size());
  A(w.velocity, w.probeOut);
  for (std::size_t i = 0; i < cloth.size(); ++i) {
    if (w.contact[i] < 0) continue;
    const Collider& touched = colliders[static_cast<std::size_t>(w.contact[i])];
    const Vec3 n = w.filter[i].p;
    const Vec3 r = w.probeOut[i] - w.b[i];  // [N·s]
    const Real impulse = glm::dot(r, n);
    if (impulse < 0.0) {
      w.released[i] = 1;
      continue;
    }
    if (w.filter[i].kind == ParticleFilter::Kind::Fixed) {
      w.sticking[i] = glm::length(r - impulse * n) <= touched.friction * impulse ? 1 : 0;
      continue;
    }
    if (touched.friction == 0.0) continue;  // frictionless: the projection below would leave x₁ as it is
    const Real depth = h * impulse / cloth.mass[i];
    const Real radius = std::max(1.0, 2.0 * depth);
    const Vec3 x1 = cloth.position[i] + h * w.velocity[i];
    const Vec3 start = cloth.position[i] + h * touched.velocity;
    const Vec3 x = projectOutOfSphere(x1 - depth * n, start, x1 - radius * n, radius, touched.friction);
    w.velocity[i] = (x - cloth.position[i]) / h;
    const Vec3 slip = x - start - glm::dot(x - start, n) * n;  // motion relative to the collider, tangential
    w.sticking[i] = glm::dot(slip, slip) <= kStuckSlip * kStuckSlip ? 1 : 0;
  }
}

}  // namespace

void implicitSystemProduct([[maybe_unused]] std::span<const SpringJacobian> springs,
                           [[maybe_unused]] std::span<const Real> mass, [[maybe_unused]] Real massDamping,
                           [[maybe_unused]] Real h, [[maybe_unused]] std::span<const Vec3> y, std::span<Vec3> out) {
  // BEGIN SOLUTION
  std::transform(y.begin(), y.end(), mass.begin(), out.begin(),
                 [&](const Vec3& yi, Real mi) { return (1.0 + h * massDamping) * mi * yi; });
  for (const SpringJacobian& J : springs) {
    const Vec3 n = J.direction;
    const Vec3 stretch = y[J.j] - y[J.i];
    // h² K_s Δy + h D_s Δy, with K_s Δy = lateral Δy + (k − lateral) n (n·Δy) and D_s Δy = k_d n (n·Δy)
    const Vec3 coupling =
        h * h * J.lateral * stretch + (h * h * (J.stiffness - J.lateral) + h * J.damping) * glm::dot(n, stretch) * n;
    out[J.i] -= coupling;
    out[J.j] += coupling;
  }
  // END SOLUTION
  // STUB: exercises::markNotImplemented("CLOTH-5");
  // STUB: std::fill(out.begin(), out.end(), Vec3(0.0));
}

ImplicitStats implicitStep(Cloth& cloth, const ClothEnvironment& env, std::span<const Collider> colliders,
                           const ImplicitSettings& settings, Real h, Real t, ImplicitWorkspace& w) {
  const std::size_t n = cloth.size();
  springJacobians(cloth.springs, cloth.material, cloth.position, settings.jacobian, w.jacobians);
  w.system.bind(w.jacobians, cloth.mass, env.massDamping, h);
  prepareImplicitSystemFast(w.system);
  const ParticleOperator A = [&](std::span<const Vec3> y, std::span<Vec3> out) {
    implicitSystemProductFast(w.system, y, out);
  };

  // b = M v₀ + h f_undamped(x₀, v₀): elastic springs, gravity, aerodynamics (damping lives in A).
  ClothEnvironment undamped = env;
  undamped.massDamping = 0.0;
  w.force.assign(n, Vec3(0.0));
  accumulateSpringForces(cloth.springs, cloth.material, cloth.position, cloth.velocity, false, w.force);
  accumulateExternalForces(cloth, undamped, t, cloth.position, cloth.velocity, w.force);
  w.b.resize(n);
  for (std::size_t i = 0; i < w.b.size(); ++i) w.b[i] = cloth.mass[i] * cloth.velocity[i] + h * w.force[i];

  ImplicitStats stats;
  stats.contactConstraints = buildFilter(cloth, colliders, settings, h, w);
  if (settings.preconditioner == Preconditioner::BlockJacobi) {
    refreshColouring(cloth, w);
    implicitBlockJacobiFast(w.system, A, w.colour, w.colours, w.preconditioner, w.probeIn, w.probeOut);
  } else {
    w.preconditioner.clear();
  }
  w.velocity = cloth.velocity;  // warm start: v₁ ≈ v₀, or v₀ + h a with the last step's a
  if (settings.extrapolatedStart && w.acceleration.size() == n) {
    for (std::size_t i = 0; i < n; ++i) w.velocity[i] += h * w.acceleration[i];
  }
  stats.cg = filteredPcg(A, w.b, w.filter, w.z, w.preconditioner, settings.cg, w.velocity, w.pcg);
  if (stats.contactConstraints > 0) contactFriction(cloth, colliders, A, h, w);

  w.acceleration.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 velocity = w.velocity[i];
    w.acceleration[i] = (velocity - cloth.velocity[i]) / h;
    cloth.position[i] += h * velocity;
    // The position alteration moves the particle, it does not set it moving: its share leaves the velocity.
    cloth.velocity[i] = w.correction[i] > 0.0 ? velocity - w.correction[i] * w.filter[i].p : velocity;
  }

  for (const Pin& p : cloth.pins) cloth.position[p.particle] = p.target;
  return stats;
}

// Start-up probe: tells the lab whether CLOTH-5 is still a stub.
PBA_EXERCISE_PROBE(implicitSystemProduct({}, {}, 0.0, 0.01, {}, {}));

}  // namespace pba::cloth
