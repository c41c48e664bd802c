// Speed of the long-run classification from rest (docs/model.md sections 12 and 13): one start of
// 200 + 100 periods (wanted <= 0.5 ms), 64 starts from rest on 2 threads (wanted <= 50 ms), a
// 256 x 256 basin map on 2 threads (wanted <= 10 s), a 1000-value bifurcation diagram in T0, both
// directions, 200 + 100 periods per value, with multipliers, on 2 threads (wanted <= 1 s).
// The default MotionOptions stop a start early once its motion repeats to 1e-11 (what the
// commands do); the ...Full300Periods variants switch that off (converged_tolerance = 0), so
// every start or value really simulates its 200 + 100 periods, every event applied: the
// targets' worst case. The simulator still takes the located events of a cycle again once
// its state repeats bit for bit (SimOptions::reuse_cycles: the same results); the
// ...SearchingEveryEvent variants switch that off too, timing the event search alone.
// The robot is the exact stable P2 optimum at T0 = 1, e = 1 (`capsubot optimize --problem
// forcing --stable --json`), whose starts from rest end in a 3-right/1-left motion.

#include <benchmark/benchmark.h>

#include "capsubot/attract/attractors.hpp"
#include "capsubot/attract/bifurcation.hpp"

namespace {

using capsubot::Forcing;
using capsubot::Params;

capsubot::RobotModel Robot() {
  return {Forcing::Harmonic(0.34063197373861814, 0.06410131873607934, -3.1181183398453047),
          Params{}, 0.6435592358295166};
}

void BM_LongRunMotionOneStart300Periods(benchmark::State& state) {
  const capsubot::RobotModel r = Robot();
  const capsubot::MotionOptions opt;  // 200 + 100 periods
  double sum = 0.0;
  for (auto _ : state) {
    sum += capsubot::LongRunMotion(r, capsubot::RestStart(0.5, 1.0), opt).mean_velocity;
  }
  benchmark::DoNotOptimize(sum);
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()) * 300);  // periods
}
BENCHMARK(BM_LongRunMotionOneStart300Periods)->Unit(benchmark::kMillisecond);

void BM_FindAttractors64StartsTwoThreads(benchmark::State& state) {
  const capsubot::RobotModel r = Robot();
  capsubot::FromRestOptions opt;  // 8 x 8 starts, 200 + 100 periods
  opt.attractor.threads = 2;
  double sum = 0.0;
  for (auto _ : state) {
    sum += capsubot::FindAttractors(r, opt).mean_velocity;
  }
  benchmark::DoNotOptimize(sum);
}
BENCHMARK(BM_FindAttractors64StartsTwoThreads)->Unit(benchmark::kMillisecond)->UseRealTime();

// A 1000-value bifurcation diagram in T0, both directions, 2 threads (wanted <= 1 s).
void Bifurcation1000Values(benchmark::State& state, double converged_tolerance, bool reuse = true) {
  const capsubot::RobotModel r = Robot();
  capsubot::BifurcationOptions opt;
  opt.param = capsubot::ModelParameter::kT0;
  opt.from = 0.5;
  opt.to = 2.0;
  opt.steps = 1000;
  opt.analytic = false;
  opt.threads = 2;
  opt.motion.converged_tolerance = converged_tolerance;
  opt.motion.reuse_cycles = reuse;
  std::size_t rows = 0;
  for (auto _ : state) {
    rows += capsubot::ComputeBifurcation(r, opt).summary.size();
  }
  benchmark::DoNotOptimize(rows);
}

void BM_Bifurcation1000ValuesBothDirections(benchmark::State& state) {
  Bifurcation1000Values(state, capsubot::MotionOptions{}.converged_tolerance);
}
BENCHMARK(BM_Bifurcation1000ValuesBothDirections)
    ->Unit(benchmark::kSecond)
    ->UseRealTime()
    ->Iterations(1);

void BM_Bifurcation1000ValuesBothDirectionsFull300Periods(benchmark::State& state) {
  Bifurcation1000Values(state, 0.0);  // 200 + 100 periods at every value
}
BENCHMARK(BM_Bifurcation1000ValuesBothDirectionsFull300Periods)
    ->Unit(benchmark::kSecond)
    ->UseRealTime()
    ->Iterations(1);

void BM_Bifurcation1000ValuesBothDirectionsFull300PeriodsSearchingEveryEvent(
    benchmark::State& state) {
  Bifurcation1000Values(state, 0.0, false);
}
BENCHMARK(BM_Bifurcation1000ValuesBothDirectionsFull300PeriodsSearchingEveryEvent)
    ->Unit(benchmark::kSecond)
    ->UseRealTime()
    ->Iterations(1);

// A 256 x 256 basin map, 200 + 100 periods per start, 2 threads (wanted <= 10 s).
void Basins256x256(benchmark::State& state, double converged_tolerance, bool reuse = true) {
  const capsubot::RobotModel r = Robot();
  capsubot::FromRestOptions opt;
  opt.n_x = 256;
  opt.n_psi = 256;
  opt.attractor.threads = 2;
  opt.attractor.motion.converged_tolerance = converged_tolerance;
  opt.attractor.motion.reuse_cycles = reuse;
  double sum = 0.0;
  for (auto _ : state) {
    sum += capsubot::FindAttractors(r, opt).mean_velocity;
  }
  benchmark::DoNotOptimize(sum);
}

void BM_Basins256x256TwoThreads(benchmark::State& state) {
  Basins256x256(state, capsubot::MotionOptions{}.converged_tolerance);
}
BENCHMARK(BM_Basins256x256TwoThreads)->Unit(benchmark::kSecond)->UseRealTime()->Iterations(1);

void BM_Basins256x256TwoThreadsFull300Periods(benchmark::State& state) {
  Basins256x256(state, 0.0);  // 200 + 100 periods at every start
}
BENCHMARK(BM_Basins256x256TwoThreadsFull300Periods)
    ->Unit(benchmark::kSecond)
    ->UseRealTime()
    ->Iterations(1);

void BM_Basins256x256TwoThreadsFull300PeriodsSearchingEveryEvent(benchmark::State& state) {
  Basins256x256(state, 0.0, false);
}
BENCHMARK(BM_Basins256x256TwoThreadsFull300PeriodsSearchingEveryEvent)
    ->Unit(benchmark::kSecond)
    ->UseRealTime()
    ->Iterations(1);

}  // namespace
