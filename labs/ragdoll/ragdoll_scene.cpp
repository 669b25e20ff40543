#include "ragdoll_scene.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "physics/core/format.h"

namespace pba::lab {

namespace {
const Color kParticleColor = colors::kBlue;
// Purple, not red: lecture mode keeps red for danger (a violated limit, the guard).
const Color kConstraintColor = colors::kPurple;

double msSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}
}  // namespace

RagdollScene::RagdollScene() {
  ragdoll::ParticleSettings& p = particleSettings_;
  rigid::WorldSettings& w = constraintSettings_.world;
  params_.choiceEnum("show", &shown_, kShownNames,
                     "Draw both methods side by side (particle blue, left; constraint purple, right) or one of them.");
  params_.real("gravity", &gravity_, 0.0, 30.0, "m/s²", "Gravitational acceleration (downwards). Earth 9.81.");
  params_.integer(
      "iterations", &p.iterations, 1, 50, "",
      "Particle method: relaxation and projection passes per step (paper test 3 compares 2, 5 and 20). Typical 20.");
  params_.real("particle_friction", &p.friction, 0.0, 1.0, "",
               "Particle method: share of a touching particle's sliding step removed each step (old position moved "
               "towards the current one). Typical 0.5.");
  params_.flag("broad_phase", &p.broadPhase,
               "Particle method: sweep and prune over bone boxes. Off: every unjointed pair, as the paper did.");
  params_.flag("bone_collisions", &p.boneCollisions,
               "Particle method: boxes of unjointed bones collide with each other.");
  params_.integer("substeps", &w.substeps, 1, 16, "",
                  "Constraint method: substeps of the rigid world's soft step. Typical 4.");
  params_.integer("constraint_iterations", &w.iterations, 1, 20, "",
                  "Constraint method: velocity iterations per substep. Typical 1.");
  params_
      .real("joint_hertz", &w.jointHertz, 5.0, 240.0, "Hz",
            "Constraint method: stiffness of the soft joints and limits. Typical 60 Hz.")
      .logarithmic();
  params_
      .real("friction", &friction_, 0.0, 1.5, "",
            "Constraint method: Coulomb friction coefficient μ of the boxes and the ground. Typical 0.5.")
      .needsReset();
  params_.flag("show_particles", &draw_.particles, "Draw the particles and sticks of the particle ragdoll.");
  params_.flag("show_joints", &draw_.joints, "Draw joint points, hinge axes, limit arcs and cones.");
  params_.flag("show_contacts", &draw_.contacts, "Draw contact points and normals.");
}

void RagdollScene::declareStartParams(Real& dropHeight, Real& tilt) {
  params_
      .real("drop_height", &dropHeight, 0.0, 5.0, "m",
            "Height of the figure's lowest point above the ground at the start. Typical " + formatShort(dropHeight) +
                " m.")
      .needsReset();
  params_
      .angle("tilt", &tilt, -90.0, 90.0,
             "Forward tilt of the figure at the start (90°: lying face down). Typical " + formatShort(radToDeg(tilt)) +
                 "°.")
      .needsReset();
}

Real RagdollScene::lowestCorner(const ragdoll::RagdollDesc& desc) {
  Real lo = 1e300;
  for (const ragdoll::BoneDesc& b : desc.bones)
    for (int i = 0; i < 8; ++i) {
      const Vec3 h = b.halfExtents;
      lo =
          std::min(lo, (b.center + b.orientation * Vec3(i & 1 ? h.x : -h.x, i & 2 ? h.y : -h.y, i & 4 ? h.z : -h.z)).y);
    }
  return lo;
}

const Color& RagdollScene::particleColor() { return kParticleColor; }
const Color& RagdollScene::constraintColor() { return kConstraintColor; }

Real RagdollScene::halfSeparation(const ragdoll::RagdollDesc& desc) const {
  Real lo = 1e30, hi = -1e30;
  for (const ragdoll::BoneDesc& b : desc.bones) {
    const Real r = glm::length(b.halfExtents);
    lo = std::min(lo, b.center.x - r), hi = std::max(hi, b.center.x + r);
  }
  return 0.5 * (hi - lo) + 0.4;
}

std::optional<app::CameraView> RagdollScene::preferredView() const {
  const ragdoll::RagdollDesc desc = build();
  const Real half = halfSeparation(desc);
  Vec3 lo(1e30), hi(-1e30);
  for (const ragdoll::BoneDesc& b : desc.bones) {
    const Vec3 r(glm::length(b.halfExtents));
    lo = glm::min(lo, b.center - r), hi = glm::max(hi, b.center + r);
  }
  lo.x -= half, hi.x += half;
  lo.y = std::min(lo.y, 0.0);
  const Vec3 size = hi - lo;
  const Real extent = std::max({size.x, 1.6 * size.y, 1.0});
  return app::CameraView{0.5 * (lo + hi), 1.05 * extent, 0.0, 0.3};
}

