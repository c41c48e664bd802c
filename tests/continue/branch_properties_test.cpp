// Properties of the continuation over random robots (docs/continuation.md): every branch point
// is a periodic motion of its period, every fold, period doubling and Neimark-Sacker point has
// its critical multiplier, and every grazing ends its motion on one side with an accuracy that
// bounds the distance to the end found by an independent bisection. References: Newton shooting
// from each point's state (periodic.hpp) and a bisection on the motion's existence written here.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "capsubot/attract/periodic.hpp"
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
std::vector<Solution> RandomOrbits() {
  std::mt19937 rng(kSeed);
  std::uniform_real_distribution<double> A(0.03, 0.3), ratio(0.1, 0.5), phi0(-0.5 * kTau, 0.5 * kTau),
      e(0.3, 1.0);
  std::vector<Solution> out;
  for (int k = 0; k < kMaxDraws && static_cast<int>(out.size()) < kRobots; ++k) {
    const double a = A(rng), c = ratio(rng) * a, p = phi0(rng), r = e(rng);
    const Solution s = Solve(Forcing::Harmonic(a, c, p), Params{1.0, r, 0.0});
    if (s.orbit.ok() && s.validity.valid() && s.orbit.alpha > 0.05 && s.orbit.alpha < 0.95) {
      out.push_back(s);
    }
  }
  return out;
}

// The motion m exists at lambda with its impacts: Newton shooting with its period from `state`.
bool Exists(const RobotFamily& f, const PeriodicMotion& m, double lambda, PhaseState* state) {
  const RobotModel r = f(lambda);
  const PeriodicMotion s =
      ShootPeriodicMotion(r.forcing, r.params, r.alpha, *state, m.period, ShootingOptions{});
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
    if (sp.type == SpecialPointType::kNeimarkSacker &&
        std::abs(std::abs(mu) - 1.0) <= kOnCircle) {
      return true;
    }
  }
  return false;
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
    const Params params{o.T0, o.e, 0.0};
    const RobotFamily family = NamedParameterFamily(o.forcing, params, o.alpha, "alpha");
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
      const double moved = std::max({std::abs(state.x - p.motion.state.x),
                                     std::abs(state.u - p.motion.state.u),
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
        ++specials;
      }
    }
  }
  EXPECT_GE(points, 40);
  EXPECT_GE(specials, 1);  // at least one special point was checked
}

}  // namespace
}  // namespace capsubot
