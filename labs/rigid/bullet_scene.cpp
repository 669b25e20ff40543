// Rigid lab, scene "bullet": 1 cm spheres shot at 100 m/s at a 1 cm wall, two lanes side by side. In
// the lane with continuous collision (time of impact) no shot passes; in the other, most do: in one
// step of 1/60 s a shot travels 1.7 m, far past a wall 1 cm thick.
#include "app/runner/scene_registry.h"
#include "world_scene.h"

namespace pba::lab {
namespace {

constexpr Real kRadius = 0.005;    // [m] a 1 cm sphere
constexpr Real kWallX = 6.0;       // [m]
constexpr Real kWallHalf = 0.005;  // [m] a 1 cm wall

class BulletScene final : public lab::WorldScene {
 public:
  BulletScene() : WorldScene(false) {
    settings_.linearSlop = 0.001;
    params_.real("speed", &speed_, 1.0, 300.0, "m/s", "Muzzle speed of the shots. Typical 100 m/s.");
    params_.real("interval", &interval_, 0.05, 2.0, "s", "Time between two shots per lane. Typical 0.25 s.");
  }
  std::string description() const override {
    return "1 cm shots at 100 m/s hit a 1 cm wall: with continuous collision (front lane) none passes, without it "
           "(back "
           "lane) they tunnel.";
  }

 protected:
  void build(rigid::World& w) override {
    rigid::addGround(w);
    for (int lane = 0; lane < 2; ++lane) {
      rigid::BodyDesc wall;
      wall.type = rigid::BodyType::Static;
      wall.shape = collision::makeBox(Vec3(kWallHalf, 1.0, 0.4)).value();
      wall.position = Vec3(kWallX, 1.0, laneZ(lane));
      wall.color = lane == 0 ? colors::kGreen : colors::kRed;
      w.addBody(wall);
    }
    shots_.clear();
    tunnelled_[0] = tunnelled_[1] = 0;
    fired_ = 0;
    clock_ = interval_;  // fire at once
  }
  static Real laneZ(int lane) { return lane == 0 ? 0.6 : -0.6; }

  void afterStep(Real dt) override {
    clock_ += dt;
    if (clock_ >= interval_) {
      clock_ = 0.0;
      for (int lane = 0; lane < 2; ++lane) {
        rigid::BodyDesc shot;
        shot.shape = collision::makeSphere(kRadius).value();
        shot.position = Vec3(0.0, 1.0 + 0.3 * ((fired_ % 5) - 2) * 0.5, laneZ(lane));
        shot.linearVelocity = Vec3(speed_, 0.0, 0.0);
        shot.density = 7800.0;
        shot.bullet = lane == 0;
        shot.continuous = lane == 0;
        shot.restitution = 0.3;
        shot.gravityScale = 0.0;
        shot.color = lane == 0 ? colors::kGreen : colors::kRed;
        shot.name = lane == 0 ? "shot (continuous)" : "shot (discrete)";
        if (const Result<int> b = world_.addBody(shot)) shots_.push_back({b.value(), lane, false});
      }
      ++fired_;
    }
    for (Shot& s : shots_) {
      if (s.counted) continue;
      if (world_.body(s.body).position.x > kWallX + kWallHalf + kRadius) {
        ++tunnelled_[s.lane];
        s.counted = true;
      }
    }
  }
  void extraMetrics(nlohmann::json& j) const override {
    j["shots"] = fired_;
    j["tunnelled_ccd"] = tunnelled_[0];
    j["tunnelled_no_ccd"] = tunnelled_[1];
    j["ccd_hits"] = world_.stats().ccdHits;
  }
  void drawExtra(DebugDraw& d) const override {
    d.text(Vec3(kWallX, 2.2, laneZ(0)), "continuous", colors::kGreen);
    d.text(Vec3(kWallX, 2.2, laneZ(1)), "discrete", colors::kRed);
    // The 1 cm shots are tiny: a marker sphere around each in flight makes them visible.
    for (const Shot& s : shots_) {
      const rigid::Body& b = world_.body(s.body);
      if (b.position.x < kWallX + 3.0 && glm::length(b.linearVelocity) > 1.0) d.point(b.position, 6.0f, b.color);
    }
  }
  // Every shot brings energy in: the runaway guard has nothing to compare with (NaN is still caught).
  std::optional<Real> energy() const override { return std::nullopt; }
  std::vector<app::Preset> presets() const override {
    return {{"slow", {{"speed", 10.0}}}, {"very fast", {{"speed", 300.0}}}};
  }
  std::vector<std::string> defaultPlots() const override { return {"tunnelled_ccd", "tunnelled_no_ccd"}; }
  std::optional<app::CameraView> preferredView() const override {
    return app::CameraView{Vec3(4.0, 1.0, 0.0), 7.0, 1.0, 0.3};
  }

 private:
  struct Shot {
    int body;
    int lane;
    bool counted;
  };
  std::vector<Shot> shots_;
  int tunnelled_[2] = {0, 0};
  int fired_ = 0;
  Real speed_ = 100.0, interval_ = 0.25, clock_ = 0.0;
};

}  // namespace

PBA_REGISTER_SCENE("Rigid bodies", "bullet", BulletScene);

}  // namespace pba::lab
