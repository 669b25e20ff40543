// Cloth benchmarks (issue 14), one frame of 1/60 s per benchmark iteration, 180 frames per run:
//  - implicit mass-spring 64 × 64 (structural + shear + bend, two pinned corners, one step per frame) at
//    k = 10³ and 10⁵ N/m, against Debian's Bullet 3.24 in double precision (btDeformableMultiBodyDynamicsWorld
//    with btDeformableMassSpringForce and btDeformableGravityForce on the same grid from CreatePatch), in the
//    same run when Bullet is installed (pkg-config bullet-float64): ms per frame and the largest stretch;
//  - XPBD on Ten Minute Physics' 30 × 200 ribbon with self-collision, 10 substeps;
//  - explicit, implicit and XPBD on the comparison scene's cloth at equal stretch.
// The label of each row gives the largest stretch (l − L)/L of the grid's axis edges over the run and the
// settings. Bullet runs the fastest way that stays stable: its implicit mode when it moves the cloth, else
// its explicit mode with the fewest substeps (powers of two up to 512) that keep the run finite with a
// stretch below 100 %; the label says which.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "physics/cloth/solver.h"

#ifdef PBA_HAVE_BULLET
#include <BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h>
#include <BulletSoftBody/btDeformableBodySolver.h>
#include <BulletSoftBody/btDeformableMultiBodyConstraintSolver.h>
#include <BulletSoftBody/btDeformableMultiBodyDynamicsWorld.h>
#include <BulletSoftBody/btSoftBodyHelpers.h>
#include <BulletSoftBody/btSoftBodyRigidBodyCollisionConfiguration.h>
#include <btBulletDynamicsCommon.h>
#endif

namespace {
using namespace pba;
using namespace pba::cloth;

constexpr int kFrames = 180;
/// The 64 × 64 rows run the first half second: the fall and the first swing, when the stretch peaks (and
/// Bullet's explicit runs take seconds per frame on the 2-core machine).
constexpr int kGridFrames = 30;
constexpr Real kFrame = 1.0 / 60.0;
constexpr Real kSize = 1.0;       // [m] side of the square cloth
constexpr Real kTotalMass = 0.2;  // [kg] 0.2 kg/m²
/// [N·s/m] 0 in the Bullet comparison: with damping Bullet's "explicit" step solves for the damping
/// implicitly (a Krylov solve per substep), 2.5× slower still; without it both sides integrate springs alone.
constexpr Real kSpringDamping = 0.0;

/// Largest stretch of the axis edges of an nx × ny grid (indices j·nx + i) with spacing h [m].
template <typename PositionOf>
Real axisStretch(int nx, int ny, Real spacingX, Real spacingY, PositionOf&& x) {
  Real worst = 0.0;
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const Vec3 p = x(j * nx + i);
      if (i + 1 < nx) worst = std::max(worst, glm::length(x(j * nx + i + 1) - p) / spacingX - 1.0);
      if (j + 1 < ny) worst = std::max(worst, glm::length(x((j + 1) * nx + i) - p) / spacingY - 1.0);
    }
  }
  return worst;
}

std::string percent(Real strain) {
  char s[32];
  std::snprintf(s, sizeof s, "%.2f %%", 100.0 * strain);
  return s;
}

Cloth squareCloth(int n, Real k, SpringLayout layout) {
  GridDesc d;
  d.resolutionX = d.resolutionY = n;
  d.width = d.height = kSize;
  d.center = Vec3(0.0, 2.0, 0.0);
  d.pins = GridPins::TopCorners;
  d.layout = layout;
  ClothMaterial m;
  m.massPerArea = kTotalMass / (kSize * kSize);
  m.stretchStiffness = m.shearStiffness = m.bendStiffness = k;
  m.springDamping = kSpringDamping;
  return buildClothGrid(d, m).value();
}

