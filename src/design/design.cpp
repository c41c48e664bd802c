// The design searches: the fastest robust one-impact gait over the inner mass (and the motor
// frequency), and the gait of a robot of given inner mass (docs/model.md sections 9 and 12).

#include "capsubot/design/design.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <vector>

#include "capsubot/model/detail/enum_names.hpp"
#include "capsubot/numerics/windows.hpp"
#include "design/search.hpp"

namespace capsubot {
namespace {

// Resolution of the refinement in log(m2) and log(f): 1e-9 relative.
constexpr double kLogTol = 1e-9;
// Resolution of the bracketing of windows in log(m2) and log(f) (docs/design.md, "How the
// search works"): a window wider than this is found where the search looks for one ...
constexpr double kWindowResolution = 1e-6;
// ... and a gap across which the robot's orbit count changes (a fold of alpha(phi0), where two
// orbits merge) is bisected to this: within 1e-5 to 1e-4 of the fold (by robot) the orbit
// search needs more than the default DesignInput::orbit_evaluations to tell two orbits from
// none, and a robot that close, met by chance, is an unresolved robot.
constexpr double kFoldResolution = 1e-3;
// Bracketing budget of one search, in robots (or m2 searches) per scan sample.
constexpr int kRefinementsPerSample = 8;

// Counts the robots evaluated and reports progress; once kDesignMaxUnresolvedRobots orbit
// searches have hit their work bound, the searches ask for no more robots.
struct Tally {
  const DesignProgress& progress;
  std::int64_t total = 0;  // upper bound for progress reports, raised for more speed maxima
  std::int64_t robots = 0;
  std::int64_t unresolved = 0;
  int exhausted = 0;  // searches whose bracketing budget ran out
  bool complete = true;

  bool stopped() const { return unresolved >= kDesignMaxUnresolvedRobots; }

