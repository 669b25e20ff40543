// IK lab, scene "six-dof": a position + orientation effector (IK slides, "6-DOF end effector"): the
// error's rotation part is the scaled axis of G·E⁻¹; the gizmos show the effector and goal frames.
#include <cmath>

#include "ik_scene.h"

namespace pba::lab {

using namespace pba::ik;
namespace {

class SixDofScene final : public IkScene {
 public:
  SixDofScene() {
    options_.solver = SolverKind::DampedLeastSquares;
    options_.maxIterations = 50;
    showLimits_ = false;  // ±150° on every Euler angle: the cones would cover the chain, not explain it
    declareSolverParams();
    params_.real("spin_speed", &spin_, 0.0, 2.0, "Hz", "How fast the goal frame turns about its own axis.");
  }
  std::string description() const override {
    return "The tip must match the goal's position and its orientation (frame gizmo): orientation rows join the "
           "Jacobian.";
  }
  void step(Real dt) override {
    const Real a = 2.0 * kPi * spin_ * (time_ + dt);
    for (Effector& e : rig_.effectors) e.targetOrientation = glm::angleAxis(a, glm::normalize(Vec3(0.3, 1.0, 0.2)));
    IkScene::step(dt);
  }

 protected:
  Rig build() const override {
    ChainDesc d;
    d.links = 6;
    d.joint = JointType::Ball;
    d.limit = degToRad(150.0);
    Rig rig = buildIkChain(d).value();
    rig.effectors[0].kind = EffectorKind::PositionOrientation;
    return rig;
  }
  Real pathRadius() const override { return 0.5; }

 private:
  Real spin_ = 0.2;
};

}  // namespace
}  // namespace pba::lab

PBA_REGISTER_SCENE("Chains", "six-dof", pba::lab::SixDofScene);
