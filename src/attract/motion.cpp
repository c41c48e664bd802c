// The long-run motion from one start (docs/model.md section 13): one continuous simulation of
// the transient and the record, the period and velocity of a periodic motion from Newton's
// method on the stroboscopic map, an early stop only on a proven attracting motion.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>

#include "capsubot/attract/attractors.hpp"
#include "capsubot/attract/detail/stroboscopic.hpp"
#include "capsubot/model/detail/enum_names.hpp"
#include "capsubot/numerics/grid_value.hpp"

namespace capsubot {
namespace {

constexpr int kMaxPeriodLimit = 64;

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

namespace detail {
namespace {

// Early stop: a state whose section states repeated to converged_tolerance is taken as settled
// only when Newton's method finds the periodic motion through it (residual within the
// shooting's tolerance), that motion attracts (spectral radius at most this) and the state lies
// on it within kSettledDistance: then the rest of the run can only converge to it.
constexpr double kSettledRadius = 1.0 - 1e-3;
constexpr double kSettledDistance = 1e-8;
// Newton's method is tried at most this many times per start (a motion it cannot settle runs
// to the end, as without the early stop).
constexpr int kMaxSettleTries = 4;
// At the end of the record, the periodic motion Newton finds is the recorded one when the last
// state lies within this of it (units of L and omega L); otherwise the period and velocity
// come from the record alone.
constexpr double kRefinedDistance = 1e-3;
// A motion whose last states repeat to this (units of L and omega L) at a section clear of its
// events is periodic to rounding: its period, impacts and mean velocity are read off its last
// periods, exact to that, without Newton's method.
constexpr double kSettledTol = 1e-11;
// An event closer than this (rad) to the section may fall on either side of it.
constexpr double kSectionClearance = 1e-6;

double Distance(const PhaseState& a, const PhaseState& b) {
  return std::max({std::abs(a.x - b.x), std::abs(a.u - b.u), std::abs(a.v - b.v)});
}

// The motion of a periodic motion found by Newton's method: its exact period, impacts, mean
// velocity, section state and largest multiplier.
Motion FromPeriodic(const PeriodicMotion& pm) {
  Motion m;
  m.status = MotionStatus::kPeriodic;
  m.period = pm.period;
  m.impacts_right = pm.impacts_right;
  m.impacts_left = pm.impacts_left;
  m.mean_velocity = pm.mean_velocity;
  m.first_half_velocity = m.second_half_velocity = pm.mean_velocity;
  m.section = pm.state;
  m.mode = pm.mode;
  m.spectral_radius = pm.spectral_radius;
  if (!pm.multipliers.empty()) {
    m.multiplier_re = pm.multipliers.front().real();
    m.multiplier_im = pm.multipliers.front().imag();
  }
  m.refined = true;
  return m;
}

// Watches one continuous simulation of a long run: the state at every whole period from the
// start (the last 2 max_period + 1 kept), the impacts of the record (in `recorder`), and at
// the end of every chunk of 2 max_period periods of the transient, the early stop.
class LongRun : public SimObserver {
 public:
  LongRun(const RobotModel& robot, const MotionOptions& o, Recorder& recorder)
      : robot_(robot),
        o_(o),
        recorder_(recorder),
        right_(static_cast<std::size_t>(2 * o.max_period), 0),
        left_(static_cast<std::size_t>(2 * o.max_period), 0) {
    ring_.reserve(static_cast<std::size_t>(2 * o.max_period + 1));
  }

  void OnEvent(const SimEvent& event) override {
    recorder_.OnEvent(event);
    const double turns = std::floor(event.after.phi / kTau);
    const double within = event.after.phi - turns * kTau;
    const auto period = static_cast<std::int64_t>(turns);
    if (within < kSectionClearance || within > kTau - kSectionClearance) near_section_ = period;
    if (event.kind != EventKind::kImpactRight && event.kind != EventKind::kImpactLeft) return;
    const auto slot = static_cast<std::size_t>(period % (2 * o_.max_period));
    ++(event.kind == EventKind::kImpactRight ? right_ : left_)[slot];
  }

  void OnSample(const SimState& state) override {
    const auto cap = static_cast<std::size_t>(2 * o_.max_period + 1);
    if (ring_.size() == cap) ring_.erase(ring_.begin());
    ring_.push_back(state);
    const auto slot = static_cast<std::size_t>(samples_ % (2 * o_.max_period));
    right_[slot] = left_[slot] = 0;  // period samples_ starts here
    if (samples_ == o_.transient) record_start_ = state;
    if (samples_ == o_.transient + o_.record / 2) record_middle_ = state;
    ++samples_;
  }