  Gait Evaluate(const DesignInput& in, double m2, double frequency, double* slack) {
    Gait g = detail::EvaluateGait(in, m2, frequency, slack);
    ++robots;
    if (!g.complete) ++unresolved;
    complete = complete && g.complete;
    if (progress) progress(robots, total);
    return g;
  }
};

// Why no gait was found over a searched range: not_robust if some robot had orbits, else
// no_orbit if some robot had a motor that does not slide the shell, else motor_slides_shell.
GaitStatus Worse(GaitStatus a, GaitStatus b) {
  const auto rank = [](GaitStatus s) {
    return s == GaitStatus::kNotRobust          ? 3
           : s == GaitStatus::kNoOrbit          ? 2
           : s == GaitStatus::kMotorSlidesShell ? 1
                                                : 0;
  };
  return rank(a) >= rank(b) ? a : b;
}

// The value at x of a log scale from lo to hi, exact at both ends.
double FromLog(double x, double lo, double hi) {
  return x == std::log(lo) ? lo : x == std::log(hi) ? hi : std::exp(x);
}

// The fastest gait at one point of a search (a robot, or the best over m2 at one frequency)
// and what the window search needs to know there.
struct Found {
  Gait gait;
  detail::Probe probe;
};

// One robot: its branches are its orbits (-1 when the motor slides the shell).
Found Robot(const DesignInput& in, double m2, double frequency, Tally& tally) {
  Found r;
  r.gait = tally.Evaluate(in, m2, frequency, &r.probe.slack);
  r.probe.feasible = r.gait.ok();
  r.probe.branches = r.gait.status == GaitStatus::kMotorSlidesShell ? -1 : r.gait.orbits;
  r.probe.value = r.gait.speed_mm_s;
  return r;
}

// Robots (or m2 searches) one search evaluates at most when its windows hold one local maximum
// of the speed; each more adds kGoldenMaxSteps.
std::int64_t SearchBound(const DesignInput& in) {
  return static_cast<std::int64_t>(in.scan_points) * (1 + kRefinementsPerSample) +
         detail::kGoldenMaxSteps;
}

// Fastest gait of inner(value) for value in [lo, hi]: the windows of values with a gait are
// bracketed in log(value), then the speed is maximised in each (detail::MaximiseOverWindows).
// The best gait met is kept; when it sits at an end of the range, that end's name joins its
// binding limits. The probe returned sums the search up for a search around it: its measure
// is the largest met, its branches say whether some robot had orbits (1), none had but some
// motor left its shell at rest (0), or every motor slid its shell (-1). `cost` is the robots
// one inner(value) evaluates at most; `windows` (if not null) receives each window's bracket.
template <class Inner>
Found Maximise(double lo, double hi, int n, const Inner& inner, Tally& tally, std::int64_t cost,
               const char* lo_name, const char* hi_name,
               std::vector<detail::M2Window>* windows = nullptr) {
  Found best;
  best.probe.branches = -1;
  GaitStatus why = GaitStatus::kNotRun;
  double best_value = kNaN;
  const auto probe = [&](double x) {
    const double value = FromLog(x, lo, hi);
    Found f = inner(value);
    best.probe.slack = std::max(best.probe.slack, f.probe.slack);
    best.probe.branches = std::max(best.probe.branches, std::min(f.probe.branches, 1));
    if (!f.gait.ok()) {
      why = Worse(why, f.gait.status);
    } else if (!best.gait.ok() || f.gait.speed_mm_s > best.gait.speed_mm_s) {
      best.gait = std::move(f.gait);
      best_value = value;
    }
    return f.probe;
  };
  detail::WindowOptions options;
  options.scan_points = n;
  options.resolution = kWindowResolution;
  options.fold_resolution = kFoldResolution;
  options.max_refinements = kRefinementsPerSample * n;
  options.tol = kLogTol;
  const detail::WindowSearch search = detail::MaximiseOverWindows(
      probe, [&tally] { return tally.stopped(); }, std::log(lo), std::log(hi), options);
  if (search.maxima > 1) {
    tally.total += static_cast<std::int64_t>(search.maxima - 1) * detail::kGoldenMaxSteps * cost;
  }
  if (search.exhausted) ++tally.exhausted;
  if (windows != nullptr) {
    const auto at = [&](int i) { return FromLog(search.samples[i].x, lo, hi); };
    const int last = static_cast<int>(search.samples.size()) - 1;
    for (const detail::Window& w : search.windows) {
      windows->push_back(
          {at(std::max(w.first - 1, 0)), at(w.first), at(w.last), at(std::min(w.last + 1, last))});
    }
  }
  if (!best.gait.ok()) {
    best.gait.status = why;
    return best;
  }
  best.probe.feasible = true;
  best.probe.value = best.gait.speed_mm_s;
  if (best_value == lo) best.gait.binding.emplace_back(lo_name);
  if (best_value == hi) best.gait.binding.emplace_back(hi_name);
  return best;
}

// The fastest gait over m2 in the input's range at frequency f.
Found OverM2(const DesignInput& in, double frequency, Tally& tally,
             std::vector<detail::M2Window>* windows = nullptr) {
  Found r = Maximise(
      in.M2Min(), in.M2Max(), in.scan_points,
      [&](double m2) { return Robot(in, m2, frequency, tally); }, tally, 1, "m2_min", "m2_max",
      windows);
  r.gait.frequency_hz = frequency;
  return r;
}

bool FixedFrequency(const DesignInput& in) { return in.frequency_min == in.frequency_max; }

std::string Describe(const DesignInput& in, const Gait& g) {
  const std::string where =
      FixedFrequency(in) ? fmt::format("{:g} Hz", in.frequency_min)
                         : fmt::format("{:g} to {:g} Hz", in.frequency_min, in.frequency_max);
  const std::string range =
      fmt::format("m2 in [{:g}, {:g}] kg at {}", in.M2Min(), in.M2Max(), where);
  switch (g.status) {
    case GaitStatus::kOk:
      return fmt::format(
          "fastest robust one-impact gait over {}: m2 = {:.6g} kg at {:.6g} Hz, {:.6g} mm/s, "
          "{:.6g} mW",
          range, g.m2_kg, g.frequency_hz, g.speed_mm_s, g.power_mw);
    case GaitStatus::kMotorSlidesShell:
      return fmt::format(
          "no one-impact gait over {}: the motor slides the shell by itself everywhere "
          "(max |F_N| > mu (m1+m2) g), so the shell never rests between impacts",
          range);
    case GaitStatus::kNoOrbit:
      return fmt::format("no one-impact gait over {}: no robot there has a one-impact orbit",
                         range);
    default:
      return fmt::format(
          "no robust one-impact gait over {}: one-impact orbits exist, but none is valid with "
          "the margins (d = {:g}, d_s = {:g}, s = {:g}) and has spectral radius <= rho_max = "
          "{:g}",
          range, in.margin, in.margin_stroke, in.stick_margin, in.rho_max);
  }
}

}  // namespace

const char* DesignStatusName(DesignStatus status) {
  static constexpr const char* kNames[] = {"not_run", "ok", "motor_slides_shell", "no_gait"};
  static_assert(std::size(kNames) == static_cast<std::size_t>(DesignStatus::kNoGait) + 1);
  return detail::EnumName(kNames, status);
}

DesignResult Design(const DesignInput& in, const DesignProgress& progress) {
  in.Validate();
  Tally tally{progress};
  DesignResult r;
  if (FixedFrequency(in)) {
    tally.total = SearchBound(in);
    r.one_impact = OverM2(in, in.frequency_min, tally).gait;
  } else {
    tally.total = SearchBound(in) * SearchBound(in);
    r.one_impact = Maximise(
                       in.frequency_min, in.frequency_max, in.scan_points,
                       [&](double f) { return OverM2(in, f, tally); }, tally, SearchBound(in),
                       "frequency_min", "frequency_max")
                       .gait;
  }
  r.robots = tally.robots;
  if (progress) progress(tally.robots, tally.robots);  // the end: the bound was an upper one
  r.complete = tally.complete;
  r.unresolved_robots = tally.unresolved;
  const GaitStatus s = r.one_impact.status;
  r.status = s == GaitStatus::kOk                 ? DesignStatus::kOk
             : s == GaitStatus::kMotorSlidesShell ? DesignStatus::kMotorSlidesShell
                                                  : DesignStatus::kNoGait;
  r.message = Describe(in, r.one_impact);
  if (tally.stopped()) {
    r.message += fmt::format(
        "; the search stopped after {} robots: the orbit searches of {} of them hit their work "
        "bound of {} evaluations (orbits may be missing there), so the rest of the range was "
        "not evaluated",
        tally.robots, tally.unresolved, in.orbit_evaluations);
  } else if (tally.exhausted > 0) {
    r.message += fmt::format(
        "; the bracketing budget of {} of its searches ran out, so a window of gaits narrower "
        "than the scan's spacing may be missing there",
        tally.exhausted);
  }
  return r;
}

Gait DesignGait(const DesignInput& in, double m2) {
  if (std::isnan(m2)) return Design(in).one_impact;
  in.Validate();
  if (!(std::isfinite(m2) && m2 > 0.0)) {
    throw std::invalid_argument(
        fmt::format("inner mass m2 = {} is invalid: expected a finite m2 > 0 [kg]", m2));
  }
  const DesignProgress none;
  Tally tally{none};
  if (FixedFrequency(in)) return Robot(in, m2, in.frequency_min, tally).gait;
  Gait g = Maximise(
               in.frequency_min, in.frequency_max, in.scan_points,
               [&](double f) { return Robot(in, m2, f, tally); }, tally, 1, "frequency_min",
               "frequency_max")
               .gait;
  g.m2_kg = m2;
  return g;
}

namespace detail {

Gait BestOverM2(const DesignInput& in, double frequency, std::vector<M2Window>* windows) {
  in.Validate();
  const DesignProgress none;
  Tally tally{none};
  return OverM2(in, frequency, tally, windows).gait;
}

}  // namespace detail

}  // namespace capsubot
