#include "capsubot/continue/branch_switch.hpp"

#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "capsubot/attract/detail/period_map.hpp"

namespace capsubot {
namespace {

// Displacements of the parameter from the period doubling (relative to max(1, |lambda|)) and
// amplitudes along the eigenvector tried, nearest first: the period-2p motion lies at
// amplitude ~ sqrt(|offset|) times a factor of order one.
constexpr double kOffsets[] = {1e-5, 1e-4, 1e-3};
constexpr double kAmplitudeFactors[] = {1.0, 0.3, 3.0};
// A period-2p state this far from its image under P^p is not a period-p motion.
constexpr double kDistinct = 1e-7;
// The motion born at the period doubling lies within about sqrt(offset) of its state (the
// amplitude of the flip grows like the square root of the distance in the parameter): at most
// this many times sqrt(offset) away (the largest trial amplitude is 3 sqrt(offset)), with the
// doubling's impacts twice over, and a mean velocity within that many times sqrt(offset) of its
// own (relative). Anything else is another motion the shooting fell onto.
constexpr double kBornDistance = 10.0;

// The unit eigenvector of the multiplier nearest -1 of the p-th iterate at the period
// doubling, in (x, u, v) (zero in the coordinates fixed at the section); false at the work
// bound.
bool FlipDirection(const RobotModel& r, const SpecialPoint& pd, const ShootingOptions& so,
                   detail::Vec3* direction) {
  const detail::PeriodMap map(r, detail::SimulationOf(so));
  const std::vector<int> free = detail::FreeCoordinates(pd.motion.mode, pd.motion.state.v);
  const int d = static_cast<int>(free.size());
  Eigen::MatrixXd J;
  if (d == 0 || !detail::CentralJacobian(map, pd.motion.state, detail::ToVec(pd.motion.state),
                                         pd.motion.period, free, so.step, &J)) {
    return false;
  }
  const Eigen::EigenSolver<Eigen::MatrixXd> es(J.topLeftCorner(d, d));
  Eigen::Index k = 0;
  for (Eigen::Index i = 1; i < d; ++i) {
    if (std::abs(es.eigenvalues()(i) + 1.0) < std::abs(es.eigenvalues()(k) + 1.0)) k = i;
  }
  const Eigen::VectorXd v = es.eigenvectors().col(k).real().normalized();
  *direction = {0.0, 0.0, 0.0};
  for (int i = 0; i < d; ++i) (*direction)[static_cast<std::size_t>(free[i])] = v(i);
  return true;
}

// Whether the period-2p motion m at robot r is not a period-p motion: Newton with period p from
// its state does not stay there.
bool GenuinelyDoubled(const RobotModel& r, const PeriodicMotion& m, int p,
                      const ShootingOptions& so) {
  const PeriodicMotion half = ShootPeriodicMotion(r, m.state, p, so);
  if (half.status != ShootingStatus::kConverged) return true;
  const double moved =
      std::max({std::abs(half.state.x - m.state.x), std::abs(half.state.u - m.state.u),
                std::abs(half.state.v - m.state.v)});
  return moved > kDistinct;
}

// Whether the period-2p motion m, found at parameter offset `offset` (relative) from the period
// doubling pd, is the motion born there.
bool BornAt(const SpecialPoint& pd, const PeriodicMotion& m, double offset) {
  const PeriodicMotion& at = pd.motion;
  const double near = kBornDistance * std::sqrt(offset);
  const double moved = std::max({std::abs(m.state.x - at.state.x), std::abs(m.state.u - at.state.u),
                                 std::abs(m.state.v - at.state.v)});
  return m.impacts_right == 2 * at.impacts_right && m.impacts_left == 2 * at.impacts_left &&
         moved <= near &&
         std::abs(m.mean_velocity - at.mean_velocity) <= near * std::abs(at.mean_velocity);
}

}  // namespace

Branch SwitchAtPeriodDoubling(const RobotFamily& family, const SpecialPoint& pd,
                              ContinuationOptions options) {
  if (pd.type != SpecialPointType::kPeriodDoubling || !pd.located) {
    throw std::invalid_argument(fmt::format(
        "special point type = {} (located = {}) is invalid: expected a located period_doubling",
        SpecialPointTypeName(pd.type), pd.located));
  }
  options.start = pd.parameter;
  options.Validate();
  const int p = pd.motion.period;
  Branch branch;
  detail::Vec3 w;
  if (!FlipDirection(family(pd.parameter), pd, options.shooting, &w)) {
    branch.status = ContinuationStatus::kEventLimit;
    branch.message = "the Jacobian at the period doubling hit the work bound";
    return branch;
  }
  const double scale = std::max(1.0, std::abs(pd.parameter));
  for (double offset : kOffsets) {
    for (double side : {-1.0, 1.0}) {
      const double lambda = pd.parameter + side * offset * scale;
      if (lambda < options.from || lambda > options.to) continue;
      const RobotModel r = family(lambda);
      for (double factor : kAmplitudeFactors) {
        const double a = factor * std::sqrt(offset);
        PhaseState z = pd.motion.state;
        z.x += a * w[0];
        z.u += a * w[1];
        z.v += a * w[2];
        const PeriodicMotion m = ShootPeriodicMotion(r, z, 2 * p, options.shooting);
        if (m.status != ShootingStatus::kConverged || !BornAt(pd, m, offset) ||
            !GenuinelyDoubled(r, m, p, options.shooting)) {
          continue;
        }
        options.start = lambda;
        options.shooting.max_period = 2 * p;
        options.shooting.transient = 0;
        return ContinueBranch(family, m.state, options);
      }
    }
  }
  branch.status = ContinuationStatus::kNoMotion;
  branch.message = fmt::format(
      "no period-{} motion born at the period doubling at {:.12g} (within {} sqrt(offset) of its "
      "state, with its impacts twice over and its speed) at the offsets 1e-5 to 1e-3",
      2 * p, pd.parameter, kBornDistance);
  return branch;
}

}  // namespace capsubot
