// Kernel benchmarks of the hello lab: one drop step (HELLO-1 + HELLO-2) and one spring step (HELLO-3 + HELLO-4).
#include <benchmark/benchmark.h>

#include "physics/hello/ball.h"

namespace {
using namespace pba;

void BM_HelloDropStep(benchmark::State& state) {
  const hello::BallDesc desc;
  hello::BallState s = hello::initialState(desc);
  for (auto _ : state) {
    s = hello::stepDrop(desc, s, 1.0 / 120.0).state;
    benchmark::DoNotOptimize(s);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_HelloDropStep);

void BM_HelloSpringStep(benchmark::State& state) {
  const hello::SpringDesc desc;
  hello::BallState s = hello::springEquilibrium(desc);
  s.position.x += 0.5;
  for (auto _ : state) {
    s = hello::stepSpringBall(desc, s, 1.0 / 240.0,
                              [&desc](const hello::BallState& b) { return hello::springBallForce(desc, b); });
    benchmark::DoNotOptimize(s);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_HelloSpringStep);

}  // namespace

BENCHMARK_MAIN();
