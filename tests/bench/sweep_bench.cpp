// The sweep's hot path (1,000,000 phi0 points, solve + exact validity + CSV row, in
// at most 2 s wall on 2 cores, near-linear scaling from 1 to 2 threads).
//
//   capsubot_bench --benchmark_filter=Sweep
// BM_SweepPhaseMillion/threads: the whole sweep to a file in /tmp (items/s = grid points per
// second); BM_SweepSolveOnly: the Solve calls of the same grid, one thread (the rest of the
// sweep's time is formatting and writing).

#include <benchmark/benchmark.h>
#include <unistd.h>

#include <cstdio>
#include <string>

#include "capsubot/sweep.hpp"
#include "capsubot/validity.hpp"

namespace {

capsubot::SweepOptions PhaseSweep(std::int64_t n) {
  capsubot::SweepOptions o;
  o.grid.axes = {capsubot::ParseGridAxis("phi0=-pi:pi:" + std::to_string(n))};
  o.forcing = capsubot::Forcing::Harmonic(0.5, 0.5, 0.0);  // the paper's c = A = T0/2
  o.output = "/tmp/capsubot_sweep_bench_" + std::to_string(::getpid()) + ".csv";
  return o;
}

void BM_SweepPhaseMillion(benchmark::State& state) {
  capsubot::SweepOptions o = PhaseSweep(1000000);
  o.threads = static_cast<int>(state.range(0));
  for (auto _ : state) capsubot::RunSweep(o);
  std::remove(o.output.c_str());
  state.SetItemsProcessed(state.iterations() * 1000000);
}
BENCHMARK(BM_SweepPhaseMillion)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_SweepSolveOnly(benchmark::State& state) {
  const capsubot::SweepOptions o = PhaseSweep(1000000);
  std::int64_t point = 0;
  for (auto _ : state) {
    const capsubot::Solution s =
        capsubot::Solve(o.forcing.WithPhase(o.grid.Value(point, 0)), o.params);
    benchmark::DoNotOptimize(s.orbit.I);
    point = (point + 7919) % 1000000;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_SweepSolveOnly);

}  // namespace
