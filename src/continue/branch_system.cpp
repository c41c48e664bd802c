// The extended system of the continuation: corrector, tangent and branch points
// (docs/continuation.md).

#include "continue/branch_system.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "capsubot/numerics/not_computed.hpp"
#include "continue/walk.hpp"

namespace capsubot::detail {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// The section is moved when an event lies closer to it than this fraction of half the largest
// gap between events: the map is smooth only while no event crosses the section.
constexpr double kSectionFraction = 0.25;
// Iterations of a correction with a fixed Jacobian (each cuts the residual by the Jacobian's
// relative error, well below 1/2 next to the point it was computed at).
constexpr int kChordIterations = 40;

Vec4 Zero() { return {0.0, 0.0, 0.0, 0.0}; }

}  // namespace

BranchSystem::BranchSystem(const RobotFamily& family, const ContinuationOptions& options,
                           int period, Section section)
    : family_(family),
      options_(options),
      motion_(SimulationOf(options.shooting)),
      p_(period),
      section_(std::move(section)) {}

double BranchSystem::LambdaStep(double lambda) const {
  return options_.shooting.step * std::max(1.0, std::abs(lambda));
}

bool BranchSystem::Image(const Vec4& y, MapState* out, double* displacement) {
  const RobotModel r = Robot(y[3]);
  const PeriodMap map(r, motion_);
  return map.Map(State(y), p_, out, displacement);
}

bool BranchSystem::Run(const Vec4& y, MapRun* run) {
  const RobotModel r = Robot(y[3]);
  return run->Run(PeriodMap(r, motion_), State(y), p_);
}

bool BranchSystem::Jacobian(const Vec4& y, Eigen::MatrixXd* J, Eigen::VectorXd* grad,
                            double step_factor) {
  const int d = dimension();
  J->resize(d, d + 1);
  if (grad != nullptr) grad->resize(d + 1);
  {
    const RobotModel r = Robot(y[3]);
    const PeriodMap map(r, motion_);
    if (!CentralJacobian(map, State(y), {y[0], y[1], y[2]}, p_, section_.free,
                         step_factor * options_.shooting.step, J, grad)) {
      return false;
    }
  }
  // The parameter's column: the same central difference over two neighbouring robots, or the
  // one-sided difference of the same order at an end of the range (beyond it the robots may
  // not exist).
  const double h = step_factor * LambdaStep(y[3]);
  const bool central = y[3] - h >= options_.from && y[3] + h <= options_.to;
  const double toward = y[3] + h > options_.to ? -1.0 : 1.0;
  Vec4 y1 = y, y2 = y;
  y1[3] = central ? y[3] + h : y[3] + toward * h;
  y2[3] = central ? y[3] - h : y[3] + 2.0 * toward * h;
  if (central) {
    MapRun r1, r2;
    return Run(y1, &r1) && Run(y2, &r2) &&
           DifferenceAcrossEvents(
               r1, r2, [&](MapRun* r0) { return Run(y, r0); }, section_.free, h, d, J, grad);
  }
  MapState i1, i2, i0;
  double d1 = 0.0, d2 = 0.0, d0 = 0.0;
  if (!Image(y1, &i1, &d1) || !Image(y2, &i2, &d2) || !Image(y, &i0, &d0)) return false;
  const Vec3 a0 = ToVec(i0.z), a1 = ToVec(i1.z), a2 = ToVec(i2.z);
  for (int r = 0; r < d; ++r) {
    const auto k = static_cast<std::size_t>(section_.free[static_cast<std::size_t>(r)]);
    (*J)(r, d) = toward * (-3.0 * a0[k] + 4.0 * a1[k] - a2[k]) / (2.0 * h);
  }
  if (grad != nullptr) (*grad)(d) = toward * (-3.0 * d0 + 4.0 * d1 - d2) / (2.0 * h);
  return true;
}

