// pba_coursework_budget --coursework N [--frames F]: steps coursework N's scene and prints one JSON object:
// the median and 95th-percentile time of one frame [ms], whether the state stayed finite, and the
// exercise or coursework stubs that ran. `./pba mark` compares the median with the rubric's budget
// (resources/coursework/rubric.tsv); speed is measured here, never asserted in a test.
//   1: a crowd of 100 walkers (CW1), one frame = every walker posed once at 120 Hz
//   2: the ball on the 24 × 24 trampoline (CW2), one frame = 4 substeps of 1/240 s
//   3: the human down six stairs (CW3), one frame = one step of 1/60 s: the stumble, the hand-over, the
//      tumble and the rest that follows (600 frames: 10 s)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>
#include "physics/coursework/ball_on_cloth.h"
#include "physics/coursework/stairs_fall.h"
#include "physics/coursework/walker.h"
#include "physics/exercises/not_implemented.h"

namespace {
using pba::Real;
using Clock = std::chrono::steady_clock;

bool finite(const pba::Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

template <typename Frame>
std::vector<double> timeFrames(int frames, Frame&& frame) {
  std::vector<double> ms;
  ms.reserve(static_cast<std::size_t>(frames));
  for (int f = 0; f < frames; ++f) {
    const auto start = Clock::now();
    frame();
    ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
  }
  return ms;
}

double percentile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(q * static_cast<double>(v.size() - 1))];
}
}  // namespace

int main(int argc, char** argv) {
  int coursework = 0, frames = 600;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--coursework" && i + 1 < argc)
      coursework = std::atoi(argv[++i]);
    else if (a == "--frames" && i + 1 < argc)
      frames = std::atoi(argv[++i]);
    else {
      std::fprintf(stderr, "pba_coursework_budget: unknown argument '%s'\n", a.c_str());
      return 2;
    }
  }
  if (frames < 1) {
    std::fprintf(stderr, "pba_coursework_budget: --frames must be at least 1\n");
    return 2;
  }
  bool ok = true;
  std::vector<double> ms;
  if (coursework == 1) {
    std::vector<pba::coursework::WalkerDesc> descs(100);
    std::vector<pba::coursework::WalkerState> states(100);
    for (std::size_t k = 0; k < descs.size(); ++k) descs[k].gait.speed = 0.8 + 0.008 * static_cast<Real>(k);
    ms = timeFrames(frames, [&] {
      for (std::size_t k = 0; k < descs.size(); ++k) pba::coursework::stepWalker(descs[k], states[k], 1.0 / 120.0);
    });
    for (const auto& s : states)
      for (int side = 0; side < 2; ++side) ok = ok && finite(s.pose.feet[side]) && finite(s.pose.hands[side]);
  } else if (coursework == 2) {
    auto built = pba::coursework::buildBallOnCloth({});
    if (!built) {
      std::fprintf(stderr, "pba_coursework_budget: %s\n", built.error().c_str());
      return 1;
    }
    auto& scene = built.value();
    ms = timeFrames(frames, [&] {
      for (int sub = 0; sub < 4; ++sub) pba::coursework::stepBallOnCloth(scene, 1.0 / 240.0);
    });
    ok = finite(scene.ball.position);
    for (const auto& x : scene.cloth.position) ok = ok && finite(x);
  } else if (coursework == 3) {
    auto built = pba::coursework::buildStairsFall({});
    if (!built) {
      std::fprintf(stderr, "pba_coursework_budget: %s\n", built.error().c_str());
      return 1;
    }
    auto& scene = built.value();
    ms = timeFrames(frames, [&] { pba::coursework::stepStairsFall(scene, 1.0 / 60.0); });
    ok = finite(pba::coursework::figureCenterOfMass(scene));
    for (const auto& m : pba::coursework::figureMotion(scene))
      ok = ok && finite(m.velocity) && finite(m.angularVelocity);
  } else {
    std::fprintf(stderr, "pba_coursework_budget: --coursework must be 1, 2 or 3\n");
    return 2;
  }
  std::string stubs;
  for (const auto& tag : pba::exercises::notImplementedTagsUsed())
    stubs += (stubs.empty() ? "\"" : ", \"") + tag + "\"";
  std::printf(
      "{\"coursework\": %d, \"frames\": %d, \"frame_ms\": {\"median\": %.6f, \"p95\": %.6f}, "
      "\"finite\": %s, \"not_implemented\": [%s]}\n",
      coursework, frames, percentile(ms, 0.5), percentile(ms, 0.95), ok ? "true" : "false", stubs.c_str());
  return 0;
}
