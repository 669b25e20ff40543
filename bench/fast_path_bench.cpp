// Fast paths against the scalar routes they replace (docs/architecture.md §5, "Fast paths"), in the same
// run, on the same data:
//  - CLOTH-2: one XPBD sweep over the 30 × 200 ribbon's stretch/shear links (bench/cloth_bench.cpp's
//    ribbon, Mesh layout), sweepXpbdLinksScalar against sweepXpbdLinksFast;
//  - RAG-1: the stick relaxation of 1,000 crowds' worth of tetrahedral bones laid out as the particle
//    ragdoll lays them out (four particles and six sticks a bone, bones one after another), one sweep,
//    relaxSticksScalar against relaxSticksFast.
// The state is not reset between iterations: both routes do the same arithmetic whatever the positions
// (no early exit but pinned or coincident ends, which stay so).
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "physics/cloth/forces.h"
#include "physics/cloth/xpbd_fast_path.h"
#include "physics/ragdoll/stick_fast_path.h"

namespace {
using namespace pba;

struct Ribbon {
  std::vector<cloth::Link> links;
  std::vector<Vec3> x;
  std::vector<Real> w;
  std::array<Real, cloth::kLinkKinds> alphaTilde{};
};

Ribbon ribbon() {
  cloth::GridDesc d;
  d.resolutionX = 30;
  d.resolutionY = 200;
  d.width = 0.29;
  d.height = 1.99;
  d.pins = cloth::GridPins::TopCorners;
  d.layout = cloth::SpringLayout::Mesh;
  const cloth::ClothMaterial m;
  const cloth::Cloth c = cloth::buildClothGrid(d, m).value();
  Ribbon r{c.constraints, c.position, c.inverseMass, {}};
  for (std::size_t i = 0; i < r.x.size(); ++i) r.x[i].z += 1e-3 * std::sin(12.9898 * static_cast<Real>(i));
  const Real h = 1.0 / 600.0;  // 10 substeps of a 60 Hz frame
  const std::array<Real, cloth::kLinkKinds> alpha = cloth::constraintCompliance(m);
  for (std::size_t k = 0; k < cloth::kLinkKinds; ++k) r.alphaTilde[k] = alpha[k] / (h * h);
  return r;
}

template <bool kFast>
void BM_XpbdRibbonSweep(benchmark::State& state) {
  Ribbon r = ribbon();
  std::vector<Real> lambda(r.links.size(), 0.0);
  for (auto _ : state) {
    if constexpr (kFast) {
      cloth::sweepXpbdLinksFast(r.links, r.alphaTilde, r.x, r.w, lambda);
    } else {
      cloth::sweepXpbdLinksScalar(r.links, r.alphaTilde, r.x, r.w, lambda);
    }
    benchmark::DoNotOptimize(r.x.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(r.links.size()));
  state.SetLabel(std::to_string(r.links.size()) + " links");
}
BENCHMARK(BM_XpbdRibbonSweep<false>)->Name("BM_XpbdRibbonSweep/scalar")->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_XpbdRibbonSweep<true>)->Name("BM_XpbdRibbonSweep/fast")->Unit(benchmark::kMicrosecond);

template <bool kFast>
void BM_StickRelaxation(benchmark::State& state) {
  constexpr int kPairs[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  const Vec3 corner[4] = {Vec3(0.0), Vec3(0.3, 0.0, 0.0), Vec3(0.0, 0.2, 0.0), Vec3(0.0, 0.0, 0.1)};
  std::vector<Vec3> x;
  std::vector<Real> w;
  std::vector<ragdoll::Stick> sticks;
  const int bones = static_cast<int>(state.range(0));
  for (int bone = 0; bone < bones; ++bone) {
    const int first = static_cast<int>(x.size());
    for (int c = 0; c < 4; ++c) {
      x.push_back(Vec3(0.5 * bone, 0.0, 0.0) + corner[c] + Vec3(0.01 * std::sin(1.7 * (4 * bone + c))));
      w.push_back(4.0 / 3.0);
    }
    for (const auto& e : kPairs)
      sticks.push_back({first + e[0], first + e[1], glm::length(corner[e[0]] - corner[e[1]])});
  }
  for (auto _ : state) {
    if constexpr (kFast) {
      ragdoll::relaxSticksFast(sticks, x, w, 1);
    } else {
      ragdoll::relaxSticksScalar(sticks, x, w, 1);
    }
    benchmark::DoNotOptimize(x.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(sticks.size()));
}
BENCHMARK(BM_StickRelaxation<false>)->Name("BM_StickRelaxation/scalar")->Arg(16000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_StickRelaxation<true>)->Name("BM_StickRelaxation/fast")->Arg(16000)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