/// Implicit Euler (Baraff & Witkin). range(0): k [N/m]; range(1): layout (0 grid, 1 mesh); range(2): steps
/// per frame (1 is the setting; more shrink the stretch one linearised step leaves in a fall).
void BM_ClothImplicit64(benchmark::State& state) {
  const Real k = static_cast<Real>(state.range(0));
  const auto layout = state.range(1) == 0 ? SpringLayout::Grid : SpringLayout::Mesh;
  const int n = 64;
  Cloth c = squareCloth(n, k, layout);
  ClothSolver solver;
  ClothSolverSettings s;
  s.kind = ClothSolverKind::Implicit;
  s.substeps = static_cast<int>(state.range(2));
  const ClothEnvironment env;
  Real t = 0.0, worst = 0.0;
  long cg = 0;
  const Real h = kSize / (n - 1);
  for (auto _ : state) {
    cg += solver.step(c, env, {}, s, kFrame, t).cgIterations;
    t += kFrame;
    state.PauseTiming();
    worst = std::max(worst, axisStretch(n, n, h, h, [&](int i) { return c.position[i]; }));
    state.ResumeTiming();
  }
  state.SetLabel("max stretch " + percent(worst) + ", " + std::to_string(c.springs.size()) + " springs (" +
                 (layout == SpringLayout::Grid ? "Provot grid" : "mesh edges + across-edge") + "), " +
                 std::to_string(s.substeps) + " step(s) per frame, mean CG " +
                 std::to_string(cg / std::max<long>(1, state.iterations())) + " iterations");
}
BENCHMARK(BM_ClothImplicit64)
    ->Args({1000, 0, 1})
    ->Args({1000, 0, 2})
    ->Args({100000, 0, 1})
    ->Args({100000, 0, 4})
    ->Args({1000, 1, 1})
    ->Args({100000, 1, 1})
    ->Iterations(kGridFrames)
    ->Unit(benchmark::kMillisecond);

/// BM_ClothImplicit64's grid with the CG started at v₀ + h a (ImplicitSettings::extrapolatedStart, off by
/// default: it leaves a little more stretch). range(0): k [N/m]; range(1): steps per frame.
void BM_ClothImplicit64ExtrapolatedStart(benchmark::State& state) {
  const int n = 64;
  Cloth c = squareCloth(n, static_cast<Real>(state.range(0)), SpringLayout::Grid);
  ClothSolver solver;
  ClothSolverSettings s;
  s.kind = ClothSolverKind::Implicit;
  s.substeps = static_cast<int>(state.range(1));
  s.implicit.extrapolatedStart = true;
  const ClothEnvironment env;
  Real t = 0.0, worst = 0.0;
  const Real h = kSize / (n - 1);
  for (auto _ : state) {
    solver.step(c, env, {}, s, kFrame, t);
    t += kFrame;
    state.PauseTiming();
    worst = std::max(worst, axisStretch(n, n, h, h, [&](int i) { return c.position[i]; }));
    state.ResumeTiming();
  }
  state.SetLabel("max stretch " + percent(worst) + ", " + std::to_string(s.substeps) + " step(s) per frame");
}
BENCHMARK(BM_ClothImplicit64ExtrapolatedStart)
    ->Args({1000, 2})
    ->Args({100000, 1})
    ->Iterations(kGridFrames)
    ->Unit(benchmark::kMillisecond);

#ifdef PBA_HAVE_BULLET
/// The same cloth in Bullet's deformable world (double precision build).
class BulletCloth {
 public:
  BulletCloth(int n, Real k, bool implicit) : n_(n) {
    world_ = new btDeformableMultiBodyDynamicsWorld(&dispatcher_, &broadphase_, &constraintSolver_, &configuration_,
                                                    &deformableSolver_);
    constraintSolver_.setDeformableSolver(&deformableSolver_);
    const btVector3 g(0.0, -kStandardGravity, 0.0);
    world_->setGravity(g);
    world_->getWorldInfo().m_gravity = g;
    const btScalar s = 0.5 * kSize, y = 2.0;
    // Corners 00 and 10 pinned (fixeds 1 + 2): row 0, like GridPins::TopCorners.
    body_ = btSoftBodyHelpers::CreatePatch(world_->getWorldInfo(), btVector3(-s, y, -s), btVector3(s, y, -s),
                                           btVector3(-s, y, s), btVector3(s, y, s), n, n, 1 + 2, true);
    body_->generateBendingConstraints(2);
    body_->setTotalMass(kTotalMass);
    world_->addSoftBody(body_);
    springs_ = new btDeformableMassSpringForce(k, kSpringDamping, true);
    gravity_ = new btDeformableGravityForce(g);
    world_->addForce(body_, springs_);
    world_->addForce(body_, gravity_);
    world_->setImplicit(implicit);
    world_->setLineSearch(false);
  }
  ~BulletCloth() {
    world_->removeSoftBody(body_);
    delete body_;
    delete springs_;
    delete gravity_;
    delete world_;
  }
  BulletCloth(const BulletCloth&) = delete;
  BulletCloth& operator=(const BulletCloth&) = delete;

