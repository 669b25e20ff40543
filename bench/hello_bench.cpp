// Kernel benchmarks of the hello lab: one drop step (HELLO-1 + HELLO-2) and one spring step (PART-4 + PART-2).
#include <benchmark/benchmark.h>

#include "physics/hello/ball.h"
#include "physics/ode/integrators.h"

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
  hello::SpringBallSystem ball(desc, s);
  ode::Workspace work;
  for (auto _ : state) {
    ode::symplecticEulerStep(ball, 1.0 / 240.0, work);
    benchmark::DoNotOptimize(ball.positions().data());
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_HelloSpringStep);

}  // namespace

BENCHMARK_MAIN();
