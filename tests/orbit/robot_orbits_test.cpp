// The one-impact orbits of a robot with a fixed mass ratio (docs/model.md section 8): every root
// phi0 of alpha(phi0) = alpha, checked against an independent dense scan of the circle.

#include "capsubot/orbit/robot_orbits.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::Near;

// The roots are polished by Newton to ~1e-14 in phase; alpha(phi0) has slopes of order 1.
constexpr double kAlphaTol = 1e-12;
// The reference scan: 20,000 phases (step 3e-4), 10x denser than FindRobotOrbits' first grid
// of 512 (which then refines adaptively): a root pair closer than the step could hide from
// the scan, not the other way round, so the scan may only find fewer brackets.
constexpr int kDenseScan = 20000;

struct Case {
  std::string name;
  Forcing force;  // phi0 is ignored
  double T0, e, alpha;
};

Params P(const Case& k) { return Params{k.T0, k.e}; }

class RobotOrbits : public ::testing::TestWithParam<Case> {};

TEST_P(RobotOrbits, EveryReturnedOrbitHasTheRobotsMassRatio) {
  const Case& k = GetParam();
  const std::vector<Solution> found = FindRobotOrbits({k.force, P(k), k.alpha});
  for (std::size_t i = 0; i < found.size(); ++i) {
    const Orbit& o = found[i].orbit;
    ASSERT_TRUE(o.ok());
    EXPECT_TRUE(Near(o.alpha, k.alpha, kAlphaTol));
    EXPECT_GE(o.forcing.phi0(), -M_PI);
    EXPECT_LT(o.forcing.phi0(), M_PI);
    if (i > 0) {
      EXPECT_GT(o.forcing.phi0(), found[i - 1].orbit.forcing.phi0());
    }
    EXPECT_TRUE(found[i].validity.checked);
  }
}

// Independent reference: a dense scan of alpha(phi0) - alpha over the circle. Every sign
// change between neighbouring scan points where alpha and phi1 are continuous (no jump of
// the first stop root) must hold exactly one returned root, and every returned root must lie
// in such a bracket.
TEST_P(RobotOrbits, NoRootIsMissedComparedWithADenseScan) {
  const Case& k = GetParam();
  const std::vector<Solution> found = FindRobotOrbits({k.force, P(k), k.alpha});
  std::vector<std::pair<double, double>> brackets;
  double prev_phi = NAN, prev_d = NAN, prev_phi1 = NAN;
  for (int i = 0; i <= kDenseScan; ++i) {
    const double phi0 = -M_PI + kTau * i / kDenseScan;
    const Orbit o = ComputeOrbit(k.force.WithPhase(phi0), P(k));
    const double d = o.ok() ? o.alpha - k.alpha : NAN;
    if (!std::isnan(d) && !std::isnan(prev_d) && (d < 0.0) != (prev_d < 0.0) &&
        std::abs(o.phi1 - prev_phi1) < 0.01) {
      brackets.emplace_back(prev_phi, phi0);
    }
    prev_phi = phi0;
    prev_d = d;
    prev_phi1 = o.phi1;
  }
  ASSERT_GE(brackets.size(), 1U) << "the case must have orbits to be a test";
  EXPECT_EQ(found.size(), brackets.size());
  for (const auto& [lo, hi] : brackets) {
    int inside = 0;
    for (const Solution& s : found) {
      const double phi0 = s.orbit.forcing.phi0();
      inside += phi0 >= lo - 1e-12 && phi0 <= hi + 1e-12;
    }
    EXPECT_EQ(inside, 1) << "bracket [" << lo << ", " << hi << "]";
  }
}

// Round trip: the robot whose alpha is that of a solved orbit has that orbit among its own.
TEST_P(RobotOrbits, ContainsTheOrbitItsMassRatioCameFrom) {
  const Case& k = GetParam();
  for (const double phi0 : {-2.8, -2.0, 2.5}) {
    const Orbit o = ComputeOrbit(k.force.WithPhase(phi0), P(k));
    if (!o.ok()) continue;
    const std::vector<Solution> found = FindRobotOrbits({k.force, P(k), o.alpha});
    int matches = 0;
    for (const Solution& s : found) matches += std::abs(s.orbit.forcing.phi0() - phi0) < 1e-9;
    EXPECT_EQ(matches, 1) << "phi0 = " << phi0 << ", alpha = " << o.alpha;
  }
}

