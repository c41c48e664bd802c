// Neimark-Sacker points (a complex pair of multipliers through the unit circle). The capsule's
// own (docs/validation.md, "A Neimark-Sacker point"): located by the continuation, checked by
// Newton shooting on both sides and by the invariant curve of long runs beyond it. The search
// for special points on smooth maps of the plane whose bifurcations are known in closed form
// (the continuation's core takes any smooth map): the delayed logistic map, whose fixed point
// loses stability through a complex pair at a = 2; a real pair of multipliers with product 1 (a
// neutral saddle: no bifurcation, though the test function changes sign there); a multiplier
// through -1.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <functional>
#include <utility>
#include <vector>

#include "capsubot/attract/detail/period_map.hpp"
#include "capsubot/attract/periodic.hpp"
#include "capsubot/continue/continuation.hpp"
#include "capsubot/continue/parameter_branch.hpp"
#include "continue/branch_system.hpp"
#include "continue/special_points.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

using detail::Condition;
using detail::Node;
using detail::SmoothSystem;
using detail::Vec4;
using Point = std::array<double, 2>;
using Map = std::function<Point(const Point& z, double lambda)>;

// Central differences of a polynomial map with this step: error about the step squared.
constexpr double kStep = 1e-6;
// Newton's method stops below this residual (a few roundings of the map's values).
constexpr double kResidual = 1e-13;
constexpr int kMaxNewton = 50;
// The located parameter against the closed form: the continuation's location tolerance.
constexpr double kLocation = 1e-9;
// The multipliers at the located point: the location error times their slope (order 1), plus
// the differences' error.
constexpr double kMultiplierTol = 1e-7;

// The capsule robot with a Neimark-Sacker point, found by the search of docs/validation.md:
// A = 0.2, c = 0.03, phi0 = -2.9, T0 = 0.1, e = 0.95, alpha = 0.5. From rest at x0 = 1/6,
// psi = 2 pi/3 it settles on a two-wall motion (1 right + 2 left impacts a period, the shell
// sliding at the section: a map of dimension 3), which is followed in A.
const Forcing kNsForce = Forcing::Harmonic(0.2, 0.03, -2.9);
constexpr double kNsT0 = 0.1, kNsE = 0.95, kNsAlpha = 0.5;
// Newton shooting of the capsule's motion, on either side of the point, this far in A: the
// pair's modulus moves by about 30 per unit of A, so 0.015 off the circle.
constexpr double kSide = 5e-4;
// A Neimark-Sacker multiplier of the capsule within the continuation's confirmation tolerance
// of the circle (its location to 1e-10 in A moves it by 3e-9; the differences, 1e-10).
constexpr double kOnCircle = 1e-5;
// The invariant curve is followed this far above A_ns and 4 times as far: close enough that its
// radius grows like sqrt(A - A_ns) (measured: 3.12e-3 and 6.25e-3 from the fixed point, and
// 1.25e-2 at 16 times; beyond 5e-4 the curve reaches a change of the events and grows slower).
constexpr double kCurveOffset = 2e-5;
// Iterates of the stroboscopic map: a transient that settles on the curve (|mu| - 1 = 6e-4 at
// kCurveOffset: about 800 periods per e-fold of the distance to it), then a record.
constexpr int kCurveTransient = 5000;
constexpr int kCurveRecord = 2000;
// A periodic motion's iterates repeat to rounding (1e-12); points of the invariant curve p <= 64
// periods apart stay further apart than this.
constexpr double kNoRepeat = 1e-9;

Params NsParams() {
  Params p;
  p.T0 = kNsT0;
  p.e = kNsE;
  return p;
}

double Distance(const PhaseState& a, const PhaseState& b) {
  return std::hypot(a.x - b.x, a.u - b.u, a.v - b.v);
}

