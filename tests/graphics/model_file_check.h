// Shared checks for the model import tests: loading a file of Debian's assimp-testmodels, comparing
// the skeleton that gfx::loadModel returns with the one a small per-format reader found in the file
// itself (never with numbers copied from the file by hand, never with the loader's own output), and
// feeding the loader a truncated copy of a real file.
#pragma once

#include "graphics/model.h"

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <vector>

#include "support/unique_name.h"

namespace pba::testing::models {

namespace gfx = pba::graphics;

/// Debian's assimp-testmodels folder (tests/CMakeLists.txt finds it; these tests are built only then).
inline const std::string kAssimpModels = PBA_ASSIMP_TEST_MODELS;
/// The model files shipped with the labs (resources/models/).
inline const std::string kShippedModels = PBA_TEST_RESOURCE_DIR "/models/";

/// True when the file exists; otherwise records a failure that names the package to install.
inline bool testModelPresent(const std::string& path) {
  if (std::filesystem::exists(path)) return true;
  ADD_FAILURE() << path << " is missing (resources/models, or Debian's assimp-testmodels)";
  return false;
}

/// The model, or an empty one after a recorded failure (missing package or an import error).
inline gfx::Model loadOrFail(const std::string& path) {
  if (!testModelPresent(path)) return {};
  std::string error;
  auto model = gfx::loadModel(path, &error);
  EXPECT_TRUE(model.has_value()) << error;
  return model ? *model : gfx::Model{};
}

inline std::string readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// A scratch directory of its own (a random token keeps parallel runs of the release and sanitizer
/// builds apart, the counter two directories of one test), removed with its files at scope end.
class ScratchDir {
 public:
  ScratchDir() {
    static int created = 0;
    path_ = std::filesystem::temp_directory_path() /
            ("pba-model-test-" + pba::testing::processUniqueToken() + "-" + std::to_string(created++));
    std::filesystem::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  /// Writes bytes to <dir>/<name> and returns the full path.
  std::string write(const std::string& name, const std::string& bytes) const {
    const std::string file = (path_ / name).string();
    std::ofstream(file, std::ios::binary) << bytes;
    return file;
  }

 private:
  std::filesystem::path path_;
};

/// A real file cut to half its length must give an error that names the copy's path and a reason,
/// and must not crash (the sanitizer build runs this too).
inline void expectTruncatedCopyFails(const std::string& path) {
  if (!testModelPresent(path)) return;
  const std::string bytes = readBytes(path);
  ASSERT_GT(bytes.size(), 100u) << path;
  const ScratchDir dir;
  const std::string copy =
      dir.write("truncated-" + std::filesystem::path(path).filename().string(), bytes.substr(0, bytes.size() / 2));
  std::string error;
  EXPECT_FALSE(gfx::loadModel(copy, &error).has_value()) << copy << " was accepted";
  EXPECT_NE(error.find(copy), std::string::npos) << error;
  EXPECT_GT(error.size(), copy.size() + 2) << "the reason must follow the path: " << error;
}

/// One node of a file's hierarchy as the test's own reader found it.
struct FileJoint {
  std::string name;       ///< the name Assimp gives the node (each reader states the format's rule)
  std::string parent;     ///< the file parent's name (any node type); empty at the top of the file
  glm::dmat4 local{1.0};  ///< rest transform relative to the parent, in the file's units
};

inline const FileJoint* findJoint(const std::vector<FileJoint>& joints, const std::string& name) {
  for (const FileJoint& j : joints)
    if (j.name == name) return &j;
  return nullptr;
}

/// Number of model nodes whose name is one of the joints' names.
inline int countNodesNamedLike(const gfx::Model& model, const std::vector<FileJoint>& joints) {
  std::set<std::string> names;
  for (const FileJoint& j : joints) names.insert(j.name);
  return static_cast<int>(std::count_if(model.nodes.begin(), model.nodes.end(),
                                        [&](const gfx::ModelNode& n) { return names.count(n.name) > 0; }));
}

/// Nodes that Assimp inserts between a node and its file parent; none by default.
using HelperNodeTest = bool (*)(const std::string& name);
inline bool noHelperNodes(const std::string&) { return false; }

/// Tolerance: the model stores float (24-bit mantissa, relative rounding 6e-8) while the readers keep
/// double; the loader composes at most a few matrices, so 1e-5 relative to the entry's size (and
/// 1e-5 absolute near zero) is far above its rounding and far below any misread value.
inline void expectTransformNear(const glm::mat4& actual, const glm::dmat4& expected, const std::string& what) {
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      EXPECT_NEAR(actual[c][r], expected[c][r], 1e-5 * (1.0 + std::abs(expected[c][r])))
          << what << ": row " << r << ", column " << c;
    }
  }
}

/// A translation (or position) against the file's, with expectTransformNear's tolerance.
inline void expectTranslationNear(const glm::vec3& actual, const glm::dvec3& expected, const std::string& what) {
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(actual[k], expected[k], 1e-5 * (1.0 + std::abs(expected[k]))) << what << ", axis " << k;
}

/// The rest translation of the named node relative to its parent node against the file's.
inline void expectLocalTranslationNear(const gfx::Model& model, const std::string& name, const glm::dvec3& expected) {
  const int node = model.findNode(name);
  ASSERT_GE(node, 0) << name;
  expectTranslationNear(glm::vec3(model.nodes[static_cast<std::size_t>(node)].local[3]), expected, name);
}

/// Every file joint is exactly one model node; its first ancestor that is not an Assimp helper node
/// is the file parent (for a joint at the top of the file: the model root Assimp may add, or none);
/// and its local transform, composed with those of the helpers in between, equals the file's.
inline void expectJointsMatchTheFile(const gfx::Model& model, const std::vector<FileJoint>& joints,
                                     HelperNodeTest isHelper = noHelperNodes) {
  for (const FileJoint& joint : joints) {
    const auto sameName = [&](const gfx::ModelNode& n) { return n.name == joint.name; };
    ASSERT_EQ(std::count_if(model.nodes.begin(), model.nodes.end(), sameName), 1) << joint.name;
    const int node = model.findNode(joint.name);
    glm::mat4 local = model.nodes[static_cast<std::size_t>(node)].local;
    int ancestor = model.nodes[static_cast<std::size_t>(node)].parent;
    while (ancestor >= 0 && isHelper(model.nodes[static_cast<std::size_t>(ancestor)].name)) {
      local = model.nodes[static_cast<std::size_t>(ancestor)].local * local;
      ancestor = model.nodes[static_cast<std::size_t>(ancestor)].parent;
    }
    if (joint.parent.empty()) {
      EXPECT_LE(ancestor, 0) << joint.name << " is at the top of the file";
    } else {
      ASSERT_GE(ancestor, 0) << joint.name << " lost its parent " << joint.parent;
      EXPECT_EQ(model.nodes[static_cast<std::size_t>(ancestor)].name, joint.parent) << joint.name;
    }
    expectTransformNear(local, joint.local, joint.name + " local transform");
  }
}

}  // namespace pba::testing::models
