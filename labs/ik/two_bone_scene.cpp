// IK lab, scene "two-bone": an arm solved in closed form by the law of cosines, its elbow pointing at
// a pole target (the usual animation-rig control; IK slides, "analytic solutions").
#include <cmath>

#include "ik_scene.h"

namespace pba::labs::ik {
namespace {

class TwoBoneScene final : public IkScene {
 public:
  TwoBoneScene() {
    options_.solver = SolverKind::Analytic;
    options_.usePole = true;
    declareSolverParams();
    params_.real("upper", &desc_.upper, 0.2, 2.0, "m", "Upper arm length (shoulder to elbow). Typical 0.9 m.").needsReset();
    params_.real("lower", &desc_.lower, 0.2, 2.0, "m", "Forearm length (elbow to wrist). Typical 0.8 m.").needsReset();
    params_.angle("pole_angle", &poleAngle_, -180.0, 180.0, "Direction of the pole target around the arm: where the elbow points.");
  }
  std::string description() const override {
    return "A two-bone arm solved exactly by the law of cosines; the elbow bends toward the pole target (purple).";
  }
  void step(Real dt) override {
    options_.polePoint = desc_.shoulder + Vec3(0.5, std::cos(poleAngle_), std::sin(poleAngle_)) * 1.5;
    IkScene::step(dt);
  }
  void draw(DebugDraw& d) const override {
    IkScene::draw(d);
    d.sphere(options_.polePoint, 0.05, colors::kPurple);
    d.line(rig_.skeleton.joint(0).offset, options_.polePoint, colors::kPurple);
  }

 protected:
  Rig build() const override { return buildTwoBoneArm(desc_).value(); }
  Real pathRadius() const override { return 0.5; }

 private:
  TwoBoneDesc desc_;
  Real poleAngle_ = 1.2;
};

}  // namespace
}  // namespace pba::labs::ik

PBA_REGISTER_SCENE("Analytic", "two-bone", pba::labs::ik::TwoBoneScene);
