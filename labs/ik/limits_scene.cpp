// IK lab, scene "limits": joint limits shown as arcs (hinges) and cones (ball joints) while a goal
// moves out of the allowed workspace (Workbook §2.1 task 5; IK slides, "Joint limits"; exercise IK-6).
#include "ik_scene.h"

namespace pba::lab {

using namespace pba::ik;
namespace {

const Vec3 kGoalCentre(0.2, 0.5, 0.0);  // [m] from the base: centre of the goal's scripted path

class LimitsScene final : public IkScene {
 public:
  LimitsScene() {
    options_.solver = SolverKind::Ccd;
    options_.maxIterations = 50;
    declareSolverParams();
    params_.angle("limit", &limit_, 5.0, 180.0, "Every joint may turn at most ±limit from its rest angle.")
        .needsReset();
    params_.integer("links", &links_, 2, 12, "", "Number of hinge links.").needsReset();
    path_ = TargetPath::Circle;
  }
  std::string description() const override {
    return "Hinges limited to ±limit (orange arcs): the chain clamps at its limits and stops short where the goal "
           "leaves the workspace.";
  }

 protected:
  Rig build() const override {
    ChainDesc d;
    d.links = links_;
    d.limit = limit_;
    d.totalLength = 2.0;
    Rig rig = buildIkChain(d).value();
    // The goal circles up and back over the chain (the rest pose points along +x), where reaching
    // it needs more bend than ±limit per joint allows: joints clamp at their limits (orange bars)
    // and the chain curls as far as it may.
    rig.effectors[0].targetPosition = rig.skeleton.joint(0).offset + kGoalCentre;
    return rig;
  }
  Real pathRadius() const override { return 0.5; }
  /// In the chain's plane (the hinges turn about z), so only the limits keep the goal out of reach.
  Vec3 pathOffset(size_t k, Real phase) const override {
    Vec3 o = IkScene::pathOffset(k, phase);
    o.z = 0.0;
    return o;
  }

 private:
  Real limit_ = degToRad(35.0);
  int links_ = 6;
};

}  // namespace
}  // namespace pba::lab

PBA_REGISTER_SCENE("Chains", "limits", pba::lab::LimitsScene);
