// Attractors from a set of starts (docs/model.md sections 12 and 13): the long-run motion of
// every start, in parallel, grouped into classes; the one-impact orbit recognised by its state.

#include "capsubot/attract/attractors.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <numeric>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include "capsubot/attract/detail/stroboscopic.hpp"
#include "capsubot/orbit/robot_orbits.hpp"

namespace capsubot {
namespace {

constexpr int kMaxThreads = 1024;
// Starts per block of work: a start costs about a millisecond; small blocks balance the threads
// and the ranks of a distributed run.
constexpr std::int64_t kStartsPerBlock = 16;

// Periodic motions of one attractor: same period, mean velocities within the tolerance.
bool SamePeriodic(const Motion& a, const Motion& b, double velocity_tolerance) {
  if (a.period != b.period) return false;
  const double scale = std::max(std::abs(a.mean_velocity), std::abs(b.mean_velocity));
  return std::abs(a.mean_velocity - b.mean_velocity) <= velocity_tolerance * scale;
}

// The cluster of every motion with no period (-1 for the others): sorted by mean velocity,
// neighbours within `tolerance` times the larger magnitude share a cluster. Clusters are
// numbered by their smallest velocity; the result does not depend on the order of the starts.
std::vector<int> IrregularClusters(const std::vector<Motion>& motions, double tolerance) {
  std::vector<std::size_t> order;
  for (std::size_t k = 0; k < motions.size(); ++k) {
    if (motions[k].status == MotionStatus::kNoPeriod) order.push_back(k);
  }
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return motions[a].mean_velocity < motions[b].mean_velocity;
  });
  std::vector<int> cluster(motions.size(), -1);
  int id = -1;
  for (std::size_t i = 0; i < order.size(); ++i) {
    const double v = motions[order[i]].mean_velocity;
    const double prev = i > 0 ? motions[order[i - 1]].mean_velocity : v;
    if (i == 0 || !(std::abs(v - prev) <= tolerance * std::max(std::abs(v), std::abs(prev)))) {
      ++id;
    }
    cluster[order[i]] = id;
  }
  return cluster;
}

// The index among `found` (the attractors met so far, with their clusters of irregular
// motions) of the attractor that motion m, of cluster `cluster`, belongs to; -1 if none.
int AttractorOf(const Motion& m, int cluster, const std::vector<Attractor>& found,
                const std::vector<int>& found_cluster, double velocity_tolerance) {
  for (std::size_t a = 0; a < found.size(); ++a) {
    const Motion& f = found[a].motion;
    if (f.status != m.status) continue;
    const bool same = m.status == MotionStatus::kPeriodic ? SamePeriodic(f, m, velocity_tolerance)
                                                          : found_cluster[a] == cluster;
    if (same) return static_cast<int>(a);
  }
  return -1;
}

// A new attractor, first reached by `example` with motion m (its starts not yet counted).
Attractor NewAttractor(const Motion& m, const PhaseState& example) {
  Attractor a;
  a.motion = m;
  a.example = example;
  a.velocity_min = a.velocity_max = m.mean_velocity;
  return a;
}

// Counts a start of motion m in attractor a: its number of starts, the range of their mean
// velocities (summed into `velocity_sum`), and the largest difference between the two halves
// of an irregular motion's record (absolute).
void AddStart(const Motion& m, Attractor& a, double& velocity_sum) {
  ++a.starts;
  velocity_sum += m.mean_velocity;
  a.velocity_min = std::min(a.velocity_min, m.mean_velocity);
  a.velocity_max = std::max(a.velocity_max, m.mean_velocity);
  if (m.status == MotionStatus::kNoPeriod) {
    a.halves_difference =
        std::max(a.halves_difference, std::abs(m.first_half_velocity - m.second_half_velocity));
  }
}

// Writes the attractors `found` (in the order first reached) into out.attractors by their
// number of starts, most first (ties: first reached first), with their fractions of
// out.starts, and each start's index into them into out.labels (from `label`, its index
// into `found`).
void RankBySize(const std::vector<Attractor>& found, const std::vector<int>& label,
                Attractors& out) {
  std::vector<int> order(found.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return found[a].starts > found[b].starts; });
  std::vector<int> rank(found.size());
  for (std::size_t r = 0; r < order.size(); ++r) {
    rank[static_cast<std::size_t>(order[r])] = static_cast<int>(r);
    out.attractors.push_back(found[static_cast<std::size_t>(order[r])]);
    out.attractors.back().fraction =
        static_cast<double>(out.attractors.back().starts) / static_cast<double>(out.starts);
  }
  out.labels.resize(label.size());
  for (std::size_t k = 0; k < label.size(); ++k) {
    out.labels[k] = rank[static_cast<std::size_t>(label[k])];
  }
}

bool OneImpactShape(const Motion& m) {
  return m.status == MotionStatus::kPeriodic && m.period == 1 && m.impacts_right == 1 &&
         m.impacts_left == 0;
}

}  // namespace

void AttractorOptions::Validate() const {
  motion.Validate();
  if (!(velocity_tolerance >= 0.0) || !std::isfinite(velocity_tolerance)) {
    throw std::invalid_argument(fmt::format(
        "velocity_tolerance = {} is invalid: expected a finite number >= 0", velocity_tolerance));
  }
  if (!(irregular_tolerance >= 0.0) || !std::isfinite(irregular_tolerance)) {
    throw std::invalid_argument(fmt::format(
        "irregular_tolerance = {} is invalid: expected a finite number >= 0", irregular_tolerance));
  }
  if (!(orbit_tolerance > 0.0) || !std::isfinite(orbit_tolerance)) {
    throw std::invalid_argument(fmt::format(
        "orbit_tolerance = {} is invalid: expected a finite number > 0", orbit_tolerance));
  }
  if (threads < 0 || threads > kMaxThreads) {
    throw std::invalid_argument(
        fmt::format("threads = {} is invalid: expected 1 <= threads <= {} (0: all cores)", threads,
                    kMaxThreads));
  }
}

void FromRestOptions::Validate() const {
  StartGrid{n_x, n_psi}.Validate();
  attractor.Validate();
}

bool MatchesOrbit(const Motion& motion, const Forcing& forcing, const Orbit& orbit,
                  double tolerance) {
  if (!orbit.ok() || !OneImpactShape(motion)) return false;
  // Motor phase at the section minus the motor phase at the orbit's impact.
  double phi = forcing.phi0() + motion.section.psi - orbit.forcing.phi0();
  phi -= kTau * std::floor(phi / kTau);
  return std::abs(motion.section.x - orbit.x(phi)) <= tolerance &&
         std::abs(motion.section.u - orbit.dx(phi)) <= tolerance &&
         std::abs(motion.section.v - orbit.v(phi)) <= tolerance;
}

std::int64_t CountReached(const Attractors& attractors, const Forcing& forcing, const Orbit& orbit,
                          double tolerance) {
  return std::count_if(attractors.motions.begin(), attractors.motions.end(),
                       [&](const Motion& m) { return MatchesOrbit(m, forcing, orbit, tolerance); });
}

BlockComputeFactory MotionBlocks(const RobotModel& robot, const std::vector<PhaseState>& starts,
                                 const AttractorOptions& options) {
  static_assert(std::is_trivially_copyable<Motion>::value, "a Motion's bytes are its value");
  return [&robot, &starts, &options]() -> BlockCompute {
    auto recorder = std::make_shared<detail::Recorder>();
    return [&robot, &starts, &options, recorder](std::int64_t begin, std::int64_t end,
                                                 std::string& out) {
      for (std::int64_t i = begin; i < end; ++i) {
        const Motion m = detail::ClassifyMotion(
            robot, options.motion, {starts[static_cast<std::size_t>(i)], SimMode::kRest},
            *recorder);
        out.append(reinterpret_cast<const char*>(&m), sizeof m);
      }
      return end - begin;
    };
  };
}

void StreamLongRunMotions(const RobotModel& robot, const std::vector<PhaseState>& starts,
                          const AttractorOptions& options, std::int64_t first,
                          const MotionSink& sink, const BlockBackend& backend) {
  robot.params.Validate();
  options.Validate();
  for (const PhaseState& s : starts) ValidateStart(robot.alpha, s);
  const auto n = static_cast<std::int64_t>(starts.size());
  if (first < 0 || first > n) {
    throw std::invalid_argument(fmt::format(
        "first start = {} is invalid: expected 0 <= first <= {} (the starts)", first, n));
  }
  BlockPlan plan;
  plan.first = first;
  plan.end = n;
  plan.threads = WorkerThreads(options.threads, std::max<std::int64_t>(1, n - first));
  plan.block = BalancedBlock(n - first, backend.Threads(plan.threads), kStartsPerBlock);
  std::vector<Motion> block;
  backend.Run(plan, MotionBlocks(robot, starts, options),
              [&](std::int64_t begin, std::int64_t end, const std::string& bytes, std::int64_t) {
                const auto count = static_cast<std::size_t>(end - begin);
                if (bytes.size() != count * sizeof(Motion)) {
                  throw std::runtime_error(fmt::format(
                      "the motions of starts {} to {} came back with {} bytes: expected {}", begin,
                      end - 1, bytes.size(), count * sizeof(Motion)));
                }
                block.resize(count);
                std::memcpy(static_cast<void*>(block.data()), bytes.data(), bytes.size());
                sink(begin, end, block.data());
                Poll(options.interrupt);  // here, on the calling thread: never on a worker
              });
}

std::vector<Motion> LongRunMotions(const RobotModel& robot, const std::vector<PhaseState>& starts,
                                   const AttractorOptions& options, const StartsProgress& progress,
                                   const BlockBackend& backend) {
  std::vector<Motion> motions(starts.size());
  const auto n = static_cast<std::int64_t>(starts.size());
  StreamLongRunMotions(
      robot, starts, options, 0,
      [&](std::int64_t begin, std::int64_t end, const Motion* block) {
        std::copy(block, block + (end - begin), motions.begin() + begin);
        if (progress) progress(end, n);
      },
      backend);
  return motions;
}

Attractors GroupMotions(const std::vector<PhaseState>& starts, std::vector<Motion> motions,
                        const Grouping& grouping) {
  if (motions.size() != starts.size()) {
    throw std::invalid_argument(fmt::format("motions: {} given: expected one per start ({})",
                                            motions.size(), starts.size()));
  }
  Attractors out;
  const auto n = static_cast<std::int64_t>(starts.size());
  out.starts = n;
  out.motions = std::move(motions);
  const std::vector<int> cluster = IrregularClusters(out.motions, grouping.irregular_tolerance);
  // Group in the order of the starts (deterministic), then sort by size.
  std::vector<int> label(starts.size(), -1);
  std::vector<Attractor> found;
  std::vector<int> found_cluster;
  std::vector<double> sums;
  double sum = 0.0;
  for (std::size_t k = 0; k < starts.size(); ++k) {
    const Motion& m = out.motions[k];
    if (m.status == MotionStatus::kEventLimit) {
      ++out.event_limit_starts;
    } else {
      sum += m.mean_velocity;
    }
    label[k] = AttractorOf(m, cluster[k], found, found_cluster, grouping.velocity_tolerance);
    if (label[k] < 0) {
      label[k] = static_cast<int>(found.size());
      found.push_back(NewAttractor(m, starts[k]));
      found_cluster.push_back(cluster[k]);
      sums.push_back(0.0);
    }
    const auto g = static_cast<std::size_t>(label[k]);
    AddStart(m, found[g], sums[g]);
  }
  for (std::size_t g = 0; g < found.size(); ++g) {
    Attractor& a = found[g];
    a.mean_velocity = sums[g] / static_cast<double>(a.starts);
    // Relative to the attractor's speed (absolute differences summed above).
    a.halves_difference = a.halves_difference > 0.0
                              ? a.halves_difference / std::abs(a.mean_velocity)
                              : a.halves_difference;
  }
  if (n > out.event_limit_starts)
    out.mean_velocity = sum / static_cast<double>(n - out.event_limit_starts);
  RankBySize(found, label, out);
  return out;
}

Attractors ClassifyStarts(const RobotModel& robot, const std::vector<PhaseState>& starts,
                          const AttractorOptions& options, const StartsProgress& progress,
                          const BlockBackend& backend) {
  Attractors out = GroupMotions(starts, LongRunMotions(robot, starts, options, progress, backend),
                                Grouping{options.velocity_tolerance, options.irregular_tolerance});
  // The analytic one-impact orbits are needed only if a motion has their shape.
  const bool any = std::any_of(out.attractors.begin(), out.attractors.end(),
                               [](const Attractor& a) { return OneImpactShape(a.motion); });
  if (any) {
    const std::vector<Solution> orbits = FindRobotOrbits(robot);
    for (Attractor& a : out.attractors) {
      for (const Solution& s : orbits) {
        if (MatchesOrbit(a.motion, robot.forcing, s.orbit, options.orbit_tolerance)) {
          a.one_impact_orbit = true;
        }
      }
    }
  }
  return out;
}

std::vector<PhaseState> GridStarts(int n_x, int n_psi) {
  std::vector<PhaseState> starts;
  if (n_x < 1 || n_psi < 1) return starts;
  starts.reserve(static_cast<std::size_t>(n_x) * static_cast<std::size_t>(n_psi));
  for (int i = 0; i < n_x; ++i) {
    for (int j = 0; j < n_psi; ++j) starts.push_back(GridStart(i, j, n_x, n_psi));
  }
  return starts;
}

Attractors FindAttractors(const RobotModel& robot, const FromRestOptions& options,
                          const StartsProgress& progress) {
  options.Validate();
  return ClassifyStarts(robot, GridStarts(options.n_x, options.n_psi), options.attractor, progress);
}

}  // namespace capsubot
