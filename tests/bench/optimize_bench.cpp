// The optimisers of docs/model.md section 7. Speed targets, Release, one core:
//   P1 (OptimizePhase) in at most 50 ms;
//   P2 (OptimizeForcing) to a relative accuracy of 1e-6 in at most 2 s.
// The P2 benchmarks report `rel_error`: |I - I_ref| / I_ref against a reference optimum
// computed once with much more effort (24x24 grid, 24 starts, 40 hops, tolerance 1e-14,
// best of LN_COBYLA and LD_SLSQP).

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "capsubot/optimize/optimize.hpp"

namespace {

using capsubot::Forcing;
using capsubot::Params;

Params Model(double T0, double e = 1.0) {
  Params p;
  p.T0 = T0;
  p.e = e;
  return p;
}

// P1 for the paper's shape c = A = T0/2: at T0 = 0.1 a valid arc whose optimum grazes the
// left wall; at T0 = 1 (the paper's) no valid orbit at all (the whole circle is scanned).
void BM_OptimizePhase(benchmark::State& state) {
  const double T0 = state.range(0) / 1000.0;
  const Params params = Model(T0);
  const Forcing shape = Forcing::Harmonic(T0 / 2, T0 / 2, 0.0);
  int evaluations = 0;
  for (auto _ : state) {
    const auto r = capsubot::OptimizePhase(shape, params);
    evaluations = r.evaluations;
    benchmark::DoNotOptimize(r.solution.orbit.I);
  }
  state.counters["evaluations"] = evaluations;
}
BENCHMARK(BM_OptimizePhase)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);

double ReferenceI(const Params& params, double margin, bool stable) {
  static std::map<std::pair<std::pair<double, double>, std::pair<double, bool>>, double> cache;
  const auto key =
      std::make_pair(std::make_pair(params.T0, params.e), std::make_pair(margin, stable));
  if (cache.count(key) == 0) {
    double best = -HUGE_VAL;
    for (const char* local : {"LN_COBYLA", "LD_SLSQP"}) {
      capsubot::ForcingDesignOptions o;
      o.grid = 24;
      o.effort.starts = 24;
      o.hops = 40;
      o.effort.rel_tol = 1e-14;
      o.effort.local_evaluations = 100000;
      o.local_algorithm = local;
      if (stable) o.gait.rho_max = 1.0;
      o.gait.margins.clearance = margin;
      const auto r = capsubot::OptimizeForcing(params, o);
      if (r.found()) best = std::max(best, r.solution.orbit.I);
    }
    cache[key] = best;
  }
  return cache[key];
}

// P2 with the default options (multistart + LN_COBYLA): T0 = range(0)/1000, stable =
// range(1), and range(2) = 1 for e = 0.6 with a clearance margin 0.1 (a rugged case: the
// clearance condition on x_max jumps when an interior maximum of x appears).
void BM_OptimizeForcing(benchmark::State& state) {
  const double T0 = state.range(0) / 1000.0;
  const bool stable = state.range(1) != 0;
  const bool rugged = state.range(2) != 0;
  const Params params = rugged ? Model(T0, 0.6) : Model(T0);
  capsubot::ForcingDesignOptions o;
  if (stable) o.gait.rho_max = 1.0;
  o.gait.margins.clearance = rugged ? 0.1 : 0.0;
  const double reference = ReferenceI(params, o.gait.margins.clearance, stable);
  double I = 0.0;
  int evaluations = 0;
  for (auto _ : state) {
    const auto r = capsubot::OptimizeForcing(params, o);
    I = r.solution.orbit.I;
    evaluations = r.evaluations;
  }
  state.counters["I"] = I;
  // Signed: negative when the default run beats the high-effort reference.
  state.counters["rel_error"] = (reference - I) / reference;
  state.counters["evaluations"] = evaluations;
}
BENCHMARK(BM_OptimizeForcing)
    ->Args({1000, 0, 0})
    ->Args({1000, 1, 0})
    ->Args({100, 0, 0})
    ->Args({1000, 0, 1})
    ->Unit(benchmark::kMillisecond);

// P3 with K = 3 harmonics at T0 = 1 (default options: P2, then 20 local polishes).
void BM_OptimizeFourier(benchmark::State& state) {
  capsubot::FourierOptions o;
  o.harmonics = static_cast<int>(state.range(0));
  double gain = 0.0;
  for (auto _ : state) {
    const auto r = capsubot::OptimizeFourier(Model(1.0), o);
    gain = r.solution.orbit.I / r.baseline_I - 1.0;
  }
  state.counters["gain"] = gain;
}
BENCHMARK(BM_OptimizeFourier)->Arg(3)->Unit(benchmark::kMillisecond);

}  // namespace
