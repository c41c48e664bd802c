// The extended system of a two-parameter curve of special points: defining conditions,
// Jacobian, corrector and curve points (docs/continuation.md, "Two-parameter curves").

#include "continue/curve_system.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "continue/walk.hpp"

namespace capsubot::detail {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// The determinants and the speed derivative are built from central differences of step 1e-6,
// whose rounding is about 1e-10: their own differences take this step (relative to
// max(1, |y|) in the parameters), where that rounding costs 1e-6 of the slope and the
// truncation 1e-8.
constexpr double kConditionStep = 1e-4;
// A determinant or speed derivative is zero to this: a few times that rounding (at the fold of
// docs/continuation.md's example the determinant moves by 4e-10 between states 1e-11 apart).
constexpr double kConditionTolerance = 1e-9;
// A grazing is followed this far inside the wall (in x, units of L): the differences of the
// map (step 1e-6, taken on the side away from the wall) then never reach it, even where the
// condition's gradient along a coordinate vanishes and only its curvature (1e-12) moves it.
// The condition holds to kGrazingTolerance around -kGrazingMargin.
constexpr double kGrazingMargin = 1e-9;
constexpr double kGrazingTolerance = 1e-12;
// An iterate whose flight comes within half the margin of the wall is pulled back along the
// condition's gradient, at most this many times.
constexpr int kPullBacks = 4;

}  // namespace

CurveSystem::CurveSystem(const RobotSurface& surface, const CurveOptions& options,
                         SpecialPointType type, int period, Section section)
    : surface_(surface),
      options_(options),
      type_(type),
      motion_(SimulationOf(options.continuation.shooting)),
      p_(period),
      section_(std::move(section)) {}

bool CurveSystem::Approach(const Vec5& y) {
  return FindWallApproach(Robot(y), State(y), p_, motion_, &approach_);
}

std::size_t CurveSystem::Coordinate(int r) const {
  const int d = dimension();
  return r < d ? static_cast<std::size_t>(section_.free[static_cast<std::size_t>(r)])
               : static_cast<std::size_t>(3 + r - d);
}

double CurveSystem::Step(int r, const Vec5& y, double base) const {
  return r < dimension() ? base : base * std::max(1.0, std::abs(y[Coordinate(r)]));
}

bool CurveSystem::InBox(const Vec5& y) const {
  const ContinuationOptions& c = options_.continuation;
  return y[3] >= c.from && y[3] <= c.to && y[4] >= options_.from2 && y[4] <= options_.to2;
}

// 0: a central difference; +1 or -1: one-sided, of the same order, towards that side. A
// parameter at an end of its range is differenced inwards (beyond it the robots may not
// exist); with `away` (the grazing condition's gradient) every unknown is differenced to the
// side where the flight moves away from the wall.
int CurveSystem::Side(int r, const Vec5& y, double h, const Eigen::RowVectorXd* away) const {
  if (r >= dimension()) {
    const ContinuationOptions& c = options_.continuation;
    const bool first = r == dimension();
    const double lo = first ? c.from : options_.from2, hi = first ? c.to : options_.to2;
    const double v = y[Coordinate(r)];
    if (v - h < lo && v + 2.0 * h <= hi) return 1;
    if (v + h > hi && v - 2.0 * h >= lo) return -1;
  }
  if (away != nullptr) return (*away)(r) > 0.0 ? -1 : 1;
  return 0;
}

bool CurveSystem::Image(const Vec5& y, MapState* out, double* displacement) {
  const RobotModel r = Robot(y);
  const PeriodMap map(r, motion_);
  return map.Map(State(y), p_, out, displacement);
}

// The first `columns` columns of [P_z, P_lambda, P_mu] at y into *P (d x columns), and the
// same derivatives of the displacement over p periods into *grad.
bool CurveSystem::MapColumns(const Vec5& y, int columns, const Eigen::RowVectorXd* away,
                             Eigen::MatrixXd* P, Eigen::VectorXd* grad) {
  const int d = dimension();
  P->resize(d, columns);
  grad->resize(columns);
  MapState at;
  double d_at = 0.0;
  bool have_at = false;
  for (int c = 0; c < columns; ++c) {
    const double h = Step(c, y, options_.continuation.shooting.step);
    const int side = Side(c, y, h, away);
    const std::size_t k = Coordinate(c);
    Vec5 y1 = y, y2 = y;
    y1[k] += side == 0 ? h : side * h;
    y2[k] += side == 0 ? -h : 2.0 * side * h;
    MapState i1, i2;
    double d1 = 0.0, d2 = 0.0;
    if (!Image(y1, &i1, &d1) || !Image(y2, &i2, &d2)) return false;
    if (side == 0) {
      DifferenceColumn(i1, i2, d1, d2, section_.free, h, c, P, grad);
      continue;
    }
    if (!have_at && !Image(y, &at, &d_at)) return false;
    have_at = true;
    const Vec3 a0 = ToVec(at.z), a1 = ToVec(i1.z), a2 = ToVec(i2.z);
    for (int r = 0; r < d; ++r) {
      const std::size_t i = Coordinate(r);
      (*P)(r, c) = side * (-3.0 * a0[i] + 4.0 * a1[i] - a2[i]) / (2.0 * h);
    }
    (*grad)(c) = side * (-3.0 * d_at + 4.0 * d1 - d2) / (2.0 * h);
  }
  return true;
}

