// The fastest motion from rest (docs/model.md sections 12 and 13): a bounded NLopt search over
// (A + c, c/(A + c), alpha) whose objective is the mean velocity reached from rest, simulated.
//
// Every evaluation runs FindAttractors with the cheap search settings; a point with an
// event_limit start scores kInfeasibleScore times the force scale, below every motion. The
// global stage (DIRECT-L by default) covers the box, the local one (Sbplx) polishes its best
// point; both stop at the wall-clock limit, which also ends an evaluation under way (its starts
// poll it, so that one evaluation of a huge grid of starts cannot outlast it). The best distinct
// points and the seed are then re-checked with the full settings; the best feasible one wins.

#include "capsubot/reach/optimize_reach.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <nlopt.hpp>
#include <stdexcept>

#include "capsubot/optimize/detail/nlopt_box.hpp"
#include "capsubot/optimize/detail/nlopt_status.hpp"
#include "capsubot/optimize/detail/optimize_common.hpp"
#include "capsubot/optimize/optimize_search.hpp"

namespace capsubot {
namespace {

using detail::Require;
using detail::RequireCount;

// Score of an infeasible point, in units of the force bound (mean velocities are far smaller
// than the bound in units of omega L: the force cannot even move the capsule alone).
constexpr double kInfeasibleScore = -1e3;
// The chatter cut-off of the spread runs is this factor smaller and larger.
constexpr double kChatterFactor = 100.0;
// Restitution of the spread run of an elastic robot.
constexpr double kNearlyElastic = 0.999;
// Two search points are the same candidate when every coordinate differs by at most this.
constexpr double kSamePoint = 1e-6;
// Search points kept for the re-check, at most (the best by score).
constexpr std::size_t kMaxCandidates = 64;
// Two local polishes start from points that differ by more than this in some coordinate (the
// coordinates span 1 or 2).
constexpr double kPolishApart = 0.05;
// Starting drives besides the robust gait, and local polishes, at most.
constexpr long long kMaxSeeds = kMaxHarmonics;
constexpr long long kMaxPolishStarts = 64;
constexpr long long kMaxScreenStarts = 4 * kMaxPolishStarts;
// With T0 free: the frequencies at which the first starting drive is scored before the search.
constexpr int kFrequencyStarts = 5;

using Point = detail::BoxPoint;
using Clock = std::chrono::steady_clock;

// Thrown by an evaluation's starts once the wall-clock limit has passed; the evaluation then
// scores the penalty (it did not finish) and the search stops.
struct TimeUp {};

// The problem NLopt sees: the box, the robot at y, and the points seen so far. The coordinates
// are the drive's, then alpha (when free), then log T0 (when free).
struct Context {
  Params params;
  DriveFamily family;
  double bound = 0.0;        // the force bound at the robot's T0
  double bound_ratio = 0.0;  // the force bound over T0
  double phi0 = 0.0;
  double fixed_alpha = 0.0;  // NaN: alpha is a coordinate
  double bound_alpha = 0.0;  // NaN: the bound does not depend on alpha
  double log_T0_min = 0.0;   // NaN: T0 is the robot's
  double log_T0_max = 0.0;
  double penalty = 0.0;
  FromRestOptions search;
  std::vector<Point> seen;
  int evaluations = 0;
  int rejected_evaluations = 0;
  Clock::time_point deadline = Clock::time_point::max();  // the wall-clock limit
  bool time_up = false;                                   // an evaluation was ended by the limit

