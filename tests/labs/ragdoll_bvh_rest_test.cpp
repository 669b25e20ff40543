// Ragdolls from every BVH file come to rest (the lab's `character` scene: the file's rest pose, its default,
// tilted 60° forward, the lowest corner 0.5 m above the ground), with both methods: within 10 s of the first ground
// contact the figure is still (no box corner faster than 5 cm/s for 1 s), and throughout that second every
// joint's two copies are within 1 cm, every limit is kept within 2° and no box corner is deeper than 1 cm.
//
// The files: every *.bvh under resources/, and Debian's assimp-testmodels (/usr/share/assimp/models/BVH),
// read at run time when the package is installed (a file with the same bytes as one in resources/ is
// tested there once). Each quantity is measured from the bones' poses, not from the solvers' stats
// (support/ragdoll_pose_measure.h: joint gaps, limit angles, the deepest box corner).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "physics/ragdoll/builders.h"
#include "physics/ragdoll/constraint_ragdoll.h"
#include "physics/ragdoll/particle_ragdoll.h"
#include "skeleton_import.h"
#include "support/ragdoll_pose_measure.h"

namespace pba::lab {
namespace bvh_rest {

namespace fs = std::filesystem;
using test::boxCorners;
using test::JointInBones;
using test::jointsInBones;
using Measure = test::PoseMeasure;

constexpr Real kDt = 1.0 / 60.0;                     // [s] the lab's step
constexpr Real kSettleWithin = 10.0;                 // [s] after the first ground contact (the bound)
constexpr Real kQuietFor = 1.0;                      // [s] of stillness that counts as rest
constexpr Real kStillSpeed = 0.05;                   // [m/s] fastest box corner of a figure at rest
constexpr Real kJointTolerance = 0.01;               // [m] the bound
constexpr Real kLimitTolerance = 2.0 * kPi / 180.0;  // [rad] the bound
constexpr Real kGroundTolerance = 0.01;              // [m] the bound
constexpr Real kTouch = 0.005;                       // [m] a corner this close to the ground has landed
const char* const kAssimpBvh = "/usr/share/assimp/models/BVH";

constexpr int kMiddleFrame = -2;  // BvhCase::frame: the middle frame of the file's animation

struct BvhCase {
  std::string name;  // for the test's name
  std::string path;  // empty: skip with `skipReason`
  std::string skipReason;
  int frame = -1;  // −1: the rest pose (the scene's default); kMiddleFrame
};

void PrintTo(const BvhCase& c, std::ostream* os) { *os << (c.path.empty() ? c.name : c.path); }

std::string bytesOf(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::vector<fs::path> bvhFilesUnder(const fs::path& dir) {
  std::vector<fs::path> out;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return out;
  for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    std::string ext = it->path().extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (it->is_regular_file(ec) && ext == ".bvh") out.push_back(it->path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::string caseName(const std::string& prefix, const fs::path& p) {
  std::string s = prefix + "_" + p.stem().string();
  for (char& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return s;
}

std::vector<BvhCase> bvhCases(int frame) {
  std::vector<BvhCase> cases;
  std::vector<std::pair<std::string, fs::path>> seen;  // bytes, file
  const auto add = [&](const std::string& prefix, const fs::path& p) {
    const std::string bytes = bytesOf(p);
    for (const auto& [b, first] : seen)
      if (b == bytes) {
        cases.push_back(
            {caseName(prefix, p), "", p.string() + " has the same bytes as " + first.string() + ", tested there"});
        return;
      }
    seen.emplace_back(bytes, p);
    cases.push_back({caseName(prefix, p), p.string(), "", frame});
  };
  for (const fs::path& p : bvhFilesUnder(PBA_TEST_RESOURCE_DIR)) add("resources", p);
  const std::vector<fs::path> assimp = bvhFilesUnder(kAssimpBvh);
  if (assimp.empty())
    cases.push_back(
        {"assimp_testmodels", "", std::string(kAssimpBvh) + " has no BVH files: install assimp-testmodels"});
  for (const fs::path& p : assimp) add("assimp", p);
  return cases;
}

/// The character scene's start: the rest pose tilted 60° forward, its lowest corner 0.5 m above the ground.
ragdoll::RagdollDesc dropped(const ragdoll::RagdollDesc& built) {
  ragdoll::RagdollDesc d = ragdoll::rotated(built, glm::angleAxis(degToRad(60.0), Vec3(1.0, 0.0, 0.0)), Vec3(0.0));
  Real lowest = 1e300;
  for (const ragdoll::BoneDesc& b : d.bones)
    for (const Vec3& c : boxCorners(collision::Transform{b.center, b.orientation}, b.halfExtents))
      lowest = std::min(lowest, c.y);
  return ragdoll::translated(d, Vec3(0.0, 0.5 - lowest, 0.0));
}

Measure measure(const ragdoll::RagdollDesc& d, const std::vector<JointInBones>& joints,
                const std::vector<collision::Transform>& pose, std::vector<Vec3>& corners) {
  return test::measurePose(d, joints, pose, kDt, corners);
}

struct Outcome {
  Real landedAt = -1.0;  // [s] first ground contact; −1: never
  Real restAt = -1.0;    // [s] start of the first 1 s of stillness after landing; −1: none
  Measure worstAtRest;   // the largest of each quantity over that second
  Measure last;          // at the end of the run
};

/// Steps until a second of stillness after landing, or 10 s + 1 s after landing (30 s at most).
template <typename StepAndPose>
Outcome run(const ragdoll::RagdollDesc& d, StepAndPose&& stepAndPose) {
  const std::vector<JointInBones> joints = jointsInBones(d);
  std::vector<Vec3> corners;
  Outcome o;
  Measure quiet;
  Real t = 0.0, quietSince = -1.0;
  while (t < 30.0 && (o.landedAt < 0.0 || t - o.landedAt <= kSettleWithin + kQuietFor)) {
    const Measure m = measure(d, joints, stepAndPose(), corners);
    t += kDt;
    o.last = m;
    if (o.landedAt < 0.0 && m.lowestCorner < kTouch) o.landedAt = t;
    if (o.landedAt < 0.0 || m.fastestCorner >= kStillSpeed) {
      quietSince = -1.0;
      continue;
    }
    if (quietSince < 0.0) quietSince = t, quiet = Measure{};
    quiet.hingeTilt = std::max(quiet.hingeTilt, m.hingeTilt);
    if (m.jointGap >= quiet.jointGap) quiet.jointGap = m.jointGap, quiet.worstGap = m.worstGap;
    quiet.penetration = std::max(quiet.penetration, m.penetration);
    if (m.limitExcess >= quiet.limitExcess) quiet.limitExcess = m.limitExcess, quiet.worstLimit = m.worstLimit;
    if (t - quietSince >= kQuietFor - 1e-9) {
      o.restAt = quietSince, o.worstAtRest = quiet;
      break;
    }
  }
  return o;
}

void expectRests(const char* method, const std::string& file, const Outcome& o, std::size_t bones) {
  const Measure& m = o.restAt >= 0.0 ? o.worstAtRest : o.last;
  std::printf(
      "%s, %s: %zu bones, landed at %.2f s, at rest %.2f s after landing; over the quiet second: joint gap "
      "%.4f m (%s), limit excess %.2f deg (%s), penetration %.4f m, hinge axes apart by %.2f deg; last fastest corner "
      "%.3f m/s\n",
      file.c_str(), method, bones, o.landedAt, o.restAt - o.landedAt, m.jointGap, m.worstGap.c_str(),
      radToDeg(m.limitExcess), m.worstLimit.c_str(), m.penetration, radToDeg(m.hingeTilt), o.last.fastestCorner);
  ASSERT_GE(o.landedAt, 0.0) << file << ", " << method << ": never touched the ground";
  EXPECT_GE(o.restAt, 0.0) << file << ", " << method << ": not at rest within 10 s of landing";
  EXPECT_LE(o.restAt - o.landedAt, kSettleWithin) << file << ", " << method;
  EXPECT_LT(m.jointGap, kJointTolerance) << file << ", " << method;
  EXPECT_LT(m.limitExcess, kLimitTolerance) << file << ", " << method << ": joint of " << m.worstLimit;
  EXPECT_LT(m.penetration, kGroundTolerance) << file << ", " << method;
}

class RagdollFromBvh : public ::testing::TestWithParam<BvhCase> {};

TEST_P(RagdollFromBvh, LandsAndComesToRestWithBothMethodsWithinTheBounds) {
  const BvhCase& c = GetParam();
  if (c.path.empty()) GTEST_SKIP() << c.skipReason;
  SkeletonFile f;
  f.path = c.path;  // the character scene's default: the rest pose, 1.7 m tall
  Result<LoadedSkeleton> s = loadSkeleton(f);
  ASSERT_TRUE(s.ok()) << s.error();
  if (c.frame == kMiddleFrame) {
    if (s.value().frames < 2) GTEST_SKIP() << c.path << " has no animation";
    f.frame = s.value().frames / 2;
    s = loadSkeleton(f);
    ASSERT_TRUE(s.ok()) << s.error();
  }
  const Result<ragdoll::RagdollDesc> built = ragdoll::buildSkeletonRagdoll(s.value().joints);
  ASSERT_TRUE(built.ok()) << built.error();
  const ragdoll::RagdollDesc d = dropped(built.value());
  const std::string file =
      fs::path(c.path).filename().string() + (f.frame < 0 ? ", rest pose" : ", frame " + std::to_string(f.frame));

  ragdoll::ParticleRagdoll p =
      ragdoll::ParticleRagdoll::build(d, ragdoll::skeletonParticleSettings()).value();  // the scene's
  const Outcome po = run(d, [&] {
    p.step(kDt);
    std::vector<collision::Transform> pose;
    for (int i = 0; i < p.boneCount(); ++i) pose.push_back(p.boneFrame(i));
    return pose;
  });
  expectRests("particle", file, po, d.bones.size());

  ragdoll::ConstraintSettings cs;  // the character scene's
  cs.world = ragdoll::skeletonRagdollWorldSettings();
  ragdoll::ConstraintRagdoll r = ragdoll::ConstraintRagdoll::build(d, cs).value();
  const Outcome ro = run(d, [&] {
    r.step(kDt);
    std::vector<collision::Transform> pose;
    for (int i = 0; i < r.boneCount(); ++i) pose.push_back(r.world().body(r.bodyOf(i)).pose());
    return pose;
  });
  expectRests("constraint", file, ro, d.bones.size());
}

const auto kCaseName = [](const ::testing::TestParamInfo<BvhCase>& i) { return i.param.name; };
INSTANTIATE_TEST_SUITE_P(EveryBvhFile, RagdollFromBvh, ::testing::ValuesIn(bvhCases(-1)), kCaseName);
// Started in the middle frame of each file's animation instead: not yet within the bounds (the particle
// ragdoll's elbows past their limits and boxes too deep, the constraint ragdoll still moving in some files;
// workbook §6.4), so disabled; run with --gtest_also_run_disabled_tests.
INSTANTIATE_TEST_SUITE_P(DISABLED_MiddleFrameOfEveryBvhFile, RagdollFromBvh,
                         ::testing::ValuesIn(bvhCases(kMiddleFrame)), kCaseName);

}  // namespace bvh_rest
}  // namespace pba::lab