void RagdollScene::reset() { start(build()); }

void RagdollScene::start(const ragdoll::RagdollDesc& desc, Real half) {
  if (half < 0.0) half = halfSeparation(desc);
  const Vec3 g(0.0, -gravity_, 0.0);
  particleSettings_.gravity = g;
  constraintSettings_.world.gravity = g;
  ragdoll::RagdollDesc left = ragdoll::translated(desc, Vec3(-half, 0.0, 0.0));
  ragdoll::RagdollDesc right = ragdoll::translated(desc, Vec3(half, 0.0, 0.0));
  right.friction = friction_;
  particle_ = ragdoll::ParticleRagdoll::build(left, particleSettings_).value();
  constraint_ = ragdoll::ConstraintRagdoll::build(right, constraintSettings_).value();
  restBound_ = 0.5 * ragdoll::totalMass(desc) * 0.05 * 0.05;
  particleRest_ = constraintRest_ = Rest{};
  particleMs_ = constraintMs_ = 0.0;
  dragStarted_ = false;
  stepped_ = false;
  startEnergy_ = *energy();
}

void RagdollScene::updateRest(Rest& rest, Real kinetic, Real dt) const {
  rest.quietFor = kinetic < restBound_ ? rest.quietFor + dt : 0.0;
}

void RagdollScene::step(Real dt) {
  const Vec3 g(0.0, -gravity_, 0.0);
  particleSettings_.gravity = g;
  particle_.settings() = particleSettings_;
  constraintSettings_.world.gravity = g;
  constraint_.world().settings() = constraintSettings_.world;
  auto start = std::chrono::steady_clock::now();
  particle_.step(dt);
  stepped_ = true;
  particleMs_ = msSince(start);
  start = std::chrono::steady_clock::now();
  constraint_.step(dt);
  constraintMs_ = msSince(start);
  updateRest(particleRest_, particle_.stats().kineticEnergy, dt);
  updateRest(constraintRest_, constraint_.stats().kineticEnergy, dt);
}

void RagdollScene::draw(DebugDraw& d) const {
  if (shown_ != Shown::Constraint) particle_.draw(d, draw_, kParticleColor);
  if (shown_ != Shown::Particle) {
    rigid::WorldDrawOptions o;
    o.contacts = draw_.contacts;
    o.joints = false;
    o.greySleeping = false;
    // The world draws each body in its own colour: the bones are red, fixed ones grey.
    const rigid::World& w = constraint_.world();
    for (int i = 0; i < w.bodyCount(); ++i) {
      const rigid::Body& b = w.body(i);
      if (b.shape.kind != collision::ShapeKind::Box) continue;
      d.box(b.position, b.shape.halfExtents, b.orientation, b.isDynamic() ? kConstraintColor : colors::kGrey);
    }
    o.shapes = false;
    w.draw(d, o);
    if (draw_.joints) constraint_.drawJoints(d);
  }
}

nlohmann::json RagdollScene::metrics() const {
  const ragdoll::ParticleStats p = particle_.stats();
  const ragdoll::ConstraintStats c = constraint_.stats();
  nlohmann::json j = {{"particle_kinetic_energy_J", p.kineticEnergy},
                      {"particle_max_joint_error_m", p.maxJointError},
                      {"particle_max_limit_violation_deg", radToDeg(p.maxLimitViolation)},
                      {"particle_max_penetration_m", p.maxPenetration},
                      {"particle_max_stick_strain", p.maxStickStrain},
                      {"particle_resting", particleRest_.resting()},
                      {"particle_bones", p.bones},
                      {"particle_particles", p.particles},
                      {"particle_constraints", p.constraints},
                      {"particle_contacts", p.contacts},
                      {"particle_step_ms", particleMs_},
                      {"constraint_kinetic_energy_J", c.kineticEnergy},
                      {"constraint_max_joint_error_m", c.maxJointError},
                      {"constraint_max_limit_violation_deg", radToDeg(c.maxLimitViolation)},
                      {"constraint_max_penetration_m", c.maxPenetration},
                      {"constraint_resting", constraintRest_.resting()},
                      {"constraint_bones", c.bones},
                      {"constraint_particles", 0},
                      {"constraint_constraints", c.constraints},
                      {"constraint_contacts", c.contacts},
                      {"constraint_step_ms", constraintMs_},
                      {"rest_bound_J", restBound_}};
  extraMetrics(j);
  return j;
}

std::optional<std::string> RagdollScene::nonFiniteState() const {
  if (std::optional<std::string> s = particle_.nonFiniteState()) return "particle ragdoll: " + *s;
  if (std::optional<std::string> s = constraint_.world().nonFiniteState()) return "constraint ragdoll: " + *s;
  return std::nullopt;
}

