// The fastest motion from rest (docs/model.md sections 12 and 13): a bounded NLopt search over
// (A + c, c/(A + c), alpha) whose objective is the mean velocity reached from rest, simulated.
//
// Every evaluation runs FindAttractors with the cheap search settings; a point with an
// event_limit start scores kInfeasibleScore times the force scale, below every motion. The
// global stage (DIRECT-L by default) covers the box, the local one (Sbplx) polishes its best
// point; both stop at the wall-clock limit. The best distinct points and the seed are then
// re-checked with the full settings; the best feasible one wins.

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <nlopt.hpp>
#include <stdexcept>

#include "capsubot/optimize/detail/nlopt_box.hpp"
#include "capsubot/optimize/detail/nlopt_status.hpp"
#include "capsubot/optimize/detail/optimize_common.hpp"
#include "capsubot/reach/optimize_reach.hpp"

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

using Point = detail::BoxPoint;

// The problem NLopt sees: the box, the robot at y, and the points seen so far.
struct Context {
  Params params;
  DriveFamily family;
  double bound = 0.0;
  double phi0 = 0.0;
  double fixed_alpha = 0.0;  // NaN: alpha is the last coordinate
  double penalty = 0.0;
  FromRestOptions search;
  std::vector<Point> seen;
  int evaluations = 0;
  int rejected_evaluations = 0;

  Forcing ForceAt(const double* y) const { return DriveAt(family, y, bound, phi0); }
  double AlphaAt(const double* y) const {
    return std::isnan(fixed_alpha) ? y[family.Dimension()] : fixed_alpha;
  }
  double Score(const Attractors& a) const {
    return a.event_limit_starts > 0 || std::isnan(a.mean_velocity) ? penalty : a.mean_velocity;
  }
};

// The mean velocity from rest at y; infeasible (the penalty) when a start ends in event_limit.
double Objective(unsigned n, const double* y, double* /*gradient*/, void* data) {
  auto* ctx = static_cast<Context*>(data);
  const Forcing f = ctx->ForceAt(y);
  const double alpha = ctx->AlphaAt(y);
  const Attractors a = FindAttractors(f, ctx->params, alpha, ctx->search);
  ++ctx->evaluations;
  const double score = ctx->Score(a);
  if (!(score > ctx->penalty)) ++ctx->rejected_evaluations;
  ctx->seen.push_back({std::vector<double>(y, y + n), score});
  return score;
}

// Mean velocity of a spread run, NaN if a start hit the work bound (counted in `spread`).
double SpreadRun(const Forcing& forcing, const Params& params, double alpha,
                 const FromRestOptions& options, ReachSpread& spread) {
  const Attractors a = FindAttractors(forcing, params, alpha, options);
  spread.event_limit_starts += a.event_limit_starts;
  return a.event_limit_starts > 0 ? ReachSpread::kNaN : a.mean_velocity;
}

ReachSpread Spread(const Forcing& forcing, const Params& params, double alpha,
                   const FromRestOptions& check, double mean_velocity) {
  ReachSpread s;
  FromRestOptions small = check, large = check;
  small.attractor.motion.chatter_velocity /= kChatterFactor;
  large.attractor.motion.chatter_velocity *= kChatterFactor;
  s.chatter_small = SpreadRun(forcing, params, alpha, small, s);
  s.chatter_large = SpreadRun(forcing, params, alpha, large, s);
  if (params.e == 1.0) {
    Params p = params;
    p.e = kNearlyElastic;
    s.e_0999 = SpreadRun(forcing, p, alpha, check, s);
  }
  if (s.event_limit_starts > 0) {
    s.max_relative_deviation = HUGE_VAL;
    return s;
  }
  for (double v : {s.chatter_small, s.chatter_large, s.e_0999}) {
    if (std::isnan(v)) continue;
    const double d = std::abs(v - mean_velocity) / std::abs(mean_velocity);
    s.max_relative_deviation =
        std::isnan(s.max_relative_deviation) ? d : std::max(s.max_relative_deviation, d);
  }
  return s;
}

// A force to re-check with the full settings, and what it reached.
struct Candidate {
  Forcing forcing;
  double alpha;
  Attractors attractors;
  bool is_seed;
};

// The box of the search: the family's coordinates, then alpha when it is free (widened to hold
// the seeds' alphas).
void SearchBoxOf(const Context& ctx, const ReachOptions& options,
                 const std::vector<DriveSeed>& starts, std::vector<double>& lower,
                 std::vector<double>& upper) {
  DriveBox(ctx.family, lower, upper);
  if (!std::isnan(options.alpha)) return;
  double lo = options.alpha_min, hi = options.alpha_max;
  for (const DriveSeed& d : starts) {
    lo = std::min(lo, d.alpha);
    hi = std::max(hi, d.alpha);
  }
  lower.push_back(lo);
  upper.push_back(hi);
}

// The box point of a starting drive (its force's coordinates, then its alpha when free); empty
// when its force is not of the family.
std::vector<double> PointOf(const Context& ctx, const DriveSeed& d) {
  std::vector<double> y = DriveCoordinates(ctx.family, d.forcing, ctx.bound);
  if (!y.empty() && std::isnan(ctx.fixed_alpha)) y.push_back(d.alpha);
  return y;
}

// The search stages (global, then local polishes) within the time limit.
detail::BoxSearchResult Search(Context& ctx, const ReachOptions& options,
                               const std::vector<double>& lower,
                               const std::vector<double>& upper, const std::vector<double>& y0) {
  const auto start = std::chrono::steady_clock::now();
  const auto elapsed = [start] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  nlopt::srand(options.seed);
  detail::BoxSearch search;
  search.objective = Objective;
  search.data = &ctx;
  search.seen = [&ctx] { return ctx.seen; };
  search.seconds_left = [&] { return options.max_seconds - elapsed(); };
  search.lower = lower;
  search.upper = upper;
  search.start = y0;
  search.SetGlobal(options.global_algorithm, ReachGlobalAlgorithmNames(), "global_algorithm");
  search.local = detail::AlgorithmFromName(options.local_algorithm, ReachLocalAlgorithmNames(),
                                           "local_algorithm");
  search.global_evaluations = options.global_evaluations;
  search.local_evaluations = options.local_evaluations;
  search.polish_starts = options.polish_starts;
  search.rel_tol = options.rel_tol;
  search.infeasible = ctx.penalty;
  search.same = kSamePoint;
  search.polish_apart = kPolishApart;
  search.candidates = std::min(options.candidates, static_cast<int>(kMaxCandidates));
  return detail::SearchBox(search);
}

// The first of `candidates` (best first) whose mean velocity holds under the other numerical
// settings, or the best one flagged; null when none is feasible.
const Candidate* Winner(std::vector<Candidate>& candidates, const Context& ctx,
                        const ReachOptions& options, ReachResult& out) {
  // Best first (ties: the seed, the simpler gait); infeasible candidates last.
  std::stable_sort(candidates.begin(), candidates.end(),
                   [&](const Candidate& a, const Candidate& b) {
                     const double sa = ctx.Score(a.attractors), sb = ctx.Score(b.attractors);
                     return sa > sb || (sa == sb && a.is_seed && !b.is_seed);
                   });
  const Candidate* best = nullptr;
  for (const Candidate& c : candidates) {
    if (!(ctx.Score(c.attractors) > ctx.penalty)) break;
    const ReachSpread spread =
        Spread(c.forcing, ctx.params, c.alpha, options.check, c.attractors.mean_velocity);
    if (best == nullptr) {
      best = &c;
      out.spread = spread;
    }
    if (spread.max_relative_deviation <= options.max_spread) {
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
  if (out.seed_won) return fmt::format("; the robust one-impact gait itself ({:.6g} from rest)", seed_v);
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

}  // namespace

std::vector<std::string> ReachGlobalAlgorithmNames() {
  return {"GN_DIRECT_L", "GN_DIRECT", "GN_DIRECT_L_RAND", "GN_CRS2_LM", "GN_ISRES",
          detail::kHaltonStage};
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
  return d;
}

ReachOptions::ReachOptions() = default;

void ReachOptions::Validate() const {
  Require(std::isnan(force_bound) || (std::isfinite(force_bound) && force_bound > 0.0),
          fmt::format("force_bound = {} is invalid: expected a finite bound > 0 (or NaN for T0)",
                      force_bound));
  Require(std::isnan(alpha) || (alpha > 0.0 && alpha < 1.0),
          fmt::format("alpha = {} is invalid: expected 0 < alpha < 1 (or NaN: free)", alpha));
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
  drive.Validate();
  RequireCount("seeds", static_cast<long long>(seeds.size()), 0, kMaxSeeds);
  for (std::size_t i = 0; i < seeds.size(); ++i) {
    Require(seeds[i].alpha > 0.0 && seeds[i].alpha < 1.0,
            fmt::format("seeds[{}].alpha = {} is invalid: expected 0 < alpha < 1", i,
                        seeds[i].alpha));
  }
  RequireCount("polish_starts", polish_starts, 1, kMaxPolishStarts);
  Require(candidates >= 1,
          fmt::format("candidates = {} is invalid: expected at least 1", candidates));
  search.Validate();
  check.Validate();
  seed_design.Validate();
  Require(seed_margin_stroke >= 0.0 && seed_margin_stroke < 0.5,
          fmt::format("seed_margin_stroke = {} is invalid: expected 0 <= seed_margin_stroke < 0.5",
                      seed_margin_stroke));
  Require(seed_stick_margin >= 0.0 && seed_stick_margin < 1.0,
          fmt::format("seed_stick_margin = {} is invalid: expected 0 <= seed_stick_margin < 1",
                      seed_stick_margin));
}

ReachResult OptimizeReach(const Params& params, const ReachOptions& options) {
  options.Validate();
  params.Validate();
  ForcingDesignOptions design = options.seed_design;
  design.gait.force_bound = options.force_bound;
  Params seed_params = params;
  seed_params.margin_stroke = options.seed_margin_stroke;
  seed_params.stick_margin = options.seed_stick_margin;
  return OptimizeReach(params, OptimizeForcing(seed_params, design), options);
}

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

  Context ctx;
  ctx.params = params;
  ctx.family = options.drive;
  ctx.bound = bound;
  ctx.phi0 = have_seed ? so.forcing.phi0() : 0.0;
  ctx.fixed_alpha = options.alpha;
  ctx.penalty = kInfeasibleScore * bound;
  ctx.search = options.search;
  std::vector<DriveSeed> starts = options.seeds;
  if (have_seed) starts.insert(starts.begin(), DriveSeed{so.forcing, so.alpha});
  std::vector<double> lower, upper;
  SearchBoxOf(ctx, options, starts, lower, upper);
  // The global stage starts at the first starting drive (the middle of the box without one);
  // every starting drive is scored first, so that the polish and the candidates know it.
  std::vector<double> y0(lower.size());
  for (std::size_t i = 0; i < y0.size(); ++i) y0[i] = 0.5 * (lower[i] + upper[i]);
  bool first = true;
  for (std::size_t i = 0; i < starts.size(); ++i) {
    const std::vector<double> y = PointOf(ctx, starts[i]);
    Require(!y.empty(), fmt::format("seeds[{}] is invalid: expected a force of the family ({}) "
                                    "with {} and the seed's motor phase",
                                    i - (have_seed ? 1 : 0), ctx.family.Describe(),
                                    BoundText(ctx.family, bound)));
    if (first) y0 = y;
    first = false;
    Objective(static_cast<unsigned>(y.size()), y.data(), nullptr, &ctx);
  }

  const auto search_start = std::chrono::steady_clock::now();
  const detail::BoxSearchResult found = Search(ctx, options, lower, upper, y0);
  out.search_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - search_start).count();
  out.algorithm = options.global_algorithm + "+" + options.local_algorithm;

  // Re-check with the full settings: the best search points, the seed and the other starts.
  std::vector<Candidate> candidates;
  for (const Point& p : found.candidates) {
    const Forcing f = ctx.ForceAt(p.y.data());
    const double alpha = ctx.AlphaAt(p.y.data());
    candidates.push_back({f, alpha, FindAttractors(f, params, alpha, options.check), false});
    ++ctx.evaluations;
  }
  for (std::size_t i = 0; i < starts.size(); ++i) {
    const bool is_seed = have_seed && i == 0;
    const double alpha = std::isnan(options.alpha) ? starts[i].alpha : options.alpha;
    if (is_seed && alpha == so.alpha) {
      candidates.push_back({WithHarmonicsOf(ctx.family, so.forcing), so.alpha,
                            out.seed.from_rest.attractors, true});
      continue;
    }
    const Forcing f = WithHarmonicsOf(ctx.family, starts[i].forcing);
    candidates.push_back({f, alpha, FindAttractors(f, params, alpha, options.check), is_seed});
    ++ctx.evaluations;
  }
  out.evaluations = ctx.evaluations;
  out.rejected_evaluations = ctx.rejected_evaluations;
  const Candidate* best = Winner(candidates, ctx, options, out);
  const std::string& message = found.message;
  if (best == nullptr) {
    out.status = OptimizeStatus::kNoValidOrbit;
    out.message = fmt::format("no motion from rest without event_limit starts found with {} ({} "
                              "evaluations{}{})",
                              BoundText(ctx.family, bound), out.evaluations,
                              message.empty() ? "" : "; ", message);
    return out;
  }
  out.status =
      found.status == OptimizeStatus::kMaxTime ? OptimizeStatus::kMaxTime : OptimizeStatus::kOk;
  out.forcing = best->forcing;
  out.max_abs_force = out.forcing.MaxAbs();
  out.alpha = best->alpha;
  out.attractors = best->attractors;
  out.mean_velocity = best->attractors.mean_velocity;
  out.seed_won = best->is_seed;
  out.summary = AttractorsSummary(out.attractors, options.check.attractor.motion.max_period);
  const double seed_v = have_seed ? out.seed.from_rest.attractors.mean_velocity : ReachResult::kNaN;
  out.message = fmt::format(
      "fastest motion from rest with {}: mean velocity {:.6g} ({}, alpha = {:.6g}){}{}{}{}",
      BoundText(ctx.family, bound), out.mean_velocity, ForceText(out), out.alpha,
      SeedComparison(out, seed_v),
      out.status == OptimizeStatus::kMaxTime ? "; the search stopped at its time limit" : "",
      out.robust_to_settings ? ""
                             : "; WARNING: no candidate keeps its mean velocity under other "
                               "numerical settings (see the spread)",
      message.empty() ? "" : "; " + message);
  return out;
}

}  // namespace capsubot
