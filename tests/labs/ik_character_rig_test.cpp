// The IK lab's character rig (labs/ik/character_rig.cpp): knees and elbows are hinges that bend the
// way human joints do. Checked with forward kinematics of the converted skeleton, not stored poses.
#include <gtest/gtest.h>

#include "app/assets/character_rig.h"

namespace pba::app {
namespace {

using namespace pba::ik;

TEST(IkCharacterRig, KneesAndElbowsAreRecognisedByTheNamingConventionsOfBvhMixamoAndCmu) {
  EXPECT_EQ(limbJointFromName("LeftForeArm"), LimbJoint::Elbow);
  EXPECT_EQ(limbJointFromName("mixamorig:RightForeArm"), LimbJoint::Elbow);
  EXPECT_EQ(limbJointFromName("l_elbow"), LimbJoint::Elbow);
  EXPECT_EQ(limbJointFromName("LowerArm.R"), LimbJoint::Elbow);
  EXPECT_EQ(limbJointFromName("LeftLeg"), LimbJoint::Knee);  // Mixamo/CMU: the shin
  EXPECT_EQ(limbJointFromName("mixamorig:RightLeg"), LimbJoint::Knee);
  EXPECT_EQ(limbJointFromName("r_knee"), LimbJoint::Knee);
  EXPECT_EQ(limbJointFromName("Calf_L"), LimbJoint::Knee);
  EXPECT_EQ(limbJointFromName("LeftUpLeg"), LimbJoint::None);  // the thigh: a ball joint
  EXPECT_EQ(limbJointFromName("RightArm"), LimbJoint::None);
  EXPECT_EQ(limbJointFromName("Hips"), LimbJoint::None);
}

// The project's humanoid faces +z with its left at +x (tools/make_humanoid_bvh.py).
class HumanoidRig : public ::testing::Test {
 protected:
  void SetUp() override {
    Result<Rig> r = loadCharacterRig(CharacterDesc{});
    ASSERT_TRUE(r.ok()) << r.error();
    rig = std::move(r).value();
  }
  /// World displacement of joint `tip` when the first DOF of joint `hinge` turns by `angle`.
  Vec3 moveOf(const std::string& hinge, const std::string& tip, Real angle) const {
    const int h = rig.skeleton.find(hinge), t = rig.skeleton.find(tip);
    Pose pose = rig.skeleton.restPose();
    const Vec3 before = forwardKinematics(rig.skeleton, pose)[static_cast<size_t>(t)].position;
    pose.dofs[static_cast<size_t>(rig.skeleton.joint(h).firstDof)] = angle;
    return forwardKinematics(rig.skeleton, pose)[static_cast<size_t>(t)].position - before;
  }
  Rig rig;
};

TEST_F(HumanoidRig, KneesAndElbowsAreHingesWithAnatomicalRanges) {
  for (const char* name : {"LeftForeArm", "RightForeArm", "LeftLeg", "RightLeg"}) {
    const int j = rig.skeleton.find(name);
    ASSERT_GE(j, 0) << name;
    EXPECT_EQ(rig.skeleton.joint(j).type, JointType::Hinge) << name;
    EXPECT_DOUBLE_EQ(rig.skeleton.joint(j).lo[0], kHingeFlexMin) << name;
    EXPECT_DOUBLE_EQ(rig.skeleton.joint(j).hi[0], kHingeFlexMax) << name;
  }
  EXPECT_EQ(rig.skeleton.joint(rig.skeleton.find("LeftArm")).type, JointType::Ball);
  EXPECT_EQ(rig.skeleton.joint(rig.skeleton.find("LeftUpLeg")).type, JointType::Ball);
}

TEST_F(HumanoidRig, FlexingAKneeMovesTheFootBackAndUpAndAnElbowTheHandForward) {
  for (const char* side : {"Left", "Right"}) {
    const Vec3 foot = moveOf(std::string(side) + "Leg", std::string(side) + "Foot", kPi / 2.0);
    EXPECT_LT(foot.z, -0.1) << side << " knee: the shin swings to the back (−z)";
    EXPECT_GT(foot.y, 0.1) << side << " knee: and up";
    EXPECT_NEAR(foot.x, 0.0, 1e-9) << side << " knee: in the sagittal plane";
    const Vec3 hand = moveOf(std::string(side) + "ForeArm", std::string(side) + "Hand", kPi / 2.0);
    EXPECT_GT(hand.z, 0.1) << side << " elbow: the forearm swings to the front (+z)";
  }
}

}  // namespace
}  // namespace pba::app
