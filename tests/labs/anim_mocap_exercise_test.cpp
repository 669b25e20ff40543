// ANIM-3 on real motion capture: the animation lab's playback of a BVH file (Assimp import →
// clip → forward kinematics) against a reader and a forward kinematics written here from the file
// format (Meredith & Maddock 2001, "Motion Capture File Formats Explained", §3.1): each joint's local
// transform is T(t) · R(channel 1) · R(channel 2) · R(channel 3) in the order the CHANNELS line lists
// the rotations, with t the position channels where the joint has them (the CMU convention Assimp
// follows), else its OFFSET; world = parent world · local. Positions in metres after the lab's scale.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>

#include "bvh_import.h"
#include "clip_import.h"
#include "graphics/model.h"
#include "graphics/skinning.h"
#include "physics/animation/skeleton.h"

namespace {

using pba::Real;
using pba::Vec3;
namespace an = pba::animation;
namespace lab = pba::labs::animation;

struct BvhJoint {
  std::string name;
  int parent = -1;
  Vec3 offset{0.0};
  std::vector<std::string> channels;
  int firstChannel = 0;
};

struct Bvh {
  std::vector<BvhJoint> joints;
  std::vector<std::vector<Real>> frames;
  Real frameTime = 0.0;  // [s]
};

Bvh readBvh(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open");
  Bvh b;
  std::vector<int> open;
  int pending = -1, channelCount = 0;
  std::string w;
  while (in >> w && w != "MOTION") {
    if (w == "ROOT" || w == "JOINT") {
      BvhJoint j;
      in >> j.name;
      for (auto it = open.rbegin(); it != open.rend(); ++it)
        if (*it >= 0) {
          j.parent = *it;
          break;
        }
      pending = static_cast<int>(b.joints.size());
      b.joints.push_back(j);
    } else if (w == "End") {
      in >> w;
      pending = -1;
    } else if (w == "{") {
      open.push_back(pending);
    } else if (w == "}") {
      open.pop_back();
    } else if (w == "OFFSET") {
      Vec3 o;
      in >> o.x >> o.y >> o.z;
      if (!open.empty() && open.back() >= 0) b.joints[static_cast<size_t>(open.back())].offset = o;
    } else if (w == "CHANNELS") {
      int n = 0;
      in >> n;
      BvhJoint& j = b.joints[static_cast<size_t>(open.back())];
      j.firstChannel = channelCount;
      for (int k = 0; k < n; ++k) {
        in >> w;
        j.channels.push_back(w);
      }
      channelCount += n;
    }
  }
  int frames = 0;
  in >> w >> frames >> w >> w >> b.frameTime;  // "Frames:" N "Frame" "Time:" dt
  for (int f = 0; f < frames; ++f) {
    std::vector<Real> row(static_cast<size_t>(channelCount));
    for (Real& v : row) in >> v;
    b.frames.push_back(row);
  }
  return b;
}

/// World joint positions [file units] of frame f.
std::vector<Vec3> bvhForwardKinematics(const Bvh& b, size_t f) {
  std::vector<glm::dmat4> world(b.joints.size());
  std::vector<Vec3> out;
  for (size_t j = 0; j < b.joints.size(); ++j) {
    const BvhJoint& joint = b.joints[j];
    Vec3 t = joint.offset;
    bool hasPosition = false;
    glm::dmat4 r(1.0);
    for (size_t c = 0; c < joint.channels.size(); ++c) {
      const Real v = b.frames[f][static_cast<size_t>(joint.firstChannel) + c];
      const std::string& name = joint.channels[c];
      const int axis = name[0] == 'X' ? 0 : name[0] == 'Y' ? 1 : 2;
      if (name.find("position") != std::string::npos) {
        if (!hasPosition) t = Vec3(0.0);
        hasPosition = true;
        t[axis] = v;
      } else {
        Vec3 a(0.0);
        a[axis] = 1.0;
        r = r * glm::rotate(glm::dmat4(1.0), v * pba::kPi / 180.0, a);
      }
    }
    const glm::dmat4 local = glm::translate(glm::dmat4(1.0), t) * r;
    world[j] = joint.parent < 0 ? local : world[static_cast<size_t>(joint.parent)] * local;
    out.emplace_back(world[j][3]);
  }
  return out;
}

void expectPlaybackMatchesTheFile(const std::string& path, int samples, Real tolerance) {
  SCOPED_TRACE(path);
  const Bvh file = readBvh(path);
  ASSERT_GT(file.frames.size(), 1u);
  const pba::Result<lab::ImportedClip> imported = lab::importClip(path, 1.7);
  ASSERT_TRUE(imported.ok()) << imported.error();
  const lab::ImportedClip& c = imported.value();
  an::Pose pose;
  Real worst = 0.0;
  for (int s = 0; s < samples; ++s) {
    const size_t f = (file.frames.size() - 1) * static_cast<size_t>(s) / static_cast<size_t>(std::max(samples - 1, 1));
    an::samplePose(c.skeleton, c.clip, static_cast<Real>(f) * file.frameTime, pose);
    const std::vector<an::JointWorld> world = an::forwardKinematics(c.skeleton, pose);
    const std::vector<Vec3> expected = bvhForwardKinematics(file, f);
    for (size_t j = 0; j < file.joints.size(); ++j) {
      const int k = c.skeleton.find(file.joints[j].name);
      ASSERT_GE(k, 0) << "no joint " << file.joints[j].name;
      const Vec3 d = world[static_cast<size_t>(k)].position - c.scale * expected[j];
      worst = std::max(worst, glm::length(d));
      EXPECT_LT(glm::length(d), tolerance) << "frame " << f << " joint " << file.joints[j].name;
    }
  }
  std::cout << "largest joint distance from the file's forward kinematics " << worst << " m\n";
}

TEST(ANIM_3_MocapPlayback, HumanoidBvhJointsMatchAnIndependentForwardKinematicsOfItsChannels) {
  expectPlaybackMatchesTheFile(lab::resolveResourcePath("resources/models/humanoid.bvh"), 2, 1e-6);
}

TEST(ANIM_3_MocapPlayback, CmuBvhOfAssimpTestModelsMatchesAnIndependentForwardKinematics) {
  const std::string path = PBA_TEST_RESOURCE_DIR "/models/mocap/01_01.bvh";
  ASSERT_TRUE(std::ifstream(path).good())
      << path << " missing: install the Debian package assimp-testmodels (./pba installs it)";
  // The lab reads .bvh files in double (bvh_import.h); through Assimp's float keys this file was 2.3e-6 m
  // off. Both files are checked at the 1e-6 m.
  expectPlaybackMatchesTheFile(path, 12, 1e-6);
}

TEST(MocapImport, FileWithoutAnimationOrUnreadableIsAnErrorNamingTheFile) {
  const std::string dir = ::testing::TempDir();
  const std::string obj = dir + "/anim_still.obj";
  std::ofstream(obj) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  const pba::Result<lab::ImportedClip> still = lab::importClip(obj, 1.7);
  ASSERT_FALSE(still.ok());
  EXPECT_NE(still.error().find("skeleton: " + obj), std::string::npos) << still.error();
  EXPECT_NE(still.error().find("no animation"), std::string::npos) << still.error();
  const pba::Result<lab::ImportedClip> missing = lab::importClip(dir + "/nope.bvh", 1.7);
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.error().find("nope.bvh"), std::string::npos) << missing.error();
  EXPECT_FALSE(lab::importClip(obj, 0.0).ok());
}

}  // namespace

