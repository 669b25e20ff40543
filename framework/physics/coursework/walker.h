#pragma once
// Coursework 1, a character that reaches and walks (docs/course/coursework-1-reach-and-walk.md): a walk
// cycle plants each foot on the ground while the body moves on, two-bone IK (ik::twoBoneGeometry, the
// law of cosines of Workbook §2.2) bends the knees to the planted feet, and an arm eases from its
// animated pose to a reach goal. CW1-1 and CW1-2 are the student's tasks; stepWalker joins them.
//
// Frames: world, right-handed, y up; the character walks along +x. Ground plane y = 0.
#include <array>
#include "physics/core/types.h"

namespace pba::coursework {

/// A walk cycle. Each foot spends `dutyFactor` of a cycle on the ground (stance) and the rest in the
/// air (swing); the two feet are half a cycle apart. One cycle lasts stride / speed seconds.
struct GaitDesc {
  Real stride = 0.7;       ///< [m] how far each foot moves forward per cycle (typical 0.5–0.9)
  Real stepHeight = 0.08;  ///< [m] highest lift of a swinging foot above the ground (0.03–0.15)
  Real dutyFactor = 0.6;   ///< fraction of a cycle a foot is planted, in (0, 1) (walking: 0.55–0.65)
  Real speed = 1.2;        ///< [m/s] forward speed of the body (walking: 0.8–1.6)
};

// ***** CW1-1: a foot's place in the walk cycle (Workbook §7.1, keyframes; §2.2, limb IK) *****
// Input: the gait and the foot's phase u [cycles] (any real number: only its fractional part counts;
// u in [0, dutyFactor) is stance, the rest swing). Output: the foot's offset [m] from the point on the
// ground below its hip, in world axes (x forward, y up, z 0).
// (1) Reduce the phase into one cycle.
// (2) Stance: the body moves on at `speed` while the foot must not slide on the ground, so the offset
//     moves backward at exactly the body's speed, centred on the hip: it starts ahead of the hip and ends
//     behind it by the same distance. Work out that distance from the stride and the duty factor.
// (3) Swing: the foot travels forward relative to the body from where stance ended to where the next
//     stance begins, never moving backward over the ground, and it lifts: zero height at both ends of
//     the swing, stepHeight exactly at its middle, never below the ground and never above stepHeight.
// Check: in world coordinates (hip position + offset) a stance foot does not move; the offset is
// continuous over the whole cycle; the highest point is mid-swing at stepHeight.
// *****
Vec3 footOffset(const GaitDesc& gait, Real phase);

// ***** CW1-2: easing an arm toward a reach goal (Workbook §2.2; §7.2, easing curves) *****
// Inputs: the shoulder [m], the arm's reach (upper + lower arm length) [m], where the animation puts the
// hand [m], the reach goal [m], and the reach weight w (0: animated hand, 1: goal; outside [0, 1] it is
// clamped). Output: the wrist target to hand to the two-bone IK.
// (1) Ease the weight: the hand must start and end its reach with zero speed, so use the cubic in w that
//     goes from 0 to 1 with zero slope at both ends.
// (2) Blend the animated hand and the goal with the eased weight.
// (3) The arm cannot stretch: a target farther than the reach from the shoulder is pulled back onto the
//     sphere of that radius, along the line from the shoulder. A target at the shoulder stays there.
// Check: w = 0 gives the animated hand, w = 1 the goal when it is in reach, w = 1/2 the midpoint; an
// out-of-reach goal gives a point exactly `reach` from the shoulder, in the goal's direction.
// *****
Vec3 reachTarget(const Vec3& shoulder, Real reach, const Vec3& animatedHand, const Vec3& goal, Real weight);

/// The character's proportions, the gait and the reach, with their defaults (an adult of 1.75 m).
struct WalkerDesc {
  GaitDesc gait;
  Real hipHeight = 0.88;            ///< [m] pelvis height above the ground while walking
  Real hipHalfWidth = 0.1;          ///< [m] from the pelvis centre to each hip joint (along z)
  Real thigh = 0.46;                ///< [m] hip to knee
  Real shin = 0.45;                 ///< [m] knee to ankle
  Real shoulderHeight = 1.45;       ///< [m] above the ground
  Real shoulderHalfWidth = 0.19;    ///< [m]
  Real upperArm = 0.3;              ///< [m]
  Real forearm = 0.28;              ///< [m]
  Vec3 reachGoal{1.5, 1.1, -0.45};  ///< [m] world point the right hand reaches for
  Real reachStart = 0.5;            ///< [s] when the reach begins
  Real reachDuration = 0.8;         ///< [s] from no reach to full reach (> 0)
};

/// The pose, world positions [m]. Index 0 is the left side (+z), 1 the right (−z).
struct WalkerPose {
  Vec3 pelvis{0.0};
  std::array<Vec3, 2> hips{}, knees{}, feet{};
  std::array<Vec3, 2> shoulders{}, elbows{}, hands{};
};

struct WalkerState {
  Real time = 0.0;  ///< [s]
  WalkerPose pose;
};

/// Poses the walker at time `state.time + h`: the pelvis moves at the gait speed, each foot takes its
/// place in the cycle (CW1-1; the right foot half a cycle behind the left), the knees follow by two-bone
/// IK with the knee pointing forward, the left arm hangs, the right arm eases toward the reach goal
/// (CW1-2) over reachDuration after reachStart.
void stepWalker(const WalkerDesc& desc, WalkerState& state, Real h);

}  // namespace pba::coursework