// The defining condition from the map's derivatives at a point (not the grazing's).
bool CurveSystem::ConditionFrom(const Eigen::MatrixXd& P, const Eigen::VectorXd& grad,
                                double* g) const {
  const int d = dimension();
  const Eigen::MatrixXd Pz = P.leftCols(d), I = Eigen::MatrixXd::Identity(d, d);
  if (type_ == SpecialPointType::kFold) {
    *g = (Pz - I).determinant();
  } else if (type_ == SpecialPointType::kPeriodDoubling) {
    *g = (Pz + I).determinant();
  } else {  // the speed extremum: d(mean velocity)/d lambda along the branch at fixed mu
    const Eigen::VectorXd w = (Pz - I).fullPivLu().solve(-P.col(d));
    *g = (grad.head(d).dot(w) + grad(d)) / (p_ * kTau);
  }
  return std::isfinite(*g);
}

bool CurveSystem::Condition(const Vec5& y, double* g) {
  if (type_ == SpecialPointType::kGrazing) {
    return GrazingCondition(Robot(y), State(y), approach_, motion_, g);
  }
  const int columns = dimension() + (type_ == SpecialPointType::kSpeedExtremum ? 1 : 0);
  Eigen::MatrixXd P;
  Eigen::VectorXd grad;
  return MapColumns(y, columns, nullptr, &P, &grad) && ConditionFrom(P, grad, g);
}

// The gradient of the condition over the unknowns by differences of the condition itself.
bool CurveSystem::ConditionRow(const Vec5& y, Eigen::RowVectorXd* row) {
  const int n = dimension() + 2;
  const double base =
      type_ == SpecialPointType::kGrazing ? options_.continuation.shooting.step : kConditionStep;
  row->resize(n);
  double g_at = 0.0;
  bool have_at = false;
  for (int c = 0; c < n; ++c) {
    const double h = Step(c, y, base);
    const int side = Side(c, y, h, nullptr);
    const std::size_t k = Coordinate(c);
    Vec5 y1 = y, y2 = y;
    y1[k] += side == 0 ? h : side * h;
    y2[k] += side == 0 ? -h : 2.0 * side * h;
    double g1 = 0.0, g2 = 0.0;
    if (!Condition(y1, &g1) || !Condition(y2, &g2)) return false;
    if (side == 0) {
      (*row)(c) = (g1 - g2) / (2.0 * h);
      continue;
    }
    if (!have_at && !Condition(y, &g_at)) return false;
    have_at = true;
    (*row)(c) = side * (-3.0 * g_at + 4.0 * g1 - g2) / (2.0 * h);
  }
  return true;
}

bool CurveSystem::Jacobian(const Vec5& y, Eigen::MatrixXd* J, double* g) {
  const int d = dimension();
  Eigen::MatrixXd P;
  Eigen::VectorXd grad;
  Eigen::RowVectorXd row;
  if (type_ == SpecialPointType::kGrazing) {
    if (!ConditionRow(y, &row) || !Condition(y, g) || !MapColumns(y, d + 2, &row, &P, &grad)) {
      return false;
    }
  } else if (!MapColumns(y, d + 2, nullptr, &P, &grad) || !ConditionFrom(P, grad, g) ||
             !ConditionRow(y, &row)) {
    return false;
  }
  J->resize(d + 1, d + 2);
  J->topRows(d) = P;
  J->row(d) = row;
  return true;
}

// Moves y along the condition's gradient (the last row of J) until its flight turns back at
// least half the margin before the wall.
bool CurveSystem::PullBack(const Eigen::MatrixXd& J, Vec5& y) {
  const int d = dimension();
  const Eigen::RowVectorXd row = J.row(d);
  const double norm2 = row.squaredNorm();
  for (int k = 0; k <= kPullBacks; ++k) {
    double g = 0.0;
    if (!Condition(y, &g)) return false;
    if (g <= -0.5 * kGrazingMargin) return true;
    if (k == kPullBacks || !(norm2 > 0.0)) break;
    const double shift = (g + kGrazingMargin) / norm2;
    for (int c = 0; c < d + 2; ++c) y[Coordinate(c)] -= shift * row(c);
  }
  return false;
}

