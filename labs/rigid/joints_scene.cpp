// Rigid lab, scene "joints": every joint type at once. From left to right: a 10-link hinge chain, a ball
// chain, a motorised paddle, a hinge with limits, a cone-twist limit, a slider with limits and a soft rope
// bridge of planks on springs.
#include <cmath>

#include "app/runner/scene_registry.h"
#include "world_scene.h"

namespace pba::lab {
namespace {

class JointsScene final : public lab::WorldScene {
 public:
  JointsScene() {
    settings_.iterations = 2;  // a 10-link chain within 1 mm (tests/physics/rigid/joints_test.cpp)
    params_.real("motor_speed", &motorSpeed_, -10.0, 10.0, "rad/s",
                 "Target speed of the paddle's hinge motor. Typical 2 rad/s.");
    params_.real("motor_torque", &motorTorque_, 0.0, 5000.0, "N·m",
                 "Largest torque the motor may apply. Typical 500 N·m.");
    params_.angle("hinge_limit", &limit_, 0.0, 170.0, "Half range of the limited hinge: ±limit. Typical 30°.")
        .needsReset();
    params_.angle("cone", &cone_, 0.0, 120.0, "Half-angle of the cone-twist joint's swing cone. Typical 30°.")
        .needsReset();
    params_
        .real("bridge_hertz", &bridgeHertz_, 0.5, 60.0, "Hz", "Stiffness of the rope bridge's springs. Typical 10 Hz.")
        .needsReset();
  }
  std::string description() const override {
    return "Hinge and ball chains, a motor, hinge, cone and slider limits, and a soft rope bridge: joint errors stay "
           "below a millimetre and limits hold.";
  }

 protected:
  void build(rigid::World& w) override {
    rigid::addGround(w);
    // The chains start 39° off vertical (a horizontal release whips the last link to ~10 m/s).
    rigid::buildChain(w, Vec3(-6.5, 6.0, 0.0), 10, 0.4, false, 500.0, glm::normalize(Vec3(0.8, -1.0, 0.0)));
    rigid::buildChain(w, Vec3(-3.5, 6.0, 0.0), 8, 0.4, true, 500.0, glm::normalize(Vec3(0.8, -1.0, 0.3)));
    // Motorised paddle.
    paddle_ = rigid::addBox(w, Vec3(0.8, 0.08, 0.3), Vec3(0.5, 3.0, 0.0), Quat(1, 0, 0, 0), 500.0, 0.6, colors::kTeal);
    rigid::JointDesc motor;
    motor.kind = rigid::JointKind::Hinge;
    motor.bodyB = paddle_;
    motor.anchor = Vec3(0.5, 3.0, 0.0);
    motor.axis = Vec3(0.0, 0.0, 1.0);
    motor.enableMotor = true;
    motor.motorSpeed = motorSpeed_;
    motor.maxMotorTorque = motorTorque_;
    motorJoint_ = w.addJoint(motor).value();
    // Limited hinge: a bar released from horizontal that must stop at −limit.
    limited_ =
        rigid::addBox(w, Vec3(0.6, 0.05, 0.05), Vec3(3.2, 4.0, 0.0), Quat(1, 0, 0, 0), 500.0, 0.6, colors::kOrange);
    rigid::JointDesc hinge;
    hinge.kind = rigid::JointKind::Hinge;
    hinge.bodyB = limited_;
    hinge.anchor = Vec3(2.6, 4.0, 0.0);
    hinge.axis = Vec3(0.0, 0.0, 1.0);
    hinge.enableLimit = true;
    hinge.lower = -limit_;
    hinge.upper = limit_;
    limitedJoint_ = w.addJoint(hinge).value();
    // Cone-twist: a capsule hanging from the world, kicked sideways.
    rigid::BodyDesc cap;
    cap.shape = collision::makeCapsule(0.4, 0.1).value();
    cap.position = Vec3(5.5, 4.0, 0.0);
    cap.angularVelocity = Vec3(3.0, 1.0, 2.0);
    cap.color = colors::kPurple;
    const int capsule = w.addBody(cap).value();
    rigid::JointDesc cone;
    cone.kind = rigid::JointKind::ConeTwist;
    cone.bodyB = capsule;
    cone.anchor = Vec3(5.5, 4.5, 0.0);
    cone.axis = Vec3(0.0, -1.0, 0.0);
    cone.swingSpan = cone_;
    cone.enableLimit = true;
    cone.lower = -degToRad(20.0);
    cone.upper = degToRad(20.0);
    coneJoint_ = w.addJoint(cone).value();
    // Slider along a tilted axis with limits ±0.8 m.
    const int slide = rigid::addBox(w, Vec3(0.2), Vec3(7.5, 3.5, 0.0), Quat(1, 0, 0, 0), 500.0, 0.6, colors::kGreen);
    rigid::JointDesc slider;
    slider.kind = rigid::JointKind::Slider;
    slider.bodyB = slide;
    slider.anchor = Vec3(7.5, 3.5, 0.0);
    slider.axis = glm::normalize(Vec3(1.0, -0.5, 0.0));
    slider.enableLimit = true;
    slider.lower = -0.8;
    slider.upper = 0.8;
    sliderJoint_ = w.addJoint(slider).value();
    buildBridge(w, Vec3(9.0, 2.0, 0.0), 12);
  }

