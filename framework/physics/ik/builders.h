#pragma once
// Scene builders of the IK lab (docs/architecture.md §1: used by the lab, the tests and the benchmarks alike).
// Descriptions with documented defaults; builders validate them and return a rig: a skeleton and its
// effectors (goals at the effectors' rest positions).
#include <cstdint>
#include <random>
#include <vector>

#include "physics/core/enum_names.h"
#include "physics/core/result.h"
#include "physics/ik/effector.h"
#include "physics/ik/skeleton.h"

namespace pba::ik {

struct Rig {
  Skeleton skeleton;
  std::vector<Effector> effectors;
};

/// Axes of a hinge chain: all about z (a planar arm in the xy plane), or alternating z and y so that
/// the chain reaches out of the plane.
enum class HingeAxes { Planar, Alternating };
inline constexpr auto kHingeAxesNames =
    enumNames<HingeAxes>({{HingeAxes::Planar, "planar"}, {HingeAxes::Alternating, "alternating"}});

/// A serial chain along +x from `base`: `links` joints, each followed by a bone of totalLength/links;
/// one position effector at the tip (Workbook §2.1 tasks 1, 3 and 5).
struct ChainDesc {
  int links = 10;                      ///< [1] 1–10,000
  Real totalLength = 2.0;              ///< [m] > 0: sum of the bone lengths (the reach)
  JointType joint = JointType::Hinge;  ///< Hinge, Ball, Free or Prismatic (prismatic makes a telescope)
  HingeAxes axes = HingeAxes::Planar;
  Real limit = degToRad(120.0);  ///< [rad] in (0, π]: every rotational DOF in [−limit, limit]
  Vec3 base{0.0, 0.0, 0.0};      ///< [m] world position of the first joint
};
Status validate(const ChainDesc& d);
Result<Rig> buildIkChain(const ChainDesc& d);

/// A single free (quaternion) joint with one bone of `length` along +x: Workbook §2.1 task 2.
Result<Rig> buildSingleJoint(Real length = 1.0);

/// Shoulder (ball, ±limit) + elbow (hinge about z, [0, 150°]) + wrist effector; bones along +x.
struct TwoBoneDesc {
  Real upper = 0.9;              ///< [m] shoulder → elbow
  Real lower = 0.8;              ///< [m] elbow → wrist
  Vec3 shoulder{0.0, 1.0, 0.0};  ///< [m]
};
Result<Rig> buildTwoBoneArm(const TwoBoneDesc& d);

/// A hand: ball wrist at the origin, a palm, five fingers of a ball knuckle and two hinges,
/// effectors at the five finger tips (Workbook §2.1 task 5: multiple end effectors).
Result<Rig> buildHand();

/// Buss & Kim's "double Y" tree: a trunk of 3 ball joints that splits in two, each branch splitting
/// again: 4 effectors at the leaves.
Result<Rig> buildDoubleY();

/// A pose with every DOF drawn uniformly inside its limits (free joints: uniform axis, angle in
/// [0, maxRotation]). Deterministic for a given engine state.
Pose randomPose(const Skeleton& s, std::mt19937_64& rng);

/// Moves every effector's goal onto its current position in `pose` (orientation too).
void setGoalsFromPose(const Skeleton& s, const Pose& pose, std::vector<Effector>& effectors);

}  // namespace pba::ik