BranchSystem::Outcome BranchSystem::Correct(const Condition& condition, Eigen::MatrixXd J, Vec4& y,
                                            int* iterations, bool keep_jacobian) {
  const int d = dimension();
  const std::vector<int>& free = section_.free;
  const int max_iterations = keep_jacobian ? kChordIterations : options_.max_corrector_iterations;
  double previous = kInf, update = kInf;
  bool fresh = false;  // J was computed at the current iterate
  for (int it = 0; it <= max_iterations; ++it) {
    if (!(y[3] >= options_.from && y[3] <= options_.to)) return Outcome::kOutOfRange;
    if (!(y[0] >= 0.0 && y[0] <= 1.0) || !std::isfinite(y[1]) || !std::isfinite(y[2])) {
      return Outcome::kFailed;
    }
    const RobotModel robot = Robot(y[3]);
    if (!WithinScale(robot, {y[0], y[1], y[2]})) {
      return Outcome::kFailed;
    }
    MapState image;
    if (!Image(y, &image) || image.mode != section_.mode) return Outcome::kFailed;
    const double res = Residual({y[0], y[1], y[2]}, image.z);
    double constraint = -condition.b;
    for (std::size_t i = 0; i < 4; ++i) constraint += condition.a[i] * y[i];
    // Converged: the residual is below the tolerance, or it has reached the rounding of the
    // simulated map (a few times the tolerance where the motion is sensitive) and Newton's
    // update has shrunk to the last digits of the state.
    const bool rounding =
        update <= kUpdateRounding && res <= kRoundingFactor * options_.residual_tolerance;
    if ((res <= options_.residual_tolerance || rounding) &&
        std::abs(constraint) <= options_.residual_tolerance * (1.0 + std::abs(condition.b))) {
      *iterations = it;
      return Outcome::kConverged;
    }
    if (it == max_iterations) break;
    if (keep_jacobian) {
      if (!(res < previous)) return Outcome::kFailed;  // the chord iterations do not contract
    } else if (it > 0 && res > kChordRate * previous) {
      if (fresh || !Jacobian(y, &J, nullptr)) return Outcome::kFailed;  // diverging when fresh
      fresh = true;
    } else {
      fresh = false;
    }
    previous = res;
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(d + 1, d + 1);
    Eigen::VectorXd rhs(d + 1);
    const Vec3 z = {y[0], y[1], y[2]}, image_z = ToVec(image.z);
    for (int r = 0; r < d; ++r) {
      const auto k = static_cast<std::size_t>(free[static_cast<std::size_t>(r)]);
      for (int c = 0; c <= d; ++c) A(r, c) = J(r, c) - (r == c ? 1.0 : 0.0);
      rhs(r) = z[k] - image_z[k];
      A(d, r) = condition.a[k];
    }
    A(d, d) = condition.a[3];
    rhs(d) = -constraint;
    const Eigen::VectorXd dy = A.fullPivLu().solve(rhs);
    if (!dy.allFinite()) return Outcome::kFailed;
    for (int r = 0; r < d; ++r)
      y[static_cast<std::size_t>(free[static_cast<std::size_t>(r)])] += dy(r);
    y[3] += dy(d);
    update = dy.lpNorm<Eigen::Infinity>();
  }
  return Outcome::kFailed;
}

bool BranchSystem::Measure(const Vec4& y, Node* node) {
  const RobotModel r = Robot(y[3]);
  const PeriodMap map(r, motion_);
  node->y = y;
  PeriodicMotion& m = node->motion;
  m.status = ShootingStatus::kConverged;
  m.period = p_;
  m.state = State(y);
  m.mode = section_.mode;
  m.dimension = dimension();
  MapState image;
  double displacement = 0.0;
  recorder_.Start(p_, false, true);
  if (!map.Map(m.state, p_, &image, &displacement, &recorder_)) return false;
  m.residual = Residual({y[0], y[1], y[2]}, image.z);
  m.impacts_right = m.impacts_left = 0;
  for (int k = 0; k < p_; ++k) {
    m.impacts_right += recorder_.right[static_cast<std::size_t>(k)];
    m.impacts_left += recorder_.left[static_cast<std::size_t>(k)];
  }
  m.mean_velocity = displacement / (p_ * kTau);
  node->half = Zero();
  if (p_ % 2 == 0) {
    MapState h;
    if (!map.Map(m.state, p_ / 2, &h)) return false;
    node->half = {h.z.x - y[0], h.z.u - y[1], h.z.v - y[2], 0.0};
  }
  node->marks = recorder_.event_marks;
  node->event_phases = recorder_.event_phases;
  return true;
}

PeriodicMotion BranchSystem::Reshoot(double lambda, const PhaseState& state,
                                     double step_factor) const {
  const RobotModel robot = Robot(lambda);
  ShootingOptions shooting = options_.shooting;
  shooting.step *= step_factor;
  return ShootPeriodicMotion(robot, state, p_, shooting);
}

