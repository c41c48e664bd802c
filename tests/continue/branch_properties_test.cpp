// Properties of the continuation over random robots (docs/continuation.md): every branch point
// is a periodic motion of its period; every fold, period doubling and Neimark-Sacker point has
// its critical multiplier and its type holds on both sides (a fold's neighbours on one side of
// it, a multiplier through -1 or the unit circle between shootings on either side); every
// grazing ends its motion on one side with an accuracy that bounds the distance to the end
// found by an independent bisection; and a branch switched at a period doubling starts on the
// motion born there. References: Newton shooting from each point's state (periodic.hpp), the
// period map, and a bisection on the motion's existence written here.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "capsubot/attract/detail/period_map.hpp"
#include "capsubot/attract/periodic.hpp"
#include "capsubot/continue/branch_switch.hpp"
#include "capsubot/continue/continuation.hpp"
#include "capsubot/continue/parameter_branch.hpp"
#include "capsubot/orbit/validity.hpp"

namespace capsubot {
namespace {

constexpr unsigned kSeed = 20261206;
// Robots drawn until this many have a valid one-impact orbit, at most kMaxDraws draws (about a
// third of the draws are valid).
constexpr int kRobots = 4;
constexpr int kMaxDraws = 400;
// The branch's corrector stops at a residual of 1e-12 relative; Newton shooting from a point's
// state moves it by that residual times the inverse of (J - I), far below this.
constexpr double kShootingTol = 1e-8;
// Folds, period doublings and Neimark-Sacker points are kept only with a multiplier this close
// to +1, -1 or the unit circle (special_points.cpp).
constexpr double kOnCircle = 1e-5;
// Bisection on the motion's existence stops at this width; grazings are probed for their side
// this far out (beyond their accuracy, far below the distance to other special points).
constexpr double kBisectionWidth = 1e-13;
constexpr double kSideProbe = 1e-6;

// Random robots with a valid one-impact orbit: A, c / A, phi0 and e drawn uniformly.
std::vector<Solution> RandomOrbits(unsigned seed = kSeed, int count = kRobots) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> A(0.03, 0.3), ratio(0.1, 0.5),
      phi0(-0.5 * kTau, 0.5 * kTau), e(0.3, 1.0);
  std::vector<Solution> out;
  for (int k = 0; k < kMaxDraws && static_cast<int>(out.size()) < count; ++k) {
    const double a = A(rng), c = ratio(rng) * a, p = phi0(rng), r = e(rng);
    const Solution s = Solve(Forcing::Harmonic(a, c, p), Params{1.0, r});
    if (s.orbit.ok() && s.validity.valid() && s.orbit.alpha > 0.05 && s.orbit.alpha < 0.95) {
      out.push_back(s);
    }
  }
  return out;
}

// The motion m exists at lambda with its impacts: Newton shooting with its period from `state`.
bool Exists(const RobotFamily& f, const PeriodicMotion& m, double lambda, PhaseState* state) {
  const RobotModel r = f(lambda);
  const PeriodicMotion s = ShootPeriodicMotion(r, *state, m.period, ShootingOptions{});
  if (s.status != ShootingStatus::kConverged || s.impacts_right != m.impacts_right ||
      s.impacts_left != m.impacts_left) {
    return false;
  }
  *state = s.state;
  return true;
}

// The end of m's motion between `inside` (it exists) and `beyond` by bisection.
double ExistenceEnd(const RobotFamily& f, const PeriodicMotion& m, double inside, double beyond) {
  PhaseState state = m.state;
  for (int k = 0; k < 200 && std::abs(beyond - inside) > kBisectionWidth; ++k) {
    const double mid = 0.5 * (inside + beyond);
    (Exists(f, m, mid, &state) ? inside : beyond) = mid;
  }
  return inside;
}

bool HasCriticalMultiplier(const SpecialPoint& sp) {
  for (const auto& mu : sp.motion.multipliers) {
    if (sp.type == SpecialPointType::kFold && std::abs(mu - 1.0) <= kOnCircle) return true;
    if (sp.type == SpecialPointType::kPeriodDoubling && std::abs(mu + 1.0) <= kOnCircle) {
      return true;
    }
    if (sp.type == SpecialPointType::kNeimarkSacker && std::abs(std::abs(mu) - 1.0) <= kOnCircle) {
      return true;
    }
  }
  return false;
}

// The multiplier of m that crosses the circle at a period doubling (nearest -1) or a
// Neimark-Sacker point (nearest the circle): its signed distance, + outside.
double CriticalSide(SpecialPointType type, const PeriodicMotion& m) {
  double best = std::numeric_limits<double>::infinity(), side = 0.0;
  for (const auto& mu : m.multipliers) {
    const double d = type == SpecialPointType::kPeriodDoubling ? std::abs(mu + 1.0)
                                                               : std::abs(std::abs(mu) - 1.0);
    if (d < best) {
      best = d;
      side = type == SpecialPointType::kPeriodDoubling ? -(mu.real() + 1.0) : std::abs(mu) - 1.0;
    }
  }
  return side;
}

// The special point's type holds on both sides. A fold: the branch's points just before and
// just after it lie on one side of its parameter (the branch turns there). A period doubling or
// Neimark-Sacker point: shot anew this far out on either side (the shooting's multipliers are
// exact to about 1e-9, far below the crossing's change over the probe), the crossing
// multiplier lies inside the circle on one side and outside on the other.
void CheckBothSides(const RobotFamily& f, const Branch& b, const SpecialPoint& sp) {
  SCOPED_TRACE(::testing::Message() << SpecialPointTypeName(sp.type) << " at " << sp.parameter);
  if (sp.type == SpecialPointType::kFold) {
    const auto i = static_cast<std::size_t>(sp.after_point);
    ASSERT_LT(i + 1, b.points.size());
    EXPECT_GT((b.points[i].parameter - sp.parameter) * (b.points[i + 1].parameter - sp.parameter),
              0.0);
    return;
  }
  const double probe =
      std::max(kSideProbe, 10.0 * sp.accuracy) * std::max(1.0, std::abs(sp.parameter));
  double sides[2];
  for (int k = 0; k < 2; ++k) {
    const double lambda = sp.parameter + (k == 0 ? -probe : probe);
    const RobotModel r = f(lambda);
    const PeriodicMotion m =
        ShootPeriodicMotion(r, sp.motion.state, sp.motion.period, ShootingOptions{});
    ASSERT_EQ(m.status, ShootingStatus::kConverged) << lambda;
    sides[k] = CriticalSide(sp.type, m);
  }
  EXPECT_LT(sides[0] * sides[1], 0.0) << sides[0] << " " << sides[1];
}

// A grazing's motion exists on exactly one side of it, and ends within the grazing's accuracy
// of the independent bisection's end.
void CheckGrazing(const RobotFamily& f, const SpecialPoint& g) {
  SCOPED_TRACE(::testing::Message() << "grazing at " << g.parameter << " +- " << g.accuracy);
  const double probe = std::max(kSideProbe, 10.0 * g.accuracy);
  PhaseState up = g.motion.state, down = g.motion.state;
  const bool above = Exists(f, g.motion, g.parameter + probe, &up);
  const bool below = Exists(f, g.motion, g.parameter - probe, &down);
  ASSERT_NE(above, below) << "the motion exists " << (above ? "on both sides" : "on neither side");
  const double end = ExistenceEnd(f, g.motion, g.parameter + (above ? probe : -probe),
                                  g.parameter + (above ? -probe : probe));
  EXPECT_LE(std::abs(end - g.parameter), g.accuracy + kBisectionWidth) << "bisection " << end;
}

TEST(BranchProperties, RandomRobotsBranchesAreMotionsAndTheirSpecialPointsHold) {
  const std::vector<Solution> robots = RandomOrbits();
  ASSERT_EQ(static_cast<int>(robots.size()), kRobots);
  int points = 0, specials = 0;
  for (const Solution& s : robots) {
    const Orbit& o = s.orbit;
    SCOPED_TRACE(::testing::Message() << "A " << o.forcing.MaxAbs() << " alpha " << o.alpha);
    const Params params{o.T0, o.e};
    const RobotFamily family = NamedParameterFamily({o.forcing, params, o.alpha}, "alpha");
    ContinuationOptions opt;
    opt.from = std::max(0.02, o.alpha - 0.1);
    opt.to = std::min(0.98, o.alpha + 0.1);
    opt.start = o.alpha;
    opt.max_points = 80;
    const Branch b = ContinueBranch(family, OrbitImpactState(o, o.forcing), opt);
    ASSERT_EQ(b.status, ContinuationStatus::kOk) << b.message;
    for (const BranchPoint& p : b.points) {
      PhaseState state = p.motion.state;
      ASSERT_TRUE(Exists(family, p.motion, p.parameter, &state)) << p.parameter;
      const double moved =
          std::max({std::abs(state.x - p.motion.state.x), std::abs(state.u - p.motion.state.u),
                    std::abs(state.v - p.motion.state.v)});
      EXPECT_LE(moved, kShootingTol) << p.parameter;
      ++points;
    }
    for (const SpecialPoint& sp : b.special_points) {
      if (sp.type == SpecialPointType::kGrazing) {
        CheckGrazing(family, sp);
        ++specials;
      } else if (sp.type != SpecialPointType::kSpeedExtremum &&
                 sp.type != SpecialPointType::kSegmentChange) {
        EXPECT_TRUE(HasCriticalMultiplier(sp))
            << SpecialPointTypeName(sp.type) << " at " << sp.parameter << ": "
            << sp.motion.multipliers.front();
        CheckBothSides(family, b, sp);
        ++specials;
      }
    }
  }
  EXPECT_GE(points, 40);
  EXPECT_GE(specials, 1);  // at least one special point was checked
}

// Period doublings of the one-impact branches in e of random robots: the switched branch starts
// on the motion born there. At a flip the period-2p motion's two halves (its state z and its
// image P^p(z), at the same forcing phase) lie on either side of the period-p motion, apart by a
// distance growing like the square root of |lambda - lambda_pd|: every switched point near the
// doubling has its two halves apart by more than rounding and by at most a factor of order one
// times sqrt(|lambda - lambda_pd|), its impacts twice over, and its speed within that much
// (relative) of the doubling's. Section-free measures: the period-2p motion's state may lie on
// another event's section than the doubling's. References: the doubling's own motion, the
// period map run here, and Newton shooting of period 2p from each such point.
constexpr unsigned kSwitchSeed = 7;
constexpr int kSwitchRobots = 24;
constexpr int kDoublingsWanted = 3;
// Points of the switched branch this near the doubling (relative) are checked: the switch's
// trials lie at 1e-5 .. 1e-3. At most this many times sqrt of their distance from it (the
// flip's amplitude has a factor of order one: the switch's own trials go up to 3 sqrt(offset)).
constexpr double kNear = 2e-3;
constexpr double kSqrtFactor = 10.0;
// The square-root law itself: apart / sqrt(offset) is the flip's normal-form factor, the same at
// every point near the doubling up to the next order (a relative change of the order of the
// offset, at most kNear here); this allows 25 times that.
constexpr double kSqrtLawSpread = 0.05;
// Halves closer than this are one period-p motion (the corrector's residual is 1e-12).
constexpr double kDistinctHalves = 1e-7;

const SpecialPoint* FirstDoubling(const Branch& b) {
  for (const SpecialPoint& sp : b.special_points) {
    if (sp.type == SpecialPointType::kPeriodDoubling && sp.located) return &sp;
  }
  return nullptr;
}

// max |P^p(z) - z| over x, u, v for the robot at lambda; infinity at the work bound.
double HalvesApart(const RobotFamily& f, double lambda, const PhaseState& z, int p) {
  const RobotModel r = f(lambda);
  const detail::PeriodMap map(r, detail::SimulationOf(ShootingOptions{}));
  detail::MapState image;
  if (!map.Map(z, p, &image)) return std::numeric_limits<double>::infinity();
  return std::max(
      {std::abs(image.z.x - z.x), std::abs(image.z.u - z.u), std::abs(image.z.v - z.v)});
}

void CheckSwitchedStart(const RobotFamily& f, const SpecialPoint& pd, const Branch& two) {
  SCOPED_TRACE(::testing::Message() << "period doubling at " << pd.parameter);
  ASSERT_EQ(two.status, ContinuationStatus::kOk) << two.message;
  const int p = pd.motion.period;
  const double scale = std::max(1.0, std::abs(pd.parameter));
  int near = 0;
  double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
  for (const BranchPoint& b : two.points) {
    const double offset = std::abs(b.parameter - pd.parameter) / scale;
    if (offset > kNear) continue;
    ++near;
    SCOPED_TRACE(::testing::Message() << "point at " << b.parameter);
    EXPECT_EQ(b.motion.period, 2 * p);
    EXPECT_EQ(b.motion.impacts_right, 2 * pd.motion.impacts_right);
    EXPECT_EQ(b.motion.impacts_left, 2 * pd.motion.impacts_left);
    const double bound = kSqrtFactor * std::sqrt(offset);
    const double apart = HalvesApart(f, b.parameter, b.motion.state, p);
    EXPECT_GT(apart, kDistinctHalves);
    EXPECT_LE(apart, bound);
    lo = std::min(lo, apart / std::sqrt(offset));
    hi = std::max(hi, apart / std::sqrt(offset));
    EXPECT_LE(std::abs(b.motion.mean_velocity - pd.motion.mean_velocity),
              bound * std::abs(pd.motion.mean_velocity));
    PhaseState state = b.motion.state;
    EXPECT_TRUE(Exists(f, b.motion, b.parameter, &state));
  }
  ASSERT_GE(near, 2) << "points of the switched branch within " << kNear << " of the doubling";
  EXPECT_LE(hi - lo, kSqrtLawSpread * hi) << "apart / sqrt(offset) from " << lo << " to " << hi;
}

TEST(BranchProperties, RandomRobotsSwitchedBranchesStartOnTheMotionBornAtTheDoubling) {
  int doublings = 0;
  for (const Solution& s : RandomOrbits(kSwitchSeed, kSwitchRobots)) {
    if (doublings == kDoublingsWanted) break;
    const Orbit& o = s.orbit;
    SCOPED_TRACE(::testing::Message() << "A " << o.forcing.MaxAbs() << " e " << o.e);
    const RobotFamily family = NamedParameterFamily({o.forcing, Params{o.T0, o.e}, o.alpha}, "e");
    ContinuationOptions opt;
    opt.from = 0.05;
    opt.to = 1.0;
    opt.start = o.e;
    opt.max_points = 200;
    const Branch one = ContinueBranch(family, OrbitImpactState(o, o.forcing), opt);
    const SpecialPoint* pd = FirstDoubling(one);
    if (one.status != ContinuationStatus::kOk || pd == nullptr) continue;
    CheckBothSides(family, one, *pd);
    CheckSwitchedStart(family, *pd, SwitchAtPeriodDoubling(family, *pd, opt));
    ++doublings;
  }
  EXPECT_EQ(doublings, kDoublingsWanted) << "random robots with a period doubling in e";
}

}  // namespace
}  // namespace capsubot
