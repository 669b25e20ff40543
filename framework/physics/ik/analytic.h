#pragma once
// Analytic (geometric) IK (Workbook §2.2, §2.1 task 2; IK slides, "Other techniques": analytic
// solutions for simple chains are fast and predictable).
#include "physics/ik/exercises.h"

namespace pba::ik {

/// Two-bone limb by the law of cosines: shoulder s, bone lengths a (upper) and b (lower), target t,
/// pole point P. The wrist lands on t when a + b ≥ |t − s| ≥ |a − b| (else on the segment toward t,
/// at the nearest reachable distance); the elbow lies in the plane (s, t, P), on P's side:
///   d = |t − s|,  cos α = (a² + d² − b²) / (2 a d)  (α: angle at the shoulder between s→t and s→elbow)
///   elbow = s + a (cos α n̂ + sin α m̂),  n̂ = unit(t − s),  m̂ = unit(P − s − ((P − s)·n̂) n̂).
struct TwoBonePose {
  Vec3 elbow{0.0};
  Vec3 wrist{0.0};
  bool reachable = true;  ///< false when d was clamped into [|a − b|, a + b]
};
TwoBonePose twoBoneGeometry(const Vec3& shoulder, Real upper, Real lower, const Vec3& target, const Vec3& pole);

}  // namespace pba::ik
