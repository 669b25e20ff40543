// Animation kernels (docs/performance-animation.md): the cost of playing a clip per joint per frame
// (sample every channel, then forward kinematics), the CPU part of skinning a mesh to that pose, and
// 100 characters playing at once (the 2 ms frame budget of docs/architecture.md §8).
#include <cmath>
#include <random>
#include <vector>

#include <benchmark/benchmark.h>

#include "graphics/skinning.h"
#include "physics/animation/builders.h"
#include "physics/animation/clip.h"

namespace {
using namespace pba;
namespace an = pba::animation;

/// A 31-joint mocap-like clip: the CMU skeleton's size (01_01.bvh: 31 joints), 120 frames per second
/// for `seconds`, one rotation key per joint per frame (slerp) and root translation keys (linear).
struct Mocap {
  an::Skeleton skeleton;
  an::Clip clip;
};
Mocap makeMocap(int joints, Real seconds) {
  Mocap m;
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  m.skeleton.add("root", -1, Vec3(0.0, 1.0, 0.0));
  for (int j = 1; j < joints; ++j)
    m.skeleton.add(std::string("j") + std::to_string(j), (j - 1) / 2, Vec3(0.05 * u(rng), -0.12, 0.05 * u(rng)));
  m.clip.name = "mocap";
  m.clip.duration = seconds;
  m.clip.tracks.resize(static_cast<size_t>(joints));
  const int frames = static_cast<int>(120.0 * seconds);
  m.clip.frames = frames;
  for (int f = 0; f < frames; ++f) {
    const Real t = f / 120.0;
    static_cast<void>(m.clip.tracks[0].translation.insert(t, Vec3(0.5 * std::sin(t), 1.0, 0.3 * t)));
    for (int j = 0; j < joints; ++j)
      static_cast<void>(m.clip.tracks[static_cast<size_t>(j)].rotation.insert(
          t, glm::angleAxis(0.5 * std::sin(3.0 * t + j), glm::normalize(Vec3(1.0, 0.3 * j, 0.2)))));
  }
  return m;
}

void BM_PlayClipPerJoint(benchmark::State& state) {
  const Mocap m = makeMocap(static_cast<int>(state.range(0)), 10.0);
  an::Pose pose;
  Real t = 0.0;
  for (auto _ : state) {
    an::playPose(m.skeleton, m.clip, t, {true, an::RootMotion::Accumulate}, pose);
    std::vector<an::JointWorld> world = an::forwardKinematics(m.skeleton, pose);
    benchmark::DoNotOptimize(world.data());
    t += 1.0 / 60.0;
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));  // items: joints evaluated
  state.SetLabel("sample + FK, 120 Hz keys, per frame");
}
BENCHMARK(BM_PlayClipPerJoint)->Arg(31);

/// CPU linear blend skinning of `vertices` vertices (4 bones each) on the 31-joint pose.
void BM_SkinCpu31Joints(benchmark::State& state) {
  const Mocap m = makeMocap(31, 2.0);
  graphics::ModelMesh mesh;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const int vertices = static_cast<int>(state.range(0));
  for (int v = 0; v < vertices; ++v) {
    mesh.positions.emplace_back(u(rng), u(rng), u(rng));
    mesh.normals.emplace_back(0.0f, 1.0f, 0.0f);
    const glm::vec4 w(u(rng), u(rng), u(rng), u(rng));
    mesh.boneWeights.push_back(w / (w.x + w.y + w.z + w.w));
    mesh.boneIds.emplace_back(v % 31, (v + 7) % 31, (v + 13) % 31, (v + 29) % 31);
  }
  an::Pose pose;
  std::vector<glm::mat4> skinning(31);
  Real t = 0.0;
  for (auto _ : state) {
    an::playPose(m.skeleton, m.clip, t, {}, pose);
    const std::vector<an::JointWorld> world = an::forwardKinematics(m.skeleton, pose);
    for (size_t j = 0; j < world.size(); ++j)  // bind pose at the origin: offset = identity
      skinning[j] = glm::mat4(glm::translate(glm::dmat4(1.0), world[j].position) * glm::mat4_cast(world[j].rotation));
    std::vector<glm::vec3> skinned = graphics::skinPositions(mesh, skinning);
    benchmark::DoNotOptimize(skinned.data());
    t += 1.0 / 60.0;
  }
  state.SetItemsProcessed(state.iterations() * vertices);  // items: vertices skinned
  state.SetLabel("sample + FK + LBS positions");
}
BENCHMARK(BM_SkinCpu31Joints)->Arg(5000);

/// `state.range(0)` humanoids walking (squad rotations, Catmull-Rom root), each at its own phase.
void BM_CharactersPlaying(benchmark::State& state) {
  const an::Skeleton s = an::buildHumanoid();
  const an::Clip walk = an::buildGaitClip(s, {});
  const int n = static_cast<int>(state.range(0));
  an::Pose pose;
  Real t = 0.0;
  for (auto _ : state) {
    for (int c = 0; c < n; ++c) {
      an::playPose(s, walk, t + 0.37 * c, {true, an::RootMotion::Accumulate}, pose);
      std::vector<an::JointWorld> world = an::forwardKinematics(s, pose);
      benchmark::DoNotOptimize(world.data());
    }
    t += 1.0 / 60.0;
  }
  state.SetItemsProcessed(state.iterations() * n * s.size());
  state.SetLabel("one frame of all characters (21 joints each)");
}
BENCHMARK(BM_CharactersPlaying)->Arg(1)->Arg(100);

/// 100 mocap characters of 31 joints (120 Hz slerp keys).
void BM_MocapCharactersPlaying(benchmark::State& state) {
  const Mocap m = makeMocap(31, 10.0);
  const int n = static_cast<int>(state.range(0));
  an::Pose pose;
  Real t = 0.0;
  for (auto _ : state) {
    for (int c = 0; c < n; ++c) {
      an::playPose(m.skeleton, m.clip, t + 0.37 * c, {true, an::RootMotion::Accumulate}, pose);
      std::vector<an::JointWorld> world = an::forwardKinematics(m.skeleton, pose);
      benchmark::DoNotOptimize(world.data());
    }
    t += 1.0 / 60.0;
  }
  state.SetItemsProcessed(state.iterations() * n * 31);
  state.SetLabel("one frame of all characters (31 joints each)");
}
BENCHMARK(BM_MocapCharactersPlaying)->Arg(100);

}  // namespace

BENCHMARK_MAIN();
