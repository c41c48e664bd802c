// The sweep's hot path: 1,000,000 phi0 points, solve + exact validity + CSV row (target:
// 0.45 s wall on 2 threads, byte-identical for any thread count).
//
//   capsubot_bench --benchmark_filter=Sweep
// BM_SweepPhaseMillion/threads: the whole sweep to a file in /tmp (items/s = grid points per
// second); BM_SweepSolveOnly: the Solve calls of the same grid, one thread;
// BM_SweepRowsOnly: Solve + the row into a reused buffer (SweepRowWriter), one thread, no file;
// BM_SweepBlock: what a computing thread does, blocks of 2048 points (SweepBlocks) into the
// reused bytes of a block (items/s = points per second);
// BM_SweepFormat/0 and /1: the 9 numbers of a row formatted as the sweep does (shortest
// round-trip) and with 17 significant digits (the former format), for comparison.

#include <benchmark/benchmark.h>
#include <unistd.h>

#include <charconv>
#include <cstdio>
#include <string>

#include "capsubot/orbit/validity.hpp"
#include "capsubot/sweep/sweep.hpp"
#include "sweep/sweep_rows.hpp"

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

void BM_SweepRowsOnly(benchmark::State& state) {
  const capsubot::SweepOptions o = PhaseSweep(1000000);
  capsubot::detail::SweepRowWriter writer(o);
  std::string bytes;
  capsubot::detail::RowBuffer buffer(bytes);
  std::int64_t point = 0;
  for (auto _ : state) {
    buffer.clear();
    writer.AppendPoint(point, buffer);
    benchmark::DoNotOptimize(buffer.data());
    point = (point + 7919) % 1000000;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_SweepRowsOnly);

void BM_SweepBlock(benchmark::State& state) {
  constexpr std::int64_t kPoints = 1000000, kBlock = 2048;
  const capsubot::SweepOptions o = PhaseSweep(kPoints);
  const capsubot::BlockCompute compute = capsubot::SweepBlocks(o)();
  std::string bytes;
  std::int64_t begin = 0;
  for (auto _ : state) {
    bytes.clear();
    compute(begin, begin + kBlock, bytes);
    benchmark::DoNotOptimize(bytes.data());
    begin = (begin + 7 * kBlock) % (kPoints - kBlock);
  }
  state.SetItemsProcessed(state.iterations() * kBlock);
}
BENCHMARK(BM_SweepBlock)->Unit(benchmark::kMillisecond);

void BM_SweepFormat(benchmark::State& state) {
  const capsubot::SweepOptions o = PhaseSweep(1000000);
  const capsubot::Solution s =
      capsubot::Solve(o.forcing.WithPhase(-3.0), o.params);  // every cell of the row exists
  const double cells[] = {-3.0,      s.orbit.phi1,   s.orbit.alpha,    s.orbit.u, s.orbit.v_plus,
                          s.orbit.I, s.orbit.v_mean, s.validity.x_min, s.orbit.T0};
  std::string bytes;
  capsubot::detail::RowBuffer buffer(bytes);
  const bool shortest = state.range(0) == 0;
  for (auto _ : state) {
    buffer.clear();
    for (double x : cells) {
      if (shortest) {
        capsubot::detail::AppendNumber(buffer, x);
      } else {
        char text[32];
        const auto r = std::to_chars(text, text + sizeof text, x, std::chars_format::general, 17);
        buffer.append(std::string_view(text, static_cast<std::size_t>(r.ptr - text)));
      }
      buffer.push_back(',');
    }
    benchmark::DoNotOptimize(buffer.data());
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_SweepFormat)->Arg(0)->Arg(1);

}  // namespace