  void frame(int substeps) { world_->stepSimulation(kFrame, substeps, kFrame / substeps); }
  Vec3 position(int i) const {
    const btVector3& x = body_->m_nodes[i].m_x;
    return {x.x(), x.y(), x.z()};
  }
  Real stretch() const {
    const Real h = kSize / (n_ - 1);
    return axisStretch(n_, n_, h, h, [&](int i) { return position(i); });
  }
  bool finite() const {
    for (int i = 0; i < body_->m_nodes.size(); ++i) {
      if (!isFinite(position(i))) return false;
    }
    return true;
  }
  int links() const { return body_->m_links.size(); }

 private:
  int n_;
  btSoftBodyRigidBodyCollisionConfiguration configuration_;
  btCollisionDispatcher dispatcher_{&configuration_};
  btDbvtBroadphase broadphase_;
  btDeformableBodySolver deformableSolver_;
  btDeformableMultiBodyConstraintSolver constraintSolver_;
  btDeformableMultiBodyDynamicsWorld* world_ = nullptr;
  btSoftBody* body_ = nullptr;
  btDeformableMassSpringForce* springs_ = nullptr;
  btDeformableGravityForce* gravity_ = nullptr;
};

struct BulletMode {
  bool implicit = false;
  int substeps = 0;  ///< 0: none found
  std::string note;
};

/// Bullet's implicit mode if it moves the pinned cloth; else the fewest explicit substeps that stay stable.
BulletMode fastestStableBulletMode(int n, Real k) {
  {
    BulletCloth implicit(n, k, true);
    const Vec3 start = implicit.position(n * n - 1);
    for (int f = 0; f < 30; ++f) implicit.frame(1);
    const Real moved = glm::length(implicit.position(n * n - 1) - start);
    if (implicit.finite() && moved > 0.05 && implicit.stretch() < 1.0) return {true, 1, "implicit, 1 step per frame"};
    char note[96];
    std::snprintf(note, sizeof note, "implicit mode moved the free corner %.1f mm in 0.5 s", 1000.0 * moved);
    for (int substeps = 1; substeps <= 512; substeps *= 2) {
      BulletCloth trial(n, k, false);
      bool ok = true;
      for (int f = 0; f < 10 && ok; ++f) {
        trial.frame(substeps);
        ok = trial.finite() && trial.stretch() < 1.0;
      }
      if (ok) return {false, substeps, std::string(note) + "; explicit, " + std::to_string(substeps) + " substeps"};
    }
    return {false, 0, std::string(note) + "; explicit unstable up to 512 substeps"};
  }
}

void BM_BulletDeformable64(benchmark::State& state) {
  const Real k = static_cast<Real>(state.range(0));
  const int n = 64;
  const BulletMode mode = fastestStableBulletMode(n, k);
  if (mode.substeps == 0) {
    state.SkipWithError(mode.note.c_str());
    return;
  }
  BulletCloth c(n, k, mode.implicit);
  Real worst = 0.0;
  for (auto _ : state) {
    c.frame(mode.substeps);
    state.PauseTiming();
    worst = std::max(worst, c.stretch());
    state.ResumeTiming();
  }
  state.SetLabel("max stretch " + percent(worst) + ", " + std::to_string(c.links()) + " links; " + mode.note);
}
BENCHMARK(BM_BulletDeformable64)->Arg(1000)->Arg(100000)->Iterations(kGridFrames)->Unit(benchmark::kMillisecond);
#endif

