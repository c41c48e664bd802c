#include "capsubot/attract/detail/stroboscopic.hpp"

#include <algorithm>
#include <cmath>

namespace capsubot::detail {

void Recorder::Start(int periods, bool samples_wanted, bool events_wanted, bool impacts_wanted,
                     double psi0_at_start, double origin_phase) {
  periods_ = periods;
  psi0 = psi0_at_start;
  origin = origin_phase;
  keep_impacts_ = impacts_wanted;
  impacts.clear();
  keep_samples_ = samples_wanted;
  keep_events_ = events_wanted;
  samples.clear();
  event_phases.clear();
  event_marks.clear();
  right.assign(static_cast<std::size_t>(periods), 0);
  left.assign(static_cast<std::size_t>(periods), 0);
}

void Recorder::OnEvent(const SimEvent& event) {
  const double phase = event.after.phi - origin;
  if (phase < 0.0) return;
  if (keep_events_ && event_phases.size() < kMaxEvents) {
    event_phases.push_back(phase - kTau * std::floor(phase / kTau));
    event_marks.push_back({event.kind, event.after.mode});
  }
  if (event.kind != EventKind::kImpactRight && event.kind != EventKind::kImpactLeft) return;
  if (periods_ <= 0) return;
  // The section lies away from every impact, so an impact belongs to one period unambiguously.
  const int k = std::clamp(static_cast<int>(std::floor(phase / kTau)), 0, periods_ - 1);
  const bool is_right = event.kind == EventKind::kImpactRight;
  ++(is_right ? right : left)[static_cast<std::size_t>(k)];
  if (keep_impacts_) impacts.push_back({phase, is_right, event.u_before, k});
}

void Recorder::OnSample(const SimState& state) {
  if (keep_samples_) samples.push_back(state);
}

SimOptions RunOptions(const MotionOptions& options, double alpha, const PhaseState& z) {
  SimOptions o;
  o.alpha = alpha;
  o.x0 = std::clamp(z.x, 0.0, 1.0);  // a free motion may overshoot a wall by rounding
  o.u0 = z.u;
  o.v0 = z.v;
  o.chatter_velocity = options.chatter_velocity;
  o.max_events_per_period = options.max_events_per_period;
  o.reuse_cycles = options.reuse_cycles;
  return o;
}

SimResult Advance(const RobotModel& robot, const MotionOptions& options, MapState& s,
                  double periods, double* displacement, SimObserver* observer, bool sample) {
  SimOptions o = RunOptions(options, robot.alpha, s.z);
  o.periods = periods;
  o.sample_step = sample ? kTau : 0.0;
  const Forcing& forcing = robot.forcing;
  const SimResult r =
      Simulate(forcing.WithPhase(forcing.phi0() + s.z.psi), robot.params, o, observer);
  const SimState& f = r.final_state;
  s.z.x = f.x;
  s.z.u = f.u;
  s.z.v = f.v;
  s.mode = f.mode;
  // Whole periods leave the forcing phase where it was (no rounding of psi + k tau).
  const double turns = std::round(f.phi / kTau);
  const double shift = std::abs(f.phi - turns * kTau) < 1e-9 ? 0.0 : f.phi - turns * kTau;
  s.z.psi += shift;
  s.z.psi -= kTau * std::floor(s.z.psi / kTau);
  if (s.z.psi >= kTau) s.z.psi = 0.0;
  if (displacement != nullptr) *displacement += r.displacement;
  return r;
}

double SectionShift(std::vector<double>& phases) {
  if (phases.empty()) return 0.0;
  std::sort(phases.begin(), phases.end());
  double best_gap = phases.front() + kTau - phases.back();  // the gap across phase 0
  double best_mid = phases.back() + 0.5 * best_gap;
  for (std::size_t i = 1; i < phases.size(); ++i) {
    const double gap = phases[i] - phases[i - 1];
    if (gap > best_gap) {
      best_gap = gap;
      best_mid = phases[i - 1] + 0.5 * gap;
    }
  }
  return best_mid - kTau * std::floor(best_mid / kTau);
}

bool SectionClear(const std::vector<double>& phases, double clearance) {
  return std::all_of(phases.begin(), phases.end(),
                     [&](double phase) { return phase > clearance && phase < kTau - clearance; });
}

bool SameState(const SimState& a, const SimState& b, double tol) {
  return a.mode == b.mode && std::abs(a.x - b.x) <= tol && std::abs(a.u - b.u) <= tol &&
         std::abs(a.v - b.v) <= tol;
}

int DetectPeriod(const std::vector<SimState>& samples, int max_period, double tol) {
  const int n = static_cast<int>(samples.size());
  for (int p = 1; p <= max_period && 2 * p < n; ++p) {
    bool same = true;
    for (int j = 0; j < p && same; ++j) {
      same = SameState(samples[static_cast<std::size_t>(n - 1 - j)],
                       samples[static_cast<std::size_t>(n - 1 - j - p)], tol);
    }
    if (same) return p;
  }
  return 0;
}

}  // namespace capsubot::detail
