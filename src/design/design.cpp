// The design searches: the fastest robust one-impact gait over the inner mass (and the motor
// frequency), and the gait of a robot of given inner mass (docs/model.md sections 9 and 12).

#include "capsubot/design.hpp"

#include <fmt/format.h>

#include <cmath>
#include <iterator>
#include <stdexcept>

#include "model/enum_names.hpp"
#include "numerics/golden.hpp"

namespace capsubot {
namespace {

// Resolution of the refinement in log(m2) and log(f): 1e-9 relative.
constexpr double kLogTol = 1e-9;

// Counts the robots evaluated and reports progress; once kDesignMaxUnresolvedRobots orbit
// searches have hit their work bound, the robots asked for next are not evaluated (status
// kNotRun: no speed, and no reason that outranks one met).
struct Tally {
  const DesignProgress& progress;
  std::int64_t total = 0;  // upper bound for progress reports
  std::int64_t robots = 0;
  std::int64_t unresolved = 0;
  bool complete = true;

  bool stopped() const { return unresolved >= kDesignMaxUnresolvedRobots; }

  Gait Evaluate(const DesignInput& in, double m2, double frequency) {
    if (stopped()) {
      Gait skipped;
      skipped.m2_kg = m2;
      skipped.frequency_hz = frequency;
      return skipped;
    }
    Gait g = EvaluateGait(in, m2, frequency);
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

// Fastest gait of inner(value) for value in [lo, hi]: log-spaced scan, then golden section
// (detail::ScanGoldenMaximize). The best gait met is kept (the search's own best point); when
// it sits at an end of the range, that end's name joins its binding limits.
template <class Inner>
Gait Maximise(double lo, double hi, int n, const Inner& inner, const char* lo_name,
              const char* hi_name) {
  Gait best;
  GaitStatus why = GaitStatus::kNotRun;
  double best_value = std::numeric_limits<double>::quiet_NaN();
  const auto speed = [&](double x) {
    const double value = FromLog(x, lo, hi);
    Gait g = inner(value);
    if (!g.ok()) {
      why = Worse(why, g.status);
      return std::numeric_limits<double>::quiet_NaN();
    }
    const double v = g.speed_mm_s;
    if (!best.ok() || v > best.speed_mm_s) {  // the same rule as the search's own best point
      best = std::move(g);
      best_value = value;
    }
    return v;
  };
  detail::ScanGoldenMaximize(speed, std::log(lo), std::log(hi), n, kLogTol);
  if (!best.ok()) {
    best.status = why;
    return best;
  }
  if (best_value == lo) best.binding.emplace_back(lo_name);
  if (best_value == hi) best.binding.emplace_back(hi_name);
  return best;
}

// The fastest gait over m2 in the input's range at frequency f.
Gait BestOverM2(const DesignInput& in, double frequency, Tally& tally) {
  Gait g = Maximise(
      in.M2Min(), in.M2Max(), in.scan_points,
      [&](double m2) { return tally.Evaluate(in, m2, frequency); }, "m2_min", "m2_max");
  g.frequency_hz = frequency;
  return g;
}

// Robots one m2 search evaluates at most.
std::int64_t SearchBound(const DesignInput& in) { return in.scan_points + detail::kGoldenMaxSteps; }

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
  const auto over_m2 = [&](double f) { return BestOverM2(in, f, tally); };
  DesignResult r;
  if (FixedFrequency(in)) {
    tally.total = SearchBound(in);
    r.one_impact = over_m2(in.frequency_min);
  } else {
    tally.total = SearchBound(in) * SearchBound(in);
    r.one_impact = Maximise(in.frequency_min, in.frequency_max, in.scan_points, over_m2,
                            "frequency_min", "frequency_max");
  }
  r.robots = tally.robots;
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
  if (FixedFrequency(in)) return tally.Evaluate(in, m2, in.frequency_min);
  Gait g = Maximise(
      in.frequency_min, in.frequency_max, in.scan_points,
      [&](double f) { return tally.Evaluate(in, m2, f); }, "frequency_min", "frequency_max");
  g.m2_kg = m2;
  return g;
}

}  // namespace capsubot
