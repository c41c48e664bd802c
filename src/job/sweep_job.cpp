// `capsubot sweep` as one call (capsubot/job/sweep_job.hpp).

#include "capsubot/job/sweep_job.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>
#include <type_traits>

#include "capsubot/optimize/optimize_search.hpp"

namespace capsubot {
namespace {

// The alternative of SweepMode at position i is the mode of enumerator i of SweepOptimize.
constexpr std::size_t kReachIndex = static_cast<std::size_t>(SweepOptimize::kReach);
static_assert(
    std::variant_size_v<SweepMode> == kReachIndex + 1 &&
        std::is_same_v<std::variant_alternative_t<kReachIndex, SweepMode>, SweepReachMode>,
    "SweepMode follows SweepOptimize");

// The force of the orbit sweep or P1 from its parts (docs/sweep.md): a part the grid varies
// may be left out, and phi0 when something else gives it (`phase_elsewhere`: a grid over phi0
// or alpha, or P1, which finds it).
Forcing SweepForcing(const SweepForce& f, const std::optional<double>& phi0, const Grid& grid,
                     bool phase_elsewhere) {
  if (f.A && !f.sin.empty()) {
    throw std::invalid_argument(fmt::format(
        "A = {} is invalid with sin: expected the amplitude A or the Fourier coefficients sin, "
        "cos, not both",
        *f.A));
  }
  if (f.sin.empty() && !f.cos.empty()) {
    throw std::invalid_argument(
        "cos is invalid without sin: expected the sine coefficients b_1..b_K of the Fourier "
        "force with its cosine coefficients");
  }
  std::optional<double> c = f.c;
  if (!c && grid.Has(ModelParameter::kMean)) c = 0.0;  // the grid gives c at every point
  if (!c) {
    throw std::invalid_argument("c is missing: give the mean force c (or a grid over c)");
  }
  const bool amplitude_elsewhere =
      grid.Has(ModelParameter::kA) || grid.Has(ModelParameter::kSin, 1);
  if (!phi0 && !phase_elsewhere && (f.A || amplitude_elsewhere) && f.sin.empty()) {
    throw std::invalid_argument(
        "phi0 is missing: give the impact phase phi0 [rad] (or a grid over phi0 or alpha, or "
        "optimize = phi0)");
  }
  if (!f.sin.empty()) {
    const std::vector<double> a = f.cos.empty() ? std::vector<double>(f.sin.size(), 0.0) : f.cos;
    return Forcing::Fourier(*c, a, f.sin, phi0.value_or(0.0));
  }
  if (!f.A && !amplitude_elsewhere) {
    throw std::invalid_argument(
        "A is missing: give the amplitude A (or the Fourier coefficients sin, cos, or a grid "
        "over A)");
  }
  return Forcing::Harmonic(f.A.value_or(0.0), *c, phi0.value_or(0.0));
}

// The budgets of the search from rest bound the work of each point (the sweep runs no clock).
void CheckReachBudgets(const ReachOptions& reach) {
  if (reach.global_evaluations < 1 || reach.global_evaluations > kMaxStageEvaluations) {
    throw std::invalid_argument(
        fmt::format("reach.global_evaluations = {} is invalid: expected from 1 to {} evaluations",
                    reach.global_evaluations, kMaxStageEvaluations));
  }
  if (reach.local_evaluations < 0 || reach.local_evaluations > kMaxStageEvaluations) {
    throw std::invalid_argument(
        fmt::format("reach.local_evaluations = {} is invalid: expected from 0 to {} evaluations",
                    reach.local_evaluations, kMaxStageEvaluations));
  }
  if (!std::isnan(reach.force_bound)) {
    throw std::invalid_argument(fmt::format(
        "reach.force_bound = {} is invalid: expected NaN (the bound of the search from rest is "
        "its seed's, search.gait.force_bound)",
        reach.force_bound));
  }
}

// Each mode's options into the sweep's.
void SetMode(const SweepOrbitMode& m, SweepOptions& s) {
  s.optimize = SweepOptimize::kNone;
  s.params = m.params;
  s.margins = m.margins;
  s.stability = m.stability;
  const bool robot = s.grid.Has(ModelParameter::kAlpha);
  if (robot && m.phi0) {
    throw std::invalid_argument(fmt::format(
        "phi0 = {} is invalid with grid alpha: expected no phi0 (the sweep finds phi0)", *m.phi0));
  }
  s.forcing = SweepForcing(m.force, m.phi0, s.grid, robot || s.grid.Has(ModelParameter::kPhi0));
}

void SetMode(const SweepPhaseMode& m, SweepOptions& s) {
  s.optimize = SweepOptimize::kPhase;
  s.params = m.params;
  s.stability = m.stability;
  s.forcing = SweepForcing(m.force, std::nullopt, s.grid, true);
  s.phase = m.phase;
}

void SetMode(const SweepForcingMode& m, SweepOptions& s) {
  s.optimize = SweepOptimize::kForcing;
  s.params = m.params;
  s.stability = m.stability;
  s.design = ForcingOptionsFor(m.search);
}

void SetMode(const SweepFourierMode& m, SweepOptions& s) {
  s.optimize = SweepOptimize::kFourier;
  s.params = m.params;
  s.stability = m.stability;
  s.fourier = FourierOptionsFor(m.search);
}

void SetMode(const SweepReachMode& m, SweepOptions& s) {
  s.optimize = SweepOptimize::kReach;
  s.params = m.params;
  CheckReachBudgets(m.reach);
  s.design = ForcingOptionsFor(m.search);
  s.reach = m.reach;
  s.reach.force_bound = m.search.gait.force_bound;
}

}  // namespace

SweepReachMode::SweepReachMode() {
  search.gait.margins = RobustMargins();
  search.gait.rho_max = kRobustRhoMax;
}

SweepMode SweepModeNamed(const std::string& name) {
  if (name.empty()) return SweepOrbitMode{};
  switch (ParseSweepOptimize(name)) {
    case SweepOptimize::kPhase:
      return SweepPhaseMode{};
    case SweepOptimize::kForcing:
      return SweepForcingMode{};
    case SweepOptimize::kFourier:
      return SweepFourierMode{};
    case SweepOptimize::kReach:
      return SweepReachMode{};
    case SweepOptimize::kNone:  // not a name ParseSweepOptimize takes
      break;
  }
  return SweepOrbitMode{};
}

SweepOptimize SweepModeOptimize(const SweepMode& mode) {
  return static_cast<SweepOptimize>(mode.index());
}

SweepOptions PlanSweepJob(const SweepJobOptions& options) {
  options.grid.Validate();
  SweepOptions s;
  static_cast<GridFileOptions&>(s) = options.file;
  s.grid = options.grid;
  std::visit([&s](const auto& mode) { SetMode(mode, s); }, options.mode);
  s.Validate();
  return s;
}

void SweepJobOptions::Validate() const { (void)PlanSweepJob(*this); }

SweepJobResult RunSweepJob(const SweepJobOptions& options, const BlockBackend& backend) {
  const SweepOptions sweep = PlanSweepJob(options);
  SweepJobResult result;
  result.summary = RunSweep(sweep, options.progress, backend);
  result.output = sweep.output;
  return result;
}

}  // namespace capsubot