// The distances from the fixed point of `m` of the stroboscopic map's iterates over kCurveRecord
// periods after kCurveTransient, from the fixed point displaced by 1e-3 in x; *closes: the
// smallest distance between an iterate and the one p <= 64 periods later (0 for a motion of
// period p).
std::vector<double> Orbit(const Forcing& forcing, const PeriodicMotion& m, double* closes) {
  const RobotModel robot{forcing, NsParams(), kNsAlpha};
  const detail::PeriodMap map(robot, detail::SimulationOf(ShootingOptions{}));
  const PhaseState& fixed = m.state;
  detail::MapState s{fixed, m.mode};
  s.z.x += 1e-3;
  std::vector<PhaseState> record;
  for (int k = 0; k < kCurveTransient + kCurveRecord; ++k) {
    detail::MapState next;
    EXPECT_TRUE(map.Map(s.z, 1, &next));
    s = next;
    if (k >= kCurveTransient) record.push_back(s.z);
  }
  std::vector<double> d;
  *closes = HUGE_VAL;
  for (std::size_t k = 0; k < record.size(); ++k) {
    d.push_back(Distance(record[k], fixed));
    for (std::size_t p = 1; p <= 64 && k + p < record.size(); ++p) {
      *closes = std::min(*closes, Distance(record[k], record[k + p]));
    }
  }
  return d;
}

TEST(NeimarkSacker, TheCapsulesTwoWallMotionLosesStabilityThroughAComplexPair) {
  const Params params = NsParams();
  ContinuationOptions o;
  o.from = 0.18;
  o.to = 0.2;
  o.start = 0.2;
  const Branch b = ContinueBranch(NamedParameterFamily({kNsForce, params, kNsAlpha}, "A"),
                                  RestStart(1.0 / 6.0, kTau / 3.0), o);
  ASSERT_EQ(b.status, ContinuationStatus::kOk) << b.message;
  const SpecialPoint* ns = nullptr;
  for (const SpecialPoint& sp : b.special_points) {
    if (sp.type == SpecialPointType::kNeimarkSacker) {
      ASSERT_EQ(ns, nullptr) << "two Neimark-Sacker points";
      ns = &sp;
    }
  }
  ASSERT_NE(ns, nullptr) << b.Summary("A");
  ASSERT_TRUE(ns->located);
  EXPECT_EQ(ns->motion.period, 1);
  EXPECT_EQ(ns->motion.impacts_right, 1);
  EXPECT_EQ(ns->motion.impacts_left, 2);
  ASSERT_EQ(ns->motion.multipliers.size(), 3U);  // sliding at the section: x, u and v free
  EXPECT_TRUE(testing::Near(std::abs(ns->motion.multipliers[0]), 1.0, kOnCircle));
  EXPECT_GT(std::abs(ns->motion.multipliers[0].imag()), 0.5);
  // Newton shooting on both sides, from the point's state: the same motion, its complex pair
  // inside the circle below A_ns and outside above, by about the same amount.
  double radius[2] = {0.0, 0.0};
  PeriodicMotion fixed[2];
  for (int side = 0; side < 2; ++side) {
    const double A = ns->parameter + (side == 0 ? -kSide : kSide);
    const Forcing f = Forcing::Harmonic(A, 0.03, -2.9);
    const PeriodicMotion m =
        ShootPeriodicMotion({f, params, kNsAlpha}, ns->motion.state, 1, ShootingOptions{});
    ASSERT_EQ(m.status, ShootingStatus::kConverged) << "A = " << A;
    EXPECT_EQ(m.impacts_right, 1);
    EXPECT_EQ(m.impacts_left, 2);
    ASSERT_FALSE(m.multipliers.empty());
    EXPECT_GT(std::abs(m.multipliers[0].imag()), 0.5) << "A = " << A;
    radius[side] = m.spectral_radius;
    fixed[side] = m;
  }
  EXPECT_LT(radius[0], 1.0 - 0.005);
  EXPECT_GT(radius[1], 1.0 + 0.005);
  EXPECT_NEAR((radius[1] - 1.0) / (1.0 - radius[0]), 1.0, 0.2);  // a transversal crossing
  // Long runs: below, back to the fixed point; above, onto a closed invariant curve around it
  // that no iterate repeats (no period up to 64), of radius growing like sqrt(A - A_ns).
  // (Below by kSide: the fixed point is stable there, |mu| ~ 0.985.)
  double closes = 0.0;
  const std::vector<double> below =
      Orbit(Forcing::Harmonic(ns->parameter - kSide, 0.03, -2.9), fixed[0], &closes);
  ASSERT_FALSE(below.empty());
  EXPECT_LT(*std::max_element(below.begin(), below.end()), 1e-9);
  double mean_radius[2] = {0.0, 0.0};
  for (int k = 0; k < 2; ++k) {
    const double A = ns->parameter + (k == 0 ? 1.0 : 4.0) * kCurveOffset;
    const Forcing f = Forcing::Harmonic(A, 0.03, -2.9);
    const PeriodicMotion m =
        ShootPeriodicMotion({f, params, kNsAlpha}, fixed[1].state, 1, ShootingOptions{});
    ASSERT_EQ(m.status, ShootingStatus::kConverged) << "A = " << A;
    EXPECT_GT(m.spectral_radius, 1.0) << "A = " << A;
    const std::vector<double> d = Orbit(f, m, &closes);
    const double lo = *std::min_element(d.begin(), d.end());
    const double hi = *std::max_element(d.begin(), d.end());
    EXPECT_GT(lo, 1e-4) << "A = " << A;  // it does not come back to the fixed point
    EXPECT_LT(hi, 0.1) << "A = " << A;   // nor leave it
    EXPECT_GT(closes, kNoRepeat) << "A = " << A;
    for (const double x : d) mean_radius[k] += x / static_cast<double>(d.size());
  }
  // Four times as far from A_ns: the curve twice as large (a supercritical Neimark-Sacker
  // point; the next order of the normal form changes the ratio by about the offset's ratio to
  // 5e-4, where the growth visibly slows).
  EXPECT_NEAR(mean_radius[1] / mean_radius[0], 2.0, 0.1);
}

