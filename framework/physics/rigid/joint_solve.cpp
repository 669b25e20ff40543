// The joint types' rows. Notation: x centre of mass, r arm from it to the anchor (world), p = x + r the
// anchor, ω angular velocity, m⁻¹ and I⁻¹ inverse mass and world inverse inertia; subscripts A, B.
//
// Point (ball, hinge, cone-twist, fixed, mouse): C = p_B − p_A (3 rows)
//   Ċ = v_B + ω_B × r_B − v_A − ω_A × r_A,   K = (m_A⁻¹ + m_B⁻¹)1 − [r_A]×I_A⁻¹[r_A]× − [r_B]×I_B⁻¹[r_B]×.
//   K is symmetric positive definite unless both bodies are static. The soft form (softness.h) with
//   f → ∞ recovers the rigid λ = −K⁻¹(Ċ + C/h).
// Hinge axis rows: with axis a fixed in A and b fixed in B (equal at creation), C = [b₁, b₂]·(a × b) for
//   b₁, b₂ ⟂ a; to first order Ċ = [b₁, b₂]·(ω_B − ω_A), K = b_iᵀ(I_A⁻¹ + I_B⁻¹)b_j (2 × 2).
// Angle rows (hinge limits and motor, twist limits): θ = twist of q_A⁻¹q_B about a, θ̇ = a·(ω_B − ω_A),
//   K = aᵀ(I_A⁻¹ + I_B⁻¹)a. A limit is one-sided (λ ≥ 0) with C = θ − lower or upper − θ, speculative
//   while C > 0 (it may close the gap in this substep, no more); the motor drives θ̇ to its speed with
//   |λ| ≤ τ_max h.
// Angular lock (fixed, slider): C = 2 vec(q_A⁻¹ q_B q₀⁻¹) (small-angle rotation vector), Ċ = ω_B − ω_A,
//   K = I_A⁻¹ + I_B⁻¹.
// Swing cone (cone-twist): θ_s = ∠(a_A, a_B) ≤ span; rotating about n = a_A × a_B/|·| opens the angle, so
//   C = span − θ_s, Ċ = −n·(ω_B − ω_A), one-sided.
// Slider: d = p_B − p_A; rows along u ⟂ the axis: C = u·d, Ċ = u·(v_B + ω_B × r_B − v_A − ω_A × (r_A + d))
//   (A's arm reaches B's anchor, Box2D prismatic_joint.c); limits along the axis the same way.
// Distance: C = |d| − L along u = d/|d|, a rigid row or a spring of the joint's own hertz and damping
//   ratio; min/max lengths as one-sided rows.
#include <cmath>

#include "physics/rigid/contact_solver.h"
#include "physics/rigid/joint_rows.h"

