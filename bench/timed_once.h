#pragma once
// Registration of a benchmark whose body runs its scene once and times itself (state.SetIterationTime,
// with the thread CPU time of thread_cpu_time.h): one row per argument, each run once, reported in `unit`.
//   BENCHMARK(BM_X)->Apply([](benchmark::internal::Benchmark* b) { bench::timedOnce(b, {1, 136}); });
#include <cstdint>
#include <initializer_list>

#include <benchmark/benchmark.h>

namespace pba::bench {

inline void timedOnce(benchmark::internal::Benchmark* b, std::initializer_list<std::int64_t> args,
                      benchmark::TimeUnit unit = benchmark::kMillisecond) {
  for (std::int64_t a : args) b->Arg(a);
  b->UseManualTime()->Iterations(1)->Unit(unit);
}

}  // namespace pba::bench