// A smooth map F(z; lambda) of the plane with a branch of fixed points, as the continuation
// sees a period map: free coordinates (x, u) of (x, u, v, lambda), the Jacobian [F_z, F_lambda]
// by central differences, no impacts and no events.
class PlaneMap : public SmoothSystem {
 public:
  explicit PlaneMap(Map f) : f_(std::move(f)) {}

  using SmoothSystem::Correct;
  Outcome Correct(const Condition& c, Eigen::MatrixXd, Vec4& y, int* iterations,
                  bool /*keep_jacobian*/) override {
    for (int it = 0; it < kMaxNewton; ++it) {
      const Point image = f_({y[0], y[1]}, y[3]);
      const double constraint = c.a[0] * y[0] + c.a[1] * y[1] + c.a[3] * y[3] - c.b;
      const Eigen::Vector3d r(image[0] - y[0], image[1] - y[1], constraint);
      if (r.lpNorm<Eigen::Infinity>() <= kResidual) {
        *iterations = it;
        return Outcome::kConverged;
      }
      Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
      A.topRows(2) = Jacobian(y, 1.0);
      A(0, 0) -= 1.0;
      A(1, 1) -= 1.0;
      A.row(2) << c.a[0], c.a[1], c.a[3];
      const Eigen::Vector3d dy = A.fullPivLu().solve(-r);
      y[0] += dy(0);
      y[1] += dy(1);
      y[3] += dy(2);
    }
    return Outcome::kFailed;
  }