/// XPBD on TMP #15's ribbon (30 × 200, spacing 1 cm, 10 substeps) falling onto the floor with self-collision.
/// range(0): 1 self-collision (the solver's default, the headline), 2 the same sweeping every pair of the frame
/// (the reference, same positions), 0 none.
void BM_XpbdRibbonSelfCollision(benchmark::State& state) {
  GridDesc d;
  d.resolutionX = 30;
  d.resolutionY = 200;
  d.width = 0.29;
  d.height = 1.99;
  d.axisV = Vec3(0.0, -1.0, 0.0);
  d.center = Vec3(0.0, 0.05 + 0.995, 0.0);
  d.pins = GridPins::None;
  d.layout = SpringLayout::Mesh;
  ClothMaterial m;
  m.thickness = 0.01;
  m.bendLinkCompliance = 100.0;
  Cloth c = buildClothGrid(d, m).value();
  for (std::size_t i = 0; i < c.size(); ++i) c.position[i].z += 1e-5 * std::sin(12.9898 * static_cast<Real>(i));
  ClothSolverSettings s;
  s.kind = ClothSolverKind::Xpbd;
  s.substeps = 10;
  s.bending = BendingModel::Distance;
  s.selfCollision = state.range(0) != 0;
  s.selfCollisionSweeps = 4;  // as the lab's scene
  s.selfCollisionNearList = state.range(0) != 2;
  ClothEnvironment env;
  env.massDamping = 0.1;
  const std::vector<Collider> floor{Collider::plane()};
  ClothSolver solver;
  Real t = 0.0;
  for (auto _ : state) {
    solver.step(c, env, floor, s, kFrame, t);
    t += kFrame;
  }
  const char* mode = !s.selfCollision          ? "without self-collision"
                     : s.selfCollisionNearList ? "with self-collision (Verlet list)"
                                               : "with self-collision (TMP: every pair of the frame)";
  state.SetLabel(std::string(mode) + ", max stretch " + percent(edgeStrain(c).max) + " at the end");
}
BENCHMARK(BM_XpbdRibbonSelfCollision)->Arg(1)->Arg(2)->Arg(0)->Iterations(kFrames)->Unit(benchmark::kMillisecond);

/// The comparison scene's cloth (16 × 16, k = 5000 N/m) under each solver. range(0): solver; range(1):
/// substeps (explicit: its stability bound needs them; XPBD: raised until its stretch matches implicit's).
void BM_ComparisonCloth(benchmark::State& state) {
  const auto kind = static_cast<ClothSolverKind>(state.range(0));
  const int n = 16;
  GridDesc d;
  d.resolutionX = d.resolutionY = n;
  d.width = d.height = 0.9;
  d.pins = GridPins::TopCorners;
  ClothMaterial m;
  m.stretchStiffness = m.shearStiffness = 5000.0;
  m.bendStiffness = 20.0;
  m.bendCompliance = 1000.0;
  Cloth c = buildClothGrid(d, m).value();
  ClothSolverSettings s;
  s.kind = kind;
  s.substeps = static_cast<int>(state.range(1));
  ClothEnvironment env;
  env.massDamping = 0.1;
  ClothSolver solver;
  Real t = 0.0, worst = 0.0;
  const Real h = 0.9 / (n - 1);
  for (auto _ : state) {
    solver.step(c, env, {}, s, kFrame, t);
    t += kFrame;
    state.PauseTiming();
    worst = std::max(worst, axisStretch(n, n, h, h, [&](int i) { return c.position[i]; }));
    state.ResumeTiming();
  }
  state.SetLabel(std::string(solverName(kind)) + ", " + std::to_string(s.substeps) + " substeps: max stretch " +
                 percent(worst));
}
BENCHMARK(BM_ComparisonCloth)
    ->Args({static_cast<int>(ClothSolverKind::Explicit), 200})
    ->Args({static_cast<int>(ClothSolverKind::Implicit), 1})
    ->Args({static_cast<int>(ClothSolverKind::Xpbd), 10})
    ->Args({static_cast<int>(ClothSolverKind::Xpbd), 40})
    ->Args({static_cast<int>(ClothSolverKind::Xpbd), 80})
    ->Args({static_cast<int>(ClothSolverKind::Xpbd), 160})
    ->Iterations(kFrames)
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
