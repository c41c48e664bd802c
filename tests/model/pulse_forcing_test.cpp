// The pulse force (Forcing::Pulse, docs/model.md section 15): F against its definition, Pi and
// Phi against GSL quadrature, the mean, max |F|, bounds and crossings against dense scans, the
// impact frame and the moved mean, and every input error with its message.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "capsubot/model/forcing.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::InvalidArgumentMessage;
using testing::Near;

// integral_a^b g(s) by GSL's QAGS between the jumps of G(s + phi0) (the switches of the test's
// definition below), where the integrands here are smooth.
double Quadrature(const std::function<double(double)>& g, double a, double b, double phi0,
                  const std::vector<double>& switches) {
  const double sign = b >= a ? 1.0 : -1.0, lo = std::min(a, b), hi = std::max(a, b);
  std::vector<double> cuts = {lo, hi};
  for (double m = std::floor((lo + phi0) / kTau) - 1; m <= std::ceil((hi + phi0) / kTau); ++m) {
    for (double sw : switches) {
      const double s = sw + m * kTau - phi0;
      if (s > lo && s < hi) cuts.push_back(s);
    }
  }
  std::sort(cuts.begin(), cuts.end());
  double sum = 0.0;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    sum += testing::Quadrature(g, cuts[i], cuts[i + 1]);
  }
  return sign * sum;
}

constexpr double kQuadratureTol = 1e-9;
// One or two roundings of sums of a few products of size 10: a few ulp.
constexpr double kRoundingTol = 1e-13;
constexpr int kScan = 100000;  // dense scan: the independent reference for bounds and crossings

const std::vector<double> kLevels = {0.9, -0.4, 0.25, -1.1};
const std::vector<double> kSwitches = {0.5, 2.0, 3.1, 5.0};

// G(s) by its definition: the level of the last switch at or before s (mod 2 pi).
double G(double s) {
  s -= kTau * std::floor(s / kTau);
  const int n = static_cast<int>(kLevels.size());
  int j = n - 1;  // before the first switch: the last piece, wrapped
  for (int i = 0; i < n; ++i) {
    if (kSwitches[i] <= s) j = i;
  }
  return kLevels[j];
}

TEST(PulseForcing, FIsTheLevelOfItsPieceSeenFromTheImpact) {
  for (double phi0 : {0.0, 1.3, -2.7}) {
    const Forcing f = Forcing::Pulse(kLevels, kSwitches, phi0);
    EXPECT_TRUE(f.pulse());
    EXPECT_FALSE(f.harmonic());
    EXPECT_EQ(f.pulse_levels(), 4);
    EXPECT_EQ(f.harmonics(), 0);
    int checked = 0;
    for (double phi = -7.0; phi < 20.0; phi += 0.0137) {
      EXPECT_EQ(f.F(phi), G(phi + phi0)) << "phi = " << phi << ", phi0 = " << phi0;
      EXPECT_EQ(f.dF(phi), 0.0);
      ++checked;
    }
    EXPECT_GT(checked, 1000);
  }
}

TEST(PulseForcing, FAtASwitchIsTheNewLevel) {
  const Forcing f = Forcing::Pulse(kLevels, kSwitches, 0.0);
  for (std::size_t j = 0; j < kSwitches.size(); ++j) EXPECT_EQ(f.F(kSwitches[j]), kLevels[j]);
}

TEST(PulseForcing, PiAndPhiAreTheIntegralsOfF) {
  for (double phi0 : {0.0, 2.2}) {
    const Forcing f = Forcing::Pulse(kLevels, kSwitches, phi0);
    for (double phi : {0.3, 1.7, 3.9, kTau, 8.0, 20.0, -3.0}) {
      const double pi =
          Quadrature([&](double s) { return G(s + phi0); }, 0.0, phi, phi0, kSwitches);
      // Cauchy's formula: Phi(phi) = integral_0^phi (phi - s) F(s) ds.
      const double Phi =
          Quadrature([&](double s) { return (phi - s) * G(s + phi0); }, 0.0, phi, phi0, kSwitches);
      EXPECT_TRUE(Near(f.Pi(phi), pi, kQuadratureTol)) << phi;
      EXPECT_TRUE(Near(f.Phi(phi), Phi, kQuadratureTol * std::max(1.0, std::abs(phi)))) << phi;
      const ForceValues w = f.Values(phi);
      EXPECT_EQ(w.F, f.F(phi));
      EXPECT_EQ(w.Pi, f.Pi(phi));
      EXPECT_EQ(w.Phi, f.Phi(phi));
      const ForceJet j = f.Jet(Angle::Of(phi));
      EXPECT_EQ(j.Pi, w.Pi);
      EXPECT_EQ(j.dF, 0.0);
      EXPECT_EQ(j.ddF, 0.0);
    }
  }
}

