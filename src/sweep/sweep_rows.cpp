#include "sweep/sweep_rows.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>

#include "capsubot/io/io.hpp"
#include "capsubot/numerics/not_computed.hpp"
#include "capsubot/optimize/optimize_phase.hpp"
#include "capsubot/orbit/robot_orbits.hpp"
#include "capsubot/orbit/stability.hpp"
#include "capsubot/reach/optimize_reach.hpp"
#include "sweep/grid_run.hpp"

namespace capsubot::detail {
namespace {

// Bumped whenever the bytes of a sweep change for the same options (invalidates checkpoints).
constexpr int kFormatVersion = 5;

bool RobotMode(const SweepOptions& o) { return o.grid.Has(ModelParameter::kAlpha); }

void Append(RowBuffer& out, const char* text) { out.append(text); }

// Exact text of a double for the description (hexadecimal: no rounding at all).
std::string Hex(double value) { return fmt::format("{:a}", value); }

// Harmonics of the swept force: the given force's, or more when a_k or b_k is gridded.
int SweepHarmonics(const SweepOptions& o) {
  int K = std::max(1, o.forcing.harmonics());
  for (const GridAxis& axis : o.grid.axes) K = std::max(K, axis.harmonic);
  return K;
}

// The shared optimiser options (OptimizeOptions).
std::string GoalDescription(const OptimizeOptions& g) {
  return fmt::format(" rho_max={} max_time={} active_tol={}", Hex(g.gait.rho_max), Hex(g.max_time),
                     Hex(g.active_tol));
}

std::string EffortDescription(const SearchEffort& s) {
  return fmt::format(" global={} starts={} rel_tol={} local_evaluations={} global_evaluations={}",
                     s.global_algorithm, s.starts, Hex(s.rel_tol), s.local_evaluations,
                     s.global_evaluations);
}

std::string SearchDescription(const SearchOptions& s) {
  return fmt::format(" bound={} local={} seed={}", Hex(s.gait.force_bound), s.local_algorithm,
                     s.seed) +
         EffortDescription(s.effort) + GoalDescription(s);
}

std::string DesignDescription(const ForcingDesignOptions& p) {
  return SearchDescription(p) + fmt::format(" grid_points={} hops={} phase_exact_evaluations={}",
                                            p.grid, p.hops, p.phase_exact_evaluations);
}

// The from-rest settings that change results (not the thread count).
std::string FromRestDescription(const FromRestOptions& f) {
  const AttractorOptions& a = f.attractor;
  const MotionOptions& m = a.motion;
  return fmt::format(
      " n_x={} n_psi={} transient={} record={} max_period={} state_tol={} converged_tol={} "
      "chatter={} events={} velocity_tol={} orbit_tol={}",
      f.n_x, f.n_psi, m.transient, m.record, m.max_period, Hex(m.state_tolerance),
      Hex(m.converged_tolerance), Hex(m.chatter_velocity), m.max_events_per_period,
      Hex(a.velocity_tolerance), Hex(a.orbit_tolerance));
}

std::string ReachDescription(const ReachOptions& r) {
  return fmt::format(
             " reach_alpha={} alpha_box={}:{} reach_global={} reach_local={} "
             "reach_global_evaluations={} reach_local_evaluations={} reach_rel_tol={} "
             "candidates={} max_spread={} reach_seed={}",
             Hex(r.alpha), Hex(r.alpha_min), Hex(r.alpha_max), r.global_algorithm,
             r.local_algorithm, r.global_evaluations, r.local_evaluations, Hex(r.rel_tol),
             r.candidates, Hex(r.max_spread), r.seed) +
         FromRestDescription(r.search) + FromRestDescription(r.check);
}

}  // namespace

std::string ShardLine(int shard, int shards, std::int64_t points) {
  return fmt::format("# shard {}/{} of {} points\n", shard, shards, points);
}

void AppendNumber(RowBuffer& out, double value) {
  out.Advance(WriteNumber(out.Room(kMaxNumberChars), value));
}

std::string SweepHeaderLines(const SweepOptions& options) {
  return GridHeader(options.comments, options.shard, options.shards, options.grid.size(),
                    SweepColumns(options));
}

std::string SweepDescription(const SweepOptions& o) {
  std::string lines = SweepHeaderLines(o);
  std::replace(lines.begin(), lines.end(), '\n', '\x1f');  // the description is one line
  std::string d = fmt::format("format={} header={}", kFormatVersion, lines);
  for (const GridAxis& axis : o.grid.axes) {
    d += fmt::format(" grid={}:{}", axis.name(), static_cast<int>(axis.spacing));
    if (axis.spacing == GridSpacing::kList) {
      for (double v : axis.values) d += ":" + Hex(v);
    } else {
      d += fmt::format(":{}:{}:{}", Hex(axis.lo), Hex(axis.hi), axis.n);
    }
  }
  const Forcing& f = o.forcing;
  d += fmt::format(" c={} phi0={} K={}", Hex(f.mean()), Hex(f.phi0()), f.harmonics());
  for (int k = 1; k <= f.harmonics(); ++k) {
    d += fmt::format(" a{}={} b{}={}", k, Hex(f.a(k)), k, Hex(f.b(k)));
  }
  d +=
      fmt::format(" T0={} e={} margin={} margin_stroke={} stick_margin={} stability={} optimize={}",
                  Hex(o.params.T0), Hex(o.params.e), Hex(SweepMargins(o).clearance),
                  Hex(SweepMargins(o).clearance_stroke), Hex(SweepMargins(o).stick), o.stability,
                  SweepOptimizeName(o.optimize));
  switch (o.optimize) {
    case SweepOptimize::kNone:
      break;
    case SweepOptimize::kPhase: {
      const PhaseOptions& p = o.phase;
      d += fmt::format(" scan_points={} phase_tol={}", p.scan_points, Hex(p.phase_tol)) +
           GoalDescription(p);
      break;
    }
    case SweepOptimize::kForcing:
      d += DesignDescription(o.design);
      break;
    case SweepOptimize::kFourier:
      d += DesignDescription(o.fourier.harmonic) + EffortDescription(o.fourier.search) +
           fmt::format(" harmonics={}", o.fourier.harmonics);
      break;
    case SweepOptimize::kReach:
      d += DesignDescription(o.design) + ReachDescription(o.reach);
      break;
  }
  return d;
}

SweepPoint::SweepPoint(const SweepOptions& o)
    : mode(o.optimize),
      phase(o.phase),
      design(o.design),
      fourier(o.fourier),
      reach(o.reach),
      margins(o.margins) {
  robot.forcing = o.forcing;
  robot.params = o.params;
  // The sweep's threads work on different points (the result does not depend on this).
  reach.search.attractor.threads = reach.check.attractor.threads = 1;
  if (!std::any_of(o.grid.axes.begin(), o.grid.axes.end(), [](const GridAxis& axis) {
        return axis.parameter == ModelParameter::kA || axis.parameter == ModelParameter::kMean ||
               IsFourierCoefficient(axis.parameter);
      })) {
    return;
  }
  // A gridded coefficient: the force as a series with every harmonic an axis names.
  const Forcing& f = o.forcing;
  const int K = SweepHarmonics(o);
  std::vector<double> a(static_cast<std::size_t>(K), 0.0), b(static_cast<std::size_t>(K), 0.0);
  for (int k = 1; k <= f.harmonics(); ++k) {
    a[static_cast<std::size_t>(k - 1)] = f.a(k);
    b[static_cast<std::size_t>(k - 1)] = f.b(k);
  }
  robot.forcing = Forcing::Fourier(f.mean(), a, b, f.phi0());
}

GaitRequirements& SweepPoint::Gait() {
  switch (mode) {
    case SweepOptimize::kPhase:
      return phase.gait;
    case SweepOptimize::kFourier:
      return fourier.harmonic.gait;
    case SweepOptimize::kNone:  // no requirement axis (SweepOptions::Validate)
    case SweepOptimize::kForcing:
    case SweepOptimize::kReach:  // the reach search's bound is its seed's
      break;
  }
  return design.gait;
}

Margins& SweepPoint::ModeMargins() {
  return mode == SweepOptimize::kNone ? margins : Gait().margins;
}

void SweepPoint::Set(const GridAxis& axis, double value) {
  switch (axis.parameter) {
    case ModelParameter::kA:  // b_1 of a series that a_k and b_k axes may have extended
      SetParameter(robot, ModelParameter::kSin, 1, value);
      break;
    case ModelParameter::kMean:
    case ModelParameter::kPhi0:
    case ModelParameter::kT0:
    case ModelParameter::kRestitution:
    case ModelParameter::kAlpha:
    case ModelParameter::kCos:
    case ModelParameter::kSin:
      SetParameter(robot, axis.parameter, axis.harmonic, value);
      break;
    case ModelParameter::kMargin:
      ModeMargins().clearance = value;
      break;
    case ModelParameter::kMarginStroke:
      ModeMargins().clearance_stroke = value;
      break;
    case ModelParameter::kStickMargin:
      ModeMargins().stick = value;
      break;
    case ModelParameter::kBound:
      Gait().force_bound = value;
      break;
    case ModelParameter::kRhoMax:
      Gait().rho_max = value;
      break;
  }
}

SweepRowWriter::SweepRowWriter(const SweepOptions& options)
    : options_(options), point_(options), values_(options.grid.axes.size()) {
  const std::vector<GridAxis>& axes = options.grid.axes;
  for (std::size_t i = 0; i < axes.size(); ++i) {
    if (axes[i].parameter == ModelParameter::kPhi0) order_.push_back(i);
  }
  for (std::size_t i = 0; i < axes.size(); ++i) {
    if (axes[i].parameter != ModelParameter::kPhi0) order_.push_back(i);
  }
  // robot mode, no orbit: orbits = 0, then an empty cell for every further column
  const std::size_t cells = SweepColumns(options).size() - axes.size() - 1;
  no_orbit_cells_ = "0" + std::string(cells, ',') + "\n";
}

void SweepRowWriter::SetPoint(std::int64_t point) {
  const Grid& g = options_.grid;
  for (const std::size_t i : order_) {
    values_[i] = g.Value(point, i);
    point_.Set(g.axes[i], values_[i]);
  }
}

void SweepRowWriter::AppendGridValues(RowBuffer& out) const {
  for (double value : values_) {
    AppendNumber(out, value);
    out.push_back(',');
  }
}

void SweepRowWriter::AppendSolution(const Solution& s, RowBuffer& out) const {
  const Orbit& o = s.orbit;
  const Validity& v = s.validity;
  for (double value : {o.phi1, o.alpha, o.u, o.v_plus, o.I, o.v_mean, v.x_min, v.x_max}) {
    AppendNumber(out, value);
    out.push_back(',');
  }
  out.push_back(v.valid() ? '1' : '0');
  out.push_back(',');
  bool first = true;
  for (int i = 0; i < static_cast<int>(Condition::kCount); ++i) {
    if (!v.violated(static_cast<Condition>(i))) continue;
    if (!first) out.push_back(';');
    Append(out, ConditionName(static_cast<Condition>(i)));
    first = false;
  }
  if (!options_.stability) return;
  // spectral_radius, lambda_re, lambda_im, stable, loss (empty cells without orbit)
  const Stability st = o.ok() ? ComputeStability(o) : Stability{};
  if (!st.computed) {
    Append(out, ",,,,,");
    return;
  }
  for (double value : {st.spectral_radius, st.multipliers[0].real(), st.multipliers[0].imag()}) {
    out.push_back(',');
    AppendNumber(out, value);
  }
  out.push_back(',');
  out.push_back(st.stable ? '1' : '0');
  out.push_back(',');
  Append(out, StabilityLossName(ClassifyLoss(st)));
}

// The optimised variables of the mode: phi0 (P1), A, c, phi0 (P2), c, a1..aK, b1..bK (P3).
void SweepRowWriter::AppendVariables(const Forcing& f, bool exists, RowBuffer& out) const {
  const auto cell = [&](double value) {
    AppendNumber(out, exists ? value : kNaN);
    out.push_back(',');
  };
  switch (options_.optimize) {
    case SweepOptimize::kNone:
      break;
    case SweepOptimize::kPhase:
      cell(f.phi0());
      break;
    case SweepOptimize::kForcing:
      cell(f.amplitude());
      cell(f.mean());
      cell(f.phi0());
      break;
    case SweepOptimize::kFourier: {
      const Forcing g = f.InImpactFrame();
      const int K = options_.fourier.harmonics;
      cell(g.mean());
      for (int k = 1; k <= K; ++k) cell(k <= g.harmonics() ? g.a(k) : 0.0);
      for (int k = 1; k <= K; ++k) cell(k <= g.harmonics() ? g.b(k) : 0.0);
      break;
    }
    case SweepOptimize::kReach:  // AppendReach
      break;
  }
}

std::vector<std::pair<const char*, double>> ReachCells(const ReachResult& r) {
  const bool found = !std::isnan(r.mean_velocity);
  const bool seed = r.seed.from_rest.checked;
  const Orbit& seed_orbit = r.seed.gait.solution.orbit;
  return {{"A", found ? r.forcing.amplitude() : kNaN},
          {"c", found ? r.forcing.mean() : kNaN},
          {"phi0", found ? r.forcing.phi0() : kNaN},
          {"alpha", r.alpha},
          {"mean_velocity", r.mean_velocity},
          {"seed_won", r.seed_won ? 1.0 : 0.0},
          {"robust_to_settings", r.robust_to_settings ? 1.0 : 0.0},
          {"max_relative_deviation", r.spread.max_relative_deviation},
          {"evaluations", static_cast<double>(r.evaluations)},
          {"seed_A", seed ? seed_orbit.forcing.amplitude() : kNaN},
          {"seed_c", seed ? seed_orbit.forcing.mean() : kNaN},
          {"seed_phi0", seed ? seed_orbit.forcing.phi0() : kNaN},
          {"seed_alpha", seed ? seed_orbit.alpha : kNaN},
          {"seed_I", seed ? seed_orbit.I : kNaN},
          {"seed_v_mean", seed ? seed_orbit.v_mean : kNaN},
          {"seed_mean_velocity_from_rest", seed ? r.seed.from_rest.attractors.mean_velocity : kNaN},
          {"seed_reached", seed ? static_cast<double>(r.seed.from_rest.reached) : kNaN}};
}

// The fastest motion from rest at the point, seeded by P2 with the sweep's design options (as
// `capsubot optimize --problem reach` does): the bound is design.force_bound.
void SweepRowWriter::AppendReach(RowBuffer& out) const {
  ReachOptions options = point_.reach;
  options.force_bound = point_.design.gait.force_bound;
  const ReachResult r = OptimizeReach(point_.robot.params,
                                      OptimizeForcing(point_.robot.params, point_.design), options);
  for (const auto& cell : ReachCells(r)) {
    AppendNumber(out, cell.second);
    out.push_back(',');
  }
  Append(out, OptimizeStatusName(r.status));
  out.push_back('\n');
}

int SweepRowWriter::AppendRobotPoint(std::int64_t point, RowBuffer& out) {
  bool complete = true;
  const RobotModel& robot = point_.robot;
  const std::vector<Solution> orbits = FindRobotOrbits(robot, point_.margins, &complete);
  if (!complete) {  // never write a row set that may miss orbits
    throw std::runtime_error(fmt::format(
        "robot orbits at grid point {} (alpha = {}): the search stopped at its work bound, "
        "orbits may be missing",
        point, robot.alpha));
  }
  if (orbits.empty()) {
    AppendGridValues(out);
    out.append(no_orbit_cells_);
    return 1;
  }
  int index = 0;
  for (const Solution& s : orbits) {
    AppendGridValues(out);
    constexpr std::size_t kCountsChars = 2 * 20 + 2;  // two 64-bit counts and their commas
    out.Advance(fmt::format_to(out.Room(kCountsChars), "{},{},", orbits.size(), ++index));
    AppendNumber(out, s.orbit.forcing.phi0());
    out.push_back(',');
    AppendSolution(s, out);
    out.push_back('\n');
  }
  return index;
}

int SweepRowWriter::AppendPoint(std::int64_t point, RowBuffer& out) {
  SetPoint(point);
  if (RobotMode(options_)) return AppendRobotPoint(point, out);
  AppendGridValues(out);
  if (options_.optimize == SweepOptimize::kNone) {
    AppendSolution(Solve(point_.robot.forcing, point_.robot.params, point_.margins), out);
    out.push_back('\n');
    return 1;
  }
  if (options_.optimize == SweepOptimize::kReach) {
    AppendReach(out);
    return 1;
  }
  OptimizeResult r;
  switch (options_.optimize) {
    case SweepOptimize::kPhase:
      r = OptimizePhase(point_.robot.forcing, point_.robot.params, point_.phase);
      break;
    case SweepOptimize::kForcing:
      r = OptimizeForcing(point_.robot.params, point_.design);
      break;
    case SweepOptimize::kFourier:
      r = OptimizeFourier(point_.robot.params, point_.fourier);
      break;
    case SweepOptimize::kNone:  // handled above
    case SweepOptimize::kReach:
      break;
  }
  const Solution& s = r.solution;
  AppendVariables(s.orbit.forcing, s.orbit.status != OrbitStatus::kNotRun, out);
  AppendSolution(s, out);
  out.push_back(',');
  Append(out, OptimizeStatusName(r.status));
  out.push_back('\n');
  return 1;
}

}  // namespace capsubot::detail
