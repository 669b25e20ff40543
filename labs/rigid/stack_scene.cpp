// Rigid lab, scene "stack": a column of 10 boxes and a pyramid with a base of 20 (210 boxes) stand still:
// warm starting and soft contacts at work; the drift of the top boxes is the measure.
#include "app/runner/scene_registry.h"
#include "world_scene.h"

namespace pba::lab {
namespace {

class StackScene final : public lab::WorldScene {
 public:
  StackScene() {
    settings_.iterations =
        2;  // the 210-box pyramid at rest within 1 cm (tests/physics/rigid/contact_behaviour_test.cpp)
    params_.integer("column", &desc_.columnHeight, 1, 40, "", "Boxes in the vertical stack. Typical 10.").needsReset();
    params_.integer("pyramid_base", &desc_.pyramidBase, 1, 40, "", "Boxes in the pyramid's bottom row (20: 210 boxes).")
        .needsReset();
    params_.real("friction", &desc_.friction, 0.0, 1.5, "", "Coulomb μ of every box. Typical 0.6.").needsReset();
  }
  std::string description() const override {
    return "A 10-box column and a 210-box pyramid stand still: warm-started soft contacts, each row scaled by its "
           "effective "
           "mass (RIGID-5), keep the tops from drifting.";
  }

 protected:
  void build(rigid::World& w) override {
    rigid::addGround(w, desc_.friction);
    bodies_ = rigid::buildStack(w, desc_);
    columnStart_ = w.body(bodies_.columnTop).position;
    pyramidStart_ = w.body(bodies_.pyramidTop).position;
  }
  // Sideways: the soft contacts' settling under load (about 0.55 mm per box above) is not drift.
  Real topDrift() const {
    const Vec3 horizontal(1.0, 0.0, 1.0);
    return std::max(glm::length(horizontal * (world_.body(bodies_.columnTop).position - columnStart_)),
                    glm::length(horizontal * (world_.body(bodies_.pyramidTop).position - pyramidStart_)));
  }
  void extraMetrics(nlohmann::json& j) const override { j["top_drift_m"] = topDrift(); }
  std::vector<app::Preset> presets() const override {
    return {{"no warm start", {{"warm_starting", false}}},
            {"baumgarte",
             {{"correction", "baumgarte"}, {"solver_substeps", 1}, {"iterations", 10}, {"relax_iterations", 0}}},
            {"tall column", {{"column", 25}, {"pyramid_base", 5}}}};
  }
  std::vector<std::string> defaultPlots() const override { return {"top_drift_m", "kinetic_energy_J"}; }
  std::optional<app::CameraView> preferredView() const override {
    return app::CameraView{Vec3(-3.0, 7.0, 0.0), 38.0, 0.1, 0.15};
  }

 private:
  rigid::StackDesc desc_;
  rigid::StackBodies bodies_;
  Vec3 columnStart_{0.0}, pyramidStart_{0.0};
};

}  // namespace

PBA_REGISTER_SCENE("Rigid bodies", "stack", StackScene);

}  // namespace pba::lab
