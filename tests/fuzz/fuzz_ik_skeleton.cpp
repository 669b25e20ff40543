// Fuzz target: the BVH/skeleton path of the IK character (app/assets/character_rig.h): the input is a BVH
// file; a rig that loads is solved once toward goals 10 cm from its effectors. Besides no sanitizer
// report: an error is one line naming the field, and the solved pose is finite.
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>

#include "app/assets/character_rig.h"
#include "fuzz_check.h"
#include "physics/ik/solver.h"

using namespace pba;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  app::CharacterDesc desc;
  desc.skeleton = fuzz::writeInput(data, size, ".bvh");
  Result<ik::Rig> rig = app::loadCharacterRig(desc);
  std::filesystem::remove(desc.skeleton);
  if (!rig) {
    fuzz::require(rig.error().find('\n') == std::string::npos, "an error is one line", rig.error());
    fuzz::require(rig.error().rfind("skeleton: ", 0) == 0 || rig.error().rfind("effectors: ", 0) == 0,
                  "an error names the field", rig.error());
    return 0;
  }
  ik::Rig& r = rig.value();
  for (ik::Effector& e : r.effectors) e.targetPosition += Vec3(0.1, 0.0, 0.0);
  ik::Pose pose = r.skeleton.restPose();
  ik::SolveOptions options;
  options.maxIterations = 20;
  ik::solve(r.skeleton, pose, r.effectors, options);
  for (const ik::Frame& f : ik::forwardKinematics(r.skeleton, pose))
    fuzz::require(std::isfinite(f.position.x) && std::isfinite(f.position.y) && std::isfinite(f.position.z),
                  "the solved pose is finite", desc.skeleton);
  return 0;
}
