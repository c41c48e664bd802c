// The p-th iterate of the stroboscopic map, its central-difference Jacobian and multipliers
// (docs/model.md section 13).

#include "capsubot/attract/detail/period_map.hpp"

#include <algorithm>
#include <cmath>

namespace capsubot::detail {

PhaseState WithCoordinates(PhaseState base, const Vec3& z) {
  base.x = z[0];
  base.u = z[1];
  base.v = z[2];
  return base;
}

double Residual(const Vec3& z, const PhaseState& image) {
  const double scale = std::max({1.0, std::abs(z[0]), std::abs(z[1]), std::abs(z[2])});
  return std::max({std::abs(image.x - z[0]), std::abs(image.u - z[1]), std::abs(image.v - z[2])}) /
         scale;
}

bool WithinScale(const RobotModel& robot, const Vec3& z) {
  const double velocity =
      kTau * (robot.forcing.MaxAbs() + robot.params.T0) / (robot.alpha * (1.0 - robot.alpha));
  const double bound = kMaxStateScale * std::max(1.0, velocity);
  return std::isfinite(z[0]) && std::abs(z[0]) <= bound && std::abs(z[1]) <= bound &&
         std::abs(z[2]) <= bound;
}

std::vector<int> FreeCoordinates(SimMode mode, double v) {
  switch (mode) {
    case SimMode::kRest:
      return {0, 1};
    case SimMode::kSlideForward:
    case SimMode::kSlideBackward:
      return {0, 1, 2};
    case SimMode::kOnRightWall:
    case SimMode::kOnLeftWall:
      return v != 0.0 ? std::vector<int>{2} : std::vector<int>{};
  }
  return {};
}

MotionOptions SimulationOf(const ShootingOptions& o) {
  MotionOptions mo;
  mo.chatter_velocity = o.chatter_velocity;
  mo.max_events_per_period = o.max_events_per_period;
  mo.reuse_cycles = o.reuse_cycles;
  return mo;
}

bool PeriodMap::Map(const PhaseState& z, int p, MapState* out, double* displacement,
                    Recorder* recorder) const {
  *out = {z, SimMode::kRest};
  return Advance(robot_, motion_, *out, p, displacement, recorder).status != SimStatus::kEventLimit;
}

bool PeriodMap::Shift(MapState& s, double periods, SimObserver* observer, bool sample) const {
  return Advance(robot_, motion_, s, periods, nullptr, observer, sample).status !=
         SimStatus::kEventLimit;
}

void DifferenceColumn(const MapState& plus, const MapState& minus, double displacement_plus,
                      double displacement_minus, const std::vector<int>& free, double h, int column,
                      Eigen::MatrixXd* J, Eigen::VectorXd* gradient) {
  const Vec3 a = ToVec(plus.z), b = ToVec(minus.z);
  for (std::size_t r = 0; r < free.size(); ++r) {
    const auto k = static_cast<std::size_t>(free[r]);
    (*J)(static_cast<Eigen::Index>(r), column) = (a[k] - b[k]) / (2.0 * h);
  }
  if (gradient != nullptr)
    (*gradient)(column) = (displacement_plus - displacement_minus) / (2.0 * h);
}

bool MapRun::Run(const PeriodMap& map, const PhaseState& z, int p) {
  recorder.Start(p, false, true);
  return map.Map(z, p, &image, &displacement, &recorder);
}

bool MapRun::SameEvents(const MapRun& o) const {
  return recorder.right == o.recorder.right && recorder.left == o.recorder.left &&
         recorder.event_marks == o.recorder.event_marks;
}

bool DifferenceAcrossEvents(const MapRun& plus, const MapRun& minus,
                            const std::function<bool(MapRun*)>& base, const std::vector<int>& free,
                            double h, int column, Eigen::MatrixXd* J, Eigen::VectorXd* gradient) {
  if (plus.SameEvents(minus)) {
    DifferenceColumn(plus.image, minus.image, plus.displacement, minus.displacement, free, h,
                     column, J, gradient);
    return true;
  }
  // The runs straddle a change of the events (an impact appears, a stick/slide segment
  // changes): the one-sided difference on the side whose run keeps the base's events.
  MapRun b;
  if (!base(&b)) return false;
  const bool plus_side = plus.SameEvents(b);
  if (!plus_side && !minus.SameEvents(b)) {  // both change: nothing smooth to take
    DifferenceColumn(plus.image, minus.image, plus.displacement, minus.displacement, free, h,
                     column, J, gradient);
    return true;
  }
  const MapRun& side = plus_side ? plus : minus;
  // (side - base) / (+-h): a central difference of half the step over [base, side] twice.
  DifferenceColumn(plus_side ? side.image : b.image, plus_side ? b.image : side.image,
                   plus_side ? side.displacement : b.displacement,
                   plus_side ? b.displacement : side.displacement, free, 0.5 * h, column, J,
                   gradient);
  return true;
}

bool CentralJacobian(const PeriodMap& map, const PhaseState& base, const Vec3& at, int p,
                     const std::vector<int>& free, double h, Eigen::MatrixXd* J,
                     Eigen::VectorXd* gradient) {
  const auto d = static_cast<Eigen::Index>(free.size());
  if (J->rows() != d || J->cols() < d) J->resize(d, d);
  if (gradient != nullptr && gradient->size() < d) gradient->resize(d);
  const auto run_base = [&](MapRun* r) { return r->Run(map, WithCoordinates(base, at), p); };
  for (Eigen::Index c = 0; c < d; ++c) {
    Vec3 plus = at, minus = at;
    const auto k = static_cast<std::size_t>(free[static_cast<std::size_t>(c)]);
    plus[k] += h;
    minus[k] -= h;
    MapRun ip, im;
    if (!ip.Run(map, WithCoordinates(base, plus), p) ||
        !im.Run(map, WithCoordinates(base, minus), p) ||
        !DifferenceAcrossEvents(ip, im, run_base, free, h, static_cast<int>(c), J, gradient)) {
      return false;
    }
  }
  return true;
}

std::vector<std::complex<double>> Multipliers(const Eigen::MatrixXd& J) {
  std::vector<std::complex<double>> out;
  if (J.rows() == 0) return out;
  const Eigen::EigenSolver<Eigen::MatrixXd> es(J, false);
  for (Eigen::Index i = 0; i < J.rows(); ++i) out.push_back(es.eigenvalues()(i));
  std::stable_sort(out.begin(), out.end(),
                   [](const std::complex<double>& a, const std::complex<double>& b) {
                     return std::abs(a) > std::abs(b);
                   });
  return out;
}

void SetMultipliers(std::vector<std::complex<double>> multipliers, PeriodicMotion* m) {
  m->multipliers = std::move(multipliers);
  if (m->multipliers.empty()) {
    m->spectral_radius = 0.0;
    m->distance_to_plus_one = m->distance_to_minus_one = m->distance_to_unit_circle = 1.0;
  } else {
    const std::complex<double> top = m->multipliers.front();
    m->spectral_radius = std::abs(top);
    m->distance_to_plus_one = std::abs(top - 1.0);
    m->distance_to_minus_one = std::abs(top + 1.0);
    m->distance_to_unit_circle = std::abs(std::abs(top) - 1.0);
  }
  // No verdict without a periodic motion: an unconverged state's multipliers say nothing.
  m->stable = m->status == ShootingStatus::kConverged && m->spectral_radius < 1.0;
}

bool MeasurePeriod(const PeriodMap& map, int p, Recorder& recorder, PeriodicMotion* m) {
  MapState end;
  double displacement = 0.0;
  recorder.Start(p, false, true);
  if (!map.Map(m->state, p, &end, &displacement, &recorder)) return false;
  m->impacts_right = m->impacts_left = 0;
  for (int k = 0; k < p; ++k) {
    m->impacts_right += recorder.right[static_cast<std::size_t>(k)];
    m->impacts_left += recorder.left[static_cast<std::size_t>(k)];
  }
  m->mean_velocity = displacement / (p * kTau);
  return true;
}

}  // namespace capsubot::detail