  bool Done() override {
    const int k = samples_ - 1;  // whole periods done
    const int chunk = 2 * o_.max_period;
    if (!(o_.converged_tolerance > 0.0) || k == 0 || k % chunk != 0 || k > o_.transient) {
      return false;
    }
    const int p = DetectPeriod(ring_, o_.max_period, o_.converged_tolerance);
    if (p == 0 || tries_ >= kMaxSettleTries) return false;
    ++tries_;
    const SimState& last = ring_.back();
    MapState s{{last.x, last.u, last.v, psi_}, last.mode}, moved;
    const PeriodicMotion pm = RefinePeriodicMotion(robot_, o_, s, p, &moved);
    if (pm.status != ShootingStatus::kConverged || !(pm.spectral_radius <= kSettledRadius) ||
        !(Distance(moved.z, pm.state) <= kSettledDistance)) {
      return false;
    }
    settled_ = pm;
    return true;
  }

  void SetPhase(double psi) { psi_ = psi; }
  const std::vector<SimState>& Ring() const { return ring_; }

  // The period of a motion whose last states repeat to kSettledTol at a section clear of its
  // events over the last max_period periods, when no shorter period repeats to
  // state_tolerance (a slowly converging motion may repeat closer every 2 periods than every
  // period: Newton's method decides that one); 0 otherwise.
  int SettledPeriod() const {
    if (!SectionClear()) return 0;
    const int p = DetectPeriod(ring_, o_.max_period, kSettledTol);
    return p > 0 && DetectPeriod(ring_, o_.max_period, o_.state_tolerance) == p ? p : 0;
  }

  // No event within kSectionClearance of the section over the last max_period periods.
  bool SectionClear() const { return near_section_ < samples_ - 1 - o_.max_period; }

  // The motion of period p read off the last states and impacts.
  Motion FromRing(int p) const {
    Motion m;
    m.status = MotionStatus::kPeriodic;
    m.period = p;
    const int done = samples_ - 1, P2 = 2 * o_.max_period;
    for (int k = done - p; k < done; ++k) {
      const auto slot = static_cast<std::size_t>(k % P2);
      m.impacts_right += right_[slot];
      m.impacts_left += left_[slot];
    }
    // Over its last period p (the earlier states of the ring may precede the motion).
    const auto n = ring_.size() - 1;
    m.mean_velocity = (ring_[n].y - ring_[n - static_cast<std::size_t>(p)].y) / (p * kTau);
    m.first_half_velocity = m.second_half_velocity = m.mean_velocity;
    const SimState& last = ring_.back();
    m.section = {last.x, last.u, last.v, psi_};
    m.mode = last.mode;
    return m;
  }
  const PeriodicMotion& Settled() const { return settled_; }
  const SimState& RecordStart() const { return record_start_; }
  const SimState& RecordMiddle() const { return record_middle_; }