  bool Complete(const Vec4& y, const Vec4& orient, Node* node) override {
    Measure(y, node);
    node->J = Jacobian(y, 1.0);
    Eigen::Matrix3d A;
    A.topRows(2) = node->J;
    A(0, 0) -= 1.0;
    A(1, 1) -= 1.0;
    A.row(2) << orient[0], orient[1], orient[3];
    const Eigen::Vector3d t = A.fullPivLu().solve(Eigen::Vector3d(0.0, 0.0, 1.0)).normalized();
    node->t = {t(0), t(1), 0.0, t(2)};
    const Eigen::Matrix2d Jz = node->J.leftCols(2);
    detail::SetMultipliers(detail::Multipliers(Jz), &node->motion);
    node->period_doubling = (Jz + Eigen::Matrix2d::Identity()).determinant();
    node->neimark_sacker = detail::NeimarkSackerFunction(node->motion.multipliers);
    node->speed = 1.0;  // no speed here: never an extremum
    node->grad = Eigen::VectorXd::Zero(3);
    return true;
  }

  bool Measure(const Vec4& y, Node* node) override {
    node->y = y;
    node->motion.status = ShootingStatus::kConverged;
    node->motion.period = 1;
    node->motion.dimension = 2;
    node->motion.state = {y[0], y[1], 0.0, 0.0};
    return true;
  }

  PeriodicMotion Reshoot(double lambda, const PhaseState& state, double factor) const override {
    PeriodicMotion m;
    Vec4 y = {state.x, state.u, 0.0, lambda};
    for (int it = 0; it < kMaxNewton; ++it) {
      const Point image = f_({y[0], y[1]}, lambda);
      const Eigen::Vector2d r(image[0] - y[0], image[1] - y[1]);
      if (r.lpNorm<Eigen::Infinity>() <= kResidual) {
        m.status = ShootingStatus::kConverged;
        break;
      }
      const Eigen::Matrix2d A = Jacobian(y, factor).leftCols(2) - Eigen::Matrix2d::Identity();
      const Eigen::Vector2d dz = A.fullPivLu().solve(-r);
      y[0] += dz(0);
      y[1] += dz(1);
    }
    m.period = 1;
    m.dimension = 2;
    m.state = {y[0], y[1], 0.0, 0.0};
    detail::SetMultipliers(detail::Multipliers(Jacobian(y, factor).leftCols(2)), &m);
    return m;
  }

  // The point of the branch at the parameter lambda, corrected from `guess` and completed.
  Node At(double lambda, const Point& guess) {
    Node n;
    Vec4 y = {guess[0], guess[1], 0.0, lambda};
    int iterations = 0;
    EXPECT_EQ(Correct(Condition::Fixed(3, lambda), {}, y, &iterations), Outcome::kConverged);
    Complete(y, {0.0, 0.0, 0.0, 1.0}, &n);
    return n;
  }

 private:
  Eigen::Matrix<double, 2, 3> Jacobian(const Vec4& y, double factor) const {
    Eigen::Matrix<double, 2, 3> J;
    const double h = kStep * factor;
    for (int k = 0; k < 3; ++k) {
      const std::size_t i = k < 2 ? static_cast<std::size_t>(k) : 3;
      Vec4 plus = y, minus = y;
      plus[i] += h;
      minus[i] -= h;
      const Point a = f_({plus[0], plus[1]}, plus[3]), b = f_({minus[0], minus[1]}, minus[3]);
      J(0, k) = (a[0] - b[0]) / (2.0 * h);
      J(1, k) = (a[1] - b[1]) / (2.0 * h);
    }
    return J;
  }

  Map f_;
};

// The delayed logistic map (x, y) -> (a x (1 - y), x): fixed point x = y = 1 - 1/a, Jacobian
// [[1, 1 - a], [1, 0]] there, so mu^2 - mu + (a - 1) = 0: a complex pair of modulus
// sqrt(a - 1) for a > 5/4, through the unit circle at a = 2 at mu = (1 +- i sqrt 3)/2.
Point DelayedLogistic(const Point& z, double a) { return {a * z[0] * (1.0 - z[1]), z[0]}; }
Point LogisticFixedPoint(double a) { return {1.0 - 1.0 / a, 1.0 - 1.0 / a}; }

