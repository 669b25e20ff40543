// Animation lab, scene "splines": one 3-D curve through draggable knots at non-uniform times, drawn by
// four interpolants side by side (CMU asst4 "Splines"): Catmull-Rom (ANIM-1, ANIM-2), a Hermite
// (cardinal) spline whose tangents are the Catmull-Rom ones scaled by 1 − tension, the natural cubic
// spline (C²) and linear interpolation. A ball follows the chosen curve with its velocity (blue) and
// acceleration (red) arrows; before the first and after the last knot it holds still (the boundary
// rules: t ≤ first knot → first value, t ≥ last → last).
#include <cmath>

#include "anim_scene.h"
#include "physics/animation/cubic_spline.h"

namespace pba::lab {
namespace {

enum class Curve { CatmullRom, Hermite, NaturalCubic, Linear };
constexpr auto kCurveNames = enumNames<Curve>({{Curve::CatmullRom, "catmull-rom"},
                                               {Curve::Hermite, "hermite"},
                                               {Curve::NaturalCubic, "natural-cubic"},
                                               {Curve::Linear, "linear"}});

class SplinesScene final : public AnimScene {
 public:
  SplinesScene() {
    params_.choiceEnum("follow", &follow_, kCurveNames,
                       "The curve the ball follows (its arrows show that curve's velocity and acceleration).");
    params_.real("tension", &tension_, 0.0, 1.0, "",
                 "Hermite curve: tangents = (1 − tension) × Catmull-Rom's. 0 is Catmull-Rom, 1 stops at every knot. "
                 "Typical 0.5.");
    params_.flag("uniform_times", &uniform_, "Knots at equal time steps (1 s) instead of the non-uniform default.")
        .needsReset();
    params_.flag("show_catmull_rom", &show_[0], "Draw the Catmull-Rom curve (blue).");
    params_.flag("show_hermite", &show_[1], "Draw the Hermite (cardinal) curve (purple).");
    params_.flag("show_natural_cubic", &show_[2], "Draw the natural cubic spline (green).");
    params_.flag("show_linear", &show_[3], "Draw the piecewise-linear curve (grey).");
    params_.real("arrow_scale", &arrowScale_, 0.01, 1.0, "s", "Velocity arrows are v × this. Typical 0.25 s.");
    params_.real("acceleration_scale", &accelerationScale_, 0.001, 0.1, "s²",
                 "Acceleration arrows are a × this. Typical 0.01 s² (the kinks at the knots reach 50 m/s²).");
  }
  std::string description() const override {
    return "Four interpolants through the same draggable knots; the ball's blue and red arrows are the chosen curve's "
           "velocity and acceleration.";
  }
  void reset() override {
    const Vec3 knots[] = {{-2.4, 0.6, 0.0}, {-1.4, 1.9, 0.6}, {-0.3, 0.9, -0.4},
                          {0.7, 2.2, 0.2},  {1.6, 1.1, 0.8},  {2.5, 1.8, -0.2}};
    const Real times[] = {0.0, 0.6, 1.0, 2.2, 2.6, 3.6};  // [s] non-uniform on purpose
    knots_.assign(std::begin(knots), std::end(knots));
    times_.clear();
    for (size_t k = 0; k < knots_.size(); ++k) times_.push_back(uniform_ ? static_cast<Real>(k) : times[k]);
    resetClock();
  }
  void draw(DebugDraw& d) const override {
    const Color palette[] = {colors::kBlue, colors::kPurple, colors::kGreen, colors::kGrey};
    for (int c = 0; c < 4; ++c) {
      if (!show_[c]) continue;
      Vec3 last = at(static_cast<Curve>(c), times_.front(), 0);
      for (int s = 1; s <= kSamples; ++s) {
        const Real t = times_.front() + (times_.back() - times_.front()) * s / kSamples;
        const Vec3 p = at(static_cast<Curve>(c), t, 0);
        d.line(last, p, palette[c]);
        last = p;
      }
    }
    for (size_t k = 0; k < knots_.size(); ++k) {
      d.sphere(knots_[k], 0.09, colors::kDark);
      d.line(Vec3(knots_[k].x, 0.0, knots_[k].z), knots_[k], colors::kGrey);
    }
    d.sphere(ball_, 0.13, colors::kYellow);
    d.arrow(ball_, ball_ + arrowScale_ * velocity_, colors::kBlue);
    d.arrow(ball_, ball_ + accelerationScale_ * acceleration_, colors::kRed);
    d.text(ball_ + Vec3(0.0, 0.25, 0.0), std::string("t = ") + std::to_string(time()).substr(0, 4) + " s",
           colors::kDark);
  }
  std::vector<app::LegendEntry> legend() const override {
    return {{colors::kBlue, "Catmull-Rom (C¹)"},
            {colors::kPurple, "Hermite, tangents × (1 − tension)"},
            {colors::kGreen, "natural cubic (C²)"},
            {colors::kGrey, "linear (C⁰)"},
            {colors::kYellow, "ball: velocity blue, acceleration red"}};
  }
  std::optional<app::PickHit> pick(const app::Ray& ray) const override {
    std::optional<app::PickHit> best;
    for (size_t k = 0; k < knots_.size(); ++k) {
      const auto h = app::pickSphere(ray, knots_[k], 0.15, static_cast<int>(k));
      if (h && (!best || h->distance < best->distance)) best = h;
    }
    return best;
  }
  void drag(int handle, const Vec3& target) override {
    if (handle >= 0 && handle < static_cast<int>(knots_.size()))
      knots_[static_cast<size_t>(handle)] = glm::max(target, Vec3(-10, 0.05, -10));
  }
  void refresh() override { evaluate(); }
  std::vector<app::DragHandle> dragHandles() const override {
    std::vector<app::DragHandle> h;
    for (size_t k = 0; k < knots_.size(); ++k) h.push_back({static_cast<int>(k), knots_[k]});
    return h;
  }
  std::optional<app::CameraView> preferredView() const override {
    return app::CameraView{Vec3(0.0, 1.0, 0.0), 8.5, 0.25, 0.3};
  }
  std::vector<app::Preset> presets() const override {
    return {{"catmull-rom", {{"follow", "catmull-rom"}}},
            {"hermite tension 0.8", {{"follow", "hermite"}, {"tension", 0.8}}},
            {"natural cubic", {{"follow", "natural-cubic"}}},
            {"linear", {{"follow", "linear"}}},
            {"uniform knots", {{"uniform_times", true}}}};
  }
  std::vector<std::string> defaultPlots() const override { return {"speed_m_s", "acceleration_m_s2"}; }