TEST(PulseForcing, MeanIsPiOverAPeriod) {
  const Forcing f = Forcing::Pulse(kLevels, kSwitches, 0.4);
  const double mean = Quadrature(G, 0.0, kTau, 0.0, kSwitches) / kTau;
  EXPECT_TRUE(Near(f.mean(), mean, kQuadratureTol));
  EXPECT_TRUE(Near(f.Pi(kTau), kTau * f.mean(), kRoundingTol));
}

TEST(PulseForcing, MaxAbsAndBoundsMatchADenseScan) {
  const Forcing f = Forcing::Pulse(kLevels, kSwitches, 0.8);
  EXPECT_EQ(f.MaxAbs(), 1.1);
  for (const auto& [lo, hi] : std::vector<std::pair<double, double>>{
           {0.0, kTau}, {0.3, 1.0}, {1.0, 4.0}, {5.0, 9.0}, {2.0, 2.1}}) {
    double mn = f.F(lo), mx = mn;
    for (int i = 0; i <= kScan; ++i) {
      const double F = f.F(lo + (hi - lo) * i / kScan);
      mn = std::min(mn, F);
      mx = std::max(mx, F);
    }
    const Range r = f.Bounds(lo, hi);
    EXPECT_EQ(r.min, mn) << lo << " " << hi;
    EXPECT_EQ(r.max, mx) << lo << " " << hi;
  }
}

TEST(PulseForcing, CrossingsAreTheSwitchesWhereFPassesTheLevel) {
  const Forcing f = Forcing::Pulse(kLevels, kSwitches, -1.0);
  for (double level : {0.0, 0.3, -0.5, 0.25, 2.0}) {
    // The scan's sign changes of F - level (0 a sign of its own), each within a scan step of a
    // listed crossing, and as many.
    const double lo = 0.2, hi = lo + kTau, step = (hi - lo) / kScan;
    const auto sign = [&](double phi) {
      const double g = f.F(phi) - level;
      return g > 0.0 ? 1 : g < 0.0 ? -1 : 0;
    };
    std::vector<double> scanned;
    for (int i = 1; i <= kScan; ++i) {
      const double a = lo + (i - 1) * step, b = lo + i * step;
      if (sign(a) != sign(b)) scanned.push_back(b);
    }
    const PhaseList c = f.Crossings(level, lo, hi);
    ASSERT_EQ(c.n, static_cast<int>(scanned.size())) << "level " << level;
    for (int i = 0; i < c.n; ++i) EXPECT_NEAR(c.phi[i], scanned[i], step) << level;
    if (level == 0.0) {  // every switch changes the sign of F
      EXPECT_EQ(c.n, 4);
    }
    if (level == 2.0) {  // above every level
      EXPECT_EQ(c.n, 0);
    }
    if (level == 0.3) {  // only the level 0.9 is above
      EXPECT_EQ(c.n, 2);
    }
    if (level == 0.25) {  // F sits on 0.25 on one piece: its ends count
      EXPECT_EQ(c.n, 4);
    }
  }
}

TEST(PulseForcing, ImpactFrameAndPhaseGiveTheSameForce) {
  const Forcing f = Forcing::Pulse(kLevels, kSwitches, 2.5);
  const Forcing g = f.InImpactFrame();
  const Forcing h = Forcing::Pulse(kLevels, kSwitches, 0.0).WithPhase(2.5);
  EXPECT_TRUE(g.pulse());
  EXPECT_EQ(g.phi0(), 0.0);
  for (double phi = 0.01; phi < 2.0 * kTau; phi += 0.0731) {
    EXPECT_EQ(g.F(phi), f.F(phi)) << phi;
    EXPECT_TRUE(Near(g.Pi(phi), f.Pi(phi), kRoundingTol)) << phi;
    EXPECT_TRUE(Near(g.Phi(phi), f.Phi(phi), 10 * kRoundingTol)) << phi;
    EXPECT_EQ(h.F(phi), f.F(phi)) << phi;
  }
}

