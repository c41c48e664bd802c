// Bifurcation diagrams by brute force with the state carried along (docs/model.md section 13).

#include "capsubot/attract/bifurcation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <iterator>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "capsubot/attract/detail/stroboscopic.hpp"
#include "capsubot/attract/periodic.hpp"
#include "capsubot/model/detail/enum_names.hpp"
#include "capsubot/model/limits.hpp"
#include "capsubot/numerics/grid_value.hpp"
#include "capsubot/numerics/not_computed.hpp"
#include "capsubot/orbit/robot_orbits.hpp"
#include "capsubot/orbit/stability.hpp"

namespace capsubot {
namespace {

constexpr int kMaxSteps = 10000000;
// Periods recorded along one continuation (steps x record): an impact row holds about 50
// bytes and a period a few impacts, so about 10 GB at this bound.
constexpr std::int64_t kMaxRecordedPeriods = 100000000;

// The robot at `value` of `parameter` (with `harmonic`), the others those of `base`.
RobotModel At(const RobotModel& base, ModelParameter parameter, int harmonic, double value) {
  RobotModel r = base;
  SetParameter(r, parameter, harmonic, value);
  return r;
}

double Value(const BifurcationOptions& o, int i) { return GridValue(o.from, o.to, o.steps, i); }

// Counts the parameter values simulated by the parts and reports them in increasing order: a
// part computed by this process's threads ticks each value as it is done, one computed by
// another process counts its values when it arrives.
class ValuesDone {
 public:
  ValuesDone(const StartsProgress& progress, std::size_t parts, std::int64_t total)
      : progress_(progress), ticked_(parts, 0), total_(total) {}
  // One value of the sweep of part k simulated here.
  void Tick(std::int64_t k) {
    if (!progress_) return;
    const std::lock_guard<std::mutex> lock(mutex_);
    ++ticked_[static_cast<std::size_t>(k)];
    progress_(++done_, total_);
  }
  // Part k with `values` values simulated has arrived: counts those not ticked.
  void Arrived(std::int64_t k, std::int64_t values) {
    if (!progress_) return;
    const std::lock_guard<std::mutex> lock(mutex_);
    const std::int64_t rest = values - ticked_[static_cast<std::size_t>(k)];
    if (rest <= 0) return;
    ticked_[static_cast<std::size_t>(k)] = values;
    done_ += rest;
    progress_(done_, total_);
  }

 private:
  const StartsProgress& progress_;
  std::vector<std::int64_t> ticked_;
  std::int64_t total_;
  std::int64_t done_ = 0;
  std::mutex mutex_;
};

// One sweep in `direction`, the state carried from each value to the next.
// `tick` is told each value done.
void Sweep(const RobotModel& base, const BifurcationOptions& o, SweepDirection direction,
           BifurcationDiagram& out, const std::function<void()>& tick) {
  detail::Recorder recorder;
  detail::MapState s{o.start, SimMode::kRest};
  const ShootingOptions shooting = detail::ShootingOf(o.motion);
  for (int n = 0; n < o.steps; ++n) {
    const int i = direction == SweepDirection::kUp ? n : o.steps - 1 - n;
    const double value = Value(o, i);
    const RobotModel r = At(base, o.param, o.harmonic, value);
    BifurcationPoint point;
    point.param = value;
    point.direction = direction;
    point.motion = detail::ClassifyMotion(r, o.motion, s, recorder, true);
    s = {point.motion.section, point.motion.mode};
    if (point.motion.status == MotionStatus::kPeriodic && recorder.impacts.empty()) {
      // Stopped early on a periodic motion: its impacts of one period p stand for the record.
      detail::MapState again = s;
      recorder.Start(point.motion.period, false, false, true, s.z.psi);
      detail::Advance(r, o.motion, again, point.motion.period, nullptr, &recorder);
    }
    if (point.motion.status != MotionStatus::kEventLimit) {
      for (const detail::Recorder::Impact& im : recorder.impacts) {
        double phase = recorder.psi0 + im.phase;
        phase -= kTau * std::floor(phase / kTau);
        out.impacts.push_back({value, direction, im.period, im.right, phase, im.u_before});
      }
    }
    if (o.multipliers && point.motion.status == MotionStatus::kPeriodic) {
      Motion& m = point.motion;
      if (!m.refined) {  // Newton's method from the motion's state gives its multipliers
        const PeriodicMotion pm = ShootPeriodicMotion(r, m.section, m.period, shooting);
        if (pm.status == ShootingStatus::kConverged && !pm.multipliers.empty()) {
          m.spectral_radius = pm.spectral_radius;
          m.multiplier_re = pm.multipliers.front().real();
          m.multiplier_im = pm.multipliers.front().imag();
        }
      }
      point.multiplier_re = m.multiplier_re;
      point.multiplier_im = m.multiplier_im;
      point.spectral_radius = m.spectral_radius;
    }
    out.summary.push_back(point);
    tick();
  }
}

void Analytic(const RobotModel& base, const BifurcationOptions& o, BifurcationDiagram& out) {
  for (int i = 0; i < o.steps; ++i) {
    const double value = Value(o, i);
    const RobotModel r = At(base, o.param, o.harmonic, value);
    for (const Solution& s : FindRobotOrbits(r)) {
      if (!s.validity.valid()) continue;
      BifurcationPoint point;
      point.param = value;
      point.direction = SweepDirection::kAnalytic;
      point.motion.status = MotionStatus::kPeriodic;
      point.motion.period = 1;
      point.motion.impacts_right = 1;
      point.motion.mean_velocity = s.orbit.v_mean;
      const Stability st = ComputeStability(s.orbit);
      if (st.computed) {
        point.multiplier_re = st.multipliers[0].real();
        point.multiplier_im = st.multipliers[0].imag();
        point.spectral_radius = st.spectral_radius;
      }
      out.summary.push_back(point);
    }
  }
}

// The robots and parts of a study, checked: one robot per value of the second parameter (the
// given one without it); the parts of the shard, in order (BifurcationDiagram::parts).
struct Part {
  int id = 0;
  std::size_t value = 0;
  SweepDirection kind = SweepDirection::kUp;
};
struct Study {
  std::vector<RobotModel> bases;
  std::vector<double> overs;
  std::vector<Part> parts;
  int total_parts = 0;
};

Study PlanStudy(const RobotModel& robot, const BifurcationOptions& options) {
  options.Validate();
  const bool two = !options.over_values.empty();
  CheckRobotParameter(robot.forcing, options.param, options.harmonic);
  if (two) CheckRobotParameter(robot.forcing, options.over, options.over_harmonic);
  Study study;
  study.overs = two ? options.over_values : std::vector<double>{kNaN};
  for (double over : study.overs) {
    study.bases.push_back(two ? At(robot, options.over, options.over_harmonic, over) : robot);
    // Every robot of the range must be valid: check both ends and name the one that is not.
    for (double value : {options.from, options.to}) {
      const RobotModel r = At(study.bases.back(), options.param, options.harmonic, value);
      try {
        r.params.Validate();
        ValidateStart(r.alpha, options.start);
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(fmt::format(
            "{} = {}{} makes the robot invalid: {}",
            ModelParameterName(options.param, options.harmonic), value,
            two ? fmt::format(" at {} = {}",
                              ModelParameterName(options.over, options.over_harmonic), over)
                : std::string(),
            e.what()));
      }
    }
  }
  // The parts of each value: up, down, analytic (those asked for); continuation q of each
  // sweep, the analytic orbits with the value's first continuation.
  std::vector<SweepDirection> kinds;
  if (options.up) kinds.push_back(SweepDirection::kUp);
  if (options.down) kinds.push_back(SweepDirection::kDown);
  const int directions = static_cast<int>(kinds.size());
  if (options.analytic) kinds.push_back(SweepDirection::kAnalytic);
  for (std::size_t i = 0; i < study.bases.size(); ++i) {
    for (std::size_t j = 0; j < kinds.size(); ++j) {
      const int q = static_cast<int>(i) * directions +
                    (kinds[j] == SweepDirection::kAnalytic ? 0 : static_cast<int>(j));
      if (q % options.shards != options.shard) continue;
      study.parts.push_back({static_cast<int>(i * kinds.size() + j), i, kinds[j]});
    }
  }
  study.total_parts = BifurcationParts(options);
  return study;
}

// Parameter values simulated by a part: a sweep's values; none for the analytic orbits.
std::int64_t SimulatedValues(const Part& p, const BifurcationOptions& o) {
  return p.kind == SweepDirection::kAnalytic ? 0 : o.steps;
}

// The rows of the k-th part of the shard, with the value of the second parameter and the
// part's id. `done` (if any) is told each value simulated.
BifurcationDiagram ComputePart(const Study& study, const BifurcationOptions& o, std::int64_t k,
                               ValuesDone* done) {
  const Part& p = study.parts[static_cast<std::size_t>(k)];
  BifurcationDiagram r;
  if (p.kind == SweepDirection::kAnalytic) {
    Analytic(study.bases[p.value], o, r);
  } else {
    Sweep(study.bases[p.value], o, p.kind, r, [done, k] {
      if (done != nullptr) done->Tick(k);
    });
  }
  for (ImpactPoint& im : r.impacts) {
    im.over = study.overs[p.value];
    im.part = p.id;
  }
  for (BifurcationPoint& point : r.summary) {
    point.over = study.overs[p.value];
    point.part = p.id;
  }
  return r;
}

// The bytes of a part's rows (the unit of a block): the count of its impacts (int64), the
// values of its ImpactPoint rows, then those of its BifurcationPoint rows.
static_assert(std::is_trivially_copyable<ImpactPoint>::value, "an impact's bytes are its value");
static_assert(std::is_trivially_copyable<BifurcationPoint>::value, "a row's bytes are its value");

void AppendPartBytes(const BifurcationDiagram& part, std::string& out) {
  const auto impacts = static_cast<std::int64_t>(part.impacts.size());
  out.append(reinterpret_cast<const char*>(&impacts), sizeof impacts);
  out.append(reinterpret_cast<const char*>(part.impacts.data()),
             part.impacts.size() * sizeof(ImpactPoint));
  out.append(reinterpret_cast<const char*>(part.summary.data()),
             part.summary.size() * sizeof(BifurcationPoint));
}

// The k-th part of the study's shard read back from AppendPartBytes: its rows, parts = {id},
// total_parts.
BifurcationDiagram ReadPartBytes(const std::string& bytes, const Study& study, std::int64_t k) {
  std::int64_t impacts = -1;
  if (bytes.size() >= sizeof impacts) std::memcpy(&impacts, bytes.data(), sizeof impacts);
  const std::size_t rest = bytes.size() - std::min(bytes.size(), sizeof impacts);
  if (impacts < 0 || rest < static_cast<std::size_t>(impacts) * sizeof(ImpactPoint) ||
      (rest - static_cast<std::size_t>(impacts) * sizeof(ImpactPoint)) % sizeof(BifurcationPoint) !=
          0) {
    throw std::runtime_error(
        fmt::format("part {} of the study came back with {} bytes: expected its rows",
                    study.parts[static_cast<std::size_t>(k)].id, bytes.size()));
  }
  BifurcationDiagram r;
  r.impacts.resize(static_cast<std::size_t>(impacts));
  r.summary.resize((rest - r.impacts.size() * sizeof(ImpactPoint)) / sizeof(BifurcationPoint));
  const char* at = bytes.data() + sizeof impacts;
  std::memcpy(static_cast<void*>(r.impacts.data()), at, r.impacts.size() * sizeof(ImpactPoint));
  at += r.impacts.size() * sizeof(ImpactPoint);
  std::memcpy(static_cast<void*>(r.summary.data()), at,
              r.summary.size() * sizeof(BifurcationPoint));
  r.parts = {study.parts[static_cast<std::size_t>(k)].id};
  r.total_parts = study.total_parts;
  return r;
}

// The computers of the parts (BifurcationBlocks); `done` (if any) is told each value they
// simulate.
BlockComputeFactory PartBlocks(const RobotModel& robot, const BifurcationOptions& options,
                               ValuesDone* done) {
  return [&robot, &options, done]() -> BlockCompute {
    auto study = std::make_shared<const Study>(PlanStudy(robot, options));
    return [study, &options, done](std::int64_t begin, std::int64_t end, std::string& out) {
      for (std::int64_t k = begin; k < end; ++k) {
        AppendPartBytes(ComputePart(*study, options, k, done), out);
      }
      return end - begin;
    };
  };
}

}  // namespace

const char* SweepDirectionName(SweepDirection direction) {
  static constexpr const char* kNames[] = {"up", "down", "analytic"};
  static_assert(std::size(kNames) == static_cast<std::size_t>(SweepDirection::kAnalytic) + 1);
  return detail::EnumName(kNames, direction);
}

void BifurcationOptions::Validate() const {
  if (!std::isfinite(from) || !std::isfinite(to)) {
    throw std::invalid_argument(
        fmt::format("range from = {} to = {} is invalid: expected two finite numbers", from, to));
  }
  if (steps < 2 || steps > kMaxSteps) {
    throw std::invalid_argument(
        fmt::format("steps = {} is invalid: expected 2 <= steps <= {}", steps, kMaxSteps));
  }
  // A continuation's rows are held until it is written: bound its recorded periods.
  if (static_cast<std::int64_t>(steps) * motion.record > kMaxRecordedPeriods) {
    throw std::invalid_argument(fmt::format(
        "steps = {} with record = {} is invalid: {} recorded periods a continuation: expected "
        "steps x record <= {} (its impacts are held in memory until written)",
        steps, motion.record, static_cast<std::int64_t>(steps) * motion.record,
        kMaxRecordedPeriods));
  }
  if (!up && !down) {
    throw std::invalid_argument("direction is invalid: expected up, down or both");
  }
  if (IsFourierCoefficient(param) ? harmonic < 1 || harmonic > kMaxHarmonics : harmonic != 0) {
    throw std::invalid_argument(
        fmt::format("harmonic = {} is invalid: expected 1 <= k <= {} for a_k and b_k, else 0",
                    harmonic, kMaxHarmonics));
  }
  motion.Validate();
  if (!over_values.empty()) {
    if (static_cast<std::int64_t>(over_values.size()) > kMaxOverValues) {
      throw std::invalid_argument(
          fmt::format("second parameter {} is invalid: {} values: expected at most {} values",
                      ModelParameterName(over, over_harmonic), over_values.size(), kMaxOverValues));
    }
    if (IsFourierCoefficient(over) ? over_harmonic < 1 || over_harmonic > kMaxHarmonics
                                   : over_harmonic != 0) {
      throw std::invalid_argument(fmt::format(
          "over harmonic = {} is invalid: expected 1 <= k <= {} for a_k and b_k, else 0",
          over_harmonic, kMaxHarmonics));
    }
    if (over == param && over_harmonic == harmonic) {
      throw std::invalid_argument(fmt::format(
          "second parameter = {} is invalid: expected a parameter other than the diagram's",
          ModelParameterName(over, over_harmonic)));
    }
    for (double v : over_values) {
      if (!std::isfinite(v)) {
        throw std::invalid_argument(
            fmt::format("second parameter {} = {} is invalid: expected finite values",
                        ModelParameterName(over, over_harmonic), v));
      }
    }
  }
  const int continuations = BifurcationContinuations(*this);
  if (shards < 1 || shards > continuations) {
    throw std::invalid_argument(fmt::format(
        "shard count N = {} is invalid: the study has {} continuations ({} values of the "
        "second parameter x {} directions): expected 1 <= N <= {}",
        shards, continuations, std::max<std::size_t>(1, over_values.size()),
        (up ? 1 : 0) + (down ? 1 : 0), continuations));
  }
  if (shard < 0 || shard >= shards) {
    throw std::invalid_argument(
        fmt::format("shard K = {} is invalid: expected 0 <= K < N = {}", shard, shards));
  }
  if (threads < 0 || threads > kMaxThreads) {
    throw std::invalid_argument(
        fmt::format("threads = {} is invalid: expected 1 <= threads <= {} (0: all cores)", threads,
                    kMaxThreads));
  }
}

int BifurcationContinuations(const BifurcationOptions& options) {
  const auto values = static_cast<int>(std::max<std::size_t>(1, options.over_values.size()));
  return values * ((options.up ? 1 : 0) + (options.down ? 1 : 0));
}

int BifurcationParts(const BifurcationOptions& options) {
  const auto values = static_cast<int>(std::max<std::size_t>(1, options.over_values.size()));
  return values * ((options.up ? 1 : 0) + (options.down ? 1 : 0) + (options.analytic ? 1 : 0));
}

void ValidateBifurcation(const RobotModel& robot, const BifurcationOptions& options) {
  PlanStudy(robot, options);
}

void StreamBifurcation(const RobotModel& robot, const BifurcationOptions& options, int first,
                       const BifurcationPartSink& sink, const StartsProgress& progress,
                       const BlockBackend& backend) {
  const Study study = PlanStudy(robot, options);
  const auto parts = static_cast<std::int64_t>(study.parts.size());
  if (first < 0 || first > parts) {
    throw std::invalid_argument(fmt::format(
        "first part = {} is invalid: expected 0 <= first <= {} (the parts of the shard)", first,
        parts));
  }
  std::int64_t values = 0;  // those of the parts computed (not those done before: a resume)
  for (std::int64_t k = first; k < parts; ++k) {
    values += SimulatedValues(study.parts[static_cast<std::size_t>(k)], options);
  }
  ValuesDone done(progress, study.parts.size(), values);
  BlockPlan plan;
  plan.first = first;
  plan.end = parts;
  plan.block = 1;  // a part a block: the parts are few and long
  plan.threads = WorkerThreads(options.threads, std::max<std::int64_t>(1, parts - first));
  backend.Run(plan, PartBlocks(robot, options, &done),
              [&](std::int64_t k, std::int64_t, const std::string& bytes, std::int64_t) {
                // Block k is part k alone (plan.block = 1).
                const BifurcationDiagram part = ReadPartBytes(bytes, study, k);
                done.Arrived(k, SimulatedValues(study.parts[static_cast<std::size_t>(k)], options));
                sink(part);
              });
}

BlockComputeFactory BifurcationBlocks(const RobotModel& robot, const BifurcationOptions& options) {
  return PartBlocks(robot, options, nullptr);
}

BifurcationDiagram ComputeBifurcation(const RobotModel& robot, const BifurcationOptions& options,
                                      const StartsProgress& progress, const BlockBackend& backend) {
  BifurcationDiagram out;
  StreamBifurcation(
      robot, options, 0,
      [&out](const BifurcationDiagram& part) {
        out.parts.push_back(part.parts.front());
        out.impacts.insert(out.impacts.end(), part.impacts.begin(), part.impacts.end());
        out.summary.insert(out.summary.end(), part.summary.begin(), part.summary.end());
      },
      progress, backend);
  out.total_parts = BifurcationParts(options);
  return out;
}

}  // namespace capsubot
