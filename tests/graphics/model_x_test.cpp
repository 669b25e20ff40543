// DirectX .X (text) import against the file: a reader written here tokenises the file, follows the
// nesting of its data objects and keeps the Frame blocks (the skeleton of an .X file: one frame per
// joint, nested as the hierarchy), their FrameTransformMatrix and the bone names of the SkinWeights
// blocks. The model must hold the same frames under the same parents with the same transforms.
#include "graphics/model.h"
#include "model_file_check.h"

#include <gtest/gtest.h>

#include <cctype>
#include <set>
#include <stdexcept>

namespace {

namespace gfx = pba::graphics;
using namespace pba::testing::models;

struct XSkeleton {
  std::vector<FileJoint> frames;    ///< Frame blocks, parents first
  int topLevelFrames = 0;           ///< frames not nested in another frame
  std::set<std::string> skinBones;  ///< transformNodeName of every SkinWeights block
};

/// Tokens of a text .X file: '{', '}', quoted strings (quotes kept), and words; ',' and ';' end a
/// word and are returned as ";" (a list separator); "//" and "#" start comments.
std::vector<std::string> tokenizeX(const std::string& text) {
  std::vector<std::string> tokens;
  std::size_t i = text.find('\n');  // skip the "xof 0303txt 0032" header line
  while (i < text.size()) {
    const char c = text[i];
    if (std::isspace(static_cast<unsigned char>(c))) {
      ++i;
    } else if (c == '#' || (c == '/' && i + 1 < text.size() && text[i + 1] == '/')) {
      i = text.find('\n', i);
    } else if (c == '{' || c == '}') {
      tokens.emplace_back(1, c), ++i;
    } else if (c == ',' || c == ';') {
      tokens.emplace_back(";"), ++i;
    } else if (c == '"') {
      const std::size_t end = text.find('"', i + 1);
      if (end == std::string::npos) throw std::runtime_error("unterminated string");
      tokens.push_back(text.substr(i, end + 1 - i));
      i = end + 1;
    } else {
      std::size_t end = i;
      while (end < text.size() && !std::isspace(static_cast<unsigned char>(text[end])) &&
             std::string("{};,\"").find(text[end]) == std::string::npos)
        ++end;
      tokens.push_back(text.substr(i, end - i));
      i = end;
    }
  }
  return tokens;
}

/// A data object starts with "<Type> [<name>] {" ; "template" blocks declare types and hold no data.
/// Assimp names a node after its frame. An .X matrix is written row by row for row vectors
/// (translation in the last row), so its 16 numbers in file order are exactly the column-major
/// storage of the column-vector matrix that GLM holds.
XSkeleton readXSkeleton(const std::string& path) {
  const std::vector<std::string> tokens = tokenizeX(readBytes(path));
  struct Block {
    std::string type;
    int frame = -1;  // index in frames for a Frame block
  };
  XSkeleton x;
  std::vector<Block> open;
  std::vector<std::string> header;  // words since the last '{', '}' or ';'
  std::vector<double> numbers;      // numbers inside the open FrameTransformMatrix
  const auto enclosingFrame = [&]() {
    for (auto it = open.rbegin(); it != open.rend(); ++it)
      if (it->frame >= 0) return it->frame;
    return -1;
  };
  for (const std::string& t : tokens) {
    if (t == "{") {
      Block b{header.empty() ? "" : header[0]};
      if (b.type == "Frame" && header.size() >= 2) {
        FileJoint f;
        f.name = header[1];
        const int parent = enclosingFrame();
        if (parent >= 0)
          f.parent = x.frames[static_cast<std::size_t>(parent)].name;
        else
          ++x.topLevelFrames;
        b.frame = static_cast<int>(x.frames.size());
        x.frames.push_back(f);
      }
      if (b.type == "FrameTransformMatrix") numbers.clear();
      open.push_back(b);
      header.clear();
    } else if (t == "}") {
      if (open.empty()) throw std::runtime_error(path + ": unbalanced '}'");
      if (open.back().type == "FrameTransformMatrix" && enclosingFrame() >= 0) {
        if (numbers.size() != 16) throw std::runtime_error(path + ": FrameTransformMatrix without 16 numbers");
        glm::dmat4& m = x.frames[static_cast<std::size_t>(enclosingFrame())].local;
        for (int k = 0; k < 16; ++k) m[k / 4][k % 4] = numbers[static_cast<std::size_t>(k)];
      }
      open.pop_back();
      header.clear();
    } else if (t == ";") {
      header.clear();
    } else {
      header.push_back(t);
      if (open.empty()) continue;
      if (open.back().type == "FrameTransformMatrix") numbers.push_back(std::stod(t));
      // The first field of a SkinWeights object is the bone's frame name, a quoted string.
      if (open.back().type == "SkinWeights" && t.front() == '"' && header.size() == 1)
        x.skinBones.insert(t.substr(1, t.size() - 2));
    }
  }
  return x;
}

/// Assimp's .X importer turns Direct3D's left-handed frame into a right-handed one by mirroring z
/// (its MakeLeftHanded step): every transform M becomes S·M·S with S = diag(1, 1, −1, 1), i.e. the
/// entries of the third row and the third column change sign, the (z, z) entry keeps its own.
glm::dmat4 mirrorZ(const glm::dmat4& m) {
  const glm::dmat4 s(glm::dvec4(1, 0, 0, 0), glm::dvec4(0, 1, 0, 0), glm::dvec4(0, 0, -1, 0), glm::dvec4(0, 0, 0, 1));
  return s * m * s;
}

const char* const kXFiles[] = {"X/Testwuson.X", "X/BCN_Epileptic.X", "X/anim_test.x"};

}  // namespace