CurveSystem::Outcome CurveSystem::Correct(const CurveClosure& closure, Eigen::MatrixXd J, Vec5& y,
                                          int* iterations) {
  const int d = dimension(), n = d + 2;
  const bool grazing = type_ == SpecialPointType::kGrazing;
  const double tol = options_.continuation.residual_tolerance;
  const double target = grazing ? -kGrazingMargin : 0.0;
  const double gtol = grazing ? kGrazingTolerance : kConditionTolerance;
  double previous = kInf, update = kInf;
  bool fresh = false;  // J was computed at the current iterate
  for (int it = 0; it <= options_.continuation.max_corrector_iterations; ++it) {
    if (!InBox(y)) return Outcome::kOutOfRange;
    if (!(y[0] >= 0.0 && y[0] <= 1.0) || !std::isfinite(y[1]) || !std::isfinite(y[2])) {
      return Outcome::kFailed;
    }
    if (grazing && !PullBack(J, y)) return Outcome::kFailed;
    MapState image;
    double g = 0.0;
    if (!InBox(y)) return Outcome::kOutOfRange;
    if (!Image(y, &image) || image.mode != section_.mode || !Condition(y, &g)) {
      return Outcome::kFailed;
    }
    const double res = Residual({y[0], y[1], y[2]}, image.z);
    const double gres = std::abs(g - target);
    double constraint = -closure.b;
    for (std::size_t i = 0; i < 5; ++i) constraint += closure.a[i] * y[i];
    const bool rounding =
        update <= kUpdateRounding && res <= kRoundingFactor * tol && gres <= kRoundingFactor * gtol;
    if (((res <= tol && gres <= gtol) || rounding) &&
        std::abs(constraint) <= tol * (1.0 + std::abs(closure.b))) {
      *iterations = it;
      return Outcome::kConverged;
    }
    if (it == options_.continuation.max_corrector_iterations) break;
    const double merit = std::max(res / tol, gres / gtol);
    if (it > 0 && merit > kChordRate * previous) {
      double unused = 0.0;
      if (fresh || !Jacobian(y, &J, &unused)) return Outcome::kFailed;  // diverging when fresh
      fresh = true;
    } else {
      fresh = false;
    }
    previous = merit;
    Eigen::MatrixXd A = J;
    A.conservativeResize(n, n);
    Eigen::VectorXd rhs(n);
    const Vec3 image_z = ToVec(image.z);
    for (int r = 0; r < d; ++r) {
      A(r, r) -= 1.0;
      rhs(r) = y[Coordinate(r)] - image_z[Coordinate(r)];
    }
    rhs(d) = target - g;
    for (int c = 0; c < n; ++c) A(d + 1, c) = closure.a[Coordinate(c)];
    rhs(d + 1) = -constraint;
    const Eigen::VectorXd dy = A.fullPivLu().solve(rhs);
    if (!dy.allFinite()) return Outcome::kFailed;
    for (int c = 0; c < n; ++c) y[Coordinate(c)] += dy(c);
    update = dy.lpNorm<Eigen::Infinity>();
  }
  return Outcome::kFailed;
}

bool CurveSystem::Complete(const Vec5& y, const Vec5& orient, CurveNode* node) {
  const int d = dimension(), n = d + 2;
  node->y = y;
  if (!Jacobian(y, &node->J, &node->condition)) return false;
  const RobotModel r = Robot(y);
  const PeriodMap map(r, motion_);
  PeriodicMotion& m = node->motion;
  m.status = ShootingStatus::kConverged;
  m.period = p_;
  m.state = State(y);
  m.mode = section_.mode;
  m.dimension = d;
  MapState image;
  if (!MeasurePeriod(map, p_, recorder_, &m)) return false;
  node->marks = recorder_.event_marks;
  node->event_phases = recorder_.event_phases;
  if (!Image(y, &image)) return false;
  m.residual = Residual({y[0], y[1], y[2]}, image.z);
  SetMultipliers(Multipliers(node->J.topLeftCorner(d, d)), &m);
  // The tangent: the null vector of the d + 1 rows of the extended system's Jacobian with
  // orient . t = 1, normalised.
  Eigen::MatrixXd A = node->J;
  A.conservativeResize(n, n);
  for (int r = 0; r < d; ++r) A(r, r) -= 1.0;
  for (int c = 0; c < n; ++c) A(d + 1, c) = orient[Coordinate(c)];
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
  rhs(d + 1) = 1.0;
  Eigen::VectorXd t = A.fullPivLu().solve(rhs);
  if (!t.allFinite() || t.norm() == 0.0) return false;
  t.normalize();
  node->t = {};
  for (int c = 0; c < n; ++c) node->t[Coordinate(c)] = t(c);
  return true;
}

bool CurveSystem::Replace(CurveNode* node) {
  const bool grazing = type_ == SpecialPointType::kGrazing;
  if (!EventNearSection(node->event_phases)) return !grazing || Approach(node->y);
  std::vector<double> phases = node->event_phases;
  const double shift = SectionShift(phases) / kTau;
  const RobotModel r = Robot(node->y);
  const PeriodMap map(r, motion_);
  MapState at{State(node->y), section_.mode};
  if (!map.Shift(at, shift)) return false;
  section_ = {at.z.psi, at.mode, FreeCoordinates(at.mode, at.z.v)};
  const Vec5 y = {at.z.x, at.z.u, at.z.v, node->y[3], node->y[4]};
  if (grazing && !Approach(y)) return false;
  // The state part of the tangent does not survive the move; its parameter part does.
  return Complete(y, {0.0, 0.0, 0.0, node->t[3], node->t[4]}, node);
}

}  // namespace capsubot::detail
