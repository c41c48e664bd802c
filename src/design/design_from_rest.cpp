// The fastest motion reached from rest in each direction over the inner mass (and the motor
// frequency), in the user's units (docs/model.md sections 9, 11, 12 and 13).
//
// Each evaluation maps the robot (m2, f) to the model and runs FindAttractors with the search's
// cheap settings; its score is the mean velocity over the starts in m/s times the direction's
// sign, or kInfeasibleSpeed when a start ends in event_limit. The two directions share the
// robots they both visit (a memo of the mean velocities), then each re-checks its best points
// with the full settings.

#include "capsubot/design/design_from_rest.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iterator>
#include <stdexcept>

#include "capsubot/model/detail/enum_names.hpp"
#include "capsubot/optimize/detail/nlopt_box.hpp"
#include "capsubot/optimize/detail/nlopt_status.hpp"
#include "capsubot/optimize/detail/optimize_common.hpp"
#include "capsubot/reach/optimize_reach.hpp"
#include "capsubot/simulate/simulator.hpp"
#include "design/user_units.hpp"

namespace capsubot {
namespace {

using detail::Require;

// Score of a robot with an event_limit start [m/s]: below every mean velocity a capsule robot
// can reach (its shell moves by millimetres per second, and the motor cannot throw it at
// kilometres per second).
constexpr double kInfeasibleSpeed = -1e3;
// Two search points are the same robot when log m2 (and log f) differ by at most this.
constexpr double kSamePoint = 1e-9;

// The robot at y = (log m2[, log f]).
struct Robot {
  double m2 = 0.0, frequency = 0.0;
};

struct Context {
  const DesignInput* input = nullptr;
  FromRestOptions search;
  double sign = 1.0;                   // +1 forward, -1 backward
  std::vector<detail::BoxPoint> seen;  // y and the mean velocity there [m/s] (NaN: infeasible)
  int evaluations = 0;
  int rejected = 0;
  std::int64_t total = 0;
  const DesignFromRestProgress* progress = nullptr;
  std::string stage;

