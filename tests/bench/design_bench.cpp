// The energy of an orbit, the gait of one robot and a whole design of the example robot
// (docs/design.md, section "Speed").

#include <benchmark/benchmark.h>

#include "../design/example_robot.hpp"
#include "capsubot/design/design.hpp"
#include "capsubot/orbit/orbit_energy.hpp"

namespace {

using capsubot::DesignInput;
using capsubot::testing::ExampleRobot;

// OrbitEnergy on valid orbits (the same phases as BM_SolveHarmonicValid), orbit built outside.
void BM_OrbitEnergy(benchmark::State& state) {
  const capsubot::Params params{0.1, 0.5};
  const capsubot::Orbit orbit =
      capsubot::ComputeOrbit(capsubot::Forcing::Harmonic(0.05, 0.02, -2.5), params);
  double sum = 0.0;
  for (auto _ : state) sum += capsubot::OrbitEnergy(orbit).motor_work_positive;
  benchmark::DoNotOptimize(sum);
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_OrbitEnergy);

// One robot: all its one-impact orbits, their stability, the fastest robust one in SI units.
void BM_EvaluateGait(benchmark::State& state) {
  const DesignInput in = ExampleRobot();
  double sum = 0.0;
  for (auto _ : state) sum += capsubot::EvaluateGait(in, 0.22, 20.0).speed_mm_s;
  benchmark::DoNotOptimize(sum);
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_EvaluateGait)->Unit(benchmark::kMillisecond);

// `capsubot design --config examples/robot.toml`: the m2 search at a fixed frequency.
void BM_DesignExample(benchmark::State& state) {
  const DesignInput in = ExampleRobot();
  for (auto _ : state) benchmark::DoNotOptimize(capsubot::Design(in).one_impact.m2_kg);
}
BENCHMARK(BM_DesignExample)->Unit(benchmark::kMillisecond);

// The same with --frequency-range 10:40: an m2 search per frequency tried.
void BM_DesignExampleFrequencyRange(benchmark::State& state) {
  DesignInput in = ExampleRobot();
  in.frequency_min = 10.0;
  in.frequency_max = 40.0;
  for (auto _ : state) benchmark::DoNotOptimize(capsubot::Design(in).one_impact.m2_kg);
}
BENCHMARK(BM_DesignExampleFrequencyRange)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
