// Continuation of periodic motions (docs/continuation.md) next to the brute-force bifurcation
// diagram of the same range, one thread each. Targets: a 1000-point branch of the one-impact
// orbit <= 0.2 s, a 200-point branch of the 3-right/1-left motion <= 1 s.

#include <benchmark/benchmark.h>

#include "capsubot/attract/bifurcation.hpp"
#include "capsubot/continue/continuation.hpp"
#include "capsubot/orbit/orbit.hpp"

namespace {

using capsubot::Forcing;
using capsubot::Params;
using capsubot::RobotModel;

// The stable one-impact orbit with clearance (docs/orbit.md) continued in alpha over
// [0.2, 0.3]: up to its fold and back down.
RobotModel SmallOrbitRobot(double alpha) {
  Params p;
  p.T0 = 0.1;
  p.e = 0.5;
  return {Forcing::Harmonic(0.05, 0.02, -2.842), p, alpha};
}

// The stable optimum's robot (docs/attractors.md) continued in T0 over [0.9, 1.1]: its
// 3-right/1-left motion.
RobotModel OptimumRobot(double T0) {
  Params p;
  p.T0 = T0;
  return {Forcing::Harmonic(0.34063197373861814, 0.06410131873607934, -3.1181183398453047), p,
          0.6435592358295166};
}

void BM_ContinueOneImpactOrbit1000Points(benchmark::State& state) {
  const RobotModel r = SmallOrbitRobot(0.2792869076315278);
  const capsubot::Orbit o = capsubot::ComputeOrbit(r.forcing, r.params);
  capsubot::ContinuationOptions opt;
  opt.from = 0.2;
  opt.to = 0.3;
  opt.start = o.alpha;
  opt.max_points = 1000;
  opt.initial_step = opt.max_step = 5e-4;  // about 1200 steps cover the branch
  std::size_t points = 0;
  for (auto _ : state) {
    points = capsubot::ContinueBranch(SmallOrbitRobot, {1.0, -o.e * o.u, o.v_plus, 0.0}, opt)
                 .points.size();
  }
  state.counters["points"] = static_cast<double>(points);
}
BENCHMARK(BM_ContinueOneImpactOrbit1000Points)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_ContinueThreeRightOneLeft200Points(benchmark::State& state) {
  capsubot::ContinuationOptions opt;
  opt.from = 0.9;
  opt.to = 1.1;
  opt.start = 1.0;
  opt.max_points = 200;
  opt.initial_step = opt.max_step = 1e-3;
  opt.shooting.transient = 200;
  std::size_t points = 0;
  for (auto _ : state) {
    points =
        capsubot::ContinueBranch(OptimumRobot, capsubot::RestStart(0.5, 1.0), opt).points.size();
  }
  state.counters["points"] = static_cast<double>(points);
}
BENCHMARK(BM_ContinueThreeRightOneLeft200Points)->Unit(benchmark::kMillisecond)->UseRealTime();

// The brute-force diagram over the same T0 range: 200 values, up and down, one thread.
void BM_BifurcationSameRange200Values(benchmark::State& state) {
  const RobotModel r = OptimumRobot(1.0);
  capsubot::BifurcationOptions opt;
  opt.param = capsubot::ModelParameter::kT0;
  opt.from = 0.9;
  opt.to = 1.1;
  opt.steps = 200;
  opt.analytic = false;
  opt.threads = 1;
  std::size_t rows = 0;
  for (auto _ : state) {
    rows += capsubot::ComputeBifurcation(r, opt).summary.size();
  }
  benchmark::DoNotOptimize(rows);
}
BENCHMARK(BM_BifurcationSameRange200Values)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
