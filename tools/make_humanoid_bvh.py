#!/usr/bin/env python3
"""Writes resources/models/humanoid.bvh: the small humanoid skeleton of the IK lab's "character"
scene (hips, spine, chest, neck, head, both arms to the hands, both legs to the toes), 1.70 m tall,
offsets in centimetres, y up, facing +z, the character's left at +x. Its motion is one walk cycle
in place (a treadmill walk: the hips bob and sway but do not advance, so the loop has no jump), 1.1 s
at 30 frames/s: 33 frames whose phase runs 0, 1/33, ..., 32/33 of the cycle, so that playing frame 0
after frame 32 continues the cycle. The joint angles are those of the library's procedural walk
(framework/physics/animation/builders.cpp, buildGaitClip with its default GaitDesc), sampled every
frame instead of every eighth of a cycle. Frame 0 is not the rest pose: the rest pose is the
HIERARCHY's offsets, which is what importers (Assimp) use for the skeleton.
Usage: python3 tools/make_humanoid_bvh.py [OUT]"""
import math
import sys

# name, offset (cm) in the parent's frame, children; None as a child list ends in an End Site.
def limb(side, sx):
    arm = (f"{side}Shoulder", (3 * sx, 18, 0), [
        (f"{side}Arm", (14 * sx, 0, 0), [
            (f"{side}ForeArm", (10 * sx, -26, 0), [
                (f"{side}Hand", (8 * sx, -24, 2), (2 * sx, -9, 1))])])])
    leg = (f"{side}UpLeg", (9 * sx, -3, 0), [
        (f"{side}Leg", (0, -44, 1), [
            (f"{side}Foot", (0, -42, -3), [
                (f"{side}ToeBase", (0, -4, 12), (0, 0, 6))])])])
    return arm, leg

left_arm, left_leg = limb("Left", 1)
right_arm, right_leg = limb("Right", -1)
SKELETON = ("Hips", (0, 95, 0), [
    ("Spine", (0, 10, 0), [
        ("Chest", (0, 15, 0), [
            ("Neck", (0, 22, 0), [("Head", (0, 10, 0), (0, 18, 0))]),
            left_arm, right_arm])]),
    left_leg, right_leg])

lines, order = [], []

def fmt(v):
    return " ".join(f"{x:.2f}" for x in v)

def write(node, depth, root=False):
    name, offset, children = node
    pad = "  " * depth
    lines.append(f"{pad}{'ROOT' if root else 'JOINT'} {name}")
    lines.append(f"{pad}{{")
    lines.append(f"{pad}  OFFSET {fmt(offset)}")
    if root:
        lines.append(f"{pad}  CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation")
    else:
        lines.append(f"{pad}  CHANNELS 3 Zrotation Xrotation Yrotation")
    order.append(name)
    if isinstance(children, tuple):  # End Site
        lines.append(f"{pad}  End Site")
        lines.append(f"{pad}  {{")
        lines.append(f"{pad}    OFFSET {fmt(children)}")
        lines.append(f"{pad}  }}")
    else:
        for c in children:
            write(c, depth + 1)
    lines.append(f"{pad}}}")

lines.append("HIERARCHY")
write(SKELETON, 0, root=True)

PERIOD = 1.1    # [s] one full cycle (two steps)
FRAMES = 33     # 30 frames/s
HIP_SWING, KNEE_FLEX, ARM_SWING, ELBOW_FLEX, LEAN = 0.45, 0.65, 0.35, 0.3, 0.05  # [rad]
BOUNCE = 2.5    # [cm] hip bounce amplitude, twice per cycle


def deg(radians):
    return math.degrees(radians)


def frame(k):
    """Channel values of frame k: root position [cm], then Z X Y rotations [deg] per joint."""
    phase = 2.0 * math.pi * k / FRAMES
    s1, c1 = math.sin(phase), math.cos(phase)
    left, right = max(0.0, c1), max(0.0, -c1)  # the knee bends while its thigh swings forward
    x = {  # rotation about x [rad]
        "LeftUpLeg": -HIP_SWING * s1 - 0.1 * HIP_SWING, "RightUpLeg": HIP_SWING * s1 - 0.1 * HIP_SWING,
        "LeftLeg": 0.08 + KNEE_FLEX * left * left, "RightLeg": 0.08 + KNEE_FLEX * right * right,
        "LeftFoot": -0.15 * s1, "RightFoot": 0.15 * s1,
        "LeftArm": ARM_SWING * s1, "RightArm": -ARM_SWING * s1,
        "LeftForeArm": -ELBOW_FLEX - 0.3 * ELBOW_FLEX * max(0.0, s1),
        "RightForeArm": -ELBOW_FLEX - 0.3 * ELBOW_FLEX * max(0.0, -s1),
        "Spine": LEAN,
    }
    y = {"Spine": 0.12 * s1, "Chest": -0.2 * s1, "Hips": -0.08 * s1}  # about y [rad]
    z = {"Hips": 0.04 * c1}  # about z [rad]
    values = []
    for name in order:
        if name == "Hips":
            values += [0.0, 95.0 - 2.0 - KNEE_FLEX + BOUNCE * math.cos(2.0 * phase), 0.0]
        values += [deg(z.get(name, 0.0)), deg(x.get(name, 0.0)), deg(y.get(name, 0.0))]
    return " ".join(f"{v:.4f}" for v in values)


lines += ["MOTION", f"Frames: {FRAMES}", f"Frame Time: {PERIOD / FRAMES:.6f}"]
lines += [frame(k) for k in range(FRAMES)]
out = sys.argv[1] if len(sys.argv) > 1 else "resources/models/humanoid.bvh"
with open(out, "w") as f:
    f.write("\n".join(lines) + "\n")
print(f"wrote {out}: {len(order)} joints, {FRAMES} frames")
