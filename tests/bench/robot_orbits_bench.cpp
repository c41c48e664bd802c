// Every one-impact orbit of a given robot (FindRobotOrbits, `capsubot orbits`): one search
// over the whole circle of impact phases per iteration, one core.
//
//   capsubot_bench --benchmark_filter=RobotOrbits

#include <benchmark/benchmark.h>

#include "capsubot/orbit/robot_orbits.hpp"

namespace {

using capsubot::Forcing;
using capsubot::Params;

void FindOrbits(benchmark::State& state, const Forcing& force, const Params& params, double alpha) {
  const capsubot::RobotModel robot{force, params, alpha};
  std::size_t found = 0;
  for (auto _ : state) found += capsubot::FindRobotOrbits(robot).size();
  benchmark::DoNotOptimize(found);
  state.SetItemsProcessed(state.iterations());
}

// The robot of docs/orbit.md: alpha = 0.28, two orbits (one stable, one unstable).
void BM_RobotOrbitsHarmonic(benchmark::State& state) {
  FindOrbits(state, Forcing::Harmonic(0.05, 0.02, 0.0), Params{0.1, 0.5}, 0.28);
}
BENCHMARK(BM_RobotOrbitsHarmonic)->Unit(benchmark::kMicrosecond);

// A three-harmonic force just below the maximum of alpha(phi0): two roots close together.
void BM_RobotOrbitsFourierNearFold(benchmark::State& state) {
  FindOrbits(state, Forcing::Fourier(0.02, {0.01, 0.0, 0.005}, {0.04, 0.01, 0.0}, 0.0),
             Params{0.1, 0.5}, 0.199);
}
BENCHMARK(BM_RobotOrbitsFourierNearFold)->Unit(benchmark::kMicrosecond);

}  // namespace
