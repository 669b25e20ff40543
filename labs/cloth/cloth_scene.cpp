#include "cloth_scene.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "physics/cloth/self_collision.h"

namespace pba::lab {

using namespace pba::cloth;

ClothScene::ClothScene() {
  params_.choiceEnum("solver", &solverKind_, solverNames(),
                     "Switch live: explicit (symplectic Euler on the springs, stable only for small steps), implicit "
                     "(Baraff & Witkin: backward Euler, one Newton step, filtered PCG), pbd (Müller 2006, stiffness "
                     "depends on iterations) or xpbd (Macklin 2016, compliance).");
  params_
      .integer("iterations", &settings_.iterations, 1, 100, "",
               "PBD/XPBD constraint sweeps per substep. Small Steps (Macklin 2019): prefer substeps. Typical 1.")
      .workload();  // 100 sweeps on every scene: 8 s of the extremes check per scene for no new state
  params_
      .integer("substeps", &settings_.substeps, 1, 200, "",
               "Substeps per step (explicit: symplectic Euler steps; pbd/xpbd: predict-solve-update cycles; "
               "implicit: backward Euler steps). Typical 10 for xpbd, 1 for implicit.")
      .workload();  // 200 substeps: 3-6 s per scene in the extremes check, the most stable setting
  params_
      .flag("explicit_stable_substeps", &stableExplicit_,
            "Explicit: take more substeps where symplectic Euler needs them, each at most half its stability "
            "limit 2/ω_max (explicit_limit_s in the metrics; ours). Off: exactly the substeps asked, and above the "
            "limit the cloth blows up (the 'boom' preset).")
      .shownWhen([this] { return solverKind_ == ClothSolverKind::Explicit; });
  params_
      .flag("long_range_attachments", &longRange_,
            "PBD/XPBD with compliance 0: no particle gets farther from a pin than at rest (Kim et al. 2012). Off: the "
            "edges at the pins stretch by tens of per cent, since one sweep cannot carry the weight up to them.")
      .shownWhen([this] { return solverKind_ == ClothSolverKind::Pbd || solverKind_ == ClothSolverKind::Xpbd; });
  params_
      .real("stiffness", &stiffness_, 1.0, 1e6, "N/m",
            "Stretch and shear spring constant of the mass-spring model (explicit, implicit). Typical 10³–10⁵.")
      .logarithmic();
  params_.real("bend_stiffness", &bendStiffness_, 0.0, 1e5, "N/m",
               "Bend springs (skip one particle) of the mass-spring model. Typical 1–100.");
  params_.real("spring_damping", &springDamping_, 0.0, 10.0, "N·s/m",
               "Damping along every spring (resists the rate of stretch). Typical 0.02.");
  params_
      .real("cg_tolerance", &settings_.implicit.cg.tolerance, 1e-12, 0.5, "",
            "Implicit: relative residual (preconditioned norm) at which the conjugate gradient stops. Typical 10⁻³.")
      .logarithmic()
      .shownWhen([this] { return solverKind_ == ClothSolverKind::Implicit; });
  params_
      .integer("cg_max_iterations", &settings_.implicit.cg.maxIterations, 1, 10000, "",
               "Implicit: at most this many conjugate-gradient iterations per step. Typical 500.")
      .shownWhen([this] { return solverKind_ == ClothSolverKind::Implicit; });
  params_
      .real("max_strain_growth", &settings_.implicit.maxStrainGrowth, 0.0, 1.0, "",
            "Implicit: a step in which some stretch or shear spring's strain grows by more than this is retried as "
            "two half steps "
            "(step control as in Baraff & Witkin's simulator; 0 = off). Typical 0.1.")
      .shownWhen([this] { return solverKind_ == ClothSolverKind::Implicit; });
  params_
      .flag("speculative_contacts", &settings_.implicit.speculativeContacts,
            "Implicit: also constrain particles that would reach a collider within the step, so that they land on "
            "it inside the solve (our addition to Baraff & Witkin; off: only touching particles).")
      .shownWhen([this] { return solverKind_ == ClothSolverKind::Implicit; });
  params_
      .flag("static_friction", &settings_.implicit.staticFriction,
            "Implicit: a contact that friction stopped is held to the collider inside the next solve, so its "
            "springs see it hold (off: friction only after the solve, which makes stiff cloth jitter).")
      .shownWhen([this] { return solverKind_ == ClothSolverKind::Implicit; });
  params_
      .real("compliance", &compliance_, 0.0, 1e-2, "m/N",
            "XPBD compliance α = 1/k of the stretch and shear constraints: 0 is inextensible. Independent of "
            "iterations and substeps, unlike PBD's stiffness. Typical 0–10⁻⁴.")
      .logarithmic();
  params_.choiceEnum(
      "bending", &settings_.bending, kBendingModelNames,
      "Bending of pbd/xpbd: isometric (Bergou 2006, one linear constraint per inner edge, CLOTH-6), distance "
      "(TMP #14–15: opposite vertices of each inner edge keep their rest distance) or none.");
  params_
      .real("bend_compliance", &bendCompliance_, 0.0, 1e4, "1/(N·m)",
            "XPBD compliance of isometric bending (Bergou 2006): larger is floppier. Typical 1–100.")
      .logarithmic()
      .shownWhen([this] { return settings_.bending == BendingModel::Isometric; });
  params_
      .real("bend_link_compliance", &bendLinkCompliance_, 0.0, 100.0, "m/N",
            "XPBD compliance of the distance bending links (TMP uses 1). Larger is floppier.")
      .logarithmic()
      .shownWhen([this] { return settings_.bending == BendingModel::Distance; });
  params_.real("damping", &damping_, 0.0, 10.0, "1/s",
               "Velocity damping c: force −c m v (mass-spring) or v ← v e^(−c h) (pbd/xpbd). Typical 0.1.");
  params_.real("thickness", &thickness_, 0.001, 0.1, "m",
               "Particles keep this distance from each other (self-collision) and half of it from colliders.");
  params_.integer("resolution", &resolution_, 2, 256, "", "Particles along the cloth's first side. Typical 32.")
      .needsReset()
      .workload();  // 65,536 particles: 10 s of the extremes check per scene
  params_
      .choiceEnum("layout", &layout_, kSpringLayoutNames,
                  "Springs of the mass-spring model: grid (Provot: axis neighbours, both diagonals, skip-one; "
                  "CLOTH-1) or mesh (every edge, and across every inner edge).")
      .needsReset();
  params_.real("gravity", &gravity_, 0.0, 30.0, "m/s²", "Gravitational acceleration. Earth 9.81.");
  params_.real("friction", &friction_, 0.0, 2.0, "", "Coulomb friction μ of every collider. Typical 0.4.");
  params_.flag("self_collision", &settings_.selfCollision,
               "Particle–particle self-collision (Ten Minute Physics #15, dense spatial hash).");
  params_
      .integer("self_sweeps", &settings_.selfCollisionSweeps, 1, 10, "",
               "Self-collision sweeps per substep (TMP: 1). Each further one follows the colliders and revisits the "
               "pairs in "
               "contact: piles of many layers stay a thickness apart.")
      .shownWhen([this] { return settings_.selfCollision; });
  params_.flag("tearing", &settings_.tearing.enabled, "Edges stretched beyond tear_threshold split the cloth.");
  params_
      .real("tear_threshold", &settings_.tearing.threshold, 0.05, 5.0, "",
            "Strain (l − L)/L at which an edge tears. Typical 0.5.")
      .shownWhen([this] { return settings_.tearing.enabled; });
}

void ClothScene::declareDisplayParams() {
  params_.choiceEnum("pattern", &pattern_, kPatternNames, "Fabric pattern: folds read on a projector.");
  params_.flag("strain_colors", &strainColors_,
               "Colour triangles by strain: blue < 0.5 %, green, yellow, orange, red ≥ 10 %.");
  params_.flag("wireframe", &wireframe_, "Draw the mesh edges.");
  params_.flag("show_links", &showLinks_, "Draw the springs (explicit, implicit) or constraints (pbd, xpbd).");
}

void ClothScene::applyParams() {
  settings_.kind = solverKind_;
  settings_.explicitLimitFraction = stableExplicit_ ? 0.5 : 0.0;
  settings_.longRangeAttachments = longRange_ && compliance_ == 0.0;  // a compliant cloth may stretch
  material_.stretchStiffness = material_.shearStiffness = stiffness_;
  material_.bendStiffness = bendStiffness_;
  material_.springDamping = springDamping_;
  material_.stretchCompliance = material_.shearCompliance = compliance_;
  material_.bendCompliance = bendCompliance_;
  material_.bendLinkCompliance = bendLinkCompliance_;
  material_.thickness = thickness_;
  cloth_.material = material_;
  env_.gravity = Vec3(0.0, -gravity_, 0.0);
  env_.massDamping = damping_;
  for (Collider& c : colliders_) c.friction = friction_;
}

GridDesc ClothScene::squareGrid(Real side, const Vec3& center, GridPins pins) const {
  GridDesc g;
  g.layout = layout_;
  g.resolutionX = g.resolutionY = resolution_;
  g.width = g.height = side;
  g.center = center;
  g.pins = pins;
  return g;
}

GridDesc ClothScene::hangingGrid(int nx, int ny, Real width, Real height, const Vec3& center, GridPins pins) const {
  GridDesc g;
  g.layout = layout_;
  g.resolutionX = nx;
  g.resolutionY = ny;
  g.width = width;
  g.height = height;
  g.axisU = Vec3(1.0, 0.0, 0.0);
  g.axisV = Vec3(0.0, -1.0, 0.0);
  g.center = center;
  g.pins = pins;
  return g;
}

void ClothScene::reset() {
  colliders_.clear();
  applyParams();
  Result<Cloth> built = build();
  if (!built) {
    // Parameters were validated; a failure here is a bad mesh file: keep the previous cloth.
    buildError_ = built.error();
  } else {
    buildError_.clear();
    cloth_ = std::move(built).value();
  }
  if (const Status s = checkColliders(colliders_); !s) {  // a mesh: no point query
    buildError_ = s.error();
    colliders_.clear();
  }
  applyParams();
  solver_.reset();
  initialEnergy_ = clothEnergy(cloth_, env_, settings_.kind, settings_.bending);
  time_ = 0.0;
  stats_ = {};
  worstColliderDistance_ = std::numeric_limits<Real>::infinity();
  selfIntersections_ = worstSelfIntersections_ = 0;
  dragged_ = -1;
  draggedWasPinned_.reset();
}

void ClothScene::step(Real dt) {
  applyParams();
  beforeStep(dt, time_);
  const auto start = std::chrono::steady_clock::now();
  stats_ = solver_.step(cloth_, env_, colliders_, settings_, dt, time_);
  solverMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  time_ += dt;
  if (!colliders_.empty()) {
    worstColliderDistance_ =
        std::min(worstColliderDistance_, minColliderDistance(colliders_, cloth_.position, 0.5 * thickness_));
  }
  if (countIntersections_) {
    selfIntersections_ = countSelfIntersections(cloth_.position, cloth_.restPosition, thickness_, hash_);
    worstSelfIntersections_ = std::max(worstSelfIntersections_, selfIntersections_);
  }
}

std::optional<Real> ClothScene::energyGainBound(Real reference) const {
  // Implicit Euler with one Newton step and an inexact CG shows transient elastic energy where stiff
  // springs meet a pin or a collider (a spike for a frame, then it settles): not a runaway, so only the
  // guard's factor of 100 applies to it.
  if (settings_.kind == ClothSolverKind::Implicit) return std::nullopt;
  const std::optional<Real> slack = Scene::energyGainBound(reference);
  const Real v = driveSpeed();
  if (v <= 0.0 || cloth_.size() == 0) return slack;
  Real mass = 0.0;
  Vec3 lo = cloth_.restPosition.front(), hi = lo;
  for (std::size_t i = 0; i < cloth_.size(); ++i) {
    if (cloth_.inverseMass[i] > 0.0) mass += 1.0 / cloth_.inverseMass[i];
    lo = glm::min(lo, cloth_.restPosition[i]);
    hi = glm::max(hi, cloth_.restPosition[i]);
  }
  return *slack + 2.0 * mass * v * v + mass * gravity_ * glm::length(hi - lo);
}

std::optional<std::string> ClothScene::divergedState() const {
  if (!stats_.diverged) return std::nullopt;
  return "the " + std::string(solverName(settings_.kind)) + " solver diverged (a particle passed " +
         std::to_string(static_cast<int>(settings_.divergedSpeed)) + " m/s after " +
         std::to_string(stats_.substepsTaken) + " of " + std::to_string(stats_.substepsPlanned) + " substeps)";
}

nlohmann::json ClothScene::clothMetrics(const Cloth& c, const ClothStepStats& stats, ClothSolverKind kind) const {
  const StrainStats strain = edgeStrain(c);
  nlohmann::json j{{"particles", c.size()},
                   {"triangles", c.triangles.size()},
                   {"solver", std::string(solverName(kind))},
                   {"max_strain", strain.max},
                   {"mean_strain", strain.mean},
                   {"max_compression", strain.maxCompression},
                   {"energy_J", clothEnergy(c, env_, kind, settings_.bending)},
                   {"energy_drift", (clothEnergy(c, env_, kind, settings_.bending) - initialEnergy_) /
                                        std::max(std::abs(initialEnergy_), 1e-9)},
                   {"mesh_valid", checkMeshConsistency(c).empty()},
                   {"cg_iterations", stats.cgIterations},
                   {"cg_residual", stats.cgResidual},
                   {"implicit_retries", stats.implicitRetries},
                   {"constraint_iterations", stats.constraintIterations},
                   {"contacts", stats.contacts},
                   {"torn", c.torn}};
  if (!colliders_.empty()) j["min_collider_distance_m"] = minColliderDistance(colliders_, c.position, 0.5 * thickness_);
  if (usesSprings(kind) && !c.springs.empty()) j["explicit_limit_s"] = explicitStabilityLimit(c);
  return j;
}

nlohmann::json ClothScene::metrics() const {
  nlohmann::json j = clothMetrics(cloth_, stats_, settings_.kind);
  j["step_ms"] = solverMs_;
  j["self_intersections"] = countIntersections_
                                ? selfIntersections_
                                : countSelfIntersections(cloth_.position, cloth_.restPosition, thickness_, hash_);
  if (countIntersections_) j["self_intersections_max"] = worstSelfIntersections_;
  if (std::isfinite(worstColliderDistance_)) j["worst_collider_distance_m"] = worstColliderDistance_;
  j["self_contacts"] = stats_.selfContacts;
  if (!buildError_.empty()) j["error"] = buildError_;
  return j;
}

std::vector<app::Preset> ClothScene::presets() const {
  return {{"xpbd", {{"solver", "xpbd"}, {"substeps", 10}, {"iterations", 1}}},
          {"pbd", {{"solver", "pbd"}, {"substeps", 1}, {"iterations", 10}}},
          {"implicit", {{"solver", "implicit"}, {"substeps", 1}}},
          {"explicit", {{"solver", "explicit"}, {"substeps", 200}}},
          {"implicit k=1e5", {{"solver", "implicit"}, {"substeps", 1}, {"stiffness", 1e5}}},
          {"explicit k=1e5: boom",
           {{"solver", "explicit"}, {"substeps", 1}, {"stiffness", 1e5}, {"explicit_stable_substeps", false}}},
          {"xpbd stretchy", {{"solver", "xpbd"}, {"compliance", 1e-3}}},
          {"xpbd 1x10 (iterations)", {{"solver", "xpbd"}, {"substeps", 1}, {"iterations", 10}}}};
}

// ----- picking and dragging -----

namespace {
/// Möller–Trumbore: distance along the ray to triangle (a, b, c), if it is hit.
std::optional<Real> rayTriangle(const app::Ray& ray, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 e1 = b - a, e2 = c - a;
  const Vec3 p = glm::cross(ray.direction, e2);
  const Real det = glm::dot(e1, p);
  if (std::abs(det) < 1e-14) return std::nullopt;
  const Vec3 s = ray.origin - a;
  const Real u = glm::dot(s, p) / det;
  if (u < 0.0 || u > 1.0) return std::nullopt;
  const Vec3 q = glm::cross(s, e1);
  const Real v = glm::dot(ray.direction, q) / det;
  if (v < 0.0 || u + v > 1.0) return std::nullopt;
  const Real t = glm::dot(e2, q) / det;
  return t >= 0.0 ? std::optional<Real>(t) : std::nullopt;
}
}  // namespace

std::optional<app::PickHit> ClothScene::pick(const app::Ray& ray) const {
  // The front-most triangle the ray hits, then the particle nearest to the ray among those no deeper than
  // that hit plus one edge length: at grazing views the vertex nearest to the hit point can be a
  // neighbour of the one under the cursor, the one nearest to the ray is not.
  std::optional<Real> front;
  for (const Triangle& tri : cloth_.triangles) {
    const std::optional<Real> t =
        rayTriangle(ray, cloth_.position[tri[0]], cloth_.position[tri[1]], cloth_.position[tri[2]]);
    if (t && (!front || *t < *front)) front = t;
  }
  if (!front) return std::nullopt;
  Real spacing = std::numeric_limits<Real>::max();
  for (const Link& l : cloth_.constraints) spacing = std::min(spacing, l.restLength);
  std::optional<app::PickHit> best;
  Real bestOffset = std::numeric_limits<Real>::max();
  for (std::size_t i = 0; i < cloth_.size(); ++i) {
    const Real t = glm::dot(cloth_.position[i] - ray.origin, ray.direction);
    if (t < 0.0 || t > *front + spacing) continue;
    const Real offset = glm::length(cloth_.position[i] - pointAt(ray, t));
    if (offset < bestOffset) {
      bestOffset = offset;
      best = app::PickHit{static_cast<int>(i), t, cloth_.position[i]};
    }
  }
  return best;
}

void ClothScene::drag(int handle, const Vec3& target) {
  if (handle < 0 || static_cast<std::size_t>(handle) >= cloth_.size()) return;
  const auto i = static_cast<std::uint32_t>(handle);
  if (dragged_ != handle) {
    if (dragged_ >= 0) release(dragged_);
    dragged_ = handle;
    const Pin* p = findPin(cloth_, i);
    draggedWasPinned_ = p ? std::optional<Pin>(*p) : std::nullopt;
  }
  pin(cloth_, i, target);       // kinematic while held: every solver moves it onto the cursor
  cloth_.position[i] = target;  // at once, so that a paused scene shows it
  cloth_.velocity[i] = Vec3(0.0);
}

void ClothScene::release(int handle) {
  if (handle != dragged_ || handle < 0 || static_cast<std::size_t>(handle) >= cloth_.size()) return;
  const auto i = static_cast<std::uint32_t>(handle);
  if (draggedWasPinned_) {
    pin(cloth_, i, draggedWasPinned_->target);
  } else {
    unpin(cloth_, i);
  }
  dragged_ = -1;
  draggedWasPinned_.reset();
}

std::vector<app::DragHandle> ClothScene::dragHandles() const {
  std::vector<app::DragHandle> handles;
  const std::size_t stride = std::max<std::size_t>(1, cloth_.size() / 25);
  for (std::size_t i = stride / 2; i < cloth_.size(); i += stride) {
    // Free particles, and the one being dragged (held as a pin while the mouse holds it).
    if (cloth_.inverseMass[i] > 0.0 || static_cast<int>(i) == dragged_) {
      handles.push_back({static_cast<int>(i), cloth_.position[i]});
    }
  }
  if (dragged_ >= 0 && (static_cast<std::size_t>(dragged_) - stride / 2) % stride != 0) {
    handles.push_back({dragged_, cloth_.position[static_cast<std::size_t>(dragged_)]});
  }
  return handles;
}

std::vector<app::LegendEntry> ClothScene::legend() const {
  std::vector<app::LegendEntry> entries;
  if (strainColors_) {
    entries = {{colors::kBlue, "stretch < 0.5 %"},
               {colors::kGreen, "< 2 %"},
               {colors::kYellow, "< 5 %"},
               {colors::kOrange, "< 10 %"},
               {colors::kRed, "≥ 10 %"}};
  }
  entries.push_back({colors::kRed, "pinned particle"});
  entries.push_back({colors::kYellow, "the particle being dragged"});
  if (showLinks_) {
    entries.push_back({colors::kBlue, "stretch links"});
    entries.push_back({colors::kGreen, "shear links"});
    entries.push_back({colors::kOrange, "bend links"});
  }
  return entries;
}

bool ClothScene::nudge(const Vec3& delta) {
  if (dragged_ < 0) return false;
  Pin* p = findPin(cloth_, static_cast<std::uint32_t>(dragged_));
  if (p) p->target += delta;
  return p != nullptr;
}

}  // namespace pba::lab