std::optional<Real> RagdollScene::energy() const {
  const ragdoll::ParticleStats p = particle_.stats();
  const ragdoll::ConstraintStats c = constraint_.stats();
  // Before its first step the particle ragdoll's velocities are implicit in nothing yet (Verlet); both
  // ragdolls start with the description's velocities and the same mass distribution, so the constraint
  // ragdoll's kinetic energy is also the particle ragdoll's.
  const Real particleKinetic = stepped_ ? p.kineticEnergy : c.kineticEnergy;
  return particleKinetic + p.potentialEnergy + c.kineticEnergy + c.potentialEnergy;
}

std::optional<Real> RagdollScene::energyGainBound(Real reference) const {
  const Real base = std::max(startEnergy_, reference);
  return base + app::kPassiveEnergySlack * std::max(std::abs(base), app::kMinEnergyScale) - reference;
}

std::vector<app::Preset> RagdollScene::presets() const {
  return {{"2 iterations", {{"iterations", 2}}},
          {"5 iterations", {{"iterations", 5}}},
          {"20 iterations", {{"iterations", 20}}},
          {"particle only, particles shown", {{"show", "particle"}, {"show_particles", true}}},
          {"constraint only", {{"show", "constraint"}}},
          {"no broad phase (the paper's cost)", {{"broad_phase", false}}},
          {"no friction", {{"particle_friction", 0.0}, {"friction", 0.0}}},
          {"stiff constraint joints (120 Hz)", {{"joint_hertz", 120.0}}},
          {"moon gravity", {{"gravity", 1.62}}}};
}

std::vector<app::LegendEntry> RagdollScene::legend() const {
  return {{kParticleColor, "particle ragdoll (Verlet, tetrahedra), left"},
          {kConstraintColor, "constraint ragdoll (rigid bodies, joints), right"},
          {colors::kOrange, "hinge axes, limit arcs and cones"},
          {colors::kYellow, "joint points"}};
}

std::optional<app::PickHit> RagdollScene::pick(const Ray& ray) const {
  std::optional<app::PickHit> best;
  if (shown_ != Shown::Constraint)
    if (const auto hit = particle_.rayCast(ray, 1e4))
      best = app::PickHit{hit->first, hit->second, pointAt(ray, hit->second)};
  if (shown_ != Shown::Particle)
    if (const auto hit = constraint_.world().rayCast(ray, 1e4, true); hit && (!best || hit->hit.t < best->distance))
      best = app::PickHit{kConstraintHandle + hit->body, hit->hit.t, hit->hit.point};
  return best;
}

void RagdollScene::drag(int handle, const Vec3& target) {
  ragdoll::ConstraintRagdoll& c = constraint_;
  if (!dragStarted_) {
    if (handle >= kConstraintHandle)
      c.world().beginDrag(handle - kConstraintHandle, target);
    else
      particle_.beginDrag(handle, target);
    dragStarted_ = true;
    return;
  }
  if (handle >= kConstraintHandle)
    c.world().dragTo(target);
  else
    particle_.dragTo(target);
}

void RagdollScene::release(int /*handle*/) {
  particle_.endDrag();
  constraint_.world().endDrag();
  dragStarted_ = false;
}

void RagdollScene::refresh() {
  particle_.placeDragged();
  constraint_.world().placeDragged();
}

std::vector<app::DragHandle> RagdollScene::dragHandles() const {
  constexpr std::size_t kPerMethod = 4;
  std::vector<app::DragHandle> out;
  if (shown_ != Shown::Constraint) {
    std::vector<app::DragHandle> bones;
    for (int b = 0; b < particle_.boneCount(); ++b)
      if (!particle_.isFixed(b)) bones.push_back({b, particle_.boneFrame(b).position});
    std::sort(bones.begin(), bones.end(), [](const auto& a, const auto& b) { return a.position.y > b.position.y; });
    const int d = particle_.draggedBone();
    for (std::size_t i = 0; i < bones.size(); ++i)
      if (i < kPerMethod || bones[i].handle == d) out.push_back(bones[i]);
  }
  if (shown_ != Shown::Particle) {
    const rigid::World& w = constraint_.world();
    std::vector<app::DragHandle> bodies;
    for (int i = 0; i < w.bodyCount(); ++i)
      if (w.body(i).isDynamic()) bodies.push_back({kConstraintHandle + i, w.body(i).position});
    std::sort(bodies.begin(), bodies.end(), [](const auto& a, const auto& b) { return a.position.y > b.position.y; });
    const int d = kConstraintHandle + w.draggedBody();
    for (std::size_t i = 0; i < bodies.size(); ++i)
      if (i < kPerMethod || bodies[i].handle == d) out.push_back(bodies[i]);
  }
  return out;
}

}  // namespace pba::lab
