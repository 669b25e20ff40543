// Bullet's classic btSoftBody cloth against our PBD and XPBD cloth (issue 36), in the same run.
//
// The scene: a square cloth of 1 m × 1 m and 0.2 kg, n × n particles, hanging from the two corners of its
// first row, released flat under gravity, frames of 1/60 s, kFrames frames (the fall, the first swings).
// Both libraries solve the same distance constraints: the grid's edges and one diagonal per quad, the
// diagonals alternating (btSoftBodyHelpers::CreatePatch with gendiags; our GridDiagonals::Alternating, the
// grid read mirrored so that the same quads get the same diagonal), stiffness 1 (kLST = 1; XPBD compliance
// 0; PBD stiffness 1), no bending (ours BendingModel::None, Bullet no bending links), no damping (kDP = 0;
// ours massDamping 0), the same particle masses (ours lumped from the triangles, copied into Bullet's
// nodes), `substeps` steps of 1/(60 substeps) s per frame with `iterations` Gauss–Seidel sweeps each
// (Bullet: m_cfg.piterations). The setup checks the node positions, pins, masses and link set and refuses
// to run if they differ.
//
// Every row reports the stretch (l − L)/L of the constraints' edges through one function for both
// libraries, pba::cloth::edgeStrain (Bullet's nodes are copied into a cloth of the same grid first):
// max_end / mean_end at the last frame, max_peak / mean_peak the largest over the run, in per cent.
// The "matched" rows give the time at equal stretch: the fewest iterations with which one side's peak
// stretch (largest and mean) is at most the other side's at the row's iteration count (counter
// `iterations`; the other side's peaks in target_max_peak and target_mean_peak).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "physics/cloth/solver.h"

#ifdef PBA_HAVE_BULLET
#include <BulletSoftBody/btSoftBodyHelpers.h>
#include <BulletSoftBody/btSoftBodyRigidBodyCollisionConfiguration.h>
#include <BulletSoftBody/btSoftRigidDynamicsWorld.h>
#include <btBulletDynamicsCommon.h>
#endif

namespace {
using namespace pba;
using namespace pba::cloth;

constexpr int kFrames = 120;  // 2 s
constexpr Real kFrame = 1.0 / 60.0;
constexpr Real kSize = 1.0;       // [m] side of the square cloth
constexpr Real kTotalMass = 0.2;  // [kg]
constexpr Real kHeight = 2.0;     // [m] of the cloth's plane
/// The most iterations a matched row tries before it gives up.
constexpr int kMaxMatchedIterations = 1024;

enum class Peer { Pbd, Xpbd, Bullet };

struct Setup {
  int n = 32;           ///< particles per side
  int substeps = 1;     ///< steps per frame
  int iterations = 10;  ///< Gauss–Seidel sweeps per step (Bullet's piterations)
};

Cloth squareCloth(int n) {
  GridDesc d;
  d.resolutionX = d.resolutionY = n;
  d.width = d.height = kSize;
  d.center = Vec3(0.0, kHeight, 0.0);
  d.pins = GridPins::TopCorners;
  d.diagonals = GridDiagonals::Alternating;
  ClothMaterial m;
  m.massPerArea = kTotalMass / (kSize * kSize);
  m.stretchCompliance = m.shearCompliance = 0.0;
  m.springDamping = 0.0;
  return buildClothGrid(d, m).value();
}

/// Stretch statistics of a run: the last frame's and the largest over the run.
struct StretchRun {
  StrainStats end, peak;
  void add(const StrainStats& s) {
    end = s;
    peak.max = std::max(peak.max, s.max);
    peak.mean = std::max(peak.mean, s.mean);
  }
};

/// Our PBD or XPBD cloth.
class OurCloth {
 public:
  OurCloth(Peer peer, const Setup& setup) : cloth_(squareCloth(setup.n)) {
    settings_.kind = peer == Peer::Pbd ? ClothSolverKind::Pbd : ClothSolverKind::Xpbd;
    settings_.substeps = setup.substeps;
    settings_.iterations = setup.iterations;
    settings_.pbdStiffness = 1.0;
    settings_.bending = BendingModel::None;
  }
  void frame() {
    solver_.step(cloth_, environment_, {}, settings_, kFrame, time_);
    time_ += kFrame;
  }
  StrainStats strain() const { return edgeStrain(cloth_); }
  std::size_t links() const { return cloth_.constraints.size(); }