// The mocap scene's skin (app/character_skin.h): the file's mesh posed by the lab's own route (clip →
// forward kinematics → joint frames → skinning matrices) against a route written here from the file:
// Assimp's node transforms sampled at the same time by the graphics import (graphics::sampleAnimation),
// multiplied down the node tree, and each vertex blended by hand, v' = Σ wᵢ (G_bᵢ · offset_bᵢ) v, then
// scaled like the lab's character. Debian assimp-testmodels' Wuson (X/Testwuson.X): a skinned mesh of
// 40 nodes with a 30-frame animation.
TEST(ANIM_3_MocapSkin, WusonMeshFollowsAnIndependentLinearBlendOfTheFilesAnimation) {
  const std::string path = PBA_TEST_RESOURCE_DIR "/models/Testwuson.X";
  ASSERT_TRUE(std::ifstream(path).good()) << path << " missing: install assimp-testmodels (./pba installs it)";
  const pba::Result<lab::ImportedClip> imported = lab::importClip(path, 1.7);
  ASSERT_TRUE(imported.ok()) << imported.error();
  const lab::ImportedClip& c = imported.value();
  ASSERT_TRUE(c.skin.model) << "the Wuson has a mesh";
  const pba::graphics::Model& model = *c.skin.model;
  ASSERT_FALSE(model.animations.empty());
  Real largestMove = 0.0, worst = 0.0;
  std::vector<Vec3> first;
  int checked = 0;
  for (int s = 0; s < 6; ++s) {
    const Real t = c.clip.duration * s / 5.0;
    an::Pose pose;
    an::samplePose(c.skeleton, c.clip, t, pose);
    const std::vector<pba::app::SkinSurface> lab = pba::app::poseSkin(c.skin, an::forwardKinematics(c.skeleton, pose));
    // The reference: Assimp's pose of the nodes, blended here.
    const std::vector<glm::mat4> local =
        pba::graphics::sampleAnimation(model, model.animations[0], static_cast<float>(t), /*loop=*/false);
    std::vector<glm::dmat4> global(model.nodes.size());
    for (size_t n = 0; n < model.nodes.size(); ++n) {
      const int p = model.nodes[n].parent;
      global[n] = p < 0 ? glm::dmat4(local[n]) : global[static_cast<size_t>(p)] * glm::dmat4(local[n]);
    }
    std::vector<Vec3> all;
    for (const pba::app::SkinSurface& surface : lab) {
      const pba::graphics::ModelMesh& mesh = model.meshes[surface.mesh];
      ASSERT_TRUE(mesh.skinned());
      ASSERT_EQ(surface.positions.size(), mesh.positions.size());
      for (size_t v = 0; v < mesh.positions.size(); ++v) {
        glm::dvec4 blended(0.0);
        for (int k = 0; k < 4; ++k) {
          const double w = mesh.boneWeights[v][k];
          if (w == 0.0) continue;
          const pba::graphics::ModelBone& bone = model.bones[static_cast<size_t>(mesh.boneIds[v][k])];
          blended += w * (global[static_cast<size_t>(bone.node)] * glm::dmat4(bone.offset) *
                          glm::dvec4(glm::dvec3(mesh.positions[v]), 1.0));
        }
        const Vec3 expected = c.scale * Vec3(blended);
        worst = std::max(worst, glm::length(surface.positions[v] - expected));
        all.push_back(surface.positions[v]);
        ++checked;
      }
    }
    if (s == 0) first = all;
    for (size_t v = 0; v < all.size() && v < first.size(); ++v)
      largestMove = std::max(largestMove, glm::length(all[v] - first[v]));
  }
  // Float vertices, bone matrices and keys (relative error 6e-8) on a 1.7 m character: micrometres.
  EXPECT_LT(worst, 1e-5) << "largest vertex difference [m] over " << checked << " vertex poses";
  // The clip moves the mesh (the Wuson walks its legs): centimetres, not a still picture.
  EXPECT_GT(largestMove, 0.02) << "largest vertex displacement from the first sample [m]";
  std::cout << "worst " << worst << " m, largest move " << largestMove << " m, " << checked << " vertex poses\n";
}