TEST(ModelImportX, EveryFrameIsOneNodeUnderItsFileParentWithItsMirroredTransform) {
  for (const char* file : kXFiles) {
    const std::string path = kAssimpModels + file;
    SCOPED_TRACE(path);
    const gfx::Model m = loadOrFail(path);
    if (m.nodes.empty()) continue;
    XSkeleton x = readXSkeleton(path);
    ASSERT_GT(x.frames.size(), 1u);
    EXPECT_EQ(countNodesNamedLike(m, x.frames), static_cast<int>(x.frames.size()));
    // Assimp adds a root ("$dummy_root") only when the file has several top-level frames.
    EXPECT_EQ(m.nodes.size(), x.frames.size() + (x.topLevelFrames > 1 ? 1u : 0u));
    for (FileJoint& f : x.frames) f.local = mirrorZ(f.local);
    expectJointsMatchTheFile(m, x.frames);
    ::testing::Test::RecordProperty(std::string("frames ") + file, static_cast<int>(x.frames.size()));
  }
}

TEST(ModelImportX, SkinBonesAreTheSkinWeightsNamesAndFollowTheirFrames) {
  for (const char* file : kXFiles) {
    const std::string path = kAssimpModels + file;
    SCOPED_TRACE(path);
    const gfx::Model m = loadOrFail(path);
    if (m.nodes.empty()) continue;
    const XSkeleton x = readXSkeleton(path);
    ASSERT_FALSE(x.skinBones.empty());
    EXPECT_EQ(m.bones.size(), x.skinBones.size());
    for (const std::string& bone : x.skinBones) {
      const int b = m.findBone(bone);
      ASSERT_GE(b, 0) << bone;
      // anim_test.x weights vertices to "joint3" and "joint4", which are no frames of the file: such a
      // bone has no node (skinning then uses the identity for it, see skinning.h).
      if (findJoint(x.frames, bone) == nullptr) {
        EXPECT_EQ(m.bones[static_cast<std::size_t>(b)].node, -1) << bone;
      } else {
        EXPECT_EQ(m.bones[static_cast<std::size_t>(b)].node, m.findNode(bone)) << bone;
      }
    }
    ::testing::Test::RecordProperty(std::string("skin bones ") + file, static_cast<int>(x.skinBones.size()));
  }
}

TEST(ModelImportX, NamedJointRestTranslationIsTheFilesWithZMirrored) {
  const std::string path = kAssimpModels + "X/Testwuson.X";
  const gfx::Model m = loadOrFail(path);
  if (m.nodes.empty()) return;
  const XSkeleton x = readXSkeleton(path);
  const FileJoint* hip = findJoint(x.frames, "HindLeg_L_01");
  ASSERT_NE(hip, nullptr) << "the reader found no HindLeg_L_01 in " << path;
  const glm::dvec3 file(hip->local[3]);
  ASSERT_GT(std::abs(file.z), 0.1) << "a joint off the z = 0 plane makes the mirror visible";
  expectLocalTranslationNear(m, "HindLeg_L_01", glm::dvec3(file.x, file.y, -file.z));
}

TEST(ModelImportX, TruncatedFileGivesAnErrorNamingThePath) {
  expectTruncatedCopyFails(kAssimpModels + "X/Testwuson.X");
}
