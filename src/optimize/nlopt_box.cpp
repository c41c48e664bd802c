#include "capsubot/optimize/detail/nlopt_box.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>

#include "capsubot/optimize/detail/nlopt_status.hpp"

namespace capsubot::detail {

OptimizeStatus MaximizeOnBox(nlopt::algorithm algorithm, nlopt::func objective, void* data,
                             const std::vector<double>& lower, const std::vector<double>& upper,
                             std::vector<double> y0, int evaluations, double seconds,
                             double rel_tol, double step_fraction, std::string& message) {
  const auto n = static_cast<unsigned>(lower.size());
  NloptCallbacks callbacks;
  OptimizeStatus status = OptimizeStatus::kNotRun;
  try {
    nlopt::opt opt(algorithm, n);
    opt.set_lower_bounds(lower);
    opt.set_upper_bounds(upper);
    opt.set_max_objective(NloptCallbacks::Call, callbacks.Wrap(objective, data));
    opt.set_maxeval(evaluations);
    opt.set_maxtime(seconds);
    opt.set_xtol_rel(rel_tol);
    opt.set_ftol_rel(rel_tol);
    std::vector<double> step(n);
    for (unsigned i = 0; i < n; ++i) step[i] = step_fraction * (upper[i] - lower[i]);
    opt.set_initial_step(step);
    for (unsigned i = 0; i < n; ++i) y0[i] = std::clamp(y0[i], lower[i], upper[i]);
    double value = 0.0;
    status = StatusFromNlopt(opt.optimize(y0, value));
  } catch (...) {
    status = StatusFromCurrentException(message);
  }
  callbacks.Rethrow();
  return status;
}

std::vector<BoxPoint> BestDistinctPoints(std::vector<BoxPoint> seen, double floor, int count,
                                         double same) {
  std::stable_sort(seen.begin(), seen.end(),
                   [](const BoxPoint& a, const BoxPoint& b) { return a.score > b.score; });
  std::vector<BoxPoint> best;
  for (const BoxPoint& p : seen) {
    if (static_cast<int>(best.size()) >= count) break;
    if (!(p.score > floor)) break;
    const bool known = std::any_of(best.begin(), best.end(), [&](const BoxPoint& q) {
      for (std::size_t i = 0; i < p.y.size(); ++i) {
        if (std::abs(p.y[i] - q.y[i]) > same) return false;
      }
      return true;
    });
    if (!known) best.push_back(p);
  }
  return best;
}

std::vector<double> HaltonPoint(long long i, int dimension) {
  static constexpr int kPrimes[] = {2,  3,  5,  7,   11,  13,  17,  19,  23,  29, 31,
                                    37, 41, 43, 47,  53,  59,  61,  67,  71,  73, 79,
                                    83, 89, 97, 101, 103, 107, 109, 113, 127, 131};
  if (dimension < 1 || dimension > static_cast<int>(std::size(kPrimes)) || i < 1) {
    throw std::invalid_argument(fmt::format(
        "Halton point {} of dimension {} is invalid: expected i >= 1 and 1 <= dimension <= {}", i,
        dimension, std::size(kPrimes)));
  }
  std::vector<double> y(static_cast<std::size_t>(dimension));
  for (int d = 0; d < dimension; ++d) {
    const int base = kPrimes[d];
    double f = 1.0, r = 0.0;
    for (long long n = i; n > 0; n /= base) {
      f /= base;
      r += f * static_cast<double>(n % base);
    }
    y[static_cast<std::size_t>(d)] = r;
  }
  return y;
}

void BoxSearch::SetGlobal(const std::string& name, const std::vector<std::string>& allowed,
                          const char* option) {
  halton = name == kHaltonStage && std::find(allowed.begin(), allowed.end(), name) != allowed.end();
  if (!halton) global = AlgorithmFromName(name, allowed, option);
}

namespace {

// The global stage as a Halton sampling of the box: `evaluations` points, stopped when no time
// is left.
void SampleHalton(const BoxSearch& search, int evaluations) {
  const auto n = static_cast<int>(search.lower.size());
  for (long long i = 1; i <= evaluations && search.seconds_left() > 0.0; ++i) {
    std::vector<double> y = HaltonPoint(i, n);
    for (std::size_t d = 0; d < y.size(); ++d) {
      y[d] = search.lower[d] + y[d] * (search.upper[d] - search.lower[d]);
    }
    double* gradient = nullptr;
    search.objective(static_cast<unsigned>(n), y.data(), gradient, search.data);
  }
}

}  // namespace

BoxSearchResult SearchBox(const BoxSearch& search) {
  constexpr double kLocalStep = 0.05;  // initial step of a stage, fraction of each box side
  BoxSearchResult out;
  bool ran = false;
  const auto stage = [&](const char* name, nlopt::algorithm algorithm, int evaluations,
                         const std::vector<double>& from) {
    const double seconds = search.seconds_left();
    if (evaluations <= 0 || !(seconds > 0.0)) {
      out.max_time = out.max_time || evaluations > 0;
      return;
    }
    if (search.on_stage) search.on_stage(name);
    const OptimizeStatus s =
        MaximizeOnBox(algorithm, search.objective, search.data, search.lower, search.upper, from,
                      evaluations, seconds, search.rel_tol, kLocalStep, out.message);
    out.max_time = out.max_time || s == OptimizeStatus::kMaxTime;
    if (!ran || s == OptimizeStatus::kMaxTime || out.status != OptimizeStatus::kMaxTime) {
      out.status = s;
    }
    ran = true;
  };
  if (search.halton) {
    if (search.on_stage) search.on_stage("global search");
    SampleHalton(search, search.global_evaluations);
    out.max_time = !(search.seconds_left() > 0.0);
    out.status = out.max_time ? OptimizeStatus::kMaxTime : OptimizeStatus::kOk;
    ran = true;
  } else {
    stage("global search", search.global, search.global_evaluations, search.start);
  }
  if (search.refine_evaluations > 0) {
    const std::vector<BoxPoint> best =
        BestDistinctPoints(search.seen(), search.infeasible, 1, search.same);
    stage("global refine", search.refine, search.refine_evaluations,
          best.empty() ? search.start : best.front().y);
  }
  const double apart = std::max(search.same, search.polish_apart);
  const auto climb = [&](const char* name, int starts, int evaluations) {
    if (evaluations <= 0) return;
    for (const BoxPoint& from :
         BestDistinctPoints(search.seen(), search.infeasible, starts, apart)) {
      stage(name, search.local, evaluations, from.y);
    }
  };
  climb("local screen", search.screen_starts, search.screen_evaluations);
  climb("local polish", search.polish_starts, search.local_evaluations);
  // Out of time before its first stage: the search evaluated nothing, and says so.
  if (!ran && out.max_time) out.status = OptimizeStatus::kMaxTime;
  out.candidates = BestDistinctPoints(search.seen(), search.infeasible, search.candidates,
                                      std::max(search.same, search.candidates_apart));
  return out;
}

}  // namespace capsubot::detail