  bool FreeT0() const { return !std::isnan(log_T0_min); }
  int T0Index() const { return family.Dimension() + (std::isnan(fixed_alpha) ? 1 : 0); }
  Params ParamsAt(const double* y) const {
    Params p = params;
    if (FreeT0()) p.T0 = std::exp(std::clamp(y[T0Index()], log_T0_min, log_T0_max));
    return p;
  }
  // The force bound of the robot at T0 and alpha (ReachOptions::bound_alpha).
  double BoundAt(double T0, double alpha) const {
    const double at_T0 = FreeT0() ? bound_ratio * T0 : bound;
    if (std::isnan(bound_alpha)) return at_T0;
    return std::min(at_T0 * (1.0 - alpha) / (1.0 - bound_alpha), T0);  // never above friction
  }
  Forcing ForceAt(const double* y) const {
    return DriveAt(family, y, BoundAt(ParamsAt(y).T0, AlphaAt(y)), phi0);
  }
  RobotModel RobotAt(const double* y) const { return {ForceAt(y), ParamsAt(y), AlphaAt(y)}; }
  double AlphaAt(const double* y) const {
    return std::isnan(fixed_alpha) ? y[family.Dimension()] : fixed_alpha;
  }
  // The mean velocity, or with T0 free the speed in units of sqrt(mu g L), v_mean / sqrt(T0)
  // (docs/reach.md, "Frequency"); the penalty when a start ended in event_limit.
  double Score(const Attractors& a, double T0) const {
    if (a.event_limit_starts > 0 || std::isnan(a.mean_velocity)) return penalty;
    return FreeT0() ? a.mean_velocity / std::sqrt(T0) : a.mean_velocity;
  }
};

// The objective at y; infeasible (the penalty) when a start ends in event_limit.
double Objective(unsigned n, const double* y, double* /*gradient*/, void* data) {
  auto* ctx = static_cast<Context*>(data);
  const RobotModel robot = ctx->RobotAt(y);
  Attractors a;
  try {
    a = FindAttractors(robot, ctx->search);
  } catch (const TimeUp&) {
    ctx->time_up = true;
    return ctx->penalty;
  }
  ++ctx->evaluations;
  const double score = ctx->Score(a, robot.params.T0);
  if (!(score > ctx->penalty)) ++ctx->rejected_evaluations;
  ctx->seen.push_back({std::vector<double>(y, y + n), score});
  return score;
}

// Mean velocity of a spread run, NaN if a start hit the work bound (counted in `spread`).
double SpreadRun(const RobotModel& robot, const FromRestOptions& options, ReachSpread& spread) {
  const Attractors a = FindAttractors(robot, options);
  spread.event_limit_starts += a.event_limit_starts;
  return a.event_limit_starts > 0 ? kNaN : a.mean_velocity;
}

// |v - mean_velocity| / |mean_velocity|.
double RelativeChange(double v, double mean_velocity) {
  return std::abs(v - mean_velocity) / std::abs(mean_velocity);
}

ReachSpread Spread(const RobotModel& robot, const FromRestOptions& check, double mean_velocity) {
  ReachSpread s;
  FromRestOptions small = check, large = check;
  small.attractor.motion.chatter_velocity /= kChatterFactor;
  large.attractor.motion.chatter_velocity *= kChatterFactor;
  s.chatter_small = SpreadRun(robot, small, s);
  s.chatter_large = SpreadRun(robot, large, s);
  if (robot.params.e == 1.0) {
    RobotModel nearly_elastic = robot;
    nearly_elastic.params.e = kNearlyElastic;
    s.e_0999 = SpreadRun(nearly_elastic, check, s);
  }
  if (s.event_limit_starts > 0) {
    s.max_relative_deviation = HUGE_VAL;
    return s;
  }
  for (double v : {s.chatter_small, s.chatter_large, s.e_0999}) {
    if (std::isnan(v)) continue;
    const double d = RelativeChange(v, mean_velocity);
    s.max_relative_deviation =
        std::isnan(s.max_relative_deviation) ? d : std::max(s.max_relative_deviation, d);
  }
  return s;
}

// A force to re-check with the full settings, and what it reached.
struct Candidate {
  RobotModel robot;  // its params the robot's, or at the candidate's T0
  Attractors attractors;
  bool is_seed;
};

// The box of the search: the family's coordinates, then alpha when it is free (widened to hold
// the seeds' alphas).
void SearchBoxOf(const Context& ctx, const ReachOptions& options,
                 const std::vector<DriveSeed>& starts, std::vector<double>& lower,
                 std::vector<double>& upper) {
  DriveBox(ctx.family, lower, upper);
  if (std::isnan(options.alpha)) {
    double lo = options.alpha_min, hi = options.alpha_max;
    for (const DriveSeed& d : options.widen_alpha_box ? starts : std::vector<DriveSeed>{}) {
      lo = std::min(lo, d.alpha);
      hi = std::max(hi, d.alpha);
    }
    lower.push_back(lo);
    upper.push_back(hi);
  }
  if (ctx.FreeT0()) {
    lower.push_back(ctx.log_T0_min);
    upper.push_back(ctx.log_T0_max);
  }
}

// The T0 of a starting drive: its own, else the robot's.
double SeedT0(const Context& ctx, const DriveSeed& d) {
  return std::isnan(d.T0) ? ctx.params.T0 : d.T0;
}

// The box point of a starting drive (its force's coordinates, then its alpha when free); empty
// when its force is not of the family.
std::vector<double> PointOf(const Context& ctx, const DriveSeed& d) {
  const double T0 = SeedT0(ctx, d);
  std::vector<double> y = DriveCoordinates(ctx.family, d.forcing, ctx.BoundAt(T0, d.alpha));
  if (y.empty()) return y;
  if (std::isnan(ctx.fixed_alpha)) y.push_back(d.alpha);
  if (ctx.FreeT0()) y.push_back(std::log(T0));
  return y;
}

// The search stages (global, then local polishes) within the time limit.
detail::BoxSearchResult Search(Context& ctx, const ReachOptions& options,
                               const std::vector<double>& lower, const std::vector<double>& upper,
                               const std::vector<double>& y0) {
  nlopt::srand(options.seed);
  detail::BoxSearch search;
  search.objective = Objective;
  search.data = &ctx;
  search.seen = [&ctx] { return ctx.seen; };
  search.seconds_left = [&ctx] {
    if (ctx.time_up) return 0.0;
    if (ctx.deadline == Clock::time_point::max()) return HUGE_VAL;
    return std::chrono::duration<double>(ctx.deadline - Clock::now()).count();
  };
  search.lower = lower;
  search.upper = upper;
  search.start = y0;
  search.SetGlobal(options.global_algorithm, ReachGlobalAlgorithmNames(), "global_algorithm");
  search.local = detail::AlgorithmFromName(options.local_algorithm, ReachLocalAlgorithmNames(),
                                           "local_algorithm");
  search.global_evaluations = options.global_evaluations;
  search.local_evaluations = options.local_evaluations;
  search.polish_starts = options.polish_starts;
  search.refine_evaluations = options.refine_evaluations;
  search.screen_starts = options.screen_starts;
  search.screen_evaluations = options.screen_evaluations;
  search.candidates_apart = options.candidates_apart;
  search.rel_tol = options.rel_tol;
  search.infeasible = ctx.penalty;
  search.same = kSamePoint;
  search.polish_apart = kPolishApart;
  search.candidates = std::min(options.candidates, static_cast<int>(kMaxCandidates));
  return detail::SearchBox(search);
}

// Whether a candidate's mean velocity holds in its spread runs: the chatter cut-offs within
// max_spread, the nearly elastic robot within max_elastic_change, no event_limit start.
bool Holds(const ReachSpread& s, double mean_velocity, const ReachOptions& options) {
  if (s.event_limit_starts > 0) return false;
  const auto within = [&](double v, double tolerance) {
    return std::isnan(v) || RelativeChange(v, mean_velocity) <= tolerance;
  };
  return within(s.chatter_small, options.max_spread) &&
         within(s.chatter_large, options.max_spread) &&
         within(s.e_0999, options.max_elastic_change);
}

// The first of `candidates` (best first) whose mean velocity holds under the other numerical
// settings, or the best one flagged; null when none is feasible.
const Candidate* Winner(std::vector<Candidate>& candidates, const Context& ctx,
                        const ReachOptions& options, ReachResult& out) {
  // Best first (ties: the seed, the simpler gait); infeasible candidates last.
  std::stable_sort(candidates.begin(), candidates.end(),
                   [&](const Candidate& a, const Candidate& b) {
                     const double sa = ctx.Score(a.attractors, a.robot.params.T0),
                                  sb = ctx.Score(b.attractors, b.robot.params.T0);
                     return sa > sb || (sa == sb && a.is_seed && !b.is_seed);
                   });
  const Candidate* best = nullptr;
  for (const Candidate& c : candidates) {
    if (!(ctx.Score(c.attractors, c.robot.params.T0) > ctx.penalty)) break;
    const ReachSpread spread = Spread(c.robot, options.check, c.attractors.mean_velocity);
    if (best == nullptr) {
      best = &c;
      out.spread = spread;
    }
    if (Holds(spread, c.attractors.mean_velocity, options)) {
      best = &c;
      out.spread = spread;
      out.robust_to_settings = true;
      break;
    }
  }
  return best;
}

// How the winner compares with the robust one-impact gait's motion from rest.
std::string SeedComparison(const ReachResult& out, double seed_v) {
  if (std::isnan(seed_v)) return "; no robust one-impact seed";
  if (out.seed_won)
    return fmt::format("; the robust one-impact gait itself ({:.6g} from rest)", seed_v);
  if (seed_v > 0.0) {
    return fmt::format("; {:.3g} times the robust one-impact gait's {:.6g} from rest",
                       out.mean_velocity / seed_v, seed_v);
  }
  return fmt::format("; the robust one-impact gait reaches {:.6g} from rest", seed_v);
}

// "A + c <= 0.5" for the sine, "max |F| <= 0.5" otherwise.
std::string BoundText(const DriveFamily& family, double bound) {
  return fmt::format("{} <= {:g}", family.sine() ? "A + c" : "max |F|", bound);
}

// The winner's force in words.
std::string ForceText(const ReachResult& out) {
  if (out.drive.sine()) {
    return fmt::format("A = {:.6g}, c = {:.6g}", out.forcing.amplitude(), out.forcing.mean());
  }
  return fmt::format("{}, c = {:.6g}, max |F| = {:.6g}", out.drive.Describe(), out.forcing.mean(),
                     out.max_abs_force);
}

// The search's problem: the robot, the family, the bound (tied to T0 when T0 is free), the
// seed's motor phase.
Context ContextOf(const Params& params, const ReachOptions& options, double bound, double phi0) {
  Context ctx;
  ctx.params = params;
  ctx.family = options.drive;
  ctx.bound = bound;
  ctx.bound_ratio = bound / params.T0;
  ctx.phi0 = phi0;
  ctx.fixed_alpha = options.alpha;
  ctx.bound_alpha = options.bound_alpha;
  ctx.log_T0_min = std::log(options.T0_min);
  ctx.log_T0_max = std::log(options.T0_max);
  // Below every score: a mean velocity is far below the force bound in units of omega L (the
  // force cannot even move the capsule alone), and v / sqrt(T0) below bound / sqrt(T0_min).
  const double top_bound = ctx.BoundAt(ctx.FreeT0() ? options.T0_max : params.T0,
                                       std::isnan(options.bound_alpha) ? 0.0 : options.alpha_min);
  const double low_root = ctx.FreeT0() ? std::sqrt(std::min(options.T0_min, 1.0)) : 1.0;
  ctx.penalty = kInfeasibleScore * top_bound / low_root;
  ctx.search = options.search;
  return ctx;
}

// Scores every starting drive first (so that the polishes and the candidates know them) and
// returns the first one's point, where the global stage starts (the middle of the box without
// one). Throws std::invalid_argument for a seed outside the family.
std::vector<double> ScoreStarts(Context& ctx, const std::vector<DriveSeed>& starts, bool have_seed,
                                const std::vector<double>& lower,
                                const std::vector<double>& upper) {
  std::vector<double> y0(lower.size());
  for (std::size_t i = 0; i < y0.size(); ++i) y0[i] = 0.5 * (lower[i] + upper[i]);
  for (std::size_t i = 0; i < starts.size(); ++i) {
    const std::vector<double> y = PointOf(ctx, starts[i]);
    Require(
        !y.empty(),
        fmt::format("seeds[{}] is invalid: expected a force of the family ({}) with {} and the "
                    "seed's motor phase",
                    i - (have_seed ? 1 : 0), ctx.family.Describe(),
                    BoundText(ctx.family, ctx.BoundAt(SeedT0(ctx, starts[i]), starts[i].alpha))));
    if (i == 0) y0 = y;
    Objective(static_cast<unsigned>(y.size()), y.data(), nullptr, &ctx);
  }
  return y0;
}

// Whether box points `a` and `b` are one drive (every coordinate within kSamePoint).
bool SamePoint(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!(std::abs(a[i] - b[i]) <= kSamePoint)) return false;
  }
  return true;
}

// The best search points and the starting drives, simulated again with the full settings (the
// robust gait's check from rest is reused when its alpha is the robot's). A search point that
// is a starting drive is that drive, re-checked once, as itself.
std::vector<Candidate> Recheck(Context& ctx, const ReachOptions& options,
                               const std::vector<Point>& points,
                               const std::vector<DriveSeed>& starts, bool seed_starts,
                               const ReachSeed& seed) {
  std::vector<Candidate> candidates;
  for (const Point& p : points) {
    if (std::any_of(starts.begin(), starts.end(),
                    [&](const DriveSeed& d) { return SamePoint(p.y, PointOf(ctx, d)); })) {
      continue;
    }
    const RobotModel robot = ctx.RobotAt(p.y.data());
    candidates.push_back({robot, FindAttractors(robot, options.check), false});
    ++ctx.evaluations;
  }
  for (std::size_t i = 0; i < starts.size(); ++i) {
    RobotModel robot{WithHarmonicsOf(ctx.family, starts[i].forcing), ctx.params,
                     std::isnan(options.alpha) ? starts[i].alpha : options.alpha};
    robot.params.T0 = SeedT0(ctx, starts[i]);
    if (i == 0 && seed_starts && robot.alpha == seed.gait.solution.orbit.alpha) {
      candidates.push_back({robot, seed.from_rest.attractors, false});
      continue;
    }
    candidates.push_back({robot, FindAttractors(robot, options.check), false});
    ++ctx.evaluations;
  }
  return candidates;
}

// The winner into the result, with its message (`searched`: whether the search evaluated any
// drive besides the starting ones).
void Report(const Candidate& best, const Context& ctx, const ReachOptions& options,
            const std::string& message, bool searched, ReachResult& out) {
  out.forcing = best.robot.forcing;
  out.max_abs_force = out.forcing.MaxAbs();
  out.force_bound = ctx.BoundAt(best.robot.params.T0, best.robot.alpha);
  out.alpha = best.robot.alpha;
  out.T0 = best.robot.params.T0;
  out.attractors = best.attractors;
  out.mean_velocity = best.attractors.mean_velocity;
  if (ctx.FreeT0()) out.physical_speed = out.mean_velocity / std::sqrt(out.T0);
  out.seed_won = best.is_seed;
  out.summary = AttractorsSummary(out.attractors, options.check.attractor.motion.max_period);
  const double seed_v =
      out.seed.from_rest.checked ? out.seed.from_rest.attractors.mean_velocity : kNaN;
  out.message = fmt::format(
      "fastest motion from rest with {}: mean velocity {:.6g} ({}, alpha = {:.6g}){}{}{}{}{}",
      BoundText(ctx.family, out.force_bound), out.mean_velocity, ForceText(out), out.alpha,
      ctx.FreeT0()
          ? fmt::format(" at T0 = {:.6g}: speed {:.6g} sqrt(mu g L)", out.T0, out.physical_speed)
          : std::string(),
      SeedComparison(out, seed_v),
      out.status != OptimizeStatus::kMaxTime ? ""
      : searched                             ? "; the search stopped at its time limit"
                 : "; the time limit came before the search evaluated any drive: only the "
                   "starting drives were compared",
      out.robust_to_settings ? ""
                             : "; WARNING: no candidate keeps its mean velocity in its spread "
                               "runs (other chatter cut-offs; e = 0.999 at e = 1)",
      message.empty() ? "" : "; " + message);
}

}  // namespace

std::vector<std::string> ReachGlobalAlgorithmNames() {
  return {"GN_DIRECT_L", "GN_DIRECT", "GN_DIRECT_L_RAND",
          "GN_CRS2_LM",  "GN_ISRES",  detail::kHaltonStage};
}

std::vector<std::string> ReachLocalAlgorithmNames() {
  return {"LN_SBPLX", "LN_BOBYQA", "LN_NELDERMEAD", "LN_COBYLA"};
}

FromRestOptions CheapFromRestOptions() {
  FromRestOptions o;
  o.n_x = 4;
  o.n_psi = 4;
  o.attractor.motion.transient = 100;
  o.attractor.motion.record = 32;
  return o;
}

ForcingDesignOptions RobustSeedDesign() {
  ForcingDesignOptions d;
  d.gait.rho_max = kRobustRhoMax;
  d.gait.margins = RobustMargins();
  return d;
}

ReachOptions::ReachOptions() = default;

void ReachOptions::Validate() const {
  Require(std::isnan(force_bound) || (std::isfinite(force_bound) && force_bound > 0.0),
          fmt::format("force_bound = {} is invalid: expected a finite bound > 0 (not given: T0)",
                      force_bound));
  Require(std::isnan(alpha) || (alpha > 0.0 && alpha < 1.0),
          fmt::format("alpha = {} is invalid: expected 0 < alpha < 1 (not given: free)", alpha));
  Require(std::isnan(bound_alpha) || (bound_alpha > 0.0 && bound_alpha < 1.0),
          fmt::format("bound_alpha = {} is invalid: expected 0 < bound_alpha < 1 (or NaN: a bound "
                      "in units of (m1+m2) omega^2 L)",
                      bound_alpha));
  Require(alpha_min > 0.0 && alpha_min < alpha_max && alpha_max < 1.0,
          fmt::format("alpha_min = {}, alpha_max = {} are invalid: expected 0 < alpha_min < "
                      "alpha_max < 1",
                      alpha_min, alpha_max));
  detail::BoxSearch{}.SetGlobal(global_algorithm, ReachGlobalAlgorithmNames(), "global_algorithm");
  detail::AlgorithmFromName(local_algorithm, ReachLocalAlgorithmNames(), "local_algorithm");
  Require(
      global_evaluations >= 1,
      fmt::format("global_evaluations = {} is invalid: expected at least 1", global_evaluations));
  Require(local_evaluations >= 0,
          fmt::format("local_evaluations = {} is invalid: expected at least 0", local_evaluations));
  Require(max_seconds > 0.0,
          fmt::format("max_seconds = {} is invalid: expected a time > 0 (infinity: none)",
                      max_seconds));
  Require(std::isfinite(rel_tol) && rel_tol > 0.0,
          fmt::format("rel_tol = {} is invalid: expected a finite rel_tol > 0", rel_tol));
  Require(std::isfinite(max_spread) && max_spread >= 0.0,
          fmt::format("max_spread = {} is invalid: expected a finite max_spread >= 0", max_spread));
  Require(std::isfinite(max_elastic_change) && max_elastic_change >= 0.0,
          fmt::format("max_elastic_change = {} is invalid: expected a finite max_elastic_change "
                      ">= 0",
                      max_elastic_change));
  drive.Validate();
  RequireCount("seeds", static_cast<long long>(seeds.size()), 0, kMaxSeeds);
  for (std::size_t i = 0; i < seeds.size(); ++i) {
    Require(
        seeds[i].alpha > 0.0 && seeds[i].alpha < 1.0,
        fmt::format("seeds[{}].alpha = {} is invalid: expected 0 < alpha < 1", i, seeds[i].alpha));
  }
  RequireCount("polish_starts", polish_starts, 1, kMaxPolishStarts);
  RequireCount("refine_evaluations", refine_evaluations, 0, kMaxStageEvaluations);
  RequireCount("screen_starts", screen_starts, 0, kMaxScreenStarts);
  RequireCount("screen_evaluations", screen_evaluations, 0, kMaxStageEvaluations);
  Require(candidates_apart >= 0.0 && candidates_apart < 1.0,
          fmt::format("candidates_apart = {} is invalid: expected 0 <= candidates_apart < 1",
                      candidates_apart));
  Require((std::isnan(T0_min) && std::isnan(T0_max)) ||
              (T0_min > 0.0 && T0_min < T0_max && std::isfinite(T0_max)),
          fmt::format("T0_min = {}, T0_max = {} are invalid: expected 0 < T0_min < T0_max, finite "
                      "(or both NaN: T0 fixed)",
                      T0_min, T0_max));
  Require(candidates >= 1,
          fmt::format("candidates = {} is invalid: expected at least 1", candidates));
  search.Validate();
  check.Validate();
  seed_design.Validate();
}

ReachResult OptimizeReach(const Params& params, const ReachOptions& options) {
  options.Validate();
  params.Validate();
  ForcingDesignOptions design = options.seed_design;
  design.gait.force_bound = options.force_bound;
  return OptimizeReach(params, OptimizeForcing(params, design), options);
}

namespace {

// With T0 free, the sine's reach at kFrequencyStarts frequencies spread evenly in log T0 over
// the range, its ends included, each with its share of the budget and its own robust seed: the
// joint search over the shape, alpha and T0 then starts from the best fixed-frequency drives
// (the speed can peak at an end of the range, where a search of the joint box rarely looks).
std::vector<DriveSeed> FrequencySeeds(const Params& params, const ReachOptions& options,
                                      double bound) {
  ReachOptions fixed = options;
  fixed.T0_min = fixed.T0_max = kNaN;
  fixed.seeds.clear();
  fixed.global_evaluations = std::max(1, options.global_evaluations / kFrequencyStarts);
  fixed.local_evaluations = options.local_evaluations / kFrequencyStarts;
  fixed.candidates = 1;
  std::vector<DriveSeed> seeds;
  for (int i = 0; i < kFrequencyStarts; ++i) {
    Params at = params;
    at.T0 =
        std::exp(std::log(options.T0_min) + (std::log(options.T0_max) - std::log(options.T0_min)) *
                                                i / (kFrequencyStarts - 1));
    fixed.force_bound = bound / params.T0 * at.T0;
    const ReachResult r = OptimizeReach(at, fixed);
    if (!std::isnan(r.mean_velocity)) seeds.push_back({r.forcing, r.alpha, at.T0});
  }
  return seeds;
}

// The starting drives: the robust gait first when it is a force of the family (not for pulse
// drives: then it gives the motor phase only; `seed_starts` says whether it is), the options'
// seeds, and with T0 free the sine's fixed-frequency winners. A hard alpha range leaves out
// the starting drives outside it.
std::vector<DriveSeed> StartingDrives(const Context& ctx, const Params& params,
                                      const ReachOptions& options, const Orbit* seed, double bound,
                                      bool& seed_starts) {
  const auto inside = [&options](double alpha) {
    return options.widen_alpha_box || !std::isnan(options.alpha) ||
           (options.alpha_min <= alpha && alpha <= options.alpha_max);
  };
  std::vector<DriveSeed> starts;
  for (const DriveSeed& d : options.seeds) {
    if (inside(d.alpha)) starts.push_back(d);
  }
  seed_starts =
      seed != nullptr && inside(seed->alpha) &&
      !DriveCoordinates(options.drive, seed->forcing, ctx.BoundAt(params.T0, seed->alpha)).empty();
  if (seed_starts) starts.insert(starts.begin(), DriveSeed{seed->forcing, seed->alpha, params.T0});
  if (ctx.FreeT0() && ctx.family.sine()) {
    for (const DriveSeed& d : FrequencySeeds(params, options, bound)) {
      if (inside(d.alpha)) starts.push_back(d);
    }
  }
  return starts;
}

}  // namespace