  Robot At(const double* y, unsigned n) const {
    return {std::exp(y[0]), n > 1 ? std::exp(y[1]) : input->frequency_min};
  }
  double Score(double speed) const { return std::isnan(speed) ? kInfeasibleSpeed : sign * speed; }
  // The points seen, scored in the current direction.
  std::vector<detail::BoxPoint> Scored() const {
    std::vector<detail::BoxPoint> out = seen;
    for (detail::BoxPoint& p : out) p.score = Score(p.score);
    return out;
  }
};

// Mean velocity from rest [m/s] of the robot at y; memoised (the directions share robots).
double Objective(unsigned n, const double* y, double* /*gradient*/, void* data) {
  auto* ctx = static_cast<Context*>(data);
  for (const detail::BoxPoint& p : ctx->seen) {
    if (std::equal(p.y.begin(), p.y.end(), y)) return ctx->Score(p.score);
  }
  const Robot r = ctx->At(y, n);
  const DesignModel m = MapToModel(*ctx->input, r.m2, r.frequency);
  const Attractors a = FindAttractors(m.robot, ctx->search);
  ++ctx->evaluations;
  const bool feasible = a.event_limit_starts == 0 && !std::isnan(a.mean_velocity);
  if (!feasible) ++ctx->rejected;
  const double speed = feasible ? m.omega * ctx->input->L * a.mean_velocity : kNaN;
  ctx->seen.push_back({std::vector<double>(y, y + n), speed});
  if (*ctx->progress) (*ctx->progress)(ctx->stage, ctx->evaluations, ctx->total);
  return ctx->Score(speed);
}

// The energy budget per forcing period of the attractor, from its section state: whole
// periods (its period, or the record without one) with the simulator's energy tally. `u` gets
// the approach velocity of the last impact. NaN budget if the run stops early.
Energy AttractorEnergy(const DesignModel& m, const Motion& motion, const MotionOptions& options,
                       double& u) {
  class LastImpact : public SimObserver {
   public:
    double u = kNaN;
    void OnEvent(const SimEvent& e) override {
      if (e.kind == EventKind::kImpactRight || e.kind == EventKind::kImpactLeft) u = e.u_before;
    }
  } observer;
  SimOptions sim;
  sim.alpha = m.robot.alpha;
  sim.x0 = motion.section.x;
  sim.u0 = motion.section.u;
  sim.v0 = motion.section.v;
  sim.periods = motion.status == MotionStatus::kPeriodic ? motion.period : options.record;
  sim.chatter_velocity = options.chatter_velocity;
  sim.max_events_per_period = options.max_events_per_period;
  sim.energy = true;
  const Forcing f = m.robot.forcing.WithPhase(m.robot.forcing.phi0() + motion.section.psi);
  const SimResult r = Simulate(f, m.robot.params, sim, &observer);
  u = observer.u;
  if (r.status != SimStatus::kOk) return {};
  Energy e = r.energy;
  for (double* x : {&e.motor_work, &e.motor_work_positive, &e.friction_loss, &e.impact_loss}) {
    *x /= sim.periods;
  }
  return e;
}

std::string Range(const DesignInput& in) {
  const std::string where =
      in.frequency_min == in.frequency_max
          ? fmt::format("{:g} Hz", in.frequency_min)
          : fmt::format("{:g} to {:g} Hz", in.frequency_min, in.frequency_max);
  return fmt::format("m2 in [{:g}, {:g}] kg at {}", in.M2Min(), in.M2Max(), where);
}

std::string Percent(double fraction) { return fmt::format("{:.0f} %", 100.0 * fraction); }

std::string Describe(const DesignInput& in, const FromRestBest& b) {
  const char* dir = DirectionName(b.direction);
  switch (b.status) {
    case FromRestStatus::kOk: {
      const bool both = b.forward_fraction > 0.0 && b.backward_fraction > 0.0;
      return fmt::format(
          "fastest {} motion from rest over {}: m2 = {:.6g} kg at {:.6g} Hz, {:.6g} mm/s on "
          "average over {} starts{}",
          dir, Range(in), b.m2_kg, b.frequency_hz, b.speed_mm_s, b.attractors.starts,
          both ? fmt::format("; forward and backward attractors coexist: {} of the starts go "
                             "forward, {} backward (the direction depends on the start)",
                             Percent(b.forward_fraction), Percent(b.backward_fraction))
               : "");
    }
    case FromRestStatus::kNoMotion:
      return fmt::format(
          "no {} motion from rest over {}: no robot searched moves {} on average over the starts",
          dir, Range(in), dir);
    case FromRestStatus::kEventLimit:
      return fmt::format(
          "no {} motion from rest over {}: every candidate robot had a start ending in the "
          "simulator's work bound (a Zeno sequence of impacts)",
          dir, Range(in));
    case FromRestStatus::kNotRun:
      break;
  }
  return "not computed";
}

// The search and re-check of one direction.
FromRestBest Search(const DesignInput& in, const DesignFromRestOptions& o, Direction direction,
                    Context& ctx, const std::vector<double>& lower,
                    const std::vector<double>& upper, double deadline_seconds,
                    const std::chrono::steady_clock::time_point& start, DesignFromRestResult& out) {
  const auto left = [&] {
    return deadline_seconds -
           std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  const char* dir = DirectionName(direction);
  ctx.sign = direction == Direction::kForward ? 1.0 : -1.0;
  detail::BoxSearch search;
  search.objective = Objective;
  search.data = &ctx;
  search.seen = [&ctx] { return ctx.Scored(); };
  search.seconds_left = left;
  search.on_stage = [&](const char* name) { ctx.stage = fmt::format("{}: {}", dir, name); };
  search.lower = lower;
  search.upper = upper;
  search.start.resize(lower.size());
  for (std::size_t i = 0; i < lower.size(); ++i) search.start[i] = 0.5 * (lower[i] + upper[i]);
  search.SetGlobal(o.global_algorithm, ReachGlobalAlgorithmNames(), "global_algorithm");
  search.local =
      detail::AlgorithmFromName(o.local_algorithm, ReachLocalAlgorithmNames(), "local_algorithm");
  search.global_evaluations = o.global_evaluations;
  search.local_evaluations = o.local_evaluations;
  search.rel_tol = o.rel_tol;
  search.infeasible = kInfeasibleSpeed;
  search.same = kSamePoint;
  search.candidates = o.candidates;
  const detail::BoxSearchResult found = detail::SearchBox(search);
  out.max_time = out.max_time || found.max_time;

  // Re-check the best distinct robots with the full settings; the best one in the direction
  // wins (a robot that no longer moves that way, or has an event_limit start, loses).
  ctx.stage = fmt::format("{}: check", dir);
  FromRestBest winner;
  winner.direction = direction;
  const auto rank = [&](const FromRestBest& b) {
    return b.status == FromRestStatus::kEventLimit ? kInfeasibleSpeed : ctx.sign * b.speed_mm_s;
  };
  for (const detail::BoxPoint& p : found.candidates) {
    const Robot r = ctx.At(p.y.data(), static_cast<unsigned>(p.y.size()));
    FromRestBest b = EvaluateFromRest(in, r.m2, r.frequency, direction, o.check);
    ++out.evaluations;
    if (*ctx.progress) (*ctx.progress)(ctx.stage, ctx.evaluations + out.evaluations, ctx.total);
    const bool better = winner.status == FromRestStatus::kNotRun || (b.ok() && !winner.ok()) ||
                        (b.ok() == winner.ok() && rank(b) > rank(winner));
    if (better) winner = std::move(b);
  }
  if (winner.status == FromRestStatus::kNotRun) {  // every search point was infeasible
    winner.status = FromRestStatus::kEventLimit;
  }
  winner.message = Describe(in, winner);
  return winner;
}

}  // namespace

const char* DirectionName(Direction direction) {
  return direction == Direction::kForward ? "forward" : "backward";
}

const char* FromRestStatusName(FromRestStatus status) {
  static constexpr const char* kNames[] = {"not_run", "ok", "no_motion", "event_limit"};
  static_assert(std::size(kNames) == static_cast<std::size_t>(FromRestStatus::kEventLimit) + 1);
  return detail::EnumName(kNames, status);
}

DesignFromRestOptions::DesignFromRestOptions() : search(CheapFromRestOptions()) {
  check.attractor.motion.record = kCheckRecord;
}

void DesignFromRestOptions::Validate() const {
  search.Validate();
  check.Validate();
  detail::BoxSearch{}.SetGlobal(global_algorithm, ReachGlobalAlgorithmNames(), "global_algorithm");
  detail::AlgorithmFromName(local_algorithm, ReachLocalAlgorithmNames(), "local_algorithm");
  detail::RequireCount("global_evaluations", global_evaluations, 1, kMaxDesignFromRestEvaluations);
  detail::RequireCount("local_evaluations", local_evaluations, 0, kMaxDesignFromRestEvaluations);
  detail::RequireCount("candidates", candidates, 1, 64);
  Require(std::isfinite(max_seconds) && max_seconds > 0.0,
          fmt::format("max_seconds = {} is invalid: expected a finite time > 0", max_seconds));
  Require(std::isfinite(rel_tol) && rel_tol > 0.0,
          fmt::format("rel_tol = {} is invalid: expected a finite rel_tol > 0", rel_tol));
}

FromRestBest EvaluateFromRest(const DesignInput& in, double m2, double frequency,
                              Direction direction, const FromRestOptions& from_rest) {
  in.Validate();
  return EvaluateModelFromRest(in, MapToModel(in, m2, frequency), m2, frequency, direction,
                               from_rest);
}

FromRestBest EvaluateModelFromRest(const DesignInput& in, const DesignModel& model, double m2,
                                   double frequency, Direction direction,
                                   const FromRestOptions& from_rest) {
  FromRestBest b;
  b.direction = direction;
  b.m2_kg = m2;
  b.frequency_hz = frequency;
  b.model = model;
  const DesignModel& m = b.model;
  b.attractors = FindAttractors(m.robot, from_rest);
  b.mean_velocity = b.attractors.mean_velocity;
  b.forward_fraction = b.backward_fraction = 0.0;
  for (const Attractor& a : b.attractors.attractors) {
    if (a.mean_velocity > 0.0) b.forward_fraction += a.fraction;
    if (a.mean_velocity < 0.0) b.backward_fraction += a.fraction;
  }
  const double sign = direction == Direction::kForward ? 1.0 : -1.0;
  if (b.attractors.event_limit_starts > 0 || std::isnan(b.mean_velocity)) {
    b.status = FromRestStatus::kEventLimit;
  } else if (!(sign * b.mean_velocity > 0.0)) {
    b.status = FromRestStatus::kNoMotion;
  } else {
    b.status = FromRestStatus::kOk;
  }
  b.message = Describe(in, b);
  if (!b.ok()) return b;  // (its message has no speed to tell)
  // The starts' average budget per period: each attractor's, weighted by its fraction.
  Energy sum{0.0, 0.0, 0.0, 0.0};
  double u = kNaN;
  for (std::size_t k = 0; k < b.attractors.attractors.size(); ++k) {
    const Attractor& a = b.attractors.attractors[k];
    double last_impact_u = kNaN;
    const Energy e = AttractorEnergy(m, a.motion, from_rest.attractor.motion, last_impact_u);
    sum.motor_work += a.fraction * e.motor_work;
    sum.motor_work_positive += a.fraction * e.motor_work_positive;
    sum.friction_loss += a.fraction * e.friction_loss;
    sum.impact_loss += a.fraction * e.impact_loss;
    const Motion& mo = a.motion;
    const bool one_impact =
        mo.status == MotionStatus::kPeriodic && mo.impacts_right + mo.impacts_left == 1;
    if (k == 0 && one_impact) u = std::abs(last_impact_u);
  }
  b.energy = sum;
  const double I = b.mean_velocity * kTau;  // displacement per forcing period [L]
  detail::FillUserUnits(in, m.robot.params.T0, m.omega, b.mean_velocity, I, u, b.energy, b);
  b.message = Describe(in, b);  // with its speed
  return b;
}

DesignFromRestResult DesignFromRest(const DesignInput& in, const DesignFromRestOptions& o,
                                    const DesignFromRestProgress& progress) {
  in.Validate();
  o.Validate();
  std::vector<double> lower = {std::log(in.M2Min())}, upper = {std::log(in.M2Max())};
  if (in.frequency_min != in.frequency_max) {
    lower.push_back(std::log(in.frequency_min));
    upper.push_back(std::log(in.frequency_max));
  }
  Context ctx;
  ctx.input = &in;
  ctx.search = o.search;
  ctx.progress = &progress;
  ctx.total = 2 * (o.global_evaluations + o.local_evaluations + o.candidates);
  DesignFromRestResult out;
  const auto start = std::chrono::steady_clock::now();
  out.forward = Search(in, o, Direction::kForward, ctx, lower, upper, o.max_seconds, start, out);
  out.backward = Search(in, o, Direction::kBackward, ctx, lower, upper, o.max_seconds, start, out);
  out.search_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  out.evaluations += ctx.evaluations;
  out.rejected_evaluations = ctx.rejected;
  // The end: the total was an upper bound.
  if (progress) progress(ctx.stage, out.evaluations, out.evaluations);
  return out;
}

}  // namespace capsubot