 private:
  const RobotModel& robot_;
  const MotionOptions& o_;
  Recorder& recorder_;
  std::vector<SimState> ring_;
  std::vector<std::int32_t> right_, left_;  // impacts of the last 2 max_period periods
  std::int64_t near_section_ = -1;          // last period with an event at the section
  int samples_ = 0;
  int tries_ = 0;
  double psi_ = 0.0;
  SimState record_start_, record_middle_;
  PeriodicMotion settled_;
};

// The period of the motion through s from a short look at a section clear of its events:
// max_period periods to see the events, the section moved into their largest gap, then
// 2 max_period periods of section states. 0 when none repeats within state_tolerance (or the
// work bound is hit).
int ProbePeriod(const RobotModel& robot, const MotionOptions& o, MapState s, Recorder& probe,
                MapState* at) {
  const int P = o.max_period;
  MapState look = s;
  probe.Start(P, false, true);
  if (Advance(robot, o, look, P, nullptr, &probe).status == SimStatus::kEventLimit) {
    return 0;
  }
  const double shift = SectionShift(probe.event_phases);
  if (shift > 0.0 && Advance(robot, o, s, shift / kTau, nullptr).status == SimStatus::kEventLimit) {
    return 0;
  }
  *at = s;
  probe.Start(2 * P, true, false);
  if (Advance(robot, o, s, 2 * P, nullptr, &probe, true).status == SimStatus::kEventLimit ||
      static_cast<int>(probe.samples.size()) != 2 * P + 1) {
    return 0;
  }
  return DetectPeriod(probe.samples, P, o.state_tolerance);
}

// The motion of period p read off the section states and impacts of a probe (ProbePeriod),
// when Newton's method did not refine it; `end` is the state at the end of the record.
Motion FromProbe(const Recorder& probe, int p, const MapState& end) {
  Motion m;
  m.status = MotionStatus::kPeriodic;
  m.period = p;
  const std::vector<SimState>& S = probe.samples;
  const int n = static_cast<int>(S.size()) - 1, whole = (n / p) * p;
  m.mean_velocity = (S[static_cast<std::size_t>(n)].y - S[static_cast<std::size_t>(n - whole)].y) /
                    (whole * kTau);
  m.first_half_velocity = m.second_half_velocity = m.mean_velocity;
  for (std::size_t k = probe.right.size() - static_cast<std::size_t>(p); k < probe.right.size();
       ++k) {
    m.impacts_right += probe.right[k];
    m.impacts_left += probe.left[k];
  }
  m.section = end.z;
  m.mode = end.mode;
  return m;
}

// No periodic motion: the figures of the record of R periods (simulated as `r`), as a direct
// run of the start gives them; `end` is the state at the end of the record.
Motion FromRecord(const Recorder& recorder, const LongRun& run, const SimResult& r, int R,
                  const MapState& end) {
  Motion m;
  m.status = MotionStatus::kNoPeriod;
  for (int k = 0; k < R; ++k) {
    m.impacts_right += recorder.right[static_cast<std::size_t>(k)];
    m.impacts_left += recorder.left[static_cast<std::size_t>(k)];
  }
  m.mean_velocity = r.displacement / (R * kTau);
  const int half = R / 2;
  m.first_half_velocity = (run.RecordMiddle().y - run.RecordStart().y) / (half * kTau);
  m.second_half_velocity = (r.final_state.y - run.RecordMiddle().y) / ((R - half) * kTau);
  m.section = end.z;
  m.mode = end.mode;
  return m;
}

}  // namespace

Motion ClassifyMotion(const RobotModel& robot, const MotionOptions& options, MapState s,
                      Recorder& recorder, bool keep_impacts) {
  s.z.psi -= kTau * std::floor(s.z.psi / kTau);
  const double psi = s.z.psi;
  const int T = options.transient, R = options.record;
  // One continuous run of the transient and the record, as a direct simulation of the start
  // would do: restarting it would perturb the motion by rounding, and a chaotic transient
  // would then end elsewhere.
  recorder.Start(R, false, false, keep_impacts, psi, T * kTau);
  LongRun run(robot, options, recorder);
  run.SetPhase(psi);
  SimOptions o = RunOptions(options, robot.alpha, s.z);
  o.transient = T;
  o.periods = R;
  o.sample_step = kTau;
  const Forcing& forcing = robot.forcing;
  const SimResult r = Simulate(forcing.WithPhase(forcing.phi0() + psi), robot.params, o, &run);
  const SimState& f = r.final_state;
  MapState end{{f.x, f.u, f.v, psi}, f.mode};
  if (r.status == SimStatus::kEventLimit) {
    Motion m;
    m.status = MotionStatus::kEventLimit;
    m.section = end.z;
    m.mode = end.mode;
    return m;
  }
  if (run.Settled().status == ShootingStatus::kConverged) {
    recorder.impacts.clear();
    // Read off the last states when they already repeat with the motion's own period.
    const int settled = run.SettledPeriod();
    return settled == run.Settled().period ? run.FromRing(settled) : FromPeriodic(run.Settled());
  }
  if (const int settled = run.SettledPeriod(); settled > 0) return run.FromRing(settled);
  // The period: from the states at the start's phase, or, when those do not repeat (the
  // phase may lie on an event), from a section clear of the events.
  MapState at = end;
  Recorder probe;
  const std::vector<SimState>* samples = &run.Ring();
  int p = DetectPeriod(*samples, options.max_period, options.state_tolerance);
  if (p == 0 && !run.SectionClear()) {  // the states may flip across an event
    p = ProbePeriod(robot, options, end, probe, &at);
    samples = &probe.samples;
  }
  if (p > 0) {
    MapState moved;
    const PeriodicMotion pm = RefinePeriodicMotion(robot, options, at, p, &moved);
    if (pm.status == ShootingStatus::kConverged &&
        Distance(moved.z, pm.state) <= kRefinedDistance) {
      return FromPeriodic(pm);
    }
    // Newton failed (a non-smooth map, a work bound): the states repeat all the same.
    return samples == &run.Ring() ? run.FromRing(p) : FromProbe(probe, p, end);
  }
  return FromRecord(recorder, run, r, R, end);
}

}  // namespace detail

Motion LongRunMotion(const RobotModel& robot, const PhaseState& start,
                     const MotionOptions& options) {
  robot.params.Validate();
  options.Validate();
  ValidateStart(robot.alpha, start);
  detail::Recorder recorder;
  return detail::ClassifyMotion(robot, options, {start, SimMode::kRest}, recorder);
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
  // Cell centres: the odd values of the grid of 2 n_x + 1 values over [0, 1].
  return RestStart(GridValue(0.0, 1.0, 2 * std::int64_t{n_x} + 1, 2 * std::int64_t{i} + 1),
                   GridValue(0.0, kTau, std::int64_t{n_psi} + 1, j));
}

}  // namespace capsubot
