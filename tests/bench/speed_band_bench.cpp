// Speed of the robustness stage of the main job (docs/optimize.md "Robustness"): the speed
// bands in T0, e and alpha of the main job's fastest motion from rest (64 starts from rest, the
// job's check), and the whole main job of `capsubot optimize` with them (RunOptimizeJob).

#include <benchmark/benchmark.h>

#include "capsubot/continue/gait_robustness.hpp"
#include "capsubot/job/optimize_job.hpp"

namespace {

using capsubot::Forcing;
using capsubot::Params;

// The main job's fastest motion from rest (results/optimum.json, key reach): 73 right-wall
// impacts in a chattering sequence and 5 left ones per period.
capsubot::RobotModel ReachWinner() {
  return {Forcing::Harmonic(0.676979732510288, 0.3230202674897121, -3.089378590956282), Params{},
          0.9431003086419751};
}

// The three bands alone (no continuation), one level, the main job's check of 8 x 8 starts.
void BM_SpeedBandsReachWinner(benchmark::State& state) {
  capsubot::RobustnessOptions options;
  options.speed_bands = true;
  int evaluations = 0;
  for (auto _ : state) {
    const auto g = capsubot::ComputeSpeedBands(ReachWinner(), options, "");
    for (const auto& p : g.parameters) evaluations += p.band.evaluations;
  }
  state.counters["evaluations"] =
      benchmark::Counter(evaluations, benchmark::Counter::kAvgIterations);
}
BENCHMARK(BM_SpeedBandsReachWinner)->Unit(benchmark::kSecond)->Iterations(1);

// The whole main job: P1, the robust P2 gait, reach, both motions' continuations and bands,
// the exact optima.
void BM_OptimizeJobMain(benchmark::State& state) {
  capsubot::OptimizeJobOptions options;
  for (auto _ : state) {
    benchmark::DoNotOptimize(capsubot::RunOptimizeJob(options).index());
  }
}
BENCHMARK(BM_OptimizeJobMain)->Unit(benchmark::kSecond)->Iterations(1);

// `capsubot optimize --problem reach --harmonics 3` with its default budgets: the sine's reach
// search, then the ladder's steps K = 2 and 3 (400 Halton points, 400 of controlled random
// search, 16 screens of 37 and 4 polishes of 150 each), their re-checks and spreads.
void BM_OptimizeJobReachThreeHarmonics(benchmark::State& state) {
  capsubot::OptimizeJobOptions options;
  capsubot::ReachProblem reach;
  reach.drive = capsubot::DriveFamily::Fourier(3);
  options.mode = reach;
  for (auto _ : state) {
    benchmark::DoNotOptimize(capsubot::RunOptimizeJob(options).index());
  }
}
BENCHMARK(BM_OptimizeJobReachThreeHarmonics)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace
