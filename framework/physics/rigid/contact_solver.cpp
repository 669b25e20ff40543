#include "physics/rigid/contact_solver.h"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "physics/rigid/exercises.h"

namespace pba::rigid {

void tangentBasis(const Vec3& n, Vec3& t1, Vec3& t2) {
  const Vec3 a = glm::abs(n);
  const Vec3 axis = a.x <= a.y && a.x <= a.z ? Vec3(1, 0, 0) : (a.y <= a.z ? Vec3(0, 1, 0) : Vec3(0, 0, 1));
  t1 = glm::normalize(glm::cross(axis, n));
  t2 = glm::cross(n, t1);
}

// Separation during the substeps (Box2D v3 contact_solver.c): the normal is held fixed and the anchors
// move with their bodies, s = s₀ + n·(Δc_B + Δθ_B × r_B − Δc_A − Δθ_A × r_A)
//                          = s₀ + n·(Δc_B − Δc_A) + Δθ_B·(r_B × n) − Δθ_A·(r_A × n),
// with Δc and Δθ the displacement and the rotation vector (Σ ω h) of each body since the step began.

void prepareContact(const ContactConstraint& c, const std::vector<SolverBody>& bodies, bool warmStarting,
                    SolverContact& out) {
  const SolverBody& a = bodies[c.bodyA];
  const SolverBody& b = bodies[c.bodyB];
  out.bodyA = c.bodyA;
  out.bodyB = c.bodyB;
  out.againstStatic = a.invMass == 0.0 || b.invMass == 0.0;
  auto atRest = [](const SolverBody& x) { return x.invMass == 0.0 && x.v == Vec3(0.0) && x.w == Vec3(0.0); };
  out.sides = atRest(b) ? ContactSides::OnlyA : atRest(a) ? ContactSides::OnlyB : ContactSides::Both;
  out.normal = c.manifold.normal;
  out.tangent[0] = c.tangent[0];  // the basis the carried friction impulses are expressed in
  out.tangent[1] = c.tangent[1];
  out.friction = c.friction;
  out.restitution = c.restitution;
  out.invMassA = a.invMass;
  out.invMassB = b.invMass;
  out.invIA = a.invI;
  out.invIB = b.invI;
  out.count = c.manifold.count;
  const Vec3 directions[3] = {out.normal, out.tangent[0], out.tangent[1]};
  const Mat3 zero(0.0);
  const Mat3& invIA = out.sides != ContactSides::OnlyB ? a.invI : zero;
  const Mat3& invIB = out.sides != ContactSides::OnlyA ? b.invI : zero;
  for (int i = 0; i < out.count; ++i) {
    SolverContactPoint& p = out.points[i];
    const collision::ManifoldPoint& mp = c.manifold.points[i];
    p.rA = mp.point - a.c;
    p.rB = mp.point - b.c;
    p.separation = mp.separation;
    // Each row's effective mass (RIGID-5); a side at rest takes part with zero inverse inertia.
    Real mass[3];
    for (int d = 0; d < 3; ++d)
      mass[d] = contactEffectiveMass(a.invMass, invIA, p.rA, b.invMass, invIB, p.rB, directions[d]);
    p.normalMass = mass[0];
    p.tangentMass[0] = mass[1];
    p.tangentMass[1] = mass[2];
    p.normalImpulse = warmStarting ? c.points[i].normalImpulse : 0.0;
    p.tangentImpulse[0] = warmStarting ? c.points[i].tangentImpulse[0] : 0.0;
    p.tangentImpulse[1] = warmStarting ? c.points[i].tangentImpulse[1] : 0.0;
    p.relativeVelocity = glm::dot(out.normal, (b.v + glm::cross(b.w, p.rB)) - (a.v + glm::cross(a.w, p.rA)));
    p.maxNormalImpulse = 0.0;
  }
}

void storeImpulses(const SolverContact& s, ContactConstraint& c) {
  for (int i = 0; i < s.count; ++i) {
    c.points[i].normalImpulse = s.points[i].normalImpulse;
    c.points[i].tangentImpulse[0] = s.points[i].tangentImpulse[0];
    c.points[i].tangentImpulse[1] = s.points[i].tangentImpulse[1];
  }
}

namespace {
// The velocities of the sides the solver works on (ContactSides), kept in registers through a
// constraint's rows. A side at rest has zero velocity, displacement and rotation for the whole step:
// its terms are left out of the sums (they would add zeros) and it takes no impulse.
template <ContactSides S>
struct PairVelocity {
  static constexpr bool kMovesA = S != ContactSides::OnlyB, kMovesB = S != ContactSides::OnlyA;
  Vec3 vA, wA, vB, wB;
  PairVelocity(const SolverBody& a, const SolverBody& b) : vA(a.v), wA(a.w), vB(b.v), wB(b.w) {}
  // Relative velocity of the points along d: J v = d·(v_B + ω_B × r_B − v_A − ω_A × r_A).
  [[gnu::always_inline]] Real along(const SolverContactPoint& p, const Vec3& d) const {
    if constexpr (S == ContactSides::OnlyA) return glm::dot(d, -vA) - glm::dot(wA, glm::cross(p.rA, d));
    if constexpr (S == ContactSides::OnlyB) return glm::dot(d, vB) + glm::dot(wB, glm::cross(p.rB, d));
    return glm::dot(d, vB - vA) + glm::dot(wB, glm::cross(p.rB, d)) - glm::dot(wA, glm::cross(p.rA, d));
  }
  // Applies the impulse P (world vector) at the point: B gets +P, A gets −P.
  [[gnu::always_inline]] void apply(const SolverContact& c, const SolverContactPoint& p, const Vec3& P) {
    if constexpr (kMovesA) {
      vA -= c.invMassA * P;
      wA -= c.invIA * glm::cross(p.rA, P);
    }
    if constexpr (kMovesB) {
      vB += c.invMassB * P;
      wB += c.invIB * glm::cross(p.rB, P);
    }
  }
  // n·(Δc_B − Δc_A) and n·(Δθ_B × r_B − Δθ_A × r_A): the separation's change since the step began.
  static Real shift(const SolverBody& a, const SolverBody& b, const Vec3& n) {
    if constexpr (S == ContactSides::OnlyA) return glm::dot(n, -a.dp);
    if constexpr (S == ContactSides::OnlyB) return glm::dot(n, b.dp);
    return glm::dot(n, b.dp - a.dp);
  }
  static Real turn(const SolverBody& a, const SolverBody& b, const SolverContactPoint& p, const Vec3& n) {
    if constexpr (S == ContactSides::OnlyA) return glm::dot(n, -glm::cross(a.dtheta, p.rA));
    if constexpr (S == ContactSides::OnlyB) return glm::dot(n, glm::cross(b.dtheta, p.rB));
    return glm::dot(n, glm::cross(b.dtheta, p.rB) - glm::cross(a.dtheta, p.rA));
  }
  void store(SolverBody& a, SolverBody& b) const {
    if (kMovesA && a.invMass > 0.0) a.v = vA, a.w = wA;
    if (kMovesB && b.invMass > 0.0) b.v = vB, b.w = wB;
  }
};

// Calls f with the contact's ContactSides as a compile-time constant.
template <typename F>
void onSides(ContactSides sides, F&& f) {
  switch (sides) {
    case ContactSides::Both:
      return f(std::integral_constant<ContactSides, ContactSides::Both>{});
    case ContactSides::OnlyA:
      return f(std::integral_constant<ContactSides, ContactSides::OnlyA>{});
    case ContactSides::OnlyB:
      return f(std::integral_constant<ContactSides, ContactSides::OnlyB>{});
  }
}

template <ContactSides S>
void warmStart(const SolverContact& c, SolverBody& a, SolverBody& b) {
  PairVelocity<S> u(a, b);
  for (int i = 0; i < c.count; ++i) {
    const SolverContactPoint& p = c.points[i];
    if (p.normalImpulse == 0.0 && p.tangentImpulse[0] == 0.0 && p.tangentImpulse[1] == 0.0) continue;  // zeros
    u.apply(c, p, p.normalImpulse * c.normal + p.tangentImpulse[0] * c.tangent[0] + p.tangentImpulse[1] * c.tangent[1]);
  }
  u.store(a, b);
}

template <ContactSides S>
void solve(SolverContact& c, SolverBody& a, SolverBody& b, const ContactSolverStep& step, bool useBias) {
  const WorldSettings& s = *step.settings;
  const Real inv_h = 1.0 / step.h;
  const Softness& soft = c.againstStatic ? step.staticSoft : step.soft;
  PairVelocity<S> u(a, b);
  const Real dc = PairVelocity<S>::shift(a, b, c.normal);
  for (int i = 0; i < c.count; ++i) {
    SolverContactPoint& p = c.points[i];
    const Real sep = p.separation + dc + PairVelocity<S>::turn(a, b, p, c.normal);
    Real bias = 0.0, massScale = 1.0, impulseScale = 0.0;
    if (sep > 0.0) {
      bias = sep * inv_h;  // speculative: close the gap exactly, no more
    } else if (useBias) {
      switch (s.positionCorrection) {
        case PositionCorrection::Soft:
          bias = std::max(soft.biasRate * sep, -s.contactPushSpeed);
          massScale = soft.massScale;
          impulseScale = soft.impulseScale;
          break;
        case PositionCorrection::Baumgarte:
          bias = std::max(s.baumgarte * inv_h * std::min(0.0, sep + s.linearSlop), -s.contactPushSpeed);
          break;
        case PositionCorrection::None:
          break;
      }
    }
    const Real vn = u.along(p, c.normal);
    const Real impulse = -p.normalMass * massScale * (vn + bias) - impulseScale * p.normalImpulse;
    const Real total = std::max(p.normalImpulse + impulse, 0.0);
    const Real applied = total - p.normalImpulse;
    p.normalImpulse = total;
    p.maxNormalImpulse = std::max(p.maxNormalImpulse, applied);
    // A point whose impulse does not change (a speculative one held at 0) would add zeros: the same bits
    // (only an exact zero may differ in sign), so it is left out.
    if (applied != 0.0) u.apply(c, p, applied * c.normal);
  }
  // Friction, bounded by μ times this point's normal impulse: each tangent row with its own mass, then the
  // pair clamped to the disk |λ_t| ≤ μλ_n (cone; Jolt does the same) or each row to ±μλ_n (pyramid). Both
  // rows are computed from the same velocities and applied together.
  for (int i = 0; i < c.count; ++i) {
    SolverContactPoint& p = c.points[i];
    const Real limit = c.friction * p.normalImpulse;
    Real next[2];
    for (int k = 0; k < 2; ++k) next[k] = p.tangentImpulse[k] - p.tangentMass[k] * u.along(p, c.tangent[k]);
    if (s.friction == FrictionModel::Cone) {
      const Real len2 = next[0] * next[0] + next[1] * next[1];
      if (len2 > limit * limit) {
        const Real scale = limit / std::sqrt(len2);
        next[0] *= scale, next[1] *= scale;
      }
    } else {
      for (Real& x : next) x = std::clamp(x, -limit, limit);
    }
    // Unchanged friction (a point without normal impulse keeps 0) is left out, as above.
    if (next[0] != p.tangentImpulse[0] || next[1] != p.tangentImpulse[1])
      u.apply(c, p, (next[0] - p.tangentImpulse[0]) * c.tangent[0] + (next[1] - p.tangentImpulse[1]) * c.tangent[1]);
    p.tangentImpulse[0] = next[0];
    p.tangentImpulse[1] = next[1];
  }
  u.store(a, b);
}

template <ContactSides S>
void restitute(SolverContact& c, SolverBody& a, SolverBody& b, const WorldSettings& settings) {
  PairVelocity<S> u(a, b);
  for (int i = 0; i < c.count; ++i) {
    SolverContactPoint& p = c.points[i];
    if (p.relativeVelocity > -settings.restitutionThreshold || p.maxNormalImpulse == 0.0) continue;
    const Real vn = u.along(p, c.normal);
    const Real impulse = -p.normalMass * (vn + c.restitution * p.relativeVelocity);
    const Real total = std::max(p.normalImpulse + impulse, 0.0);
    const Real applied = total - p.normalImpulse;
    p.normalImpulse = total;
    p.maxNormalImpulse = std::max(p.maxNormalImpulse, applied);
    u.apply(c, p, applied * c.normal);
  }
  u.store(a, b);
}
}  // namespace

void warmStartContact(const SolverContact& c, std::vector<SolverBody>& bodies) {
  onSides(c.sides, [&](auto S) { warmStart<decltype(S)::value>(c, bodies[c.bodyA], bodies[c.bodyB]); });
}

void solveContact(SolverContact& c, std::vector<SolverBody>& bodies, const ContactSolverStep& step, bool useBias) {
  onSides(c.sides, [&](auto S) { solve<decltype(S)::value>(c, bodies[c.bodyA], bodies[c.bodyB], step, useBias); });
}

void applyRestitution(SolverContact& c, std::vector<SolverBody>& bodies, const WorldSettings& settings) {
  if (c.restitution == 0.0) return;
  onSides(c.sides, [&](auto S) { restitute<decltype(S)::value>(c, bodies[c.bodyA], bodies[c.bodyB], settings); });
}

}  // namespace pba::rigid
