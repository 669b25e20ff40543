// Particles lab, scene "granular": grains poured into a bin pile up through particle–particle collisions
// found with a spatial hash grid (Teschner et al. 2003) feeding a Verlet neighbour list, with friction
// against the floor and walls.
#include <random>

#include "app/runner/scene_registry.h"
#include "common.h"
#include "physics/particles/spatial_hash.h"

namespace pba::lab {
namespace {

constexpr Real kBin = 0.8;  // [m] half-width of the bin
// Skin of the neighbour list as a multiple of the grain radius: pairs are listed up to 2r + skin apart.
// Larger skins rebuild less often but sweep over more pairs; 0.5 and 1 measured alike, 2 slower.
constexpr Real kSkinPerRadius = 1.0;

class GranularScene final : public app::Scene {
 public:
  GranularScene() {
    params_.integer("particles", &count_, 10, 20000, "", "Number of grains. Typical 1000.")
        .needsReset()
        .workload();  // 20,000 grains: 21 s of the extremes check
    params_.real("radius", &radius_, 0.01, 0.1, "m", "Grain radius. Typical 0.04 m.").needsReset();
    params_.integer("iterations", &iterations_, 1, 10, "",
                    "Collision sweeps per step: more = stiffer pile. Typical 3.");
    params_.real("restitution", &obstacles_.material.restitution, 0.0, 1.0, "", "Bounciness of all contacts.");
    params_.real("friction", &obstacles_.material.kineticFriction, 0.0, 1.5, "", "μ_k against floor and walls.");
    sim_.declareParams(params_);
  }

  std::string description() const override {
    return "Grains rain into a bin and pile up: every pair contact is found through a spatial hash grid.";
  }

  void reset() override {
    sim_.system = particles::ParticleSystem{};
    std::mt19937_64 rng(seed());
    std::uniform_real_distribution<Real> u(-1.0, 1.0);
    for (int i = 0; i < count_; ++i) {
      const Vec3 x(0.9 * kBin * u(rng), 0.3 + 0.9 * (u(rng) + 1.0), 0.9 * kBin * u(rng));
      sim_.system.particles.add(x, Vec3(0.0), 0.01, i % 2 ? colors::kYellow : colors::kOrange);
    }
    obstacles_.planes = {{Vec3(0.0), kUp},
                         {Vec3(-kBin, 0, 0), Vec3(1, 0, 0)},
                         {Vec3(kBin, 0, 0), Vec3(-1, 0, 0)},
                         {Vec3(0, 0, -kBin), Vec3(0, 0, 1)},
                         {Vec3(0, 0, kBin), Vec3(0, 0, -1)}};
    obstacles_.material.staticFriction = std::max(obstacles_.material.kineticFriction, 0.6);
    sim_.finishReset();
    neighbours_.invalidate();
  }

  void step(Real dt) override {
    sim_.integrate(dt);
    particles::Particles& p = sim_.system.particles;
    contacts_ = 0;
    for (int k = 0; k < iterations_; ++k) {
      const bool last = k + 1 == iterations_;
      // The neighbour list stays valid while no grain has moved more than skin/2 since it was built:
      // checked before every sweep, rebuilt about once per step while grains fall, rarely in a pile.
      neighbours_.update(p.position, 2.0 * radius_, kSkinPerRadius * radius_, hash_);
      const particles::PairCollisionStats sweep =
          particles::collideParticlePairs(p, radius_, obstacles_.material.restitution, neighbours_.pairs());
      contacts_ += sweep.contacts;
      if (last) deepestOverlap_ = sweep.deepestPenetration;
      particles::collideWithObstacles(p, obstacles_, radius_);
    }
    sim_.finishStep();
  }

  void draw(DebugDraw& d) const override {
    const Vec3 c[4] = {{-kBin, 0, -kBin}, {kBin, 0, -kBin}, {kBin, 0, kBin}, {-kBin, 0, kBin}};
    for (int i = 0; i < 4; ++i) {
      d.line(c[i], c[(i + 1) % 4], colors::kDark);
      d.line(c[i] + Vec3(0, 0.6, 0), c[(i + 1) % 4] + Vec3(0, 0.6, 0), colors::kDark);
      d.line(c[i], c[i] + Vec3(0, 0.6, 0), colors::kDark);
    }
    lab::drawParticles(d, sim_.system.particles, radius_, 3000);
  }

  nlohmann::json metrics() const override {
    nlohmann::json j = sim_.metrics();
    j["pair_contacts"] = contacts_;
    j["deepest_overlap_m"] = deepestOverlap_;  // found by the last sweep of the last step
    j["neighbour_list_builds"] = neighbours_.builds();
    Real top = 0.0;
    for (const Vec3& x : sim_.system.particles.position) top = std::max(top, x.y);
    j["pile_top_m"] = top;
    return j;
  }
  std::optional<std::string> nonFiniteState() const override { return sim_.nonFiniteState(); }
  std::optional<Real> energy() const override { return sim_.system.energy(); }
  std::vector<std::string> defaultPlots() const override { return {"energy", "pair_contacts"}; }
  std::vector<app::Preset> presets() const override {
    return {{"sand", {{"restitution", 0.05}, {"friction", 0.6}}},
            {"marbles", {{"restitution", 0.6}, {"friction", 0.1}}},
            {"lots", {{"particles", 5000}, {"radius", 0.025}}}};
  }

 private:
  int count_ = 1000, iterations_ = 3;
  Real radius_ = 0.04;
  std::size_t contacts_ = 0;
  Real deepestOverlap_ = 0.0;
  lab::IntegratedSystem sim_;
  particles::Obstacles obstacles_{{}, {}, {}, particles::ContactMaterial{0.1, 0.6, 0.4, 0.1}};
  particles::SpatialHash hash_;
  particles::NeighbourList neighbours_;
};

}  // namespace

PBA_REGISTER_SCENE("Particles", "granular", GranularScene);

}  // namespace pba::lab
