// Fuzz target: the animation lab's motion import of .bvh files (labs/animation/bvh_import.h through
// clip_import.h): the input is a BVH file; a clip that loads is sampled at a few times and posed.
// Besides no sanitizer report: an error is one line naming the field, and every pose is finite.
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>

#include "clip_import.h"
#include "fuzz_check.h"

using namespace pba;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = fuzz::writeInput(data, size, ".bvh");
  Result<lab::ImportedClip> clip = lab::importClip(path, 1.7);
  std::filesystem::remove(path);
  if (!clip) {
    fuzz::require(clip.error().find('\n') == std::string::npos, "an error is one line", clip.error());
    fuzz::require(clip.error().rfind("skeleton: ", 0) == 0 || clip.error().rfind("height: ", 0) == 0,
                  "an error names the field", clip.error());
    return 0;
  }
  const lab::ImportedClip& c = clip.value();
  animation::Pose pose;
  for (int s = 0; s <= 4; ++s) {
    animation::samplePose(c.skeleton, c.clip, c.clip.duration * s / 4.0, pose);
    for (const animation::JointWorld& w : animation::forwardKinematics(c.skeleton, pose))
      fuzz::require(std::isfinite(w.position.x) && std::isfinite(w.position.y) && std::isfinite(w.position.z),
                    "every pose is finite", path);
  }
  return 0;
}