bool BranchSystem::Tangent(const Eigen::MatrixXd& J, const Vec4& orient, Vec4* tangent) const {
  const int d = dimension();
  // [P_z - I, P_lambda] t = 0 with orient . t = 1, then normalised.
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(d + 1, d + 1);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(d + 1);
  for (int r = 0; r < d; ++r) {
    for (int c = 0; c <= d; ++c) A(r, c) = J(r, c) - (r == c ? 1.0 : 0.0);
    A(d, r) = orient[static_cast<std::size_t>(section_.free[static_cast<std::size_t>(r)])];
  }
  A(d, d) = orient[3];
  rhs(d) = 1.0;
  Eigen::VectorXd t = A.fullPivLu().solve(rhs);
  if (!t.allFinite() || t.norm() == 0.0) return false;
  t.normalize();
  *tangent = Zero();
  for (int r = 0; r < d; ++r)
    (*tangent)[static_cast<std::size_t>(section_.free[static_cast<std::size_t>(r)])] = t(r);
  (*tangent)[3] = t(d);
  return true;
}

double BranchSystem::Speed(const Eigen::VectorXd& grad, const Vec4& t) const {
  double s = grad(dimension()) * t[3];
  for (int r = 0; r < dimension(); ++r) {
    s += grad(r) * t[static_cast<std::size_t>(section_.free[static_cast<std::size_t>(r)])];
  }
  return s / (p_ * kTau);
}

double BranchSystem::SpeedWithStep(const Node& node, double step_factor) {
  Eigen::MatrixXd J;
  Eigen::VectorXd grad;
  Vec4 t;
  if (!Jacobian(node.y, &J, &grad, step_factor) || !Tangent(J, node.t, &t)) {
    return kNaN;
  }
  return Speed(grad, t);
}

bool BranchSystem::Complete(const Vec4& y, const Vec4& orient, Node* node) {
  const int d = dimension();
  node->y = y;
  if (!Jacobian(y, &node->J, &node->grad) || !Measure(y, node) ||
      !Tangent(node->J, orient, &node->t)) {
    return false;
  }
  // Multipliers and the test functions.
  const Eigen::MatrixXd Jz = node->J.leftCols(d);
  SetMultipliers(Multipliers(Jz), &node->motion);
  node->period_doubling = d > 0 ? (Jz + Eigen::MatrixXd::Identity(d, d)).determinant() : 1.0;
  node->neimark_sacker = NeimarkSackerFunction(node->motion.multipliers);
  node->speed = Speed(node->grad, node->t);
  return true;
}

double NeimarkSackerFunction(const std::vector<std::complex<double>>& mu) {
  double ns = 1.0;
  for (std::size_t i = 0; i < mu.size(); ++i) {
    for (std::size_t j = i + 1; j < mu.size(); ++j) ns *= (mu[i] * mu[j] - 1.0).real();
  }
  return ns;
}

bool EventNearSection(std::vector<double> phases) {
  if (phases.empty()) return false;
  std::sort(phases.begin(), phases.end());
  double gap = phases.front() + kTau - phases.back();
  const double nearest = std::min(phases.front(), kTau - phases.back());
  for (std::size_t i = 1; i < phases.size(); ++i) gap = std::max(gap, phases[i] - phases[i - 1]);
  return nearest < kSectionFraction * 0.5 * gap;
}

bool BranchSystem::Replace(Node* node) {
  if (!EventNearSection(node->event_phases)) return true;
  std::vector<double> phases = node->event_phases;
  const double shift = SectionShift(phases) / kTau;
  // The node and two neighbours along its tangent, carried to the new section by the flow.
  const double h = options_.shooting.step;
  const auto carry = [&](const Vec4& y, MapState* s) {
    const RobotModel r = Robot(y[3]);
    const PeriodMap map(r, motion_);
    *s = {State(y), section_.mode};
    return map.Shift(*s, shift);
  };
  Vec4 plus = node->y, minus = node->y;
  for (std::size_t i = 0; i < 4; ++i) {
    plus[i] += h * node->t[i];
    minus[i] -= h * node->t[i];
  }
  MapState at, ap, am;
  if (!carry(node->y, &at) || !carry(plus, &ap) || !carry(minus, &am)) return false;
  section_ = {at.z.psi, at.mode, FreeCoordinates(at.mode, at.z.v)};
  Vec4 orient = {(ap.z.x - am.z.x) / (2.0 * h), (ap.z.u - am.z.u) / (2.0 * h),
                 (ap.z.v - am.z.v) / (2.0 * h), node->t[3]};
  for (int i = 0; i < 3; ++i) {
    if (std::find(section_.free.begin(), section_.free.end(), i) == section_.free.end()) {
      orient[static_cast<std::size_t>(i)] = 0.0;
    }
  }
  return Complete({at.z.x, at.z.u, at.z.v, node->y[3]}, orient, node);
}

}  // namespace capsubot::detail