namespace pba::rigid {
namespace {

using detail::anchorA;
using detail::anchorB;

// j.rA and j.rB are the current arms (solveJoint sets them before any row): the anchors are c + r.
void solvePoint(Joint& j, SolverBody& A, SolverBody& B, const Softness& soft, bool useBias) {
  const Vec3 C = (B.c + j.rB) - (A.c + j.rA);
  Vec3 bias(0.0);
  Real massScale = 1.0, impulseScale = 0.0;
  if (useBias) bias = soft.biasRate * C, massScale = soft.massScale, impulseScale = soft.impulseScale;
  const Vec3 cdot = B.v + glm::cross(B.w, j.rB) - A.v - glm::cross(A.w, j.rA);
  const Vec3 impulse = -massScale * (j.pointMass * (cdot + bias)) - impulseScale * j.pointImpulse;
  j.pointImpulse += impulse;
  applyImpulse(A, j.rA, impulse, -1.0);
  applyImpulse(B, j.rB, impulse, 1.0);
}

void solveLock(Joint& j, SolverBody& A, SolverBody& B, const Softness& soft, bool useBias) {
  const Vec3 C = detail::lockError(j, A, B);
  Vec3 bias(0.0);
  Real massScale = 1.0, impulseScale = 0.0;
  if (useBias) bias = soft.biasRate * C, massScale = soft.massScale, impulseScale = soft.impulseScale;
  const Vec3 impulse = -massScale * (j.angularMass * (B.w - A.w + bias)) - impulseScale * j.angularImpulse;
  j.angularImpulse += impulse;
  applyAngularImpulse(A, impulse, -1.0);
  applyAngularImpulse(B, impulse, 1.0);
}

void solveMotorAndLimits(Joint& j, SolverBody& A, SolverBody& B, const JointStep& step, bool useBias, Real angle) {
  const JointDesc& d = j.desc;
  const Vec3& u = j.axisWorld;
  if (d.enableMotor) {
    const Real cdot = glm::dot(u, B.w - A.w);
    Real impulse = -j.axialMass * (cdot - d.motorSpeed);
    const Real maxImpulse = d.maxMotorTorque * step.h;
    const Real next = std::clamp(j.motorImpulse + impulse, -maxImpulse, maxImpulse);
    impulse = next - j.motorImpulse;
    j.motorImpulse = next;
    applyAngularImpulse(A, impulse * u, -1.0);
    applyAngularImpulse(B, impulse * u, 1.0);
  }
  if (d.enableLimit) {
    detail::solveAngularLimit(A, B, u, 1.0, angle - d.lower, j.axialMass, j.lowerImpulse, step.soft, step.h, useBias);
    detail::solveAngularLimit(A, B, u, -1.0, d.upper - angle, j.axialMass, j.upperImpulse, step.soft, step.h, useBias);
  }
}

void solveHingeAxis(Joint& j, SolverBody& A, SolverBody& B, const Softness& soft, bool useBias) {
  const Vec3 err = glm::cross(A.q * j.axisA, B.q * j.axisB);
  const Vec3 dw = B.w - A.w;
  const Real cdot[2] = {glm::dot(j.hingeBasis[0], dw), glm::dot(j.hingeBasis[1], dw)};
  Real bias[2] = {0.0, 0.0}, massScale = 1.0, impulseScale = 0.0;
  if (useBias) {
    bias[0] = soft.biasRate * glm::dot(j.hingeBasis[0], err);
    bias[1] = soft.biasRate * glm::dot(j.hingeBasis[1], err);
    massScale = soft.massScale, impulseScale = soft.impulseScale;
  }
  const Mat3& k = j.angularMass;  // the 2 × 2 inverse in its upper-left block
  const Real r0 = cdot[0] + bias[0], r1 = cdot[1] + bias[1];
  const Real i0 = -massScale * (k[0][0] * r0 + k[1][0] * r1) - impulseScale * j.angularImpulse.x;
  const Real i1 = -massScale * (k[0][1] * r0 + k[1][1] * r1) - impulseScale * j.angularImpulse.y;
  j.angularImpulse.x += i0;
  j.angularImpulse.y += i1;
  const Vec3 L = i0 * j.hingeBasis[0] + i1 * j.hingeBasis[1];
  applyAngularImpulse(A, L, -1.0);
  applyAngularImpulse(B, L, 1.0);
}

// One linear row along u with arms armA (for A) and rB, one-sided when `limit`, else bilateral.
void solveLinearRow(SolverBody& A, SolverBody& B, const Vec3& armA, const Vec3& rB, const Vec3& u, Real sign, Real C,
                    Real mass, Real& accumulated, const Softness& soft, Real h, bool useBias, bool limit) {
  Real bias = 0.0, massScale = 1.0, impulseScale = 0.0;
  if (limit && C > 0.0)
    bias = C / h;
  else if (useBias)
    bias = soft.biasRate * C, massScale = soft.massScale, impulseScale = soft.impulseScale;
  const Real cdot = sign * glm::dot(u, B.v + glm::cross(B.w, rB) - A.v - glm::cross(A.w, armA));
  Real impulse = -mass * massScale * (cdot + bias) - impulseScale * accumulated;
  if (limit) {
    const Real next = std::max(accumulated + impulse, 0.0);
    impulse = next - accumulated;
    accumulated = next;
  } else {
    accumulated += impulse;
  }
  applyImpulse(A, armA, sign * impulse * u, -1.0);
  applyImpulse(B, rB, sign * impulse * u, 1.0);
}

}  // namespace

void prepareJoint(Joint& j, const std::vector<SolverBody>& bodies, const JointStep& step) {
  const SolverBody& A = bodies[j.a];
  const SolverBody& B = bodies[j.b];
  j.rA = A.q * j.localA;
  j.rB = B.q * j.localB;
  const Mat3 isum = A.invI + B.invI;
  auto axial = [&](const Vec3& u) {
    const Real k = glm::dot(u, isum * u);
    return k > 0.0 ? 1.0 / k : 0.0;
  };
  switch (j.desc.kind) {
    case JointKind::Hinge: {
      j.axisWorld = A.q * j.axisA;
      tangentBasis(j.axisWorld, j.hingeBasis[0], j.hingeBasis[1]);
      Real k[2][2];
      for (int r = 0; r < 2; ++r)
        for (int c = 0; c < 2; ++c) k[r][c] = glm::dot(j.hingeBasis[r], isum * j.hingeBasis[c]);
      const Real det = k[0][0] * k[1][1] - k[0][1] * k[1][0];
      j.angularMass = Mat3(0.0);
      if (det > 0.0) {
        j.angularMass[0][0] = k[1][1] / det, j.angularMass[1][1] = k[0][0] / det;
        j.angularMass[1][0] = -k[0][1] / det, j.angularMass[0][1] = -k[1][0] / det;
      }
      j.axialMass = axial(j.axisWorld);
      break;
    }
    case JointKind::ConeTwist:
      j.axisWorld = glm::normalize(A.q * j.axisA + B.q * j.axisB);
      j.axialMass = axial(j.axisWorld);
      break;
    case JointKind::Fixed:
    case JointKind::Slider:
      j.angularMass = std::abs(glm::determinant(isum)) > 1e-300 ? glm::inverse(isum) : Mat3(0.0);
      if (j.desc.kind == JointKind::Slider) {
        j.axisWorld = A.q * j.axisA;
        tangentBasis(j.axisWorld, j.hingeBasis[0], j.hingeBasis[1]);
        j.axialMass = rowMass(A, B, anchorB(j, B) - A.c, j.rB, j.axisWorld);
      }
      break;
    case JointKind::Distance: {
      const Vec3 d = anchorB(j, B) - anchorA(j, A);
      const Real l = glm::length(d);
      j.axisWorld = l > 1e-12 ? d / l : Vec3(0.0, 1.0, 0.0);
      j.axialMass = rowMass(A, B, j.rA, j.rB, j.axisWorld);
      break;
    }
    case JointKind::Ball:
    case JointKind::Mouse:
      break;  // the point rows' mass is formed where they are solved, from the current arms (solveJoint)
  }
  if (!step.warmStarting) {
    j.pointImpulse = j.angularImpulse = Vec3(0.0);
    j.motorImpulse = j.lowerImpulse = j.upperImpulse = j.springImpulse = j.swingImpulse = 0.0;
  }
}

void solveJoint(Joint& j, std::vector<SolverBody>& bodies, const JointStep& step, bool useBias) {
  SolverBody& A = bodies[j.a];
  SolverBody& B = bodies[j.b];
  const JointDesc& d = j.desc;
  // Current anchors: the arms turn with the bodies during the substeps, and the point rows' effective
  // mass with them (Box2D v3 revolute_joint.c does the same; contacts keep fixed anchors instead).
  j.rA = A.q * j.localA;
  j.rB = B.q * j.localB;
  if (d.kind != JointKind::Slider && d.kind != JointKind::Distance) j.pointMass = detail::pointMass(A, B, j.rA, j.rB);
  switch (d.kind) {
    case JointKind::Ball:
      solvePoint(j, A, B, step.soft, useBias);
      break;
    case JointKind::Hinge:
      // The angle (a quaternion product and an atan2) only where a limit reads it.
      solveMotorAndLimits(j, A, B, step, useBias, d.enableLimit ? detail::twistAngle(j, A, B) : 0.0);
      solveHingeAxis(j, A, B, step.soft, useBias);
      solvePoint(j, A, B, step.soft, useBias);
      break;
    case JointKind::ConeTwist: {
      if (d.enableLimit) solveMotorAndLimits(j, A, B, step, useBias, detail::twistAngle(j, A, B));
      const Vec3 a = A.q * j.axisA, b = B.q * j.axisB;
      const Vec3 n = glm::cross(a, b);
      const Real sinSwing = glm::length(n);
      if (sinSwing > 1e-9) {
        j.hingeBasis[0] = n / sinSwing;
        const Real swing = std::atan2(sinSwing, glm::dot(a, b));
        const Real k = glm::dot(j.hingeBasis[0], (A.invI + B.invI) * j.hingeBasis[0]);
        detail::solveAngularLimit(A, B, j.hingeBasis[0], -1.0, d.swingSpan - swing, k > 0.0 ? 1.0 / k : 0.0,
                                  j.swingImpulse, step.soft, step.h, useBias);
      }
      solvePoint(j, A, B, step.soft, useBias);
      break;
    }
    case JointKind::Fixed:
      solveLock(j, A, B, step.soft, useBias);
      solvePoint(j, A, B, step.soft, useBias);
      break;
    case JointKind::Slider: {
      const Vec3 dvec = anchorB(j, B) - anchorA(j, A);
      const Vec3 armA = anchorB(j, B) - A.c;
      const Vec3& u = j.axisWorld;
      const Real t = glm::dot(dvec, u);
      if (d.enableMotor) {
        Real motor = j.motorImpulse;
        const Real cdot = glm::dot(u, B.v + glm::cross(B.w, j.rB) - A.v - glm::cross(A.w, armA));
        Real impulse = -j.axialMass * (cdot - d.motorSpeed);
        const Real maxImpulse = d.maxMotorTorque * step.h;
        motor = std::clamp(j.motorImpulse + impulse, -maxImpulse, maxImpulse);
        impulse = motor - j.motorImpulse;
        j.motorImpulse = motor;
        applyImpulse(A, armA, impulse * u, -1.0);
        applyImpulse(B, j.rB, impulse * u, 1.0);
      }
      if (d.enableLimit) {
        solveLinearRow(A, B, armA, j.rB, u, 1.0, t - d.lower, j.axialMass, j.lowerImpulse, step.soft, step.h, useBias,
                       true);
        solveLinearRow(A, B, armA, j.rB, u, -1.0, d.upper - t, j.axialMass, j.upperImpulse, step.soft, step.h, useBias,
                       true);
      }
      solveLock(j, A, B, step.soft, useBias);
      for (int k = 0; k < 2; ++k) {
        const Vec3& p = j.hingeBasis[k];
        Real accumulated = glm::dot(j.pointImpulse, p);
        const Real before = accumulated;
        solveLinearRow(A, B, armA, j.rB, p, 1.0, glm::dot(dvec, p), rowMass(A, B, armA, j.rB, p), accumulated,
                       step.soft, step.h, useBias, false);
        j.pointImpulse += (accumulated - before) * p;
      }
      break;
    }
    case JointKind::Distance: {
      // The rope's direction turns with the bodies: axis and mass from the current anchors.
      const Vec3 dvec = anchorB(j, B) - anchorA(j, A);
      const Real l = glm::length(dvec);
      if (l > 1e-12) j.axisWorld = dvec / l;
      const Vec3& u = j.axisWorld;
      j.axialMass = rowMass(A, B, j.rA, j.rB, u);
      if (d.hertz > 0.0) {
        // A spring always acts, with its own softness (and no relax: it is a force, not an error).
        const Softness spring = makeSoft(d.hertz, d.dampingRatio, step.h);
        solveLinearRow(A, B, j.rA, j.rB, u, 1.0, l - j.restLength, j.axialMass, j.springImpulse, spring, step.h, true,
                       false);
      } else {
        solveLinearRow(A, B, j.rA, j.rB, u, 1.0, l - j.restLength, j.axialMass, j.springImpulse, step.soft, step.h,
                       useBias, false);
      }
      if (d.minLength > 0.0)
        solveLinearRow(A, B, j.rA, j.rB, u, 1.0, l - d.minLength, j.axialMass, j.lowerImpulse, step.soft, step.h,
                       useBias, true);
      if (d.maxLength < 1e29)
        solveLinearRow(A, B, j.rA, j.rB, u, -1.0, d.maxLength - l, j.axialMass, j.upperImpulse, step.soft, step.h,
                       useBias, true);
      break;
    }
    case JointKind::Mouse: {
      // Box2D's mouse joint: a soft point constraint to the target with its own spring, force-limited.
      const Softness spring =
          makeSoft(d.hertz > 0.0 ? d.hertz : 5.0, d.dampingRatio > 0.0 ? d.dampingRatio : 0.7, step.h);
      const Vec3 C = anchorB(j, B) - j.target;
      const Vec3 cdot = B.v + glm::cross(B.w, j.rB);
      Vec3 impulse =
          -spring.massScale * (j.pointMass * (cdot + spring.biasRate * C)) - spring.impulseScale * j.pointImpulse;
      Vec3 next = j.pointImpulse + impulse;
      const Real maxImpulse = d.maxForce * step.h;
      if (glm::length(next) > maxImpulse) next *= maxImpulse / glm::length(next);
      impulse = next - j.pointImpulse;
      j.pointImpulse = next;
      applyImpulse(B, j.rB, impulse, 1.0);
      B.w *= 1.0 / (1.0 + step.h * 2.0);  // a little angular damping so a dragged body does not spin forever
      break;
    }
  }
}

}  // namespace pba::rigid