TEST(NeimarkSacker, DelayedLogisticMapLosesStabilityThroughAComplexPairAtTwo) {
  PlaneMap map(DelayedLogistic);
  const Node a = map.At(1.9, LogisticFixedPoint(1.9));
  const Node b = map.At(2.1, LogisticFixedPoint(2.1));
  // Both sides by their own multipliers: inside the circle before, outside after, a complex pair.
  ASSERT_EQ(a.motion.multipliers.size(), 2U);
  EXPECT_TRUE(testing::Near(std::abs(a.motion.multipliers[0]), std::sqrt(0.9), kMultiplierTol));
  EXPECT_TRUE(testing::Near(std::abs(b.motion.multipliers[0]), std::sqrt(1.1), kMultiplierTol));
  EXPECT_GT(std::abs(b.motion.multipliers[0].imag()), 0.5);
  std::vector<SpecialPoint> found;
  detail::FindSpecialPoints(map, a, b, kLocation, &found);
  ASSERT_EQ(found.size(), 1U);
  const SpecialPoint& ns = found[0];
  EXPECT_EQ(ns.type, SpecialPointType::kNeimarkSacker);
  EXPECT_TRUE(ns.located);
  EXPECT_TRUE(testing::Near(ns.parameter, 2.0, kLocation));
  ASSERT_EQ(ns.motion.multipliers.size(), 2U);
  for (const std::complex<double>& mu : ns.motion.multipliers) {
    EXPECT_TRUE(testing::Near(std::abs(mu), 1.0, kMultiplierTol));
    EXPECT_TRUE(testing::Near(mu.real(), 0.5, kMultiplierTol));
    EXPECT_TRUE(testing::Near(std::abs(mu.imag()), std::sqrt(3.0) / 2.0, kMultiplierTol));
  }
  // Away from a = 2 the pair stays inside (or outside) the circle: nothing to find.
  std::vector<SpecialPoint> none;
  detail::FindSpecialPoints(map, map.At(1.5, LogisticFixedPoint(1.5)), a, kLocation, &none);
  detail::FindSpecialPoints(map, b, map.At(2.4, LogisticFixedPoint(2.4)), kLocation, &none);
  EXPECT_TRUE(none.empty());
}

// (x, y) -> (2 x + x^2, lambda y / 2 + y^2): the fixed point 0 for every lambda, with the real
// multipliers 2 and lambda/2, whose product crosses 1 at lambda = 1. The Neimark-Sacker test
// function changes sign there, but no complex pair crosses the circle: not a bifurcation.
TEST(NeimarkSacker, ARealPairOfProductOneIsNoNeimarkSackerPoint) {
  PlaneMap map([](const Point& z, double lambda) -> Point {
    return {2.0 * z[0] + z[0] * z[0], 0.5 * lambda * z[1] + z[1] * z[1]};
  });
  const Node a = map.At(0.8, {0.0, 0.0});
  const Node b = map.At(1.2, {0.0, 0.0});
  ASSERT_LT(a.neimark_sacker * b.neimark_sacker, 0.0);  // the test function changes sign
  std::vector<SpecialPoint> found;
  detail::FindSpecialPoints(map, a, b, kLocation, &found);
  EXPECT_TRUE(found.empty());
}

// (x, y) -> (-lambda x + x^2, y/2): a multiplier -lambda through -1 at lambda = 1, a period
// doubling (the same search, its other test function).
TEST(NeimarkSacker, AMultiplierThroughMinusOneIsAPeriodDoublingNotANeimarkSackerPoint) {
  PlaneMap map([](const Point& z, double lambda) -> Point {
    return {-lambda * z[0] + z[0] * z[0], 0.5 * z[1]};
  });
  std::vector<SpecialPoint> found;
  detail::FindSpecialPoints(map, map.At(0.9, {0.0, 0.0}), map.At(1.1, {0.0, 0.0}), kLocation,
                            &found);
  ASSERT_EQ(found.size(), 1U);
  EXPECT_EQ(found[0].type, SpecialPointType::kPeriodDoubling);
  EXPECT_TRUE(testing::Near(found[0].parameter, 1.0, kLocation));
}

}  // namespace
}  // namespace capsubot
