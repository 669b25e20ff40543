#!/usr/bin/env python3
"""Writes resources/models/humanoid.bvh: the small humanoid skeleton of the IK lab's "character"
scene (hips, spine, chest, neck, head, both arms to the hands, both legs to the toes), 1.70 m tall,
offsets in centimetres, y up, facing +z, the character's left at +x. Two frames of motion: the rest
pose and a wave of the right arm (so animation importers have something to read).
Usage: python3 tools/make_humanoid_bvh.py [OUT]"""
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

def frame(wave):
    values = []
    for name in order:
        if name == "Hips":
            values += [0, 95, 0, 0, 0, 0]
        elif wave and name == "RightArm":
            values += [-60, 0, 0]   # Z X Y rotation [deg]: lift the right arm
        elif wave and name == "RightForeArm":
            values += [-40, 0, 0]
        else:
            values += [0, 0, 0]
    return " ".join(f"{v:.1f}" for v in values)

lines += ["MOTION", "Frames: 2", "Frame Time: 0.5", frame(False), frame(True)]
out = sys.argv[1] if len(sys.argv) > 1 else "resources/models/humanoid.bvh"
with open(out, "w") as f:
    f.write("\n".join(lines) + "\n")
print(f"wrote {out}: {len(order)} joints")
