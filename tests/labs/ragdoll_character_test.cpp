// Ragdolls from skeleton files (labs/ragdoll/skeleton_import.h + physics/ragdoll/skeleton_ragdoll.h): the
// project's humanoid.bvh (rest pose) and Debian's assimp-testmodels CMU 01_01.bvh (frame 100), with both
// methods: built, they land
// and come to rest (kinetic energy below ½ M (5 cm/s)² for 1 s, as the lab's `resting` metric) within 10 s of
// landing, joints within 1 cm, no box deeper than 1 cm in the ground.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

#include "physics/ragdoll/builders.h"
#include "physics/ragdoll/constraint_ragdoll.h"
#include "physics/ragdoll/particle_ragdoll.h"
#include "skeleton_import.h"

namespace pba::lab {
namespace {

constexpr Real kDt = 1.0 / 60.0;         // [s] the lab's step
constexpr Real kJointTolerance = 0.01;   // [m] the bound
constexpr Real kGroundTolerance = 0.01;  // [m] the bound

/// The lab's character scene's start: tilted 60° forward, lowest corner 0.5 m above the ground.
ragdoll::RagdollDesc dropped(const std::vector<ragdoll::SkeletonJoint>& joints) {
  Result<ragdoll::RagdollDesc> built = ragdoll::buildSkeletonRagdoll(joints);
  EXPECT_TRUE(built.ok()) << built.error();
  ragdoll::RagdollDesc d =
      ragdoll::rotated(built.value(), glm::angleAxis(degToRad(60.0), Vec3(1.0, 0.0, 0.0)), Vec3(0.0));
  Real lowest = 1e300;
  for (const ragdoll::BoneDesc& b : d.bones)
    for (int i = 0; i < 8; ++i) {
      const Vec3 h = b.halfExtents;
      lowest = std::min(
          lowest, (b.center + b.orientation * Vec3(i & 1 ? h.x : -h.x, i & 2 ? h.y : -h.y, i & 4 ? h.z : -h.z)).y);
    }
  return ragdoll::translated(d, Vec3(0.0, 0.5 - lowest, 0.0));
}

struct Outcome {
  Real restAfterLanding = -1.0;  // [s] from the first ground contact to 1 s of quiet; −1: never
  Real peakJointError = 0.0;     // [m] largest during the run (the landing's impacts), reported
  Real peakPenetration = 0.0;    // [m] largest during the run, reported
  Real jointError = 0.0;         // [m] at rest (the lab's metric at that moment)
  Real penetration = 0.0;        // [m] at rest
  Real finalKinetic = 0.0;       // [J]
};

/// Runs `step` until the kinetic energy stays below ½ M (5 cm/s)² for 1 s, at most 10 s after landing.
template <typename Stepper>
Outcome run(Stepper&& stepOnce, Real mass) {
  const Real bound = 0.5 * mass * 0.05 * 0.05;
  Outcome o;
  Real landed = -1.0, quiet = 0.0, t = 0.0;
  while (t < 30.0 && (landed < 0.0 || t - landed < 11.0)) {
    const auto [kinetic, jointError, penetration, contacts] = stepOnce();
    t += kDt;
    if (landed < 0.0 && contacts) landed = t;
    o.peakJointError = std::max(o.peakJointError, jointError);
    o.peakPenetration = std::max(o.peakPenetration, penetration);
    o.jointError = jointError, o.penetration = penetration, o.finalKinetic = kinetic;
    quiet = kinetic < bound ? quiet + kDt : 0.0;
    if (landed >= 0.0 && quiet >= 1.0) {
      o.restAfterLanding = t - landed;
      break;
    }
  }
  return o;
}

void expectLandsAndRests(const std::vector<ragdoll::SkeletonJoint>& joints, const std::string& what) {
  const ragdoll::RagdollDesc d = dropped(joints);
  const Real mass = ragdoll::totalMass(d);
  ragdoll::ParticleRagdoll p = ragdoll::ParticleRagdoll::build(d).value();
  const Outcome po = run(
      [&] {
        p.step(kDt);
        const ragdoll::ParticleStats s = p.stats();
        return std::tuple{s.kineticEnergy, s.maxJointError, s.maxPenetration, s.contacts > 0};
      },
      mass);
  ragdoll::ConstraintRagdoll c = ragdoll::ConstraintRagdoll::build(d).value();
  const Outcome co = run(
      [&] {
        c.step(kDt);
        const ragdoll::ConstraintStats s = c.stats();
        return std::tuple{s.kineticEnergy, s.maxJointError, s.maxPenetration, s.contacts > 0};
      },
      mass);
  for (const auto& [name, o] : {std::pair{"particle", po}, std::pair{"constraint", co}}) {
    std::printf(
        "%s, %s: %zu bones, at rest %.2f s after landing with joint error %.4f m, penetration %.4f m, KE %.3f J;"
        " peaks while landing %.4f m, %.4f m\n",
        what.c_str(), name, d.bones.size(), o.restAfterLanding, o.jointError, o.penetration, o.finalKinetic,
        o.peakJointError, o.peakPenetration);
    EXPECT_GE(o.restAfterLanding, 0.0) << what << ", " << name << ": not at rest within 10 s of landing";
    EXPECT_LT(o.jointError, kJointTolerance) << what << ", " << name;
    EXPECT_LT(o.penetration, kGroundTolerance) << what << ", " << name;
  }
}

LoadedSkeleton load(const std::string& path, int frame) {
  SkeletonFile f;
  f.path = path;
  f.frame = frame;
  Result<LoadedSkeleton> s = loadSkeleton(f);
  EXPECT_TRUE(s.ok()) << s.error();
  return s ? s.value() : LoadedSkeleton{};
}

const char* const kCmu = PBA_TEST_RESOURCE_DIR "/models/mocap/01_01.bvh";

TEST(RagdollCharacter, HumanoidBvhLandsAndComesToRestWithBothMethods) {
  expectLandsAndRests(load("resources/models/humanoid.bvh", -1).joints, "humanoid.bvh");
}

TEST(RagdollCharacter, CmuBvhOfAssimpTestModelsAtFrame100LandsAndComesToRestWithBothMethods) {
  ASSERT_TRUE(std::filesystem::exists(kCmu)) << kCmu << " is missing: install assimp-testmodels (./pba does)";
  // Its 31 joints make 21 bones: the helper joints at the hips (LHipJoint, RHipJoint, LowerBack) and the
  // thumbs merge into their parents (skeleton_ragdoll.h).
  const LoadedSkeleton s = load(kCmu, 100);
  EXPECT_EQ(s.joints.size(), 38u);  // Assimp's nodes: 31 joints and 7 end sites
  EXPECT_EQ(ragdoll::buildSkeletonRagdoll(s.joints).value().bones.size(), 21u);
  expectLandsAndRests(s.joints, "01_01.bvh frame 100");
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
