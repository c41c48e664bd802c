// One full solve (orbit + exact validity), the unit of work of every sweep and optimiser.
// Target (issue 2): at least 500,000 solves per second on one core (Release).

#include <benchmark/benchmark.h>

#include "capsubot/validity.hpp"

namespace {

using capsubot::Forcing;
using capsubot::Params;

// A valid orbit with two interior extrema of x (found with `capsubot solve`): the common case.
void BM_SolveHarmonicValid(benchmark::State& state) {
  const Forcing base = Forcing::Harmonic(0.05, 0.02, 0.0);
  Params params;
  params.T0 = 0.1;
  params.e = 0.5;
  double phi0 = -3.0, sum = 0.0;
  for (auto _ : state) {
    const auto s = capsubot::Solve(base.WithPhase(phi0), params);
    sum += s.validity.x_min;
    phi0 = phi0 > -2.0 ? -3.0 : phi0 + 1e-4;  // walk over a range of valid phases
  }
  benchmark::DoNotOptimize(sum);
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_SolveHarmonicValid);

// The paper's worked example (c = A = T0/2), over the whole circle of phases.
void BM_SolvePaperExampleWholeCircle(benchmark::State& state) {
  const Forcing base = Forcing::Harmonic(0.5, 0.5, 0.0);
  const Params params;
  double phi0 = -3.14159, sum = 0.0;
  for (auto _ : state) {
    const auto s = capsubot::Solve(base.WithPhase(phi0), params);
    sum += s.orbit.phi1;
    phi0 = phi0 > 3.14159 ? -3.14159 : phi0 + 1e-3;
  }
  benchmark::DoNotOptimize(sum);
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_SolvePaperExampleWholeCircle);

// A three-harmonic Fourier force (companion-matrix crossings).
void BM_SolveFourier3(benchmark::State& state) {
  const Forcing base = Forcing::Fourier(0.02, {0.01, 0.0, 0.005}, {0.04, 0.01, 0.0}, 0.0);
  Params params;
  params.T0 = 0.1;
  params.e = 0.5;
  double phi0 = -3.14159, sum = 0.0;
  for (auto _ : state) {
    const auto s = capsubot::Solve(base.WithPhase(phi0), params);
    sum += s.orbit.phi1;
    phi0 = phi0 > 3.14159 ? -3.14159 : phi0 + 1e-3;
  }
  benchmark::DoNotOptimize(sum);
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_SolveFourier3);

}  // namespace
