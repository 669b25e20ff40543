#pragma once
// A double-precision BVH reader for the animation lab (Meredith & Maddock 2001, "Motion Capture File
// Formats Explained", §3.1). Assimp, which reads every other format, stores keys in float: on CMU's
// 01_01.bvh its joint positions are 2–3 µm off the file's own forward kinematics; read here in double
// they are at round-off (nm). The result is the one importClip makes from Assimp's nodes, so the two
// routes name and order the joints alike:
//   - joints in file order (parents first); an End Site becomes joint "EndSite_<parent>";
//   - rest translation = OFFSET, rest rotation = identity;
//   - a joint's position channels (the root's, usually) replace its OFFSET in the clip; its rotation
//     channels compose in the order the CHANNELS line lists them, R = R(c₁) R(c₂) R(c₃);
//   - frame f at f · Frame Time, duration (Frames − 1) · Frame Time.
// Errors name the file and the line: "x.bvh: line 12: expected OFFSET and 3 numbers". importClip runs
// the graphics import first, whose checks name every malformed file the corpus holds
// (tests/corpora/expected.tsv), and uses this reader for the numbers only; the reader still refuses
// what it cannot read on its own (tested, and fuzzed by fuzz.anim_clip).
#include <string>

#include "physics/animation/clip.h"
#include "physics/core/result.h"

namespace pba::lab {

/// A BVH file in file units (scale 1): its skeleton and its clip (rotation keys slerp, positions linear).
struct BvhClip {
  pba::animation::Skeleton skeleton;
  pba::animation::Clip clip;
};

/// Reads `path`; errors start with the path.
Result<BvhClip> readBvh(const std::string& path);

/// True when the path ends in .bvh (any case).
bool isBvhPath(const std::string& path);

}  // namespace pba::lab