  // Planks on springs: seam k joins plank k − 1 (or the left post) to plank k (or the right post) at both
  // edges, a few centimetres of rope each.
  void buildBridge(rigid::World& w, const Vec3& start, int planks) {
    const Real pitch = 0.45, gap = 0.05;
    std::vector<int> plank;
    for (int i = 0; i < planks; ++i)
      plank.push_back(rigid::addBox(w, Vec3(0.5 * (pitch - gap), 0.03, 0.5), start + Vec3((i + 0.5) * pitch, 0.0, 0.0),
                                    Quat(1, 0, 0, 0), 400.0, 0.6, colors::kYellow));
    for (int k = 0; k <= planks; ++k) {
      const Vec3 seam = start + Vec3(k * pitch, 0.0, 0.0);
      for (Real z : {-0.45, 0.45}) {
        rigid::JointDesc rope;
        rope.kind = rigid::JointKind::Distance;
        rope.hertz = bridgeHertz_;
        rope.dampingRatio = 0.7;
        if (k == planks) {  // the right post (the world) is A
          rope.bodyA = -1, rope.bodyB = plank[k - 1];
          rope.anchor = seam + Vec3(0.0, 0.0, z), rope.anchorB = seam + Vec3(-0.5 * gap, 0.0, z);
        } else {
          rope.bodyA = k == 0 ? -1 : plank[k - 1], rope.bodyB = plank[k];
          rope.anchor = seam + Vec3(k == 0 ? 0.0 : -0.5 * gap, 0.0, z), rope.anchorB = seam + Vec3(0.5 * gap, 0.0, z);
        }
        w.addJoint(rope);
      }
    }
  }

  void extraMetrics(nlohmann::json& j) const override {
    const std::vector<rigid::Joint>& joints = world_.joints();
    std::vector<rigid::SolverBody> poses(world_.bodyCount() + 1);
    for (int i = 0; i < world_.bodyCount(); ++i)
      poses[i].c = world_.body(i).position, poses[i].q = world_.body(i).orientation;
    const Real angle = rigid::jointCoordinate(joints[limitedJoint_], poses);
    j["hinge_limit_violation_deg"] = radToDeg(std::max({0.0, angle - limit_, -limit_ - angle}));
    j["cone_swing_deg"] = radToDeg(rigid::jointSwingAngle(joints[coneJoint_], poses));
    j["slider_position_m"] = rigid::jointCoordinate(joints[sliderJoint_], poses);
    j["motor_speed_rad_s"] = glm::dot(world_.body(paddle_).angularVelocity, Vec3(0.0, 0.0, 1.0));
  }
  void step(Real dt) override {
    // The motor's settings may change live.
    world_.jointDesc(motorJoint_).motorSpeed = motorSpeed_;
    world_.jointDesc(motorJoint_).maxMotorTorque = motorTorque_;
    WorldScene::step(dt);
  }
  std::vector<app::Preset> presets() const override {
    return {{"fast motor", {{"motor_speed", 8.0}}},
            {"weak motor", {{"motor_torque", 10.0}}},
            {"stiff bridge", {{"bridge_hertz", 40.0}}},
            {"wide cone", {{"cone", 90.0}}}};
  }
  std::vector<std::string> defaultPlots() const override { return {"max_joint_error_m", "motor_speed_rad_s"}; }
  std::optional<app::CameraView> preferredView() const override {
    return app::CameraView{Vec3(4.0, 3.0, 0.0), 19.0, 0.0, 0.12};
  }

 private:
  Real motorSpeed_ = 2.0, motorTorque_ = 500.0, limit_ = degToRad(30.0), cone_ = degToRad(30.0), bridgeHertz_ = 10.0;
  int paddle_ = -1, limited_ = -1, motorJoint_ = -1, limitedJoint_ = -1, coneJoint_ = -1, sliderJoint_ = -1;
};

}  // namespace

PBA_REGISTER_SCENE("Rigid bodies", "joints", JointsScene);

}  // namespace pba::lab
