#include "physics/rigid/contact_solver.h"

#include <algorithm>
#include <cmath>

namespace pba::rigid {

void tangentBasis(const Vec3& n, Vec3& t1, Vec3& t2) {
  const Vec3 a = glm::abs(n);
  const Vec3 axis = a.x <= a.y && a.x <= a.z ? Vec3(1, 0, 0) : (a.y <= a.z ? Vec3(0, 1, 0) : Vec3(0, 0, 1));
  t1 = glm::normalize(glm::cross(axis, n));
  t2 = glm::cross(n, t1);
}

void prepareContact(ContactConstraint& c, const std::vector<SolverBody>& bodies) {
  const SolverBody& a = bodies[c.bodyA];
  const SolverBody& b = bodies[c.bodyB];
  c.againstStatic = a.invMass == 0.0 || b.invMass == 0.0;
  c.normal = c.manifold.normal;
  tangentBasis(c.normal, c.tangent[0], c.tangent[1]);
  c.count = c.manifold.count;
  for (int i = 0; i < c.count; ++i) {
    ContactPoint& p = c.points[i];
    const collision::ManifoldPoint& mp = c.manifold.points[i];
    p.rA = mp.point - a.c;
    p.rB = mp.point - b.c;
    p.localA = glm::conjugate(a.q) * p.rA;
    p.localB = glm::conjugate(b.q) * p.rB;
    p.separation = mp.separation;
    p.id = mp.id;
    p.normalMass = rowMass(a, b, p.rA, p.rB, c.normal);
    // Tangent K = J_t M⁻¹ J_tᵀ (2 × 2); the pyramid uses its diagonal, the cone its inverse.
    Real k[2][2];
    for (int r = 0; r < 2; ++r)
      for (int s = 0; s < 2; ++s) {
        const Vec3 ar = glm::cross(p.rA, c.tangent[r]), as = glm::cross(p.rA, c.tangent[s]);
        const Vec3 br = glm::cross(p.rB, c.tangent[r]), bs = glm::cross(p.rB, c.tangent[s]);
        k[r][s] = (r == s ? a.invMass + b.invMass : 0.0) + glm::dot(ar, a.invI * as) + glm::dot(br, b.invI * bs);
      }
    p.tangentMass[0] = k[0][0] > 0.0 ? 1.0 / k[0][0] : 0.0;
    p.tangentMass[1] = k[1][1] > 0.0 ? 1.0 / k[1][1] : 0.0;
    const Real det = k[0][0] * k[1][1] - k[0][1] * k[1][0];
    if (det > 0.0) {
      p.tangentK[0] = k[1][1] / det, p.tangentK[1] = -k[0][1] / det, p.tangentK[2] = k[0][0] / det;
    } else {
      p.tangentK[0] = p.tangentK[1] = p.tangentK[2] = 0.0;
    }
    const Vec3 dv = b.v + glm::cross(b.w, p.rB) - a.v - glm::cross(a.w, p.rA);
    p.relativeVelocity = glm::dot(c.normal, dv);
    p.maxNormalImpulse = 0.0;
  }
}

void warmStartContact(const ContactConstraint& c, std::vector<SolverBody>& bodies) {
  SolverBody& a = bodies[c.bodyA];
  SolverBody& b = bodies[c.bodyB];
  for (int i = 0; i < c.count; ++i) {
    const ContactPoint& p = c.points[i];
    const Vec3 P = p.normalImpulse * c.normal + p.tangentImpulse[0] * c.tangent[0] + p.tangentImpulse[1] * c.tangent[1];
    applyImpulse(a, p.rA, P, -1.0);
    applyImpulse(b, p.rB, P, 1.0);
  }
}

void solveContact(ContactConstraint& c, std::vector<SolverBody>& bodies, const ContactSolverStep& step, bool useBias) {
  SolverBody& a = bodies[c.bodyA];
  SolverBody& b = bodies[c.bodyB];
  const WorldSettings& s = *step.settings;
  const Real inv_h = 1.0 / step.h;
  const Softness& soft = c.againstStatic ? step.staticSoft : step.soft;
  for (int i = 0; i < c.count; ++i) {
    ContactPoint& p = c.points[i];
    // Current separation from the bodies' motion since the start of the step (anchors fixed in the bodies).
    const Vec3 d = (b.c + b.q * p.localB) - (a.c + a.q * p.localA);
    const Real sep = p.separation + glm::dot(c.normal, d);
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
        case PositionCorrection::None: break;
      }
    }
    const Vec3 dv = b.v + glm::cross(b.w, p.rB) - a.v - glm::cross(a.w, p.rA);
    const Real vn = glm::dot(c.normal, dv);
    const Real impulse = -p.normalMass * massScale * (vn + bias) - impulseScale * p.normalImpulse;
    const Real total = std::max(p.normalImpulse + impulse, 0.0);
    const Real applied = total - p.normalImpulse;
    p.normalImpulse = total;
    p.maxNormalImpulse = std::max(p.maxNormalImpulse, applied);
    const Vec3 P = applied * c.normal;
    applyImpulse(a, p.rA, P, -1.0);
    applyImpulse(b, p.rB, P, 1.0);
  }
  // Friction, bounded by μ times this point's normal impulse.
  for (int i = 0; i < c.count; ++i) {
    ContactPoint& p = c.points[i];
    const Vec3 dv = b.v + glm::cross(b.w, p.rB) - a.v - glm::cross(a.w, p.rA);
    const Real vt[2] = {glm::dot(c.tangent[0], dv), glm::dot(c.tangent[1], dv)};
    const Real limit = c.friction * p.normalImpulse;
    Real next[2];
    if (s.friction == FrictionModel::Cone) {
      next[0] = p.tangentImpulse[0] - p.tangentMass[0] * vt[0];
      next[1] = p.tangentImpulse[1] - p.tangentMass[1] * vt[1];
      const Real len = std::sqrt(next[0] * next[0] + next[1] * next[1]);
      if (len > limit && len > 0.0) next[0] *= limit / len, next[1] *= limit / len;
    } else {
      for (int k = 0; k < 2; ++k) next[k] = std::clamp(p.tangentImpulse[k] - p.tangentMass[k] * vt[k], -limit, limit);
    }
    const Vec3 P = (next[0] - p.tangentImpulse[0]) * c.tangent[0] + (next[1] - p.tangentImpulse[1]) * c.tangent[1];
    p.tangentImpulse[0] = next[0];
    p.tangentImpulse[1] = next[1];
    applyImpulse(a, p.rA, P, -1.0);
    applyImpulse(b, p.rB, P, 1.0);
  }
}

void applyRestitution(ContactConstraint& c, std::vector<SolverBody>& bodies, const WorldSettings& settings) {
  if (c.restitution == 0.0) return;
  SolverBody& a = bodies[c.bodyA];
  SolverBody& b = bodies[c.bodyB];
  for (int i = 0; i < c.count; ++i) {
    ContactPoint& p = c.points[i];
    if (p.relativeVelocity > -settings.restitutionThreshold || p.maxNormalImpulse == 0.0) continue;
    const Vec3 dv = b.v + glm::cross(b.w, p.rB) - a.v - glm::cross(a.w, p.rA);
    const Real vn = glm::dot(c.normal, dv);
    const Real impulse = -p.normalMass * (vn + c.restitution * p.relativeVelocity);
    const Real total = std::max(p.normalImpulse + impulse, 0.0);
    const Real applied = total - p.normalImpulse;
    p.normalImpulse = total;
    p.maxNormalImpulse = std::max(p.maxNormalImpulse, applied);
    applyImpulse(a, p.rA, applied * c.normal, -1.0);
    applyImpulse(b, p.rB, applied * c.normal, 1.0);
  }
}

}  // namespace pba::rigid
