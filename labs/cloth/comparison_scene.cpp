// Cloth lab, scene "comparison": four identical cloths, pinned at two corners, side by side under the
// explicit, implicit, PBD and XPBD solvers; each reports its ms per frame, stretch (max strain) and energy.
#include <chrono>
#include <cmath>

#include "cloth_scene.h"
#include "physics/cloth/self_collision.h"

namespace pba::lab {

using namespace pba::cloth;
namespace {

constexpr Real kGap = 1.1;  // [m] between the cloths

class ComparisonScene final : public ClothScene {
 public:
  ComparisonScene() {
    declareDisplayParams();
    resolution_ = 16;
    stiffness_ = 5000.0;
  }
  // A benchmark of the four solvers: the explicit cloth takes as many substeps as its stability bound asks
  // for, and that cost is what the scene shows, so it is timed but not held to the 2 ms budget.
  bool heavy() const override { return true; }
  std::optional<app::CameraView> preferredView() const override {
    return app::CameraView{Vec3(0.4, 0.75, 0.0), 6.0, 0.2, 0.25};
  }
  std::string description() const override {
    return "The same cloth under explicit, implicit, PBD and XPBD side by side: compare stretch, energy and cost.";
  }
  void step(Real dt) override {
    applyParams();
    for (std::size_t k = 0; k < kAllClothSolvers.size(); ++k) {
      ClothSolverSettings s = settings_;
      s.kind = kAllClothSolvers[k];
      cloths_[k].material = material_;
      if (s.kind == ClothSolverKind::Explicit) {
        // As many substeps as symplectic Euler needs: half the stability bound 2/ω_max.
        s.substeps = stableExplicitSubsteps(cloths_[k], dt, 0.5);
      } else if (s.kind == ClothSolverKind::Implicit) {
        s.substeps = 1;
      } else if (s.kind == ClothSolverKind::Pbd) {
        s.iterations = s.substeps * s.iterations;  // the same budget as XPBD, spent on iterations
        s.substeps = 1;
      }
      const auto start = std::chrono::steady_clock::now();
      stats_[k] = solvers_[k].step(cloths_[k], env_, colliders_, s, dt, time_);
      ms_[k] = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    }
    time_ += dt;
  }
  void draw(DebugDraw& d) const override {
    const std::array<Color, 4> tint{colors::kOrange, colors::kBlue, colors::kGreen, colors::kPurple};
    for (std::size_t k = 0; k < cloths_.size(); ++k) {
      drawCloth(d, cloths_[k], tint[k]);
      d.text(cloths_[k].position[0] + Vec3(0.3, 0.25, 0.0), solverName(kAllClothSolvers[k]), colors::kDark);
    }
  }
  nlohmann::json metrics() const override {
    nlohmann::json j = clothMetrics(cloths_[3], stats_[3], ClothSolverKind::Xpbd);
    for (std::size_t k = 0; k < cloths_.size(); ++k) {
      const std::string name(solverName(kAllClothSolvers[k]));
      j[name + "_ms"] = ms_[k];
      j[name + "_max_strain"] = edgeStrain(cloths_[k]).max;
      j[name + "_energy_J"] = clothEnergy(cloths_[k], env_, kAllClothSolvers[k]);
    }
    j["explicit_substeps"] = stableExplicitSubsteps(cloths_[0], 1.0 / 60.0, 0.5);
    j["implicit_cg_iterations"] = stats_[1].cgIterations;
    j["step_ms"] = ms_[0] + ms_[1] + ms_[2] + ms_[3];
    particles::SpatialHash hash;
    j["self_intersections"] = countSelfIntersections(cloths_[3].position, cloths_[3].restPosition, thickness_, hash);
    return j;
  }
  std::optional<std::string> nonFiniteState() const override {
    for (std::size_t k = 0; k < cloths_.size(); ++k) {
      if (auto bad = describeNonFinite(cloths_[k])) return std::string(solverName(kAllClothSolvers[k])) + ": " + *bad;
    }
    return std::nullopt;
  }
  std::optional<Real> energy() const override {
    Real e = 0.0;
    for (std::size_t k = 0; k < cloths_.size(); ++k) e += clothEnergy(cloths_[k], env_, kAllClothSolvers[k]);
    return e;
  }
  std::vector<std::string> defaultPlots() const override { return {"pbd_max_strain", "xpbd_max_strain"}; }
  std::vector<app::Preset> presets() const override { return {}; }
  std::optional<app::PickHit> pick(const app::Ray&) const override { return std::nullopt; }
  std::vector<app::DragHandle> dragHandles() const override { return {}; }

 protected:
  Result<Cloth> build() override {
    colliders_.push_back(Collider::plane());
    for (std::size_t k = 0; k < cloths_.size(); ++k) {
      grid_ = squareGrid(0.9, Vec3((static_cast<Real>(k) - 1.5) * kGap, 1.6, 0.0), GridPins::TopCorners);
      Result<Cloth> c = buildClothGrid(grid_, material_);
      if (!c) return c;
      cloths_[k] = std::move(c).value();
      solvers_[k].reset();
      stats_[k] = {};
      ms_[k] = 0.0;
    }
    return cloths_[3];
  }

 private:
  std::array<Cloth, 4> cloths_;
  std::array<ClothSolver, 4> solvers_;
  std::array<ClothStepStats, 4> stats_;
  std::array<double, 4> ms_{};
};

}  // namespace
}  // namespace pba::lab

PBA_REGISTER_SCENE("Cloth", "comparison", pba::lab::ComparisonScene);