 private:
  Cloth cloth_;
  ClothSolver solver_;
  ClothSolverSettings settings_;
  ClothEnvironment environment_;  // gravity, no damping, no wind
  Real time_ = 0.0;
};

#ifdef PBA_HAVE_BULLET
Vec3 toVec3(const btVector3& v) { return {v.x(), v.y(), v.z()}; }

/// Bullet's classic soft body on the same grid, alone in a btSoftRigidDynamicsWorld.
class BulletCloth {
 public:
  explicit BulletCloth(const Setup& setup) : n_(setup.n), substeps_(setup.substeps), probe_(squareCloth(setup.n)) {
    world_ = new btSoftRigidDynamicsWorld(&dispatcher_, &broadphase_, &constraintSolver_, &configuration_);
    const btVector3 g(0.0, -kStandardGravity, 0.0);
    world_->setGravity(g);
    world_->getWorldInfo().m_gravity = g;
    // Bullet's node (ix, iy) is our particle (n − 1 − ix, iy): its corner00 is our (n − 1, 0), so that
    // its diagonals (alternating, the other parity) fall on ours. Fixeds 1 + 2 pin our corners of row 0.
    const btScalar s = 0.5 * kSize, y = kHeight;
    body_ = btSoftBodyHelpers::CreatePatch(world_->getWorldInfo(), btVector3(s, y, -s), btVector3(-s, y, -s),
                                           btVector3(s, y, s), btVector3(-s, y, s), n_, n_, 1 + 2, true);
    for (int k = 0; k < body_->m_nodes.size(); ++k) {
      const std::uint32_t i = ours(k);
      if (probe_.inverseMass[i] != 0.0) body_->setMass(k, probe_.mass[i]);
    }
    body_->m_materials[0]->m_kLST = 1.0;  // CreatePatch's default: stiffness 1, as our constraints
    body_->m_cfg.kDP = 0.0;               // no damping (Bullet's default)
    body_->m_cfg.piterations = setup.iterations;
    body_->setSolver(btSoftBody::eSolverPresets::Positions);
    world_->addSoftBody(body_);
    error_ = checkSameCloth();
  }
  ~BulletCloth() {
    world_->removeSoftBody(body_);
    delete body_;
    delete world_;
  }
  BulletCloth(const BulletCloth&) = delete;
  BulletCloth& operator=(const BulletCloth&) = delete;

  /// Empty when Bullet's cloth has our nodes, pins, masses and links; else what differs.
  std::string error() const { return error_; }
  /// `substeps` steps of exactly h (maxSubSteps 0: one step of the given length, no interpolation).
  void frame() {
    const btScalar h = kFrame / substeps_;
    for (int i = 0; i < substeps_; ++i) world_->stepSimulation(h, 0);
  }
  StrainStats strain() {
    for (int k = 0; k < body_->m_nodes.size(); ++k) probe_.position[ours(k)] = toVec3(body_->m_nodes[k].m_x);
    return edgeStrain(probe_);
  }
  std::size_t links() const { return static_cast<std::size_t>(body_->m_links.size()); }

 private:
  std::uint32_t ours(int k) const { return static_cast<std::uint32_t>((k / n_) * n_ + (n_ - 1 - k % n_)); }
  std::uint32_t ours(const btSoftBody::Node* node) const { return ours(static_cast<int>(node - &body_->m_nodes[0])); }