// The "none missed" argument of robot_orbits.cpp rests on
//   dPsi/dphi0 = (1-a) tau (F(0) - c) - a (Pi(phi1) - phi1 F(0)),  |dPsi/dphi0| <= tau S (1+a),
// Psi = (1-a) psi0 + a psi1. Both are checked here against central differences of Psi.
TEST_P(RobotOrbits, PsiDerivativeAndItsBoundHoldAlongTheCircle) {
  const Case& k = GetParam();
  const double a = k.alpha, h = 1e-6;
  double S = 0.0;
  for (int j = 1; j <= k.force.harmonics(); ++j) S += std::hypot(k.force.a(j), k.force.b(j));
  const auto psi = [&](double phi0) {
    const Orbit o = ComputeOrbit(k.force.WithPhase(phi0), P(k));
    return (1.0 - a) * o.psi0 + a * o.psi1;
  };
  for (int i = 0; i < 200; ++i) {
    const double phi0 = -M_PI + kTau * (i + 0.5) / 200;
    const Orbit o = ComputeOrbit(k.force.WithPhase(phi0), P(k));
    const Orbit lo = ComputeOrbit(k.force.WithPhase(phi0 - h), P(k));
    const Orbit hi = ComputeOrbit(k.force.WithPhase(phi0 + h), P(k));
    if (std::abs(hi.phi1 - lo.phi1) > 1e-3) continue;  // a jump of phi1: Psi is not smooth here
    const Forcing& f = o.forcing;
    const double F0 = f.F(0.0);
    const double formula = (1.0 - a) * kTau * (F0 - f.mean()) - a * (f.Pi(o.phi1) - o.phi1 * F0);
    const double fd = (psi(phi0 + h) - psi(phi0 - h)) / (2.0 * h);
    EXPECT_TRUE(Near(formula, fd, 1e-7)) << "phi0 = " << phi0;
    EXPECT_LE(std::abs(formula), kTau * S * (1.0 + a));
  }
}

// Cases: the paper's family at small T0 with valid orbits (found with `capsubot solve`
// scans), e = 1, the paper's worked example (T0 = 1, A = c = 1/2), a force exceeding -T0
// (phi1 may jump: the non-smooth path), and a three-harmonic Fourier force.
INSTANTIATE_TEST_SUITE_P(
    Robot, RobotOrbits,
    ::testing::Values(
        Case{"harmonic_e0p5_alpha0p28", Forcing::Harmonic(0.05, 0.02, 0.0), 0.1, 0.5, 0.28},
        Case{"harmonic_e0p5_alpha0p1", Forcing::Harmonic(0.05, 0.02, 0.0), 0.1, 0.5, 0.1},
        Case{"harmonic_e1_alpha0p2", Forcing::Harmonic(0.05, 0.02, 0.0), 0.1, 1.0, 0.2},
        Case{"paper_example_alpha0p3", Forcing::Harmonic(0.5, 0.5, 0.0), 1.0, 1.0, 0.3},
        Case{"strong_force_alpha0p5", Forcing::Harmonic(2.5, 0.5, 0.0), 1.0, 1.0, 0.5},
        Case{"fourier3_alpha0p17",
             Forcing::Fourier(0.02, {0.01, 0.0, 0.005}, {0.04, 0.01, 0.0}, 0.0), 0.1, 0.5, 0.17},
        // Just below the maximum of alpha(phi0) (about 0.1995): two roots close together.
        Case{"fourier3_alpha0p199_near_fold",
             Forcing::Fourier(0.02, {0.01, 0.0, 0.005}, {0.04, 0.01, 0.0}, 0.0), 0.1, 0.5, 0.199},
        Case{"fourier3_alpha0p05",
             Forcing::Fourier(0.02, {0.01, 0.0, 0.005}, {0.04, 0.01, 0.0}, 0.0), 0.1, 0.5, 0.05}),
    [](const ::testing::TestParamInfo<Case>& info) { return info.param.name; });

