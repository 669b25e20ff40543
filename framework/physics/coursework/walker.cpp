#include "physics/coursework/walker.h"

#include <algorithm>
#include <cmath>
#include "physics/exercises/not_implemented.h"
#include "physics/ik/analytic.h"

namespace pba::coursework {

Vec3 footOffset(const GaitDesc& gait, Real phase) {
  // BEGIN SOLUTION
  const Real u = phase - std::floor(phase);
  const Real beta = gait.dutyFactor;
  // The body covers stride·β during stance; the planted foot falls back by as much relative to it.
  const Real half = 0.5 * gait.stride * beta;
  if (u < beta) return {half - gait.stride * u, 0.0, 0.0};
  const Real s = (u - beta) / (1.0 - beta);    // swing progress in [0, 1)
  const Real eased = s * s * (3.0 - 2.0 * s);  // monotone, zero slope at both ends
  return {-half + 2.0 * half * eased, gait.stepHeight * std::sin(kPi * s), 0.0};
  // END SOLUTION
  // STUB: return exercises::notImplemented("CW1-1", Vec3(0.0), gait, phase);
}

Vec3 reachTarget(const Vec3& shoulder, Real reach, const Vec3& animatedHand, const Vec3& goal, Real weight) {
  // BEGIN SOLUTION
  const Real w = std::clamp(weight, 0.0, 1.0);
  const Real eased = w * w * (3.0 - 2.0 * w);
  const Vec3 target = animatedHand + eased * (goal - animatedHand);
  const Vec3 fromShoulder = target - shoulder;
  const Real distance = glm::length(fromShoulder);
  if (distance <= reach || distance < 1e-12) return target;
  return shoulder + fromShoulder * (reach / distance);
  // END SOLUTION
  // STUB: return exercises::notImplemented("CW1-2", animatedHand, shoulder, reach, goal, weight);
}

void stepWalker(const WalkerDesc& desc, WalkerState& state, Real h) {
  state.time += h;
  const GaitDesc& gait = desc.gait;
  const Real cycle = gait.stride / gait.speed;  // [s]
  WalkerPose& p = state.pose;
  p.pelvis = Vec3(gait.speed * state.time, desc.hipHeight, 0.0);
  for (int side = 0; side < 2; ++side) {
    const Real z = side == 0 ? desc.hipHalfWidth : -desc.hipHalfWidth;
    p.hips[side] = p.pelvis + Vec3(0.0, 0.0, z);
    const Real phase = state.time / cycle + 0.5 * side;
    p.feet[side] = Vec3(p.hips[side].x, 0.0, z) + footOffset(gait, phase);
    const Vec3 kneePole = p.hips[side] + Vec3(1.0, -0.5 * desc.hipHeight, 0.0);  // knees bend forward
    const ik::TwoBonePose leg = ik::twoBoneGeometry(p.hips[side], desc.thigh, desc.shin, p.feet[side], kneePole);
    p.knees[side] = leg.elbow;
    p.feet[side] = leg.wrist;  // a foot out of reach stops where the straight leg ends
    const Real sz = side == 0 ? desc.shoulderHalfWidth : -desc.shoulderHalfWidth;
    p.shoulders[side] = Vec3(p.pelvis.x, desc.shoulderHeight, sz);
    const Real reach = desc.upperArm + desc.forearm;
    const Vec3 hanging = p.shoulders[side] + Vec3(0.0, -0.97 * reach, 0.0);
    const Real weight = side == 1 ? (state.time - desc.reachStart) / desc.reachDuration : 0.0;
    const Vec3 target = reachTarget(p.shoulders[side], reach, hanging, desc.reachGoal, weight);
    const Vec3 elbowPole = p.shoulders[side] + Vec3(-1.0, -0.5, 0.0);  // elbows bend backward
    const ik::TwoBonePose arm = ik::twoBoneGeometry(p.shoulders[side], desc.upperArm, desc.forearm, target, elbowPole);
    p.elbows[side] = arm.elbow;
    p.hands[side] = arm.wrist;
  }
}

}  // namespace pba::coursework
