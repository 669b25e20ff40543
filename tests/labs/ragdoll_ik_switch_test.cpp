// The ragdoll lab's ik-to-ragdoll scene (labs/ragdoll/ik_to_ragdoll_scene.h): at the switch both ragdolls
// start in the IK pose with the finite-difference velocities of the last two IK frames, then fall and rest.
// References: the bones' ends against forward kinematics of the IK pose (the box of a one-child joint spans
// the segment to its child), and the velocities as differences of the posed bones recorded by the test.
#include <algorithm>
#include <vector>

#include <gtest/gtest.h>

#include "ik_to_ragdoll_scene.h"
#include "physics/ik/skeleton.h"

namespace pba::lab {
namespace {

constexpr Real kFrame = 1.0 / 60.0;  // [s] the lab's step

/// The scene with an IK method outside the IK exercises (the tests pass in the student release too).
void exerciseFreeIk(IkToRagdollScene& s) {
  for (const auto& [name, value] :
       {std::pair{"ik_solver", "sdls"}, {"ik_jacobian", "differences"}, {"ik_limits", "false"}})
    ASSERT_TRUE(s.params().setFromText(name, value).ok()) << name;
}

TEST(RagdollIkSwitch, TheIkPoseIsTheSkeletonsForwardKinematics) {
  IkToRagdollScene s;
  exerciseFreeIk(s);
  ASSERT_TRUE(s.params().setFromText("throw_at", "-1").ok());
  s.reset();
  for (int i = 0; i < 75; ++i) s.step(kFrame);  // the hand is well up (the reach peaks at 1.25 s)
  ASSERT_TRUE(s.posing());
  const std::vector<pba::ik::Frame> frames = pba::ik::forwardKinematics(s.rig().skeleton, s.pose());
  int checked = 0;
  for (int b = 0; b < s.boneCount(); ++b) {
    const int j = s.boneJoints()[static_cast<size_t>(b)];
    const std::vector<int> children = s.rig().skeleton.children(j);
    if (children.size() != 1) continue;
    const IkToRagdollScene::BonePose& p = s.posedBones()[static_cast<size_t>(b)];
    const Vec3 axis = p.orientation * Vec3(1.0, 0.0, 0.0);
    // The box's long axis spans joint j to its child (1e-9 m: rounding of the pose mapping).
    const Vec3 start = frames[static_cast<size_t>(j)].position, end = frames[static_cast<size_t>(children[0])].position;
    const Real length = glm::length(end - start);
    if (length < 0.02) continue;  // a helper segment without a bone of its own
    EXPECT_NEAR(glm::length(p.center - 0.5 * (start + end)), 0.0, 1e-9) << s.rig().skeleton.joint(j).name;
    EXPECT_NEAR(glm::length(glm::cross(axis, end - start)) / length, 0.0, 1e-9) << s.rig().skeleton.joint(j).name;
    ++checked;
  }
  EXPECT_GE(checked, 12);  // limbs, spine, neck, head of humanoid.bvh
}

TEST(RagdollIkSwitch, AThrownBoxSwitchesControlWhenItReachesTheFigureAndJoinsBothRagdolls) {
  IkToRagdollScene s;
  exerciseFreeIk(s);
  s.reset();  // the default: a box thrown at 2 s
  int steps = 0;
  while (s.posing() && steps < 600) s.step(kFrame), ++steps;
  ASSERT_FALSE(s.posing()) << "the thrown box never reached the figure";
  EXPECT_EQ(s.metrics()["switch_reason"], "hit");
  EXPECT_GT(steps * kFrame, 2.0);
  ASSERT_EQ(s.switchDescription().bones.size(), static_cast<size_t>(s.boneCount()) + 1);  // the box joins
  EXPECT_GT(glm::length(s.switchDescription().bones.back().velocity), 5.0);               // [m/s] still flying
}

TEST(RagdollIkSwitch, AtTheSwitchTheRagdollsTakeThePoseAndTheFiniteDifferenceVelocities) {
  IkToRagdollScene s;
  exerciseFreeIk(s);
  ASSERT_TRUE(s.params().setFromText("throw_at", "-1").ok());
  s.reset();
  for (int i = 0; i < 37; ++i) s.step(kFrame);  // the hand moves fastest at 0.625 s
  const std::vector<IkToRagdollScene::BonePose> before = s.posedBones();
  s.step(kFrame);
  const std::vector<IkToRagdollScene::BonePose> now = s.posedBones();
  ASSERT_TRUE(s.posing());
  EXPECT_TRUE(s.keyPressed('G'));
  ASSERT_FALSE(s.posing());
  const Vec3 right(s.sideOffset(), 0.0, 0.0);
  const rigid::World& w = s.constraint().world();
  Real fastest = 0.0;
  for (int b = 0; b < s.boneCount(); ++b) {
    const size_t k = static_cast<size_t>(b);
    const Vec3 v = (now[k].center - before[k].center) / kFrame;  // [m/s] finite difference of the IK frames
    fastest = std::max(fastest, glm::length(v));
    const rigid::Body& body = w.body(s.constraint().bodyOf(b));
    EXPECT_NEAR(glm::length(body.position - (now[k].center + right)), 0.0, 1e-9) << b;
    EXPECT_NEAR(glm::length(body.linearVelocity - v), 0.0, 1e-9) << b;
    // The particle ragdoll: its tetrahedron's frame is the box's (1e-9 m), its start velocity the same.
    EXPECT_NEAR(glm::length(s.particle().boneFrame(b).position - (now[k].center - right)), 0.0, 1e-9) << b;
    EXPECT_NEAR(glm::length(s.switchDescription().bones[k].velocity - v), 0.0, 1e-12) << b;
  }
  EXPECT_GT(fastest, 0.5);  // [m/s] the hand was moving: the test compares something
}

// The constraint ragdoll does not reliably reach `resting` in this scene (workbook §6.4b, open problems):
// both fall, the particle one comes to rest within 10 s, and the constraint one stays near rest, its joints
// and contacts within the bounds.
TEST(RagdollIkSwitch, AfterASwitchWithTheHandMovingFastBothFallAndTheParticleRagdollComesToRest) {
  // Preset 4: the hand reaches at 1 Hz and G is pressed at 0.6 s (by the script), while it moves.
  IkToRagdollScene s;
  exerciseFreeIk(s);
  for (const auto& [name, value] : {std::pair{"throw_at", "-1"}, {"path_hertz", "1"}, {"switch_at", "0.6"}})
    ASSERT_TRUE(s.params().setFromText(name, value).ok()) << name;
  s.reset();
  int steps = 0;
  while (s.posing() && steps < 600) s.step(kFrame), ++steps;
  ASSERT_FALSE(s.posing());
  EXPECT_EQ(s.metrics()["switch_reason"], "time");
  const Real highest = [&] {
    Real y = 0.0;
    for (const IkToRagdollScene::BonePose& p : s.posedBones()) y = std::max(y, p.center.y);
    return y;
  }();
  nlohmann::json m;
  for (int i = 0; i < 600 && !(m.contains("particle_resting") && m["particle_resting"].get<bool>());
       ++i) {  // within 10 s
    s.step(kFrame);
    m = s.metrics();
  }
  EXPECT_TRUE(m["particle_resting"]) << m.dump();
  EXPECT_LT(m["constraint_kinetic_energy_J"].get<double>(), 0.5) << m.dump();  // [J] 74 kg at 12 cm/s
  EXPECT_LT(m["particle_max_joint_error_m"].get<double>(), 0.01);
  EXPECT_LT(m["constraint_max_joint_error_m"].get<double>(), 0.01);
  // The constraint ragdoll is near rest, not at rest: its deepest contact moves from step to step, so one
  // step's value says little (built with MinGW it read 10.8 mm at the step the particle ragdoll rested).
  // Over the next second: the median of the deepest contact within the 1 cm, none past 2 cm.
  std::vector<double> depths;
  for (int i = 0; i < 60; ++i) {
    s.step(kFrame);
    depths.push_back(s.metrics()["constraint_max_penetration_m"].get<double>());
  }
  std::sort(depths.begin(), depths.end());
  EXPECT_LT(depths[depths.size() / 2], 0.01);
  EXPECT_LT(depths.back(), 0.02);
  // It fell: the highest bone is now far lower than when it stood.
  Real y = 0.0;
  const rigid::World& w = s.constraint().world();
  for (int b = 0; b < s.boneCount(); ++b) y = std::max(y, w.body(s.constraint().bodyOf(b)).position.y);
  EXPECT_LT(y, 0.5 * highest);
}

}  // namespace
}  // namespace pba::lab