// Near a fold of alpha(phi0) (its local maximum alpha*), Psi is flat: the roots' acceptance
// bands span many of the search's finest intervals. Each root is one orbit. Reference: a dense
// scan of alpha(phi0) (ComputeOrbit only) on a 2e-5 grid over [-pi, pi) for the count, and a
// golden-section search of alpha on the scan's best cell for alpha* (the fold of the case
// `orbits --A 0.2 --c 0.03 --T0 1 --e 1`, near phi0 = -3.1356, alpha* = 0.68618243).
TEST(RobotOrbitsNearFold, ReturnEachOrbitOnceForAlphasApproachingTheFoldFromBothSides) {
  const Forcing f = Forcing::Harmonic(0.2, 0.03, 0.0);
  const Params p{1.0, 1.0};
  const auto alpha = [&](double phi0) {
    const Orbit o = ComputeOrbit(f.WithPhase(phi0), p);
    return o.ok() ? o.alpha : NAN;
  };
  constexpr int kScan = 314159;  // step 2e-5: the closest pair below (1e-3 apart), 50 cells
  std::vector<double> scan(kScan + 1);
  int best = 0;
  for (int i = 0; i <= kScan; ++i) {
    const double phi0 = -M_PI + kTau * i / kScan;
    scan[i] = alpha(phi0);
    if (phi0 > -3.2 && phi0 < -3.07 && !(scan[i] <= scan[best])) best = i;
  }
  double lo = -M_PI + kTau * (best - 1) / kScan, hi = -M_PI + kTau * (best + 1) / kScan;
  for (int it = 0; it < 100; ++it) {  // golden section for the maximum of alpha
    const double m1 = lo + 0.381966 * (hi - lo), m2 = lo + 0.618034 * (hi - lo);
    if (alpha(m1) < alpha(m2)) {
      lo = m1;
    } else {
      hi = m2;
    }
  }
  const double fold = alpha(0.5 * (lo + hi));
  ASSERT_TRUE(Near(fold, 0.68618243, 1e-8));
  const auto scan_count = [&](double a) {
    int n = 0;
    for (int i = 1; i <= kScan; ++i) {
      n += !std::isnan(scan[i]) && !std::isnan(scan[i - 1]) && (scan[i] < a) != (scan[i - 1] < a);
    }
    return n;
  };
  int checked = 0, below_with_pair = 0;
  for (int k = 0; k < 10; ++k) {
    const double d = std::pow(10.0, -3.0 - 0.5 * k);  // 1e-3 down to 3e-8
    for (const double side : {-1.0, 1.0}) {
      const double a = fold + side * d;
      const int expected = scan_count(a);
      const std::vector<Solution> found = FindRobotOrbits({f, p, a});
      EXPECT_EQ(static_cast<int>(found.size()), expected) << "alpha = fold + " << side * d;
      // Below the fold the pair exists: two more orbits than above it.
      if (side < 0.0) below_with_pair += expected >= 2;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 20);
  EXPECT_EQ(below_with_pair, 10);
  // The command line's case: two orbits, 0.0095 apart (it listed 32 before the bands).
  EXPECT_EQ(FindRobotOrbits({f, p, 0.68618}).size(), 2U);
}

TEST(RobotOrbitsInput, BadMassRatioIsRejectedWithItsRule) {
  Params p;
  try {
    FindRobotOrbits({Forcing::Harmonic(0.5, 0.5, 0.0), p, 1.5});
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "mass ratio alpha = 1.5 is invalid: expected 0 < alpha < 1");
  }
  p.T0 = -1.0;
  try {
    FindRobotOrbits({Forcing::Harmonic(0.5, 0.5, 0.0), p, 0.5});
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "friction bound T0 = -1 is invalid: expected a finite T0 > 0");
  }
}

// The work bound: a search stopped by it says so (the list may miss orbits), a full search
// says it is complete. The Fourier force with roots close together near the fold needs a few
// thousand refinement steps beyond the 513 points of the first grid; 600 cannot decide it.
TEST(RobotOrbitsInput, SearchStoppedByTheWorkBoundIsReportedIncomplete) {
  const Forcing f = Forcing::Fourier(0.02, {0.01, 0.0, 0.005}, {0.04, 0.01, 0.0}, 0.0);
  Params p;
  p.T0 = 0.1;
  p.e = 0.5;
  bool complete = false;
  const std::vector<Solution> all = FindRobotOrbits({f, p, 0.199}, {}, &complete);
  EXPECT_TRUE(complete);
  EXPECT_GE(all.size(), 2U);
  complete = true;
  const std::vector<Solution> cut = FindRobotOrbits({f, p, 0.199}, {}, &complete, 600);
  EXPECT_FALSE(complete);
  EXPECT_LE(cut.size(), all.size());
  try {
    FindRobotOrbits({f, p, 0.199}, {}, &complete, 0);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "max_evaluations = 0 is invalid: expected >= 1");
  }
}

TEST(RobotOrbitsInput, NoOrbitWithoutPositiveMeanForce) {
  Params p;
  EXPECT_TRUE(FindRobotOrbits({Forcing::Harmonic(0.5, 0.0, 0.0), p, 0.3}).empty());
  EXPECT_TRUE(FindRobotOrbits({Forcing::Harmonic(0.5, -0.1, 0.0), p, 0.3}).empty());
  bool complete = false;  // nothing to search: complete
  EXPECT_TRUE(FindRobotOrbits({Forcing::Harmonic(0.5, 0.0, 0.0), p, 0.3}, {}, &complete).empty());
  EXPECT_TRUE(complete);
}

}  // namespace
}  // namespace capsubot