ReachResult OptimizeReach(const Params& params, const OptimizeResult& seed,
                          const ReachOptions& options) {
  options.Validate();
  params.Validate();
  GaitRequirements gait;  // the force bound's rule is that of P2 and P3
  gait.force_bound = options.force_bound;
  const double bound = gait.BoundFor(params);
  ReachResult out;
  out.drive = options.drive;
  out.force_bound = bound;
  out.seed.gait = seed;
  const Orbit& so = seed.solution.orbit;
  const bool have_seed = seed.found() && so.forcing.harmonic();
  if (have_seed) out.seed.from_rest = CheckGaitFromRest(so, params, options.check);
  Require(
      std::isnan(options.T0_min) || (options.T0_min <= params.T0 && params.T0 <= options.T0_max),
      fmt::format("T0 = {} is invalid: expected T0_min = {} <= T0 <= T0_max = {} (the robot's "
                  "own frequency is in the range searched)",
                  params.T0, options.T0_min, options.T0_max));

  Context ctx = ContextOf(params, options, bound, have_seed ? so.forcing.phi0() : 0.0);
  // The wall-clock limit bounds the starting drives' scores and the search, evaluations under
  // way included (their starts poll it after every block); the re-checks come on top.
  if (std::isfinite(options.max_seconds)) {
    ctx.deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                      std::chrono::duration<double>(options.max_seconds));
    ctx.search.attractor.interrupt = [user = options.search.attractor.interrupt,
                                      deadline = ctx.deadline] {
      Poll(user);
      if (Clock::now() > deadline) throw TimeUp{};
    };
  }
  bool seed_starts = false;
  const std::vector<DriveSeed> starts =
      StartingDrives(ctx, params, options, have_seed ? &so : nullptr, bound, seed_starts);
  std::vector<double> lower, upper;
  SearchBoxOf(ctx, options, starts, lower, upper);
  const std::vector<double> y0 = ScoreStarts(ctx, starts, seed_starts, lower, upper);

  const auto search_start = std::chrono::steady_clock::now();
  const int scored = ctx.evaluations;
  const detail::BoxSearchResult found = Search(ctx, options, lower, upper, y0);
  const bool searched = ctx.evaluations > scored;
  out.search_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - search_start).count();
  out.algorithm = options.global_algorithm + "+" + options.local_algorithm;

  std::vector<Candidate> candidates =
      Recheck(ctx, options, found.candidates, starts, seed_starts, out.seed);
  if (seed_starts) candidates[candidates.size() - starts.size()].is_seed = true;
  out.evaluations = ctx.evaluations;
  out.rejected_evaluations = ctx.rejected_evaluations;
  const Candidate* best = Winner(candidates, ctx, options, out);
  if (best == nullptr) {
    out.status = OptimizeStatus::kNoValidOrbit;
    out.message = fmt::format(
        "no motion from rest without event_limit starts found with {} ({} "
        "evaluations{}{})",
        BoundText(ctx.family, bound), out.evaluations, found.message.empty() ? "" : "; ",
        found.message);
    return out;
  }
  out.status = found.status == OptimizeStatus::kMaxTime || ctx.time_up ? OptimizeStatus::kMaxTime
                                                                       : OptimizeStatus::kOk;
  Report(*best, ctx, options, found.message, searched, out);
  return out;
}

}  // namespace capsubot