// The double-precision BVH reader builds the skeleton Assimp's nodes give (bvh_import.h): the same joint
// names in the same order (End Sites as "EndSite_<parent>") and the same rest offsets.
TEST(MocapImport, BvhReaderNamesAndOrdersTheJointsAsTheAssimpImport) {
  for (const std::string& path : {lab::resolveResourcePath("resources/models/humanoid.bvh"),
                                  std::string(PBA_TEST_RESOURCE_DIR "/models/mocap/01_01.bvh")}) {
    SCOPED_TRACE(path);
    const pba::Result<lab::BvhClip> read = lab::readBvh(path);
    ASSERT_TRUE(read.ok()) << read.error();
    std::string error;
    const std::optional<pba::graphics::Model> model = pba::graphics::loadModel(path, &error);
    ASSERT_TRUE(model) << error;
    const an::Skeleton& s = read.value().skeleton;
    ASSERT_EQ(s.names.size(), model->nodes.size());
    for (size_t j = 0; j < s.names.size(); ++j) {
      EXPECT_EQ(s.names[j], model->nodes[j].name) << "joint " << j;
      EXPECT_EQ(s.parents[j], model->nodes[j].parent) << s.names[j];
      EXPECT_LT(glm::length(s.restTranslations[j] - Vec3(model->nodes[j].local[3])), 1e-5) << s.names[j];
    }
  }
}

// The reader's own errors (importClip shows the graphics import's for these files, which reads them
// first: tests/corpora/expected.tsv).
TEST(MocapImport, MalformedBvhIsAnErrorNamingTheFileAndTheLine) {
  const std::string dir = ::testing::TempDir();
  const struct {
    const char* text;
    const char* expected;
  } cases[] = {
      {"HIERARCHY\nROOT Hips\n{\n OFFSET 0 oops 0\n", "line 4: expected OFFSET and 3 numbers"},
      {"HIERARCHY\nROOT Hips\n{\n OFFSET 0 0 0\n CHANNELS 3 Zrotation Wrotation Yrotation\n}\n",
       "line 5: unknown channel 'Wrotation'"},
      {"HIERARCHY\nROOT Hips\n{\n OFFSET 0 0 0\n CHANNELS 1 Zrotation\n}\nMOTION\nFrames: 2\nFrame Time: 0.1\n1\n",
       "line 10: frame 1: expected 1 numbers"},
      {"HIERARCHY\nROOT A\n{\n OFFSET 0 0 0\n CHANNELS 0\n JOINT A\n {\n  OFFSET 0 1 0\n  CHANNELS 0\n }\n}\n",
       "line 8: joint name 'A' is used twice"},
  };
  for (const auto& c : cases) {
    const std::string path = dir + "/anim_bad.bvh";
    std::ofstream(path) << c.text;
    const pba::Result<lab::BvhClip> r = lab::readBvh(path);
    ASSERT_FALSE(r.ok()) << c.text;
    EXPECT_EQ(r.error().rfind(path + ": " + c.expected, 0), 0u) << r.error();
  }
}
