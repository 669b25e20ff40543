// IK lab, scene "single-joint": one quaternion joint and one bone follow the goal analytically
// (Workbook §2.1 task 2; exercise IK-1: the axis from the cross product, the angle from the dot product).
#include "ik_scene.h"

namespace pba::lab {

using namespace pba::ik;
namespace {

class SingleJointScene final : public IkScene {
 public:
  SingleJointScene() {
    options_.solver = SolverKind::Analytic;
    declareSolverParams();
    params_.real("length", &length_, 0.2, 2.0, "m", "Bone length. Typical 1 m.").needsReset();
  }
  std::string description() const override {
    return "One joint turns its bone toward the goal in a single step, by the smallest rotation (IK-1).";
  }

 protected:
  Rig build() const override { return buildSingleJoint(length_).value(); }
  Real pathRadius() const override { return 0.5 * length_; }

 private:
  Real length_ = 1.0;
};

}  // namespace
}  // namespace pba::lab

PBA_REGISTER_SCENE("Analytic", "single-joint", pba::lab::SingleJointScene);
