// Both ragdolls on the paper's test scenes (Ragdoll paper §5) and its human: finite for 60 s, joints
// held within 1 cm, limits within 2°, no bone deeper than 1 cm in the ground (the 8× box included), no
// energy gained after the first contact in passive scenes (kinetic + potential ≤ its value then + 1 %),
// and the human at rest within 10 s of landing. The references are physical bounds, not recorded runs,
// and every quantity is measured from the bones' poses (support/ragdoll_pose_measure.h), not from the
// solvers' own statistics.
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include <gtest/gtest.h>

#include "physics/ragdoll/builders.h"
#include "physics/ragdoll/constraint_ragdoll.h"
#include "physics/ragdoll/particle_ragdoll.h"
#include "support/ragdoll_pose_measure.h"

namespace pba::ragdoll {
namespace {

using Pose = std::vector<collision::Transform>;

constexpr Real kDt = 1.0 / 60.0;  // [s] the lab's step
constexpr Real kTouch = 0.005;    // [m] a box corner this close to the ground has landed

// One method behind one interface, for the tests that hold for both: a step, and the bones' poses.
struct Method {
  std::string name;
  std::function<void()> step;
  std::function<Pose()> pose;
  Vec3 gravity{0.0};
};

Method particleMethod(const RagdollDesc& desc, ParticleSettings settings = {}) {
  auto r = std::make_shared<ParticleRagdoll>(ParticleRagdoll::build(desc, settings).value());
  return {"particle", [r] { r->step(kDt); },
          [r] {
            Pose pose;
            for (int i = 0; i < r->boneCount(); ++i) pose.push_back(r->boneFrame(i));
            return pose;
          },
          settings.gravity};
}

Method constraintMethod(const RagdollDesc& desc) {
  auto r = std::make_shared<ConstraintRagdoll>(ConstraintRagdoll::build(desc).value());
  return {"constraint", [r] { r->step(kDt); },
          [r] {
            Pose pose;
            for (int i = 0; i < r->boneCount(); ++i) pose.push_back(r->world().body(r->bodyOf(i)).pose());
            return pose;
          },
          r->world().settings().gravity};
}

struct Worst {
  Real jointError = 0.0, limitViolation = 0.0, penetration = 0.0;
  void add(const test::PoseMeasure& s) {
    jointError = std::max(jointError, s.jointGap);
    limitViolation = std::max(limitViolation, s.limitExcess);
    penetration = std::max(penetration, s.penetration);
  }
};
struct RunResult {
  Worst all, settled;  // every step; the steps after `settleTime`
  bool finite = true;
};

bool finitePose(const Pose& pose) {
  for (const collision::Transform& t : pose)
    if (!std::isfinite(t.position.x + t.position.y + t.position.z + t.rotation.w)) return false;
  return true;
}

RunResult run(const RagdollDesc& desc, Method& m, Real seconds, Real settleTime) {
  RunResult r;
  const std::vector<test::JointInBones> joints = test::jointsInBones(desc);
  std::vector<Vec3> corners;
  const int steps = static_cast<int>(std::lround(seconds / kDt));
  for (int i = 0; i < steps; ++i) {
    m.step();
    const Pose pose = m.pose();
    r.finite = r.finite && finitePose(pose);
    if (!r.finite) break;
    const test::PoseMeasure s = test::measurePose(desc, joints, pose, kDt, corners);
    r.all.add(s);
    if ((i + 1) * kDt > settleTime) r.settled.add(s);
  }
  return r;
}

struct SceneCase {
  std::string name;
  std::function<RagdollDesc()> build;
};

std::vector<SceneCase> scenes() {
  return {{"boxes", buildBoxesTest},
          {"ball_chain", [] { return buildChainTest(JointKind::Ball); }},
          {"hinge_chain", [] { return buildChainTest(JointKind::Hinge); }},
          {"masses", buildMassesTest},
          {"ball_limits", [] { return buildLimitsTest(JointKind::Ball); }},
          {"hinge_limits", [] { return buildLimitsTest(JointKind::Hinge); }},
          {"spider", [] { return buildSpider(); }},
          {"human", [] {
             HumanDesc h;
             h.position = Vec3(0.0, 0.6, 0.0);
             h.orientation = glm::angleAxis(degToRad(80.0), Vec3(1.0, 0.0, 0.0));
             return buildHumanRagdoll(h);
           }}};
}

class BothMethods : public ::testing::TestWithParam<int> {};

// Penetration < 1 cm in every step. Joints < 1 cm and limits < 2° in every step of the still scenes, and
// from 10 s on for the scenes that start with a swing or a fall (the chains, the spider, the human): a
// figure's landing, and the chains' first swings, part the boxes at a joint by up to 1.5 cm and push
// limits up to 4° for a few steps (bounded below 2 cm and 5°). The particle method's largest gaps are
// there: its boxes are frames fitted to tetrahedra that the load deforms, so a joint held by the
// particles still shows a gap between the boxes drawn.
TEST_P(BothMethods, EveryTestSceneStaysFiniteForSixtySecondsWithJointsLimitsAndGroundHeld) {
  const SceneCase scene = scenes()[GetParam()];
  const bool moving = scene.name == "spider" || scene.name == "human" || scene.name.find("chain") != std::string::npos;
  const RagdollDesc desc = scene.build();
  for (Method m : {particleMethod(desc), constraintMethod(desc)}) {
    SCOPED_TRACE(scene.name + " / " + m.name);
    const RunResult r = run(desc, m, 60.0, 10.0);
    EXPECT_TRUE(r.finite);
    EXPECT_LT(r.all.penetration, 0.01) << "[m]";
    const Worst& strict = moving ? r.settled : r.all;
    EXPECT_LT(strict.jointError, 0.01) << "[m]";
    EXPECT_LT(radToDeg(strict.limitViolation), 2.0) << "[deg]";
    EXPECT_LT(r.all.jointError, 0.02) << "[m] landing or swing";
    EXPECT_LT(radToDeg(r.all.limitViolation), 5.0) << "[deg] landing or swing";
  }
}

// Passive scenes: after the first contact kinetic + potential energy never exceeds its value then by
// more than 1 % of the drop's potential energy scale (m g × 1 m, so that a figure at rest near E = 0
// does not make the bound vanish), and the human comes to rest (kinetic energy below ½ M (5 cm/s)²
// for 1 s) within 10 s of landing. The energy is the boxes' (support/ragdoll_pose_measure.h), from the
// poses one step before and after each step's.
TEST(RagdollHuman, NeverGainsEnergyAfterLandingAndComesToRestWithinTenSeconds) {
  const RagdollDesc desc = scenes()[7].build();
  const Real mass = totalMass(desc);
  const Real restBound = 0.5 * mass * 0.05 * 0.05;  // [J]
  for (Method m : {particleMethod(desc), constraintMethod(desc)}) {
    SCOPED_TRACE(m.name);
    std::optional<Real> landing, energyAtLanding;
    Real restStart = -1.0, maxGain = -1e30;
    bool rested = false;
    m.step();
    Pose before = m.pose();
    m.step();
    Pose now = m.pose();
    std::vector<Vec3> corners;
    for (int i = 2; i <= 1200 && !rested; ++i) {
      m.step();
      Pose after = m.pose();
      const Real t = (i - 1) * kDt;  // the time of `now`
      const test::PoseEnergy s = test::energyFromPoses(desc, before, now, after, kDt, m.gravity);
      const Real e = s.kinetic + s.potential;
      const test::PoseMeasure shape = test::measurePose(desc, {}, now, kDt, corners);
      if (!landing && shape.lowestCorner < kTouch) landing = t, energyAtLanding = e;
      if (landing) maxGain = std::max(maxGain, e - *energyAtLanding);
      if (s.kinetic < restBound) {
        if (restStart < 0.0) restStart = t;
        rested = landing && t - restStart >= 1.0;
      } else {
        restStart = -1.0;
      }
      before = std::move(now);
      now = std::move(after);
    }
    ASSERT_TRUE(landing.has_value());
    EXPECT_LE(maxGain, 0.01 * mass * kStandardGravity * 1.0) << "[J] energy gained after the first contact";
    EXPECT_TRUE(rested) << "not at rest within 20 s";
    if (rested) {
      EXPECT_LE(restStart - *landing, 10.0) << "[s] from landing to rest";
    }
  }
}

INSTANTIATE_TEST_SUITE_P(RagdollScenes, BothMethods, ::testing::Range(0, 8),
                         [](const ::testing::TestParamInfo<int>& i) { return scenes()[i.param].name; });

}  // namespace
}  // namespace pba::ragdoll
