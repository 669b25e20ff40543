#pragma once
// Ragdoll builders shared by the lab, the tests and the benchmarks (docs/architecture.md §1): the
// Ragdoll paper's human (§5, its table of part sizes), its test scenes 1–7 (§5, "Visual tests"), chains,
// the four-legged spider, stairs and piles. Every builder returns a RagdollDesc that makes either kind.
// Ground y = 0, y up; the figures face +z, so a figure's left is +x (its width axis), z its depth.
#include <string>
#include <vector>

#include "physics/ragdoll/ragdoll_desc.h"

namespace pba::ragdoll {

struct HumanDesc {
  Vec3 position{0.0};            ///< [m] the point between the feet on the ground
  Quat orientation{1, 0, 0, 0};  ///< of the whole figure about `position`
  Real totalMass = 75.0;         ///< [kg] shared by volume (mass ∝ volume, paper §5)
  Real scale = 1.0;              ///< 1: the table's sizes (1.83 m tall)
  bool limits = true;            ///< the paper's hinge and cone limits
};
/// The paper's 16-bone human (sizes H × W × D in cm of its table; joints centred on the smaller part):
/// head–neck hinge (±45°), neck–chest ball (45°), chest–hip ball (45°), shoulders ball (90°), elbows
/// hinge (135° forward / 0°), wrists hinge (±90°), hips ball (45°), knees hinge (0° / 135° back), ankles
/// hinge (0° / 90°), in a T-pose. Bones: head 0, neck 1, chest 2, hip 3, then left/right pairs.
RagdollDesc buildHumanRagdoll(const HumanDesc& desc = {});
/// The names of the human's bones in order.
const std::vector<std::string>& humanBoneNames();

struct ChainDesc {
  int links = 6;  ///< boxes, the first fixed when `fixedTop`
  JointKind joint = JointKind::Ball;
  Vec3 start{0.0, 2.5, 0.0};               ///< [m] centre of the first box
  Vec3 direction{1.0, 0.0, 0.0};           ///< unit, along the chain (horizontal: it starts raised and swings down)
  Vec3 hingeAxis{0.0, 0.0, 1.0};           ///< unit, ⟂ direction
  Vec3 linkHalfExtents{0.15, 0.06, 0.06};  ///< [m] along direction first
  Real density = 500.0;                    ///< [kg/m³]
  bool fixedTop = true;
};
/// Boxes joined end to end (paper tests 2 and 3; the performance tests' chains).
RagdollDesc buildChain(const ChainDesc& desc);

/// Test 1: two boxes thrown at each other: they collide, fall and slide.
RagdollDesc buildBoxesTest();
/// Tests 2 and 3: six boxes on ball joints (or hinges), the top one fixed, starting horizontal, and a
/// seventh box dropped onto them.
RagdollDesc buildChainTest(JointKind joint);
/// Test 4: a box 8× larger (and 8× heavier) slides into a small one: the big one dominates.
RagdollDesc buildMassesTest();
/// Tests 5 and 6: four fixed boxes, each holding a box that starts horizontal on a ball joint with a
/// cone limit (or a hinge with ±limit) of 0°, 45°, 90° and 135°.
RagdollDesc buildLimitsTest(JointKind joint);
/// The limits of buildLimitsTest [rad].
std::vector<Real> limitsTestAngles();

struct SpiderDesc {
  Vec3 position{0.0, 1.2, 0.0};  ///< [m] centre of the body
  Real bodyHalfSize = 0.2;       ///< [m]
  Real density = 500.0;          ///< [kg/m³]
};
/// Test 7: a central cube with four ball-jointed upper legs (cone 45°) and hinged lower legs (±60°).
RagdollDesc buildSpider(const SpiderDesc& desc = {});

/// Static stairs of fixed boxes: `steps` steps of rise × run, `width` wide, rising along −x from x = 0.
RagdollDesc buildStairs(int steps, Real rise, Real run, Real width);
/// `count` humans dropped in a loose column above stairs (the `pile` scene), seeded.
RagdollDesc buildPile(int count, unsigned seed);

/// The whole ragdoll turned by q about `pivot`.
RagdollDesc rotated(RagdollDesc desc, const Quat& q, const Vec3& pivot);

}  // namespace pba::ragdoll
