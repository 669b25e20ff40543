// IK lab, scene "chain": a chain of 1–1,000 links with the method of your choice (Workbook §2.1
// tasks 3–5; CCD is O(n) per pass and FABRIK O(n) per iteration, so 1,000 links stay interactive).
#include "ik_scene.h"

namespace pba::lab {

using namespace pba::ik;
namespace {

enum class ChainJoint { Hinge, Ball, Free };
constexpr auto kChainJointNames =
    enumNames<ChainJoint>({{ChainJoint::Hinge, "hinge"}, {ChainJoint::Ball, "ball"}, {ChainJoint::Free, "free"}});

class ChainScene final : public IkScene {
 public:
  ChainScene() {
    options_.solver = SolverKind::Ccd;
    options_.maxIterations = 50;
    declareSolverParams();
    params_.integer("links", &desc_.links, 1, 1000, "", "Number of links (joints). Workbook §2.1: try 10 to 1000.")
        .needsReset();
    params_.choiceEnum("joint", &joint_, kChainJointNames, "Joint type of every link.").needsReset();
    params_.choiceEnum("axes", &desc_.axes, kHingeAxesNames, "Hinge axes: all z (planar arm) or alternating z/y (3D).")
        .needsReset();
    params_.angle("limit", &desc_.limit, 5.0, 180.0, "Every rotational DOF is limited to ±limit.").needsReset();
    params_.real("length", &desc_.totalLength, 0.5, 4.0, "m", "Total length of the chain (its reach). Typical 2 m.")
        .needsReset();
    desc_.axes = HingeAxes::Alternating;
  }
  std::string description() const override {
    return "A chain of links reaching for the goal; pick the method and the number of links and compare iterations and "
           "time.";
  }
  std::vector<app::Preset> presets() const override {
    return {{"ccd 10", {{"solver", "ccd"}, {"links", 10}}},
            {"fabrik 10", {{"solver", "fabrik"}, {"links", 10}}},
            {"dls 10", {{"solver", "dls"}, {"links", 10}}},
            {"ccd 1000", {{"solver", "ccd"}, {"links", 1000}, {"joint", "ball"}}},
            {"fabrik 1000", {{"solver", "fabrik"}, {"links", 1000}, {"joint", "ball"}}}};
  }

 protected:
  Rig build() const override {
    ChainDesc d = desc_;
    d.joint = joint_ == ChainJoint::Hinge  ? JointType::Hinge
              : joint_ == ChainJoint::Ball ? JointType::Ball
                                           : JointType::Free;
    return buildIkChain(d).value();
  }
  Real pathRadius() const override { return 0.3 * desc_.totalLength; }

 private:
  ChainDesc desc_;
  ChainJoint joint_ = ChainJoint::Hinge;
};

}  // namespace
}  // namespace pba::lab

PBA_REGISTER_SCENE("Chains", "chain", pba::lab::ChainScene);
