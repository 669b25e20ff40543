// Ragdolls from skeleton files (labs/ragdoll/skeleton_import.h + physics/ragdoll/skeleton_ragdoll.h): what the
// import makes of Debian's assimp-testmodels CMU 01_01.bvh, and its errors. That every BVH file's ragdoll
// lands and comes to rest with both methods is tests/labs/ragdoll_bvh_rest_test.cpp.
#include <gtest/gtest.h>

#include <filesystem>

#include "physics/ragdoll/skeleton_ragdoll.h"
#include "skeleton_import.h"

namespace pba::lab {
namespace {

const char* const kCmu = PBA_TEST_RESOURCE_DIR "/models/mocap/01_01.bvh";

TEST(RagdollCharacter, CmuBvhMakesTwentyOneBonesFromItsThirtyOneJoints) {
  ASSERT_TRUE(std::filesystem::exists(kCmu)) << kCmu << " is missing";
  // Its 31 joints make 21 bones: the helper joints at the hips (LHipJoint, RHipJoint, LowerBack) and the
  // thumbs merge into their parents (skeleton_ragdoll.h).
  SkeletonFile f;
  f.path = kCmu;
  f.frame = 100;
  const Result<LoadedSkeleton> s = loadSkeleton(f);
  ASSERT_TRUE(s.ok()) << s.error();
  EXPECT_EQ(s.value().joints.size(), 38u);  // Assimp's nodes: 31 joints and 7 end sites
  EXPECT_EQ(ragdoll::buildSkeletonRagdoll(s.value().joints).value().bones.size(), 21u);
}

TEST(RagdollCharacter, AMissingFileOrFrameIsAnErrorNamingTheFile) {
  SkeletonFile f;
  f.path = "/nonexistent/skeleton.bvh";
  Result<LoadedSkeleton> s = loadSkeleton(f);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.error().find("/nonexistent/skeleton.bvh"), std::string::npos) << s.error();
  f.path = "resources/models/humanoid.bvh";
  f.frame = 33;  // the walk cycle has frames 0 ... 32
  s = loadSkeleton(f);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.error().find("humanoid.bvh has 33 frames"), std::string::npos) << s.error();
}

}  // namespace
}  // namespace pba::lab