TEST(PulseForcing, WithMeanMovesEveryLevel) {
  const Forcing f = Forcing::Pulse(kLevels, kSwitches, 0.0);
  const Forcing g = f.WithMean(0.5);
  EXPECT_EQ(g.mean(), 0.5);
  for (int j = 0; j < 4; ++j) {
    EXPECT_TRUE(Near(g.level(j) - f.level(j), 0.5 - f.mean(), kRoundingTol));
  }
  EXPECT_TRUE(Near(g.Pi(kTau), 0.5 * kTau, kRoundingTol));
}

TEST(PulseForcing, OneLevelIsAConstantForce) {
  const Forcing f = Forcing::Pulse({0.3}, {1.0}, 0.0);
  EXPECT_EQ(f.mean(), 0.3);
  EXPECT_EQ(f.F(5.0), 0.3);
  EXPECT_TRUE(Near(f.Phi(2.0), 0.3 * 2.0, kRoundingTol));
  EXPECT_EQ(f.Crossings(0.0, 0.0, kTau).n, 0);
}

TEST(PulseForcing, BadInputIsRefusedWithItsRule) {
  EXPECT_EQ(InvalidArgumentMessage([] { Forcing::Pulse({}, {}, 0.0); }),
            "levels: N = 0 is invalid: expected 1 <= N <= 16 levels of the pulse force");
  EXPECT_EQ(InvalidArgumentMessage(
                [] { Forcing::Pulse(std::vector<double>(17, 0.1), std::vector<double>(17), 0.0); }),
            "levels: N = 17 is invalid: expected 1 <= N <= 16 levels of the pulse force");
  EXPECT_EQ(InvalidArgumentMessage([] {
              Forcing::Pulse({1.0, 2.0}, {0.5}, 0.0);
            }),
            "switches: 1 phases given for 2 levels: expected one switch phase per level");
  EXPECT_EQ(InvalidArgumentMessage([] {
              Forcing::Pulse({1.0, NAN}, {0.5, 1.0}, 0.0);
            }),
            "levels: L_2 = nan is invalid: expected a finite number");
  EXPECT_EQ(InvalidArgumentMessage([] {
              Forcing::Pulse({1.0, 2.0}, {0.5, 7.0}, 0.0);
            }),
            "switches: s_2 = 7 is invalid: expected 0 <= s < 2 pi (phases in radians)");
  EXPECT_EQ(InvalidArgumentMessage([] {
              Forcing::Pulse({1.0, 2.0}, {-0.1, 1.0}, 0.0);
            }),
            "switches: s_1 = -0.1 is invalid: expected 0 <= s < 2 pi (phases in radians)");
  EXPECT_EQ(InvalidArgumentMessage([] {
              Forcing::Pulse({1.0, 2.0}, {1.0, 1.0}, 0.0);
            }),
            "switches: s_2 = 1 is invalid: expected it above s_1 = 1 (switch phases strictly "
            "increasing)");
  EXPECT_EQ(InvalidArgumentMessage([] { Forcing::Pulse({1.0}, {1.0}, NAN); }),
            "phi0 = nan is invalid: expected a finite number");
  const Forcing f = Forcing::Pulse({1.0, 2.0}, {0.5, 1.0}, 0.0);
  EXPECT_EQ(
      InvalidArgumentMessage([&] { f.WithSine(1, 0.2); }),
      "b_1 is invalid for a pulse force: it has levels and switches, no Fourier coefficients");
  EXPECT_EQ(InvalidArgumentMessage([&] { f.WithMean(INFINITY); }),
            "c = inf is invalid: expected a finite number");
  EXPECT_TRUE(std::isnan(f.amplitude()));
}

}  // namespace
}  // namespace capsubot