 protected:
  // The clock runs half a second past both ends so the boundary rules show.
  Real duration() const override { return times_.back() - times_.front() + 1.0; }
  std::vector<Real> keyTimes() const override {
    std::vector<Real> k;
    for (Real t : times_) k.push_back(t - times_.front() + 0.5);
    return k;
  }
  void evaluate() override {
    const Real t = times_.front() - 0.5 + time();
    ball_ = at(follow_, t, 0);
    velocity_ = at(follow_, t, 1);
    acceleration_ = at(follow_, t, 2);
    an::Channel<Vec3> c(an::Interpolation::CatmullRom, Vec3(0.0));
    for (size_t k = 0; k < knots_.size(); ++k) static_cast<void>(c.insert(times_[k], knots_[k]));
    continuity_ = continuityError(c);
    world_ = {{ball_, Quat(1, 0, 0, 0)}};
    skeleton_ = an::Skeleton{};
    skeleton_.add("ball", -1, ball_);
  }
  void addMetrics(nlohmann::json& m) const override {
    m["speed_m_s"] = glm::length(velocity_);
    m["acceleration_m_s2"] = glm::length(acceleration_);
    m["curve"] = kNames[static_cast<int>(follow_)];
  }

 private:
  static constexpr int kSamples = 240;
  static constexpr const char* kNames[] = {"catmull-rom", "hermite", "natural-cubic", "linear"};

  Vec3 at(Curve c, Real t, int derivative) const {
    switch (c) {
      case Curve::CatmullRom:
        return an::catmullRom(std::span<const Real>(times_), knots_, t, derivative);
      case Curve::Hermite:
        return hermiteAt(t, derivative);
      case Curve::NaturalCubic: {
        const auto m = an::cubicSplineMoments<Vec3>(times_, knots_, an::CubicEnds::Natural, Vec3(0.0), Vec3(0.0));
        return an::cubicSplineEvaluate<Vec3>(times_, knots_, m, t, derivative);
      }
      case Curve::Linear:
        return an::linearInterpolate<Vec3>(times_, knots_, t, derivative);
    }
    return Vec3(0.0);
  }
  /// Cardinal spline: the Catmull-Rom segment with both tangents scaled by (1 − tension).
  Vec3 hermiteAt(Real t, int derivative) const {
    const an::CatmullRomSegment s = an::catmullRomSegment(times_, t);
    if (s.region == an::SegmentRegion::Empty) return Vec3(0.0);
    if (s.region == an::SegmentRegion::Constant)
      return derivative == 0 ? knots_[static_cast<size_t>(s.key)] : Vec3(0.0);
    const Real k = 1.0 - tension_;
    const Vec3 m1 = k * an::weightedKnots(knots_, s.key, s.startTangent),
               m2 = k * an::weightedKnots(knots_, s.key, s.endTangent);
    return std::pow(s.length, -derivative) * an::hermite(knots_[static_cast<size_t>(s.key)], m1,
                                                         knots_[static_cast<size_t>(s.key) + 1], m2, s.u, derivative);
  }

  std::vector<Vec3> knots_;
  std::vector<Real> times_;
  Curve follow_ = Curve::CatmullRom;
  Real tension_ = 0.5;
  bool uniform_ = false;
  bool show_[4] = {true, true, true, true};
  Real arrowScale_ = 0.25;         // [s]
  Real accelerationScale_ = 0.01;  // [s²] a tenth of arrow_scale²: the curves stay the largest thing drawn
  Vec3 ball_{0.0}, velocity_{0.0}, acceleration_{0.0};
};

}  // namespace
}  // namespace pba::lab

PBA_REGISTER_SCENE("Curves", "splines", pba::lab::SplinesScene);
