// Speed of the reach problem (docs/model.md sections 12 and 13): one evaluation of its objective
// (the mean velocity from rest with the cheap search settings, 4 x 4 starts of 100 + 32
// periods, 2 threads) on two robots, and the main job of `capsubot optimize` (P1, the robust P2
// gait, the reach search with its default 20 s wall-clock limit and the re-checks).

#include <benchmark/benchmark.h>

#include "capsubot/optimize/optimize.hpp"
#include "capsubot/reach/optimize_reach.hpp"

namespace {

using capsubot::Forcing;
using capsubot::Params;

// One evaluation of the reach objective for the robot (A, c, phi0, alpha).
void ReachObjective(benchmark::State& state, const Forcing& forcing, double alpha) {
  const capsubot::RobotModel robot{forcing, Params{}, alpha};  // T0 = 1, e = 1
  capsubot::FromRestOptions opt = capsubot::CheapFromRestOptions();
  opt.attractor.threads = 2;
  double sum = 0.0;
  for (auto _ : state) {
    sum += capsubot::FindAttractors(robot, opt).mean_velocity;
  }
  benchmark::DoNotOptimize(sum);
}

// The robust P2 gait of the main job (3 right + 1 left impacts per period from rest).
void BM_ReachObjectiveRobustGait(benchmark::State& state) {
  ReachObjective(state, Forcing::Harmonic(0.3407, 0.0624056, -3.08763), 0.64922);
}
BENCHMARK(BM_ReachObjectiveRobustGait)->Unit(benchmark::kMillisecond);

// The main job's fastest motion from rest (about 130 impacts per period).
void BM_ReachObjectiveManyImpacts(benchmark::State& state) {
  ReachObjective(state, Forcing::Harmonic(0.675562, 0.322381, -3.08763), 0.94074);
}
BENCHMARK(BM_ReachObjectiveManyImpacts)->Unit(benchmark::kMillisecond);

// The main job's computation (no output): P1 at c = A = T0/2, the robust P2 gait, reach.
void BM_MainJob(benchmark::State& state) {
  const Params params;
  for (auto _ : state) {
    const auto paper = capsubot::OptimizePhase(Forcing::Harmonic(0.5, 0.5, 0.0), params);
    const auto robust = capsubot::OptimizeForcing(params, capsubot::RobustSeedDesign());
    const auto reach = capsubot::OptimizeReach(params, robust);
    benchmark::DoNotOptimize(paper.solution.orbit.I + reach.mean_velocity);
  }
}
BENCHMARK(BM_MainJob)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace
