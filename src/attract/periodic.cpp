// Newton shooting on the p-th iterate of the stroboscopic map (docs/model.md section 13).

#include "capsubot/attract/periodic.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <stdexcept>

#include "capsubot/attract/detail/period_map.hpp"
#include "capsubot/attract/detail/stroboscopic.hpp"
#include "capsubot/model/detail/enum_names.hpp"

namespace capsubot {
namespace {

constexpr int kMaxPeriodLimit = 64;
constexpr double kInf = std::numeric_limits<double>::infinity();
// A candidate period whose return distance is within this factor of the smallest one (plus
// rounding) is preferred when it is shorter: near a period-p motion every multiple of p
// returns about as close.
constexpr double kReturnFactor = 2.0;
constexpr double kReturnRounding = 1e-12;
// Newton steps are halved at most this many times while the residual does not decrease.
constexpr int kMaxHalvings = 8;
// A fixed point of the p-th iterate is one of the d-th (d a divisor of p) when its d-th iterate
// returns within this: the fixed point's own error (residual_tolerance) grown by the motion's
// multipliers stays far below it, while distinct points of a period-p motion are apart by far
// more.
constexpr double kSameOrbitTol = 1e-9;

using detail::Vec3;

// Asks the interrupt at every forcing period of a run (the transient, however long): an
// observer changes nothing in the run it watches.
class InterruptObserver : public SimObserver {
 public:
  explicit InterruptObserver(const Interrupt& interrupt) : interrupt_(interrupt) {}
  void OnPeriods(std::int64_t) override { Poll(interrupt_); }

 private:
  const Interrupt& interrupt_;
};

class Shooter {
 public:
  Shooter(const RobotModel& robot, const ShootingOptions& o)
      : map_(robot, detail::SimulationOf(o)), interrupt_(o.interrupt) {}

  // P^p(z): false if the simulation hit the work bound. Asks the interrupt first.
  bool Map(const PhaseState& z, int p, detail::MapState* out) const {
    Poll(interrupt_);
    return map_.Map(z, p, out);
  }
  const detail::PeriodMap& map() const { return map_; }

  // The section: events of `periods` periods from s, then s moved to the middle of their
  // largest gap.
  bool PlaceSection(detail::MapState& s, int periods) {
    detail::MapState probe = s;
    recorder_.Start(periods, false, true);
    if (!map_.Shift(probe, periods, &recorder_)) return false;
    const double shift = detail::SectionShift(recorder_.event_phases);
    if (shift <= 0.0) return true;
    return map_.Shift(s, shift / kTau);
  }

  // The period whose iterate returns closest (the shortest within kReturnFactor).
  int ChoosePeriod(const detail::MapState& s, int max_period, bool* ok) {
    detail::MapState probe = s;
    recorder_.Start(max_period, true, false);
    *ok = map_.Shift(probe, max_period, &recorder_, true);
    const std::vector<SimState>& S = recorder_.samples;
    if (!*ok || static_cast<int>(S.size()) != max_period + 1) return 1;
    std::vector<double> back(static_cast<std::size_t>(max_period) + 1, kInf);
    double best = kInf;
    for (int p = 1; p <= max_period; ++p) {
      const SimState& a = S[static_cast<std::size_t>(p)];
      const SimState& b = S[0];
      if (a.mode != b.mode) continue;
      back[static_cast<std::size_t>(p)] =
          std::max({std::abs(a.x - b.x), std::abs(a.u - b.u), std::abs(a.v - b.v)});
      best = std::min(best, back[static_cast<std::size_t>(p)]);
    }
    for (int p = 1; p <= max_period; ++p) {
      if (back[static_cast<std::size_t>(p)] <= kReturnFactor * best + kReturnRounding) return p;
    }
    return 1;
  }

  detail::Recorder recorder_;

 private:
  detail::PeriodMap map_;
  Interrupt interrupt_;
};

// A damped Newton step from *z along dz on the free coordinates: halved while the residual
// does not decrease (at most kMaxHalvings times); *z, *res, *f move to the first trial that
// lowers the residual. False when none does.
template <class Evaluate>
bool DampedStep(const Evaluate& evaluate, const std::vector<int>& free, const Eigen::VectorXd& dz,
                Vec3* z, double* res, Vec3* f) {
  double scale = 1.0;
  for (int h = 0; h <= kMaxHalvings; ++h, scale *= 0.5) {
    Vec3 trial = *z;
    for (std::size_t r = 0; r < free.size(); ++r) {
      trial[static_cast<std::size_t>(free[r])] += scale * dz(static_cast<Eigen::Index>(r));
    }
    trial[0] = std::clamp(trial[0], 0.0, 1.0);
    double tres = kInf;
    Vec3 tf{};
    if (evaluate(trial, &tres, &tf) && tres < *res) {
      *z = trial;
      *res = tres;
      *f = tf;
      return true;
    }
  }
  return false;
}

PeriodicMotion Shoot(Shooter& shooter, PhaseState z0, int p, const ShootingOptions& o) {
  PeriodicMotion out;
  out.period = p;
  detail::MapState image;
  if (!shooter.Map(z0, p, &image)) {
    out.status = ShootingStatus::kEventLimit;
    out.state = z0;
    return out;
  }
  const SimMode mode = image.mode;
  const std::vector<int> free = detail::FreeCoordinates(mode, image.z.v);
  const int d = static_cast<int>(free.size());
  // Fixed coordinates take the values the mode imposes (those of the image).
  Vec3 z = detail::ToVec(z0);
  for (int i = 0; i < 3; ++i) {
    if (std::find(free.begin(), free.end(), i) == free.end())
      z[static_cast<std::size_t>(i)] = detail::ToVec(image.z)[static_cast<std::size_t>(i)];
  }
  const auto evaluate = [&](const Vec3& at, double* res, Vec3* f) {
    detail::MapState im;
    if (!shooter.Map(detail::WithCoordinates(z0, at), p, &im)) return false;
    *res = detail::Residual(at, im.z);
    const Vec3 v = detail::ToVec(im.z);
    for (std::size_t i = 0; i < 3; ++i) (*f)[i] = v[i] - at[i];
    return true;
  };

  double res = kInf;
  Vec3 f{};
  if (!evaluate(z, &res, &f)) {
    out.status = ShootingStatus::kEventLimit;
    return out;
  }
  Eigen::MatrixXd J;
  int it = 0;
  for (; it < o.max_iterations && res > o.residual_tolerance && d > 0; ++it) {
    if (!detail::CentralJacobian(shooter.map(), z0, z, p, free, o.step, &J)) {
      out.status = ShootingStatus::kEventLimit;
      break;
    }
    Eigen::VectorXd rhs(d);
    for (int r = 0; r < d; ++r)
      rhs(r) = -f[static_cast<std::size_t>(free[static_cast<std::size_t>(r)])];
    const Eigen::MatrixXd A = J - Eigen::MatrixXd::Identity(d, d);
    if (!DampedStep(evaluate, free, A.fullPivLu().solve(rhs), &z, &res, &f)) break;
  }
  out.iterations = it;
  out.residual = res;
  out.state = detail::WithCoordinates(z0, z);
  out.mode = mode;
  out.dimension = d;
  if (out.status == ShootingStatus::kEventLimit) return out;
  const bool resolved = detail::WithinScale(shooter.map().robot(), z);
  out.out_of_scale = !resolved;
  out.status = res <= o.residual_tolerance && resolved ? ShootingStatus::kConverged
                                                       : ShootingStatus::kNoConvergence;
  // Multipliers at the reported state.
  if (d == 0 || detail::CentralJacobian(shooter.map(), z0, z, p, free, o.step, &J)) {
    detail::SetMultipliers(d == 0 ? std::vector<std::complex<double>>{} : detail::Multipliers(J),
                           &out);
  }
  // Impacts and displacement over one period p of the motion.
  detail::MeasurePeriod(shooter.map(), p, shooter.recorder_, &out);
  return out;
}

// Shoot, then the smallest period: a converged fixed point of the p-th iterate that is one of
// the d-th for a divisor d of p is the motion of period d (its multipliers those of one period).
PeriodicMotion ShootMinimal(Shooter& shooter, const PhaseState& z0, int p,
                            const ShootingOptions& o) {
  PeriodicMotion pm = Shoot(shooter, z0, p, o);
  if (pm.status != ShootingStatus::kConverged) return pm;
  for (int d = 1; d < p; ++d) {
    if (p % d != 0) continue;
    detail::MapState image;
    if (!shooter.Map(pm.state, d, &image) ||
        detail::Residual(detail::ToVec(pm.state), image.z) > kSameOrbitTol) {
      continue;
    }
    PeriodicMotion shorter = Shoot(shooter, pm.state, d, o);
    if (shorter.status == ShootingStatus::kConverged) return shorter;
  }
  return pm;
}

}  // namespace

namespace detail {

ShootingOptions ShootingOf(const MotionOptions& mo) {
  ShootingOptions o;
  o.chatter_velocity = mo.chatter_velocity;
  o.max_events_per_period = mo.max_events_per_period;
  o.reuse_cycles = mo.reuse_cycles;
  return o;
}

PeriodicMotion RefinePeriodicMotion(const RobotModel& robot, const MotionOptions& options,
                                    MapState s, int p, MapState* moved) {
  const ShootingOptions o = ShootingOf(options);
  Shooter shooter(robot, o);
  *moved = s;
  if (!shooter.PlaceSection(s, p)) {
    PeriodicMotion fail;
    fail.status = ShootingStatus::kEventLimit;
    return fail;
  }
  *moved = s;
  return ShootMinimal(shooter, s.z, p, o);
}

}  // namespace detail

const char* ShootingStatusName(ShootingStatus status) {
  static constexpr const char* kNames[] = {"not_run", "converged", "no_convergence", "event_limit"};
  static_assert(std::size(kNames) == static_cast<std::size_t>(ShootingStatus::kEventLimit) + 1);
  return detail::EnumName(kNames, status);
}

void ShootingOptions::Validate() const {
  const auto fail = [](const char* name, double value, const char* rule) {
    throw std::invalid_argument(fmt::format("{} = {} is invalid: expected {}", name, value, rule));
  };
  if (transient < 0) fail("transient", transient, ">= 0 periods");
  if (max_period < 1 || max_period > kMaxPeriodLimit) {
    fail("max_period", max_period, "1 <= max_period <= 64");
  }
  if (!(residual_tolerance > 0.0) || !std::isfinite(residual_tolerance)) {
    fail("residual_tolerance", residual_tolerance, "a finite number > 0");
  }
  if (max_iterations < 1) fail("max_iterations", max_iterations, ">= 1");
  if (!(step > 0.0) || !std::isfinite(step)) fail("step", step, "a finite number > 0");
  if (!(chatter_velocity > 0.0) || !std::isfinite(chatter_velocity)) {
    fail("chatter_velocity", chatter_velocity, "a finite number > 0");
  }
  if (max_events_per_period < 10) {
    fail("max_events_per_period", static_cast<double>(max_events_per_period), ">= 10");
  }
}

PeriodicMotion FindPeriodicMotion(const RobotModel& robot, const PhaseState& start,
                                  const ShootingOptions& options) {
  robot.params.Validate();
  options.Validate();
  ValidateStart(robot.alpha, start);
  Shooter shooter(robot, options);
  detail::MapState s{start, SimMode::kRest};
  s.z.psi -= kTau * std::floor(s.z.psi / kTau);
  PeriodicMotion fail;
  fail.status = ShootingStatus::kEventLimit;
  const MotionOptions mo = detail::SimulationOf(options);
  InterruptObserver watch(options.interrupt);
  if (options.transient > 0 &&
      detail::Advance(robot, mo, s, options.transient, nullptr, &watch).status ==
          SimStatus::kEventLimit) {
    return fail;
  }
  if (!shooter.PlaceSection(s, options.max_period)) return fail;
  bool ok = true;
  const int p = shooter.ChoosePeriod(s, options.max_period, &ok);
  if (!ok) return fail;
  return ShootMinimal(shooter, s.z, p, options);
}

PeriodicMotion ShootPeriodicMotion(const RobotModel& robot, const PhaseState& start, int period,
                                   const ShootingOptions& options) {
  robot.params.Validate();
  options.Validate();
  ValidateStart(robot.alpha, start);
  if (period < 1 || period > kMaxPeriodLimit) {
    throw std::invalid_argument(
        fmt::format("period = {} is invalid: expected 1 <= period <= 64", period));
  }
  Shooter shooter(robot, options);
  PhaseState z = start;
  z.psi -= kTau * std::floor(z.psi / kTau);
  return ShootMinimal(shooter, z, period, options);
}

}  // namespace capsubot
