#include "world_scene.h"

#include <algorithm>
#include <cmath>

namespace pba::lab {

WorldScene::WorldScene(bool withShooting) : shooting_(withShooting) {
  rigid::WorldSettings& s = settings_;
  params_.real("gravity", &gravity_, 0.0, 30.0, "m/s²", "Gravitational acceleration (downwards). Earth 9.81.");
  params_.integer("solver_substeps", &s.substeps, 1, 16, "",
                  "Substeps per step (Box2D v3 soft step): each integrates, solves and relaxes. Typical 4.");
  params_.integer("iterations", &s.iterations, 1, 50, "",
                  "Velocity iterations per substep, with bias. Typical 1 (soft step) or 10 (Baumgarte, one substep).");
  params_.integer(
      "relax_iterations", &s.relaxIterations, 0, 10, "",
      "Iterations per substep without bias after the position update (removes the push-out velocity). Typical 1.");
  params_.flag("warm_starting", &s.warmStarting,
               "Start each step from last step's impulses (matched by feature id). Off: stacks sag and jitter.");
  params_.choiceEnum(
      "correction", &s.positionCorrection, rigid::positionCorrectionNames(),
      "Penetration removal: soft (spring of contact_hertz, Box2D v3), baumgarte (β/h × depth beyond the slop), none.");
  params_.choiceEnum("friction_model", &s.friction, rigid::frictionModelNames(),
                     "Coulomb friction as a cone (|λ_t| ≤ μλ_n) or a pyramid (each tangent ≤ μλ_n).");
  params_.choiceEnum("gyroscopic", &s.gyroscopic, rigid::gyroscopicModeNames(),
                     "Gyroscopic term ω × Iω: off (ω constant in free flight), implicit (Catto GDC 2015), midpoint "
                     "(conserves L and energy).");
  params_
      .real("contact_hertz", &s.contactHertz, 1.0, 240.0, "Hz",
            "Stiffness of soft contacts (capped at a quarter of the substep rate). Typical 30 Hz.")
      .logarithmic();
  params_.real("contact_damping", &s.contactDampingRatio, 0.0, 20.0, "",
               "Damping ratio of soft contacts. Typical 10 (no bounce).");
  params_.real("baumgarte", &s.baumgarte, 0.0, 1.0, "",
               "β of the Baumgarte bias: share of the penetration removed per step. Typical 0.2.");
  params_.real("restitution_threshold", &s.restitutionThreshold, 0.0, 10.0, "m/s",
               "Impacts slower than this do not bounce. Typical 1 m/s.");
  params_.choiceEnum("broad_phase", &s.broadPhase, collision::broadPhaseNames(),
                     "Pair finding: dynamic AABB tree, sweep and prune, or brute force (all pairs; the reference).");
  params_.flag("sleeping", &s.sleeping, "Islands of bodies at rest for 0.5 s sleep (grey) until touched.");
  params_.flag("continuous", &s.continuous, "Time of impact against static bodies for fast bodies (no tunnelling).");
  params_.flag("show_contacts", &drawOptions_.contacts,
               "Draw contact points (red: touching, grey: speculative) and normals (yellow).");
  params_.flag("show_impulses", &drawOptions_.impulses, "Draw normal impulses as orange arrows.");
  params_.flag("show_aabb_tree", &drawOptions_.aabbTree, "Draw the broad phase's AABB tree.");
  params_.flag("show_frames", &drawOptions_.frames, "Draw each body's frame (x red, y green, z blue).");
  if (shooting_)
    params_.real("shot_speed", &shotSpeed_, 1.0, 100.0, "m/s",
                 "Speed of the ball shot by clicking where no body is. Typical 15 m/s.");
}

void WorldScene::reset() {
  settings_.gravity = Vec3(0.0, -gravity_, 0.0);
  world_ = rigid::World(settings_);
  dragStarted_ = false;
  build(world_);
}

void WorldScene::step(Real dt) {
  settings_.gravity = Vec3(0.0, -gravity_, 0.0);
  world_.settings() = settings_;
  world_.step(dt);
  afterStep(dt);
}

void WorldScene::draw(DebugDraw& d) const {
  world_.draw(d, drawOptions_);
  drawExtra(d);
}

std::optional<Real> WorldScene::energy() const {
  const rigid::WorldStats s = world_.stats();
  return s.kineticEnergy + s.potentialEnergy;
}

nlohmann::json WorldScene::metrics() const {
  const rigid::WorldStats s = world_.stats();
  nlohmann::json j = {{"bodies", s.bodies},
                      {"contacts", s.contacts},
                      {"kinetic_energy_J", s.kineticEnergy},
                      {"momentum", glm::length(s.momentum)},
                      {"angular_momentum", glm::length(s.angularMomentum)},
                      {"max_penetration_m", s.maxPenetration},
                      {"max_joint_error_m", s.maxJointError},
                      {"sleeping", s.sleeping},
                      {"solver_iterations", s.solverIterations}};
  extraMetrics(j);
  return j;
}

std::optional<app::PickHit> WorldScene::pick(const Ray& ray) const {
  if (const std::optional<rigid::WorldRayHit> hit = world_.rayCast(ray, 1e4, true))
    return app::PickHit{hit->body, hit->hit.t, hit->hit.point};
  if (!shooting_) return std::nullopt;
  // Nothing to drag: a click shoots a ball from the camera along the ray (handled in drag()).
  pendingShot_ = ray;
  return app::PickHit{kShootHandle, 1.0, ray.origin + ray.direction};
}

void WorldScene::drag(int handle, const Vec3& target) {
  if (handle == kShootHandle) {
    if (!pendingShot_) return;
    rigid::BodyDesc ball;
    ball.shape = collision::makeSphere(0.25).value();
    ball.position = pendingShot_->origin + 0.5 * pendingShot_->direction;
    ball.linearVelocity = shotSpeed_ * pendingShot_->direction;
    ball.density = 2000.0;
    ball.bullet = true;
    ball.color = colors::kRed;
    ball.name = "shot";
    world_.addBody(ball);
    pendingShot_.reset();
    return;
  }
  if (!dragStarted_) {
    world_.beginDrag(handle, target);
    dragStarted_ = true;
  } else {
    world_.dragTo(target);
  }
}

std::vector<app::DragHandle> WorldScene::dragHandles() const {
  constexpr std::size_t kMaxHandles = 8;
  std::vector<int> dynamic;
  for (int i = 0; i < world_.bodyCount(); ++i)
    if (world_.body(i).isDynamic()) dynamic.push_back(i);
  const auto higher = [this](int a, int b) { return world_.body(a).position.y > world_.body(b).position.y; };
  const std::size_t n = std::min(kMaxHandles, dynamic.size());
  std::partial_sort(dynamic.begin(), dynamic.begin() + static_cast<std::ptrdiff_t>(n), dynamic.end(), higher);
  dynamic.resize(n);
  const int dragged = world_.draggedBody();
  if (dragged >= 0 && std::find(dynamic.begin(), dynamic.end(), dragged) == dynamic.end()) dynamic.push_back(dragged);
  std::vector<app::DragHandle> out;
  for (int i : dynamic) out.push_back({i, world_.body(i).position});
  return out;
}

void WorldScene::release(int /*handle*/) {
  world_.endDrag();
  dragStarted_ = false;
  pendingShot_.reset();
}

}  // namespace pba::lab
