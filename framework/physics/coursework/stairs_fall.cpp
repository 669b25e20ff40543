#include "physics/coursework/stairs_fall.h"

#include <algorithm>
#include <cmath>
#include <random>
#include "physics/exercises/not_implemented.h"
#include "physics/ik/skeleton.h"
#include "physics/ragdoll/builders.h"

namespace pba::coursework {

BoneMotion handOverMotion([[maybe_unused]] const BonePose& twoBefore, [[maybe_unused]] const BonePose& before,
                          [[maybe_unused]] const BonePose& now, [[maybe_unused]] Real h) {
  // BEGIN SOLUTION
  // Backward difference of second order: f'(t) ≈ (3 f(t) − 4 f(t − h) + f(t − 2h)) / 2h, exact for
  // quadratics. For rotations, with φ₁, φ₂ the rotation vectors from t − 2h to t − h and from t − h to t
  // (about one axis, φ₁ = θ(t−h) − θ(t−2h), φ₂ = θ(t) − θ(t−h)): 3θ(t) − 4θ(t−h) + θ(t−2h) = 3φ₂ − φ₁.
  if (!(h > 0.0)) return {};
  const auto turn = [](const Quat& from, const Quat& to) {
    Quat q = to * glm::conjugate(from);
    if (q.w < 0.0) q = -q;
    return ik::rotationVector(q);
  };
  BoneMotion m;
  m.velocity = (3.0 * now.center - 4.0 * before.center + twoBefore.center) / (2.0 * h);
  m.angularVelocity =
      (3.0 * turn(before.orientation, now.orientation) - turn(twoBefore.orientation, before.orientation)) / (2.0 * h);
  return m;
  // END SOLUTION
  // STUB: return exercises::notImplemented("CW3-1", BoneMotion{});
}

void updateRest([[maybe_unused]] RestDetector& detector, [[maybe_unused]] const std::vector<BoneMotion>& bones,
                [[maybe_unused]] Real time, [[maybe_unused]] Real h) {
  // BEGIN SOLUTION
  if (!(h > 0.0)) return;
  const RestSettings& s = detector.settings;
  const bool quiet = std::all_of(bones.begin(), bones.end(), [&](const BoneMotion& b) {
    return glm::length(b.velocity) < s.linearSpeed && glm::length(b.angularVelocity) < s.angularSpeed;
  });
  if (!quiet) {
    detector.quiet = 0.0;
    detector.atRest = false;
    return;
  }
  detector.quiet += h;
  if (!detector.atRest && detector.quiet >= s.quietTime - 1e-9) {
    detector.atRest = true;
    detector.restTime = time - detector.quiet;
  }
  // END SOLUTION
  // STUB: exercises::markNotImplemented("CW3-2");  // the figure is never found at rest
}

namespace {

constexpr Real kFootGap = 0.01;               // [m] from the figure's foremost toe back to the nosing at t = 0
constexpr Real kMaxYaw = 15.0 * kPi / 180.0;  // [rad] the seed's largest turn about the vertical

/// The controlled figure at time t: the t = 0 figure tipped by ½ α t² about the nosing, moved by the drift.
ragdoll::RagdollDesc posedFigure(const StairsFall& scene, Real t) {
  const Quat tip = glm::angleAxis(0.5 * scene.tipAcceleration * t * t, scene.tipAxis);
  return ragdoll::translated(ragdoll::rotated(scene.figure, tip, scene.pivot), Vec3(scene.driftSpeed * t, 0.0, 0.0));
}

// Finite first: an ordered comparison with NaN raises the invalid-operation flag (the tests trap it).
bool positive(Real x) { return std::isfinite(x) && x > 0.0; }
bool nonNegative(Real x) { return std::isfinite(x) && x >= 0.0; }

int firstFigureBone(const StairsFall& scene) { return static_cast<int>(scene.stairs.bones.size()); }

void switchToRagdoll(StairsFall& scene) {
  ragdoll::RagdollDesc figure = posedFigure(scene, scene.time);
  scene.handedOver.clear();
  for (std::size_t b = 0; b < figure.bones.size(); ++b) {
    const BoneMotion m = handOverMotion(scene.frames[0][b], scene.frames[1][b], scene.frames[2][b], scene.h);
    figure.bones[b].velocity = m.velocity;
    figure.bones[b].angularVelocity = m.angularVelocity;
    scene.handedOver.push_back(m);
  }
  ragdoll::RagdollDesc all = scene.stairs;
  ragdoll::append(all, figure);
  ragdoll::ConstraintSettings settings;
  settings.world.sleeping = false;  // rest is CW3-2's to find, not the world's
  auto built = ragdoll::ConstraintRagdoll::build(all, settings);
  if (!built) return;  // cannot happen: buildStairsFall validated the same bones
  scene.ragdoll = std::move(built).value();
  // Joint friction: every hinge holds against torques up to jointFriction (Box2D v3's human, shared/human.c:
  // a motor of speed 0 whose torque is bounded), so that hands and feet stop flapping on their limits.
  rigid::World& world = scene.ragdoll.world();
  for (int j = 0; j < static_cast<int>(world.joints().size()); ++j) {
    rigid::JointDesc& joint = world.jointDesc(j);
    if (joint.kind != rigid::JointKind::Hinge) continue;
    joint.enableMotor = true;
    joint.motorSpeed = 0.0;
    joint.maxMotorTorque = scene.jointFriction;
  }
  scene.controlled = false;
  scene.switchedAt = scene.time;
}

}  // namespace

Result<StairsFall> buildStairsFall(const StairsFallDesc& desc) {
  if (desc.steps < 1) return Error{"steps: must be at least 1"};
  if (!positive(desc.rise)) return Error{"rise: must be positive"};
  if (!positive(desc.run)) return Error{"run: must be positive"};
  if (!positive(desc.width)) return Error{"width: must be positive"};
  if (!positive(desc.figureMass)) return Error{"figureMass: must be positive"};
  if (!positive(desc.figureScale)) return Error{"figureScale: must be positive"};
  if (!nonNegative(desc.tipAcceleration)) return Error{"tipAcceleration: must be >= 0"};
  if (!std::isfinite(desc.driftSpeed)) return Error{"driftSpeed: must be finite"};
  if (!nonNegative(desc.switchAt)) return Error{"switchAt: must be >= 0"};
  if (!nonNegative(desc.jointFriction)) return Error{"jointFriction: must be >= 0"};
  if (!positive(desc.rest.linearSpeed)) return Error{"rest.linearSpeed: must be positive"};
  if (!positive(desc.rest.angularSpeed)) return Error{"rest.angularSpeed: must be positive"};
  if (!nonNegative(desc.rest.quietTime)) return Error{"rest.quietTime: must be >= 0"};
  StairsFall scene;
  scene.stairs = ragdoll::buildStairs(desc.steps, desc.rise, desc.run, desc.width);
  // The human faces +x (down the stairs), turned by the seed's yaw.
  // The engine's output is the same everywhere; std::uniform_real_distribution's is not.
  std::mt19937 rng(desc.seed);
  const Real unit = static_cast<Real>(rng()) / 4294967296.0;  // [0, 1)
  const Real yaw = desc.seed == 0 ? 0.0 : kMaxYaw * (2.0 * unit - 1.0);
  ragdoll::HumanDesc human;
  human.totalMass = desc.figureMass;
  human.scale = desc.figureScale;
  human.orientation = glm::angleAxis(0.5 * kPi + yaw, kUp);
  ragdoll::RagdollDesc figure = ragdoll::buildHumanRagdoll(human);
  // Feet on the top step, the foremost box corner kFootGap behind its nosing.
  Real front = -1e30;
  for (const ragdoll::BoneDesc& b : figure.bones)
    for (int k = 0; k < 8; ++k) {
      const Vec3 s((k & 1) ? 1.0 : -1.0, (k & 2) ? 1.0 : -1.0, (k & 4) ? 1.0 : -1.0);
      front = std::max(front, (b.center + b.orientation * (s * b.halfExtents)).x);
    }
  const Real top = desc.steps * desc.rise;
  const Real nosing = -(desc.steps - 1) * desc.run;
  scene.figure = ragdoll::translated(figure, Vec3(nosing - kFootGap - front, top, 0.0));
  if (Status s = ragdoll::validate(scene.figure, "figure"); !s) return Error{s.error()};
  scene.pivot = Vec3(nosing, top, 0.0);
  scene.tipAcceleration = desc.tipAcceleration;
  scene.driftSpeed = desc.driftSpeed;
  scene.switchAt = desc.switchAt;
  scene.jointFriction = desc.jointFriction;
  scene.rest.settings = desc.rest;
  for (auto& f : scene.frames) f = scriptedPose(scene, 0.0);  // at rest before t = 0
  if (desc.switchAt <= 0.0) switchToRagdoll(scene);
  return scene;
}

std::vector<BonePose> scriptedPose(const StairsFall& scene, Real t) {
  std::vector<BonePose> poses;
  for (const ragdoll::BoneDesc& b : posedFigure(scene, t).bones) poses.push_back({b.center, b.orientation});
  return poses;
}

std::vector<BoneMotion> scriptedMotion(const StairsFall& scene, Real t) {
  // d/dt [pivot + drift t x̂ + R(θ(t)) r₀] = drift x̂ + ω × R r₀, with ω = θ'(t) axis = α t axis.
  const Vec3 omega = scene.tipAcceleration * t * scene.tipAxis;
  std::vector<BoneMotion> motion;
  for (const BonePose& p : scriptedPose(scene, t)) {
    const Vec3 arm = p.center - scene.pivot - Vec3(scene.driftSpeed * t, 0.0, 0.0);
    motion.push_back({Vec3(scene.driftSpeed, 0.0, 0.0) + glm::cross(omega, arm), omega});
  }
  return motion;
}

void stepStairsFall(StairsFall& scene, Real h) {
  if (!(h > 0.0)) return;
  scene.time += h;
  if (scene.controlled) {
    scene.frames[0] = std::move(scene.frames[1]);
    scene.frames[1] = std::move(scene.frames[2]);
    scene.frames[2] = scriptedPose(scene, scene.time);
    scene.h = h;
    if (scene.time >= scene.switchAt - 1e-9) switchToRagdoll(scene);
    return;
  }
  scene.ragdoll.step(h);
  updateRest(scene.rest, figureMotion(scene), scene.time, h);
}

std::vector<BoneMotion> figureMotion(const StairsFall& scene) {
  if (scene.controlled) return scriptedMotion(scene, scene.time);
  std::vector<BoneMotion> motion;
  const int first = firstFigureBone(scene);
  for (int b = first; b < scene.ragdoll.boneCount(); ++b) {
    const rigid::Body& body = scene.ragdoll.world().body(scene.ragdoll.bodyOf(b));
    motion.push_back({body.linearVelocity, body.angularVelocity});
  }
  return motion;
}

Vec3 figureCenterOfMass(const StairsFall& scene) {
  Vec3 sum(0.0);
  Real mass = 0.0;
  const std::vector<BonePose> poses = scene.controlled ? scriptedPose(scene, scene.time) : std::vector<BonePose>{};
  for (std::size_t b = 0; b < scene.figure.bones.size(); ++b) {
    const Real m = scene.figure.bones[b].mass;
    const Vec3 c =
        scene.controlled
            ? poses[b].center
            : scene.ragdoll.world().body(scene.ragdoll.bodyOf(firstFigureBone(scene) + static_cast<int>(b))).position;
    sum += m * c;
    mass += m;
  }
  return sum / mass;
}

}  // namespace pba::coursework
