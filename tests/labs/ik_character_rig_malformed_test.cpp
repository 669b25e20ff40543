// The IK character's import refuses what the corpora found it mishandling (tests/corpora/models):
// duplicate joint names, files where nothing can move, skeletons too large for the Jacobian.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "app/assets/character_rig.h"

namespace pba::app {
namespace {

std::string rigError(const std::string& name, const std::string& text, const std::string& effectors = "") {
  const std::string path = (std::filesystem::temp_directory_path() / ("pba_rig_" + name)).string();
  std::ofstream(path) << text;
  CharacterDesc d;
  d.skeleton = path;
  d.effectors = effectors;
  const Result<pba::ik::Rig> r = loadCharacterRig(d);
  std::filesystem::remove(path);
  EXPECT_FALSE(r.ok()) << name << " loaded";
  return r.ok() ? "" : r.error();
}

/// A root with `children` joints below it, each with an end site; every name from `name(i)`.
template <typename Name>
std::string starBvh(int children, Name name) {
  std::string t = "HIERARCHY\nROOT Hips\n{\n  OFFSET 0 0 0\n  CHANNELS 3 Xposition Yposition Zposition\n";
  for (int i = 0; i < children; ++i)
    t += "  JOINT " + name(i) + "\n  {\n    OFFSET " + std::to_string(i % 7) +
         " 1 0\n    CHANNELS 3 Zrotation Xrotation Yrotation\n    End Site\n    {\n      OFFSET 0 1 0\n    }\n  }\n";
  t += "}\nMOTION\nFrames: 1\nFrame Time: 0.033333\n0 0 0";
  for (int i = 0; i < children; ++i) t += " 0 0 0";
  return t + "\n";
}

TEST(IkCharacterRigMalformed, TwoJointsOfOneNameAreRefused) {
  const std::string e = rigError("twins.bvh", starBvh(2, [](int) { return std::string("Arm"); }));
  EXPECT_NE(e.find(": joint name 'Arm' is used by joints 1 and 3 (names must be unique)"), std::string::npos) << e;
}

TEST(IkCharacterRigMalformed, AFileWhereNoJointCanMoveIsNotASkeleton) {
  const std::string e = rigError("quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\n");
  EXPECT_NE(e.find(": no joint can move ("), std::string::npos) << e;
}

TEST(IkCharacterRigMalformed, TooManyJointsOrEffectorsAreRefusedBeforeTheJacobianIsBuilt) {
  // 20,000 joints made the first solve allocate a 28 GB Jacobian (std::bad_alloc, exit 1).
  auto name = [](int i) { return "J" + std::to_string(i); };
  const std::string joints = rigError("many.bvh", starBvh(600, name));
  EXPECT_NE(joints.find(": has 1201 joints; the character scene takes at most 1000"), std::string::npos) << joints;
  const std::string effectors = rigError("leaves.bvh", starBvh(100, name));
  EXPECT_NE(effectors.find("effectors: 100 effectors in "), std::string::npos) << effectors;
  // Naming a few of them is the way out.
  const std::string path = (std::filesystem::temp_directory_path() / "pba_rig_named.bvh").string();
  std::ofstream(path) << starBvh(100, name);
  CharacterDesc d;
  d.skeleton = path;
  d.effectors = "J1,J2";
  const Result<pba::ik::Rig> r = loadCharacterRig(d);
  std::filesystem::remove(path);
  ASSERT_TRUE(r.ok()) << r.error();
  EXPECT_EQ(r.value().effectors.size(), 2u);
}

}  // namespace
}  // namespace pba::app
