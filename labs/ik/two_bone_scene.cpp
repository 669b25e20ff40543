// IK lab, scene "two-bone": an arm solved in closed form by the law of cosines, its elbow pointing at
// a pole target (the usual animation-rig control; IK slides, "analytic solutions").
#include <cmath>

#include "ik_scene.h"

namespace pba::lab {

using namespace pba::ik;
namespace {

class TwoBoneScene final : public IkScene {
 public:
  TwoBoneScene() {
    options_.solver = SolverKind::Analytic;
    options_.usePole = true;
    declareSolverParams();
    params_.real("upper", &desc_.upper, 0.2, 2.0, "m", "Upper arm length (shoulder to elbow). Typical 0.9 m.")
        .needsReset();
    params_.real("lower", &desc_.lower, 0.2, 2.0, "m", "Forearm length (elbow to wrist). Typical 0.8 m.").needsReset();
    params_.angle("pole_angle", &poleAngle_, -180.0, 180.0,
                  "Direction of the pole target around the arm: where the elbow points.");
  }
  std::string description() const override {
    return "A two-bone arm solved exactly by the law of cosines; the elbow bends toward the pole target (purple: drag "
           "it, or pick it and use the arrow keys).";
  }
  void step(Real dt) override {
    options_.polePoint = polePoint();
    IkScene::step(dt);
  }
  // The pole target (purple ball) is picked, dragged and nudged like the goal: it moves on its circle
  // around the shoulder (pole_angle), and the keys move whichever of the two was picked last.
  std::optional<app::PickHit> pick(const app::Ray& ray) const override {
    std::optional<app::PickHit> hit = IkScene::pick(ray);
    const std::optional<app::PickHit> pole = app::pickSphere(ray, options_.polePoint, 2.0 * kPoleRadius, kPoleHandle);
    return pole && (!hit || pole->distance < hit->distance) ? pole : hit;
  }
  void drag(int handle, const Vec3& target) override {
    poleSelected_ = handle == kPoleHandle;
    if (!poleSelected_) return IkScene::drag(handle, target);
    setPoleToward(target);
  }
  bool nudge(const Vec3& delta) override {
    if (!poleSelected_) return IkScene::nudge(delta);
    setPoleToward(options_.polePoint + delta);
    return true;
  }
  std::vector<app::DragHandle> dragHandles() const override {
    std::vector<app::DragHandle> out = IkScene::dragHandles();
    out.push_back({kPoleHandle, options_.polePoint});
    return out;
  }
  void draw(DebugDraw& d) const override {
    IkScene::draw(d);
    d.sphere(options_.polePoint, kPoleRadius, colors::kPurple);
    if (poleSelected_) d.circle(options_.polePoint, Vec3(1, 0, 0), 1.8 * kPoleRadius, colors::kDark);
    d.line(rig_.skeleton.joint(0).offset, options_.polePoint, colors::kPurple);
  }

 protected:
  Rig build() const override { return buildTwoBoneArm(desc_).value(); }
  Real pathRadius() const override { return 0.5; }

 private:
  static constexpr int kPoleHandle = 1000;   // the goal is handle 0
  static constexpr Real kPoleRadius = 0.05;  // [m]
  Vec3 polePoint() const { return desc_.shoulder + Vec3(0.5, std::cos(poleAngle_), std::sin(poleAngle_)) * 1.5; }
  /// The pole angle whose point on the circle is nearest `p` (its angle about the x axis).
  void setPoleToward(const Vec3& p) {
    const Vec3 r = p - desc_.shoulder;
    if (std::abs(r.y) + std::abs(r.z) > 1e-9) poleAngle_ = std::atan2(r.z, r.y);
    options_.polePoint = polePoint();  // solved by the next step, or by refresh() while paused
  }

  TwoBoneDesc desc_;
  Real poleAngle_ = 1.2;
  bool poleSelected_ = false;
};

}  // namespace
}  // namespace pba::lab

PBA_REGISTER_SCENE("Analytic", "two-bone", pba::lab::TwoBoneScene);