  std::string checkSameCloth() const {
    for (int k = 0; k < body_->m_nodes.size(); ++k) {
      const btSoftBody::Node& node = body_->m_nodes[k];
      const std::uint32_t i = ours(k);
      if (glm::length(toVec3(node.m_x) - probe_.position[i]) > 1e-12) return "node positions differ";
      if ((node.m_im == 0.0) != (probe_.inverseMass[i] == 0.0)) return "pins differ";
      if (node.m_im != 0.0 && std::abs(1.0 / node.m_im - probe_.mass[i]) > 1e-15) return "masses differ";
    }
    std::set<std::pair<std::uint32_t, std::uint32_t>> ourLinks, bulletLinks;
    for (const Link& l : probe_.constraints) ourLinks.insert(std::minmax(l.i, l.j));
    for (int k = 0; k < body_->m_links.size(); ++k) {
      const btSoftBody::Link& l = body_->m_links[k];
      bulletLinks.insert(std::minmax(ours(l.m_n[0]), ours(l.m_n[1])));
    }
    return ourLinks == bulletLinks ? std::string() : "link sets differ";
  }

  int n_, substeps_;
  Cloth probe_;  ///< our cloth of the same grid: the masses to copy, and Bullet's positions for edgeStrain
  std::string error_;
  btSoftBodyRigidBodyCollisionConfiguration configuration_;
  btCollisionDispatcher dispatcher_{&configuration_};
  btDbvtBroadphase broadphase_;
  btSequentialImpulseConstraintSolver constraintSolver_;
  btSoftRigidDynamicsWorld* world_ = nullptr;
  btSoftBody* body_ = nullptr;
};
#endif

/// Runs kFrames frames untimed and returns the stretch.
template <typename Sim>
StretchRun untimedRun(Sim&& sim) {
  StretchRun run;
  for (int f = 0; f < kFrames; ++f) {
    sim.frame();
    run.add(sim.strain());
  }
  return run;
}

#ifdef PBA_HAVE_BULLET
StretchRun untimedRun(Peer peer, const Setup& setup) {
  if (peer == Peer::Bullet) return untimedRun(BulletCloth(setup));
  return untimedRun(OurCloth(peer, setup));
}

/// Whether a run's stretch is at most the target's by both measures (peak largest and peak mean).
bool atMost(const StrainStats& stretch, const StrainStats& target) {
  return stretch.max <= target.max && stretch.mean <= target.mean;
}

/// The fewest iterations (1 … kMaxMatchedIterations) whose peak stretch is at most `target` by both
/// measures, or 0. Doubling, then bisection: the stretch falls as the sweeps rise (the bisection trusts
/// that; only the counts it visits are run).
int iterationsToMatch(Peer peer, Setup setup, const StrainStats& target) {
  auto meets = [&](int iterations) {
    setup.iterations = iterations;
    return atMost(untimedRun(peer, setup).peak, target);
  };
  int high = 1;
  while (!meets(high)) {
    if (high >= kMaxMatchedIterations) return 0;
    high = std::min(2 * high, kMaxMatchedIterations);
  }
  int low = high / 2;  // fails (or 0)
  while (high - low > 1) {
    const int mid = (low + high) / 2;
    (meets(mid) ? high : low) = mid;
  }
  return high;
}
#endif

template <typename Sim>
void timeFrames(benchmark::State& state, Sim& sim, const std::string& label) {
  StretchRun run;
  for (auto _ : state) {
    sim.frame();
    state.PauseTiming();
    run.add(sim.strain());
    state.ResumeTiming();
  }
  state.counters["max_end"] = 100.0 * run.end.max;
  state.counters["mean_end"] = 100.0 * run.end.mean;
  state.counters["max_peak"] = 100.0 * run.peak.max;
  state.counters["mean_peak"] = 100.0 * run.peak.mean;
  state.counters["links"] = static_cast<double>(sim.links());
  // The label carries the peaks too, for the CSV that ./pba bench reads (it keeps no counters).
  char peaks[64];
  std::snprintf(peaks, sizeof peaks, "; peak stretch %.3g %% largest, %.3g %% mean", 100.0 * run.peak.max,
                100.0 * run.peak.mean);
  state.SetLabel(label + peaks);
}

const char* peerName(Peer peer) {
  switch (peer) {
    case Peer::Pbd:
      return "ours PBD";
    case Peer::Xpbd:
      return "ours XPBD";
    case Peer::Bullet:
      return "Bullet btSoftBody";
  }
  return "";
}

void timePeer(benchmark::State& state, Peer peer, const Setup& setup, const std::string& label) {
  state.counters["iterations"] = setup.iterations;
#ifdef PBA_HAVE_BULLET
  if (peer == Peer::Bullet) {
    BulletCloth sim(setup);
    if (!sim.error().empty()) return state.SkipWithError(sim.error().c_str());
    return timeFrames(state, sim, label);
  }
#endif
  if (peer == Peer::Bullet) return state.SkipWithError("built without Bullet (apt-get install libbullet-dev)");
  OurCloth sim(peer, setup);
  timeFrames(state, sim, label);
}

Setup setupOf(const benchmark::State& state) {
  return {static_cast<int>(state.range(1)), static_cast<int>(state.range(2)), static_cast<int>(state.range(3))};
}

/// range(0): Peer (0 PBD, 1 XPBD, 2 Bullet); range(1): n; range(2): substeps; range(3): sweeps (iterations).
void BM_SoftBodyCloth(benchmark::State& state) {
  const auto peer = static_cast<Peer>(state.range(0));
  timePeer(state, peer, setupOf(state), peerName(peer));
}

#ifdef PBA_HAVE_BULLET
/// Time at equal stretch. range(0): the side that is matched (1 our XPBD, 2 Bullet); it runs with the fewest
/// iterations whose peak stretch, largest and mean, is at most the other side's (Bullet's, our XPBD's) at
/// range(3) iterations.
void BM_SoftBodyClothMatched(benchmark::State& state) {
  const auto peer = static_cast<Peer>(state.range(0));
  Setup setup = setupOf(state);
  const Peer other = peer == Peer::Bullet ? Peer::Xpbd : Peer::Bullet;
  const StrainStats target = untimedRun(other, setup).peak;
  setup.iterations = iterationsToMatch(peer, setup, target);
  state.counters["target_max_peak"] = 100.0 * target.max;
  state.counters["target_mean_peak"] = 100.0 * target.mean;
  if (setup.iterations == 0) return state.SkipWithError("no iteration count up to 1024 matches");
  timePeer(state, peer, setup,
           std::string(peerName(peer)) + " at " + peerName(other) + "'s stretch with " +
               std::to_string(state.range(3)) + " iterations: " + std::to_string(setup.iterations) + " iterations");
}
#endif

/// The grids and solver budgets: 32 × 32 (the lab's hanging cloth) and 64 × 64; one step per frame (Bullet's
/// usual use of piterations) with 10 and 40 sweeps, and 10 steps per frame (the lab's XPBD default) with 1
/// and 4 sweeps.
void grids(benchmark::internal::Benchmark* b, std::initializer_list<int> peers) {
  const std::pair<int, int> budgets[] = {{1, 10}, {1, 40}, {10, 1}, {10, 4}};  // substeps, iterations
  for (int n : {32, 64}) {
    for (const auto& [substeps, iterations] : budgets) {
      for (int peer : peers) b->Args({peer, n, substeps, iterations});
    }
  }
  b->ArgNames({"peer", "n", "substeps", "sweeps"})->Iterations(kFrames)->Unit(benchmark::kMillisecond);
}
BENCHMARK(BM_SoftBodyCloth)->Apply([](benchmark::internal::Benchmark* b) { grids(b, {0, 1, 2}); });
#ifdef PBA_HAVE_BULLET
BENCHMARK(BM_SoftBodyClothMatched)->Apply([](benchmark::internal::Benchmark* b) { grids(b, {1, 2}); });
#endif

}  // namespace

BENCHMARK_MAIN();
