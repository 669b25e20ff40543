// Ragdoll lab, scene "character": a ragdoll from an imported skeleton (any file Assimp reads; default the
// project's resources/models/humanoid.bvh), in the file's rest pose or one frame of its animation, dropped
// with both methods side by side. The skeleton becomes boxes and joints in the library
// (physics/ragdoll/skeleton_ragdoll.h); the file is read here (skeleton_import.h). Examples:
//   pba-ragdoll --skeleton resources/models/mocap/01_01.bvh --frame 100
#include "app/runner/scene_registry.h"
#include "physics/ragdoll/builders.h"
#include "physics/ragdoll/constraint_ragdoll.h"
#include "physics/ragdoll/particle_ragdoll.h"
#include "ragdoll_scene.h"
#include "skeleton_import.h"

// The same flag as the IK lab's character scene; --frame picks the start frame.
PBA_REGISTER_LAB_FLAG("skeleton", "skeleton", "skeleton file Assimp reads (BVH, FBX, COLLADA, glTF)", "character", 1);
PBA_REGISTER_LAB_FLAG("frame", "frame", "frame of the skeleton file's animation to start in (-1: its rest pose)",
                      "character", 1);

namespace pba::lab {
namespace {

class CharacterScene final : public lab::RagdollScene {
 public:
  CharacterScene() {
    particleSettings_ = ragdoll::skeletonParticleSettings();
    constraintSettings_.world = ragdoll::skeletonRagdollWorldSettings();
    params_
        .text("skeleton", &file_.path,
              "Skeleton file (BVH, FBX, COLLADA, glTF: anything Assimp reads). Relative paths are also tried from the "
              "repository root. Default: the project's humanoid, resources/models/humanoid.bvh.")
        .needsReset();
    params_
        .integer("frame", &file_.frame, -1, 1000000, "",
                 "Frame of the file's animation the ragdoll starts in; -1: the file's rest pose; past the last frame: "
                 "the last. Joint limits are centred on the start pose.")
        .needsReset();
    params_
        .real("height", &file_.height, 0.5, 3.0, "m",
              "The skeleton is scaled so its rest pose is this tall. Typical 1.7 m.")
        .needsReset();
    declareStartParams(drop_, tilt_);
    params_.real("mass", &shape_.totalMass, 10.0, 200.0, "kg", "Total mass, shared by volume. Typical 70 kg.")
        .needsReset();
  }
  std::string description() const override {
    return "A ragdoll from an imported skeleton (boxes sized from the joint offsets, limits by joint name) falls and "
           "comes to rest; load your own with --skeleton and --frame.";
  }
  Status validate() override {
    const Result<ragdoll::RagdollDesc> d = load();
    return d ? Status::success() : Status(Error{d.error()});
  }
  std::vector<app::Preset> presets() const override {
    std::vector<app::Preset> p = RagdollScene::presets();
    // The CMU motion-capture skeleton shipped in resources/models/mocap, 31 joints.
    p.resize(8);
    p.push_back({"CMU 01_01.bvh, frame 100", {{"skeleton", "resources/models/mocap/01_01.bvh"}, {"frame", 100}}});
    return p;
  }

 protected:
  /// From the front and above, as the human scene: both figures lie on the ground after the fall.
  std::optional<app::CameraView> preferredView() const override {
    return app::CameraView{Vec3(0.0, 0.0, 0.5), 7.0, 0.0, 0.8};
  }
  ragdoll::RagdollDesc build() const override {
    Result<ragdoll::RagdollDesc> d = load();
    if (d) last_ = std::move(d).value();
    // The window keeps the running skeleton on a bad file (the command line exits 2 in validate()).
    if (last_.bones.empty()) last_ = ragdoll::buildHumanRagdoll();
    ragdoll::RagdollDesc r = ragdoll::rotated(last_, glm::angleAxis(tilt_, Vec3(1.0, 0.0, 0.0)), Vec3(0.0));
    return ragdoll::translated(r, Vec3(0.0, drop_ - lowestCorner(r), 0.0));
  }

 private:
  Result<ragdoll::RagdollDesc> load() const {
    Result<lab::LoadedSkeleton> s = lab::loadSkeleton(file_);
    if (!s) return Error{s.error()};
    Result<ragdoll::RagdollDesc> d = ragdoll::buildSkeletonRagdoll(s.value().joints, shape_);
    if (!d) return Error{d.error() + " (" + file_.path + ")"};
    return d;
  }

  lab::SkeletonFile file_{.clampFrame = true};
  ragdoll::SkeletonRagdollDesc shape_;
  Real drop_ = 0.5, tilt_ = degToRad(60.0);
  mutable ragdoll::RagdollDesc last_;
};

}  // namespace

PBA_REGISTER_SCENE("Ragdolls", "character", CharacterScene);

}  // namespace pba::lab
