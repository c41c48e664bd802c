// One full solve (orbit + exact validity), the unit of work of every sweep and optimiser.
// Target: at least 500,000 solves per second on one core (Release).

#include <benchmark/benchmark.h>

#include "capsubot/orbit/validity.hpp"

namespace {

using capsubot::Forcing;
using capsubot::Params;

// Solves `base` at impact phases walking over [lo, hi] in steps of `step`, one per iteration.
void SolveOverPhases(benchmark::State& state, const Forcing& base, const Params& params, double lo,
                     double hi, double step) {
  double phi0 = lo, sum = 0.0;
  for (auto _ : state) {
    const auto s = capsubot::Solve(base.WithPhase(phi0), params);
    sum += s.orbit.phi1 + s.validity.x_min;
    phi0 = phi0 > hi ? lo : phi0 + step;
  }
  benchmark::DoNotOptimize(sum);
  state.SetItemsProcessed(state.iterations());
}

// Valid orbits, most with interior extrema of x (found with `capsubot solve`): the common case.
void BM_SolveHarmonicValid(benchmark::State& state) {
  SolveOverPhases(state, Forcing::Harmonic(0.05, 0.02, 0.0), Params{0.1, 0.5}, -3.0, -2.0, 1e-4);
}
BENCHMARK(BM_SolveHarmonicValid);

// The paper's worked example (c = A = T0/2), over the whole circle of phases.
void BM_SolvePaperExampleWholeCircle(benchmark::State& state) {
  SolveOverPhases(state, Forcing::Harmonic(0.5, 0.5, 0.0), Params{}, -3.14159, 3.14159, 1e-3);
}
BENCHMARK(BM_SolvePaperExampleWholeCircle);

// A three-harmonic Fourier force (crossings by Bernstein subdivision).
void BM_SolveFourier3(benchmark::State& state) {
  SolveOverPhases(state, Forcing::Fourier(0.02, {0.01, 0.0, 0.005}, {0.04, 0.01, 0.0}, 0.0),
                  Params{0.1, 0.5}, -3.14159, 3.14159, 1e-3);
}
BENCHMARK(BM_SolveFourier3);

}  // namespace
