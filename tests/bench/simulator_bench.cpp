// Simulated periods per second of a one-impact orbit (target: at least 200,000 on one core,
// Release; one period <= 0.7 us) and the cost of the analytic stability (wanted: about 2
// microseconds or less). These time the event search itself: every event is searched
// (SimOptions::reuse_cycles off), except in ...ReusingCycles, where the orbit's events are
// searched until its state repeats bit for bit and then taken again (the default of the
// simulator, the same results).

#include <benchmark/benchmark.h>

#include "capsubot/orbit/stability.hpp"
#include "capsubot/orbit/validity.hpp"
#include "capsubot/simulate/simulator.hpp"

namespace {

using capsubot::Forcing;
using capsubot::Params;

// A valid, stable orbit (spectral radius about 0.16; found by scanning phi0 with
// `capsubot solve --stability`): A = 0.05, c = 0.02, T0 = 0.1, e = 0.5, phi0 = -2.842.
struct StableOrbit {
  Params params;
  capsubot::Orbit orbit;
  StableOrbit() {
    params.T0 = 0.1;
    params.e = 0.5;
    orbit = capsubot::ComputeOrbit(Forcing::Harmonic(0.05, 0.02, -2.842), params);
  }
};

void SimulateOrbit(benchmark::State& state, double periods, bool energy = false,
                   bool reuse = false) {
  const StableOrbit s;
  capsubot::SimOptions opt;
  opt.alpha = s.orbit.alpha;
  opt.x0 = 1.0;
  opt.u0 = -s.params.e * s.orbit.u;
  opt.v0 = s.orbit.v_plus;
  opt.periods = periods;
  opt.energy = energy;
  opt.reuse_cycles = reuse;
  double sum = 0.0;
  for (auto _ : state) {
    const capsubot::SimResult r = capsubot::Simulate(s.orbit.forcing, s.params, opt);
    sum += r.displacement;
  }
  benchmark::DoNotOptimize(sum);
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * periods));  // periods
}

// items_per_second = simulated periods per second.
void BM_SimulateOrbitOnePeriod(benchmark::State& state) { SimulateOrbit(state, 1.0); }
BENCHMARK(BM_SimulateOrbitOnePeriod);

void BM_SimulateOrbit1000Periods(benchmark::State& state) { SimulateOrbit(state, 1000.0); }
BENCHMARK(BM_SimulateOrbit1000Periods);

void BM_SimulateOrbit1000PeriodsReusingCycles(benchmark::State& state) {
  SimulateOrbit(state, 1000.0, false, true);
}
BENCHMARK(BM_SimulateOrbit1000PeriodsReusingCycles);

// The same with the energy budget accumulated (SimOptions::energy).
void BM_SimulateOrbit1000PeriodsWithEnergy(benchmark::State& state) {
  SimulateOrbit(state, 1000.0, true);
}
BENCHMARK(BM_SimulateOrbit1000PeriodsWithEnergy);

// A two-harmonic Fourier force (crossings by Bernstein subdivision): a slower path.
void BM_SimulateFourierOrbit100Periods(benchmark::State& state) {
  Params params;
  params.T0 = 0.1;
  params.e = 0.5;
  const auto orbit =
      capsubot::ComputeOrbit(Forcing::Fourier(0.02, {0.0, 0.005}, {0.05, 0.0}, -2.842), params);
  capsubot::SimOptions opt;
  opt.alpha = orbit.alpha;
  opt.x0 = 1.0;
  opt.u0 = -params.e * orbit.u;
  opt.v0 = orbit.v_plus;
  opt.periods = 100.0;
  opt.reuse_cycles = false;
  double sum = 0.0;
  for (auto _ : state) sum += capsubot::Simulate(orbit.forcing, params, opt).displacement;
  benchmark::DoNotOptimize(sum);
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * 100));
}
BENCHMARK(BM_SimulateFourierOrbit100Periods);

// The robot (f, params, alpha) from rest in the middle, 200 + 100 periods; `reuse` takes the
// repeated cycles' events again (the default) or searches every event. Counters:
// events_per_period; items_per_second = periods per second.
void SimulateFromRest(benchmark::State& state, const Forcing& f, const Params& params, double alpha,
                      bool reuse) {
  capsubot::SimOptions opt;
  opt.alpha = alpha;
  opt.x0 = 0.5;
  opt.u0 = 0.0;
  opt.v0 = 0.0;
  opt.transient = 200.0;
  opt.periods = 100.0;
  opt.reuse_cycles = reuse;
  constexpr double kPeriods = 300.0;
  double sum = 0.0, events = 0.0;
  for (auto _ : state) {
    const capsubot::SimResult r = capsubot::Simulate(f, params, opt);
    sum += r.displacement;
    events = static_cast<double>(r.events + r.transient.events);
  }
  benchmark::DoNotOptimize(sum);
  state.counters["events_per_period"] = events / kPeriods;
  state.SetItemsProcessed(static_cast<int64_t>(static_cast<double>(state.iterations()) * kPeriods));
}

// A chattering motion: the main job's robot ("fastest motion from rest": the paper's force at
// T0 = 1, A = 0.676954732510288, c = 0.323045267489712, phi0 = -3.089378590956282,
// alpha = 0.9428190586419751), e = state.range(0)/1000 (1000: e = 1; 900: e = 0.9), every event
// searched. About 70 impacts a period end on one wall in a chattering sequence.
void BM_SimulateChatteringFromRest(benchmark::State& state) {
  Params params;
  params.T0 = 1.0;
  params.e = static_cast<double>(state.range(0)) / 1000.0;
  SimulateFromRest(state,
                   Forcing::Harmonic(0.676954732510288, 0.323045267489712, -3.089378590956282),
                   params, 0.9428190586419751, false);
}
BENCHMARK(BM_SimulateChatteringFromRest)->Arg(1000)->Arg(900)->Unit(benchmark::kMillisecond);

// A pulse force (docs/model.md section 15): 0.3 for a motor phase in [0, 1.5), -0.05 for the
// rest, T0 = 0.1, e = 0.5, alpha = 0.3; every start of this robot ends in one period-1 motion
// of 1 right and 6 left impacts a period (tests/cli/pulse_cli_test.cpp). state.range(0): 1
// reuses the repeated cycles (the default), 0 searches every event.
void BM_SimulatePulseFromRest(benchmark::State& state) {
  Params params;
  params.T0 = 0.1;
  params.e = 0.5;
  SimulateFromRest(state, Forcing::Pulse({0.3, -0.05}, {0.0, 1.5}, 0.0), params, 0.3,
                   state.range(0) != 0);
}
BENCHMARK(BM_SimulatePulseFromRest)->Arg(0)->Arg(1);

// The analytic stability of one orbit (what an optimiser or a sweep pays per point).
void BM_ComputeStability(benchmark::State& state) {
  const StableOrbit s;
  double sum = 0.0;
  for (auto _ : state) sum += capsubot::ComputeStability(s.orbit).spectral_radius;
  benchmark::DoNotOptimize(sum);
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ComputeStability);

}  // namespace
