// BVH import against the file: a reader written here walks the HIERARCHY section (ROOT, JOINT and
// End Site blocks with their OFFSETs) and the model must hold the same joints, under the same
// parents, at the same rest offsets. BVH's rest pose has no rotation: a joint's rest position is the
// sum of the OFFSETs from the root down (Meredith & Maddock 2001, "Motion Capture File Formats
// Explained", §3.1).
#include "graphics/model.h"
#include "graphics/skinning.h"
#include "model_file_check.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <sstream>
#include <stdexcept>

namespace {

namespace gfx = pba::graphics;
using namespace pba::testing::models;

struct BvhHierarchy {
  std::vector<FileJoint> joints;  ///< ROOT and JOINT blocks, parents first; local = translate(OFFSET)
  int endSites = 0;               ///< End Site blocks (leaf markers with an offset but no channels)
};

double readNumber(std::istream& in, const std::string& path) {
  double v = 0.0;
  if (!(in >> v)) throw std::runtime_error(path + ": a number expected after OFFSET");
  return v;
}

/// The HIERARCHY section of a BVH file. Assimp names a node after its ROOT/JOINT name.
BvhHierarchy readBvhHierarchy(const std::string& path) {
  std::istringstream in(readBytes(path));
  BvhHierarchy h;
  std::vector<int> open;  // index in h.joints of each open block, -1 for an End Site
  int pending = -1;       // the block whose '{' comes next
  std::string word;
  while (in >> word && word != "MOTION") {
    if (word == "ROOT" || word == "JOINT") {
      FileJoint j;
      in >> j.name;
      for (auto it = open.rbegin(); it != open.rend(); ++it) {
        if (*it >= 0) {
          j.parent = h.joints[static_cast<std::size_t>(*it)].name;
          break;
        }
      }
      pending = static_cast<int>(h.joints.size());
      h.joints.push_back(j);
    } else if (word == "End") {
      in >> word;  // "Site"
      ++h.endSites;
      pending = -1;
    } else if (word == "{") {
      open.push_back(pending);
    } else if (word == "}") {
      if (open.empty()) throw std::runtime_error(path + ": unbalanced '}'");
      open.pop_back();
    } else if (word == "OFFSET") {
      glm::dvec3 offset;
      for (int k = 0; k < 3; ++k) offset[k] = readNumber(in, path);
      if (!open.empty() && open.back() >= 0)
        h.joints[static_cast<std::size_t>(open.back())].local = glm::translate(glm::dmat4(1.0), offset);
    }
  }
  return h;
}

const char* const kBvhFiles[] = {"BVH/01_01.bvh", "BVH/01_03.bvh", "BVH/Boxing_Toes.bvh"};

}  // namespace

TEST(ModelImportBvh, EveryFileJointIsOneNodeUnderItsFileParentAtItsOffset) {
  for (const char* file : kBvhFiles) {
    const std::string path = kAssimpModels + file;
    SCOPED_TRACE(path);
    const gfx::Model m = loadOrFail(path);
    if (m.nodes.empty()) continue;
    const BvhHierarchy h = readBvhHierarchy(path);
    ASSERT_GT(h.joints.size(), 1u);
    EXPECT_EQ(countNodesNamedLike(m, h.joints), static_cast<int>(h.joints.size()));
    // Assimp adds one node per End Site and no other node (the ROOT is the model's root).
    EXPECT_EQ(m.nodes.size(), h.joints.size() + static_cast<std::size_t>(h.endSites));
    EXPECT_EQ(m.nodes[0].name, h.joints[0].name);
    expectJointsMatchTheFile(m, h.joints);
    ::testing::Test::RecordProperty(std::string("joints ") + file, static_cast<int>(h.joints.size()));
  }
}

TEST(ModelImportBvh, NamedJointRestPositionIsTheSumOfItsChainsOffsets) {
  const std::string path = kAssimpModels + "BVH/01_01.bvh";
  const gfx::Model m = loadOrFail(path);
  if (m.nodes.empty()) return;
  const BvhHierarchy h = readBvhHierarchy(path);
  const FileJoint* foot = findJoint(h.joints, "LeftFoot");
  ASSERT_NE(foot, nullptr) << "the reader found no LeftFoot in " << path;
  glm::dvec3 expected(0.0);
  for (const FileJoint* j = foot; j != nullptr; j = j->parent.empty() ? nullptr : findJoint(h.joints, j->parent))
    expected += glm::dvec3(j->local[3]);
  ASSERT_GT(glm::length(expected), 1.0) << "a joint away from the root makes the sum meaningful";
  const int node = m.findNode("LeftFoot");
  ASSERT_GE(node, 0);
  const glm::vec3 actual(gfx::globalTransforms(m, gfx::restPose(m))[static_cast<std::size_t>(node)][3]);
  expectTranslationNear(actual, expected, "LeftFoot rest position");
}

TEST(ModelImportBvh, TruncatedFileGivesAnErrorNamingThePath) {
  expectTruncatedCopyFails(kAssimpModels + "BVH/Boxing_Toes.bvh");
}
