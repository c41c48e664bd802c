// The long-run motion from one start (docs/model.md section 13): transient, section, record,
// period from the state of the stroboscopic map.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>

#include "attract/stroboscopic.hpp"
#include "capsubot/attractors.hpp"
#include "model/enum_names.hpp"

namespace capsubot {
namespace {

constexpr int kMaxPeriodLimit = 64;
// A section closer than this (rad) to an event may see the state before or after it: the
// early stop does not trust such a section and moves it.
constexpr double kSectionClearance = 1e-6;

}  // namespace

const char* MotionStatusName(MotionStatus status) {
  static constexpr const char* kNames[] = {"not_run", "periodic", "no_period", "event_limit"};
  static_assert(std::size(kNames) == static_cast<std::size_t>(MotionStatus::kEventLimit) + 1);
  return detail::EnumName(kNames, status);
}

void MotionOptions::Validate() const {
  if (transient < 0) {
    throw std::invalid_argument(
        fmt::format("transient = {} is invalid: expected >= 0 periods", transient));
  }
  if (max_period < 1 || max_period > kMaxPeriodLimit) {
    throw std::invalid_argument(fmt::format(
        "max_period = {} is invalid: expected 1 <= max_period <= {}", max_period, kMaxPeriodLimit));
  }
  if (record < 2 * max_period || record > kMaxRecord) {
    throw std::invalid_argument(
        fmt::format("record = {} is invalid: expected 2 * max_period = {} <= record <= 1e7 periods",
                    record, 2 * max_period));
  }
  if (!(state_tolerance > 0.0) || !std::isfinite(state_tolerance)) {
    throw std::invalid_argument(fmt::format(
        "state_tolerance = {} is invalid: expected a finite number > 0", state_tolerance));
  }
  if (!(chatter_velocity > 0.0) || !std::isfinite(chatter_velocity)) {
    throw std::invalid_argument(fmt::format(
        "chatter_velocity = {} is invalid: expected a finite number > 0", chatter_velocity));
  }
  if (!(converged_tolerance >= 0.0) || !std::isfinite(converged_tolerance)) {
    throw std::invalid_argument(fmt::format(
        "converged_tolerance = {} is invalid: expected a finite number >= 0 (0: no early stop)",
        converged_tolerance));
  }
  if (max_events_per_period < 10) {
    throw std::invalid_argument(fmt::format("max_events_per_period = {} is invalid: expected >= 10",
                                            max_events_per_period));
  }
}

namespace detail {

void ValidateStart(double alpha, const PhaseState& start) {
  SimOptions o;  // the simulator's own rules for alpha and the state
  o.alpha = alpha;
  o.x0 = start.x;
  o.u0 = start.u;
  o.v0 = start.v;
  o.Validate();
  if (!std::isfinite(start.psi)) {
    throw std::invalid_argument(
        fmt::format("start phase psi = {} is invalid: expected a finite number", start.psi));
  }
}

// Counts and mean velocity of a motion of period p from a record of whole periods: impacts of
// the last p periods; displacement over the largest whole number of periods p at the end of
// the record along which the section states repeat with period p (within tol), so a record
// that starts before the motion settled does not bias it.
void FillPeriodic(Motion& m, int p, const Recorder& recorder, double tol) {
  const int R = static_cast<int>(recorder.right.size());
  const std::vector<SimState>& S = recorder.samples;
  m.status = MotionStatus::kPeriodic;
  m.period = p;
  for (int k = R - p; k < R; ++k) {
    m.impacts_right += recorder.right[static_cast<std::size_t>(k)];
    m.impacts_left += recorder.left[static_cast<std::size_t>(k)];
  }
  int first = R - p;  // S[first..R] repeats with period p
  while (first > 0 && SameState(S[static_cast<std::size_t>(first - 1)],
                                S[static_cast<std::size_t>(first - 1 + p)], tol)) {
    --first;
  }
  const int whole = ((R - first) / p) * p;
  m.mean_velocity = (S[static_cast<std::size_t>(R)].y - S[static_cast<std::size_t>(R - whole)].y) /
                    (whole * kTau);
}

Motion ClassifyMotion(const Forcing& forcing, const Params& params, double alpha,
                      const MotionOptions& options, MapState s, Recorder& recorder,
                      bool keep_impacts) {
  Motion m;
  s.z.psi -= kTau * std::floor(s.z.psi / kTau);
  const auto stopped = [&](const SimResult& r) {
    if (r.status != SimStatus::kEventLimit) return false;
    m.status = MotionStatus::kEventLimit;
    m.section = s.z;
    m.mode = s.mode;
    return true;
  };
  const auto advance = [&](double periods, bool record) {
    return stopped(Advance(forcing, params, alpha, options, s, periods, nullptr,
                           record ? &recorder : nullptr, record));
  };
  const int P = options.max_period;
  // Early stop: in chunks of 2P periods, a motion that already repeats to converged_tolerance
  // at a section clear of every event is periodic; the rest of the run would repeat it.
  int done = 0;
  const int chunk = 2 * P;
  while (options.converged_tolerance > 0.0 && done + chunk <= options.transient) {
    recorder.Start(chunk, true, true);
    if (advance(chunk, true)) return m;
    done += chunk;
    const bool clear = SectionClear(recorder.event_phases, kSectionClearance);
    const int p = static_cast<int>(recorder.samples.size()) == chunk + 1
                      ? DetectPeriod(recorder.samples, P, options.converged_tolerance)
                      : 0;
    if (clear && p > 0) {
      FillPeriodic(m, p, recorder, options.converged_tolerance);
      m.section = s.z;
      m.mode = s.mode;
      recorder.impacts.clear();
      return m;
    }
    if (!clear && advance(SectionShift(recorder.event_phases) / kTau, false)) return m;
  }
  // Transient; its last P periods tell where the events of the motion lie.
  const int tail = std::min(P, options.transient - done);
  if (options.transient - done > tail && advance(options.transient - done - tail, false)) return m;
  recorder.Start(tail, false, true);
  if (tail > 0 && stopped(Advance(forcing, params, alpha, options, s, tail, nullptr, &recorder))) {
    return m;
  }
  const double shift = SectionShift(recorder.event_phases);
  if (shift > 0.0 && advance(shift / kTau, false)) return m;
  // Record: the state at every whole period from the section.
  const int R = options.record;
  recorder.Start(R, true, false, keep_impacts);
  double displacement = 0.0;
  const SimResult r =
      Advance(forcing, params, alpha, options, s, R, &displacement, &recorder, true);
  if (stopped(r)) return m;
  m.section = s.z;
  m.mode = s.mode;
  const int p = static_cast<int>(recorder.samples.size()) == R + 1
                    ? DetectPeriod(recorder.samples, P, options.state_tolerance)
                    : 0;
  if (p > 0) {
    FillPeriodic(m, p, recorder, options.state_tolerance);
    return m;
  }
  m.status = MotionStatus::kNoPeriod;
  for (int k = 0; k < R; ++k) {
    m.impacts_right += recorder.right[static_cast<std::size_t>(k)];
    m.impacts_left += recorder.left[static_cast<std::size_t>(k)];
  }
  m.mean_velocity = displacement / (R * kTau);
  return m;
}

}  // namespace detail

Motion LongRunMotion(const Forcing& forcing, const Params& params, double alpha,
                     const PhaseState& start, const MotionOptions& options) {
  params.Validate();
  options.Validate();
  detail::ValidateStart(alpha, start);
  detail::Recorder recorder;
  return detail::ClassifyMotion(forcing, params, alpha, options, {start, SimMode::kRest}, recorder);
}

PhaseState RestStart(double x0, double psi) {
  PhaseState s;
  s.x = x0;
  s.u = 0.0;
  s.v = 0.0;
  s.psi = psi;
  return s;
}

PhaseState GridStart(int i, int j, int n_x, int n_psi) {
  return RestStart((i + 0.5) / n_x, kTau * j / n_psi);
}

}  // namespace capsubot
