// Energy of the one-impact orbit (docs/model.md section 11): the energy balance over many valid
// orbits, and each closed-form integral against an independent adaptive quadrature.

#include "capsubot/orbit/orbit_energy.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "capsubot/orbit/validity.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::Near;
using testing::Quadrature;

// The balance W = friction + impacts holds exactly; the closed forms lose a few ulps of the
// largest term (|F x'| tau), so 1e-10 relative to the motor work is far above rounding.
constexpr double kBalanceRelTol = 1e-10;
// GSL's QAGS is asked for 1e-13 relative on smooth pieces; 1e-10 of the positive work leaves
// room for the bisected sign changes of the reference (to 1e-15 in phase).
constexpr double kQuadratureRelTol = 1e-10;
constexpr int kSignScan = 4096;  // samples per span where the reference looks for sign changes
constexpr int kPhaseGrid = 48;   // impact phases tried per force (valid ones are kept)

// integral_a^b max(f, 0), independent of the code under test: the sign changes of f are
// bracketed on a uniform grid and bisected, then each piece of constant sign goes to QAGS
// (QAGS alone over a kink loses digits). A pair of sign changes closer than the grid step
// would be missed; such a piece is of order step^2 in size.
double PositivePart(const std::function<double(double)>& f, double a, double b) {
  std::vector<double> cuts = {a};
  double prev = f(a);
  for (int i = 1; i <= kSignScan; ++i) {
    const double x = i == kSignScan ? b : a + (b - a) * i / kSignScan, fx = f(x);
    if ((prev < 0.0) != (fx < 0.0)) {
      double lo = a + (b - a) * (i - 1) / kSignScan, hi = x;
      for (int k = 0; k < 60 && hi - lo > 1e-15; ++k) {
        const double mid = 0.5 * (lo + hi);
        ((f(mid) < 0.0) == (prev < 0.0) ? lo : hi) = mid;
      }
      cuts.push_back(0.5 * (lo + hi));
    }
    prev = fx;
  }
  cuts.push_back(b);
  double sum = 0.0;
  for (std::size_t i = 1; i < cuts.size(); ++i) {
    sum += std::max(0.0, Quadrature(f, cuts[i - 1], cuts[i]));
  }
  return sum;
}

struct Family {
  const char* name;
  Forcing forcing;  // phi0 is replaced by the grid
  Params params;
};

// Harmonic and Fourier forces, e < 1, e = 1 and e = 0, with valid orbits on part of the circle
// (parameters from scans of `capsubot solve` over phi0). The example robot of docs/design.md is
// the second family (m2 = 0.21 kg).
const Family kFamilies[] = {
    {"harmonic_e05", Forcing::Harmonic(0.05, 0.02, 0.0), Params{0.1, 0.5}},
    {"robot_e07", Forcing::Harmonic(0.0038613, 0.00077226, 0.0), Params{0.0093182, 0.7}},
    {"harmonic_e1", Forcing::Harmonic(0.05, 0.02, 0.0), Params{0.1, 1.0}},
    {"harmonic_e1_strong", Forcing::Harmonic(0.3, 0.06, 0.0), Params{1.0, 1.0}},
    {"plastic_e0", Forcing::Harmonic(0.08, 0.01, 0.0), Params{0.1, 0.0}},
    {"fourier_k3_e07", Forcing::Fourier(0.02, {0.01, 0.0, 0.005}, {0.04, 0.01, 0.0}, 0.0),
     Params{0.1, 0.7}},
    {"fourier_k2_e1", Forcing::Fourier(0.02, {0.0, 0.01}, {0.05, 0.0}, 0.0), Params{0.1, 1.0}},
};

struct ValidOrbit {
  const char* family;
  Orbit orbit;
};

std::vector<ValidOrbit> ValidOrbits() {
  std::vector<ValidOrbit> out;
  for (const Family& f : kFamilies) {
    for (int i = 0; i < kPhaseGrid; ++i) {
      const double phi0 = -M_PI + kTau * (i + 0.5) / kPhaseGrid;
      const Solution s = Solve(f.forcing.WithPhase(phi0), f.params);
      if (s.validity.valid()) out.push_back({f.name, s.orbit});
    }
  }
  return out;
}

// How many valid orbits the families give, and how many with e = 1 and with a Fourier force.
// Counted once from the grid above (88 = 14 + 11 + 22 + 1 + 2 + 17 + 21 by family): a change
// means the cases changed.
constexpr int kValidOrbits = 88;

struct Counts {
  int all = 0, elastic = 0, fourier = 0;
};

Counts Count(const std::vector<ValidOrbit>& orbits) {
  Counts c;
  for (const ValidOrbit& v : orbits) {
    ++c.all;
    c.elastic += v.orbit.e == 1.0;
    c.fourier += !v.orbit.forcing.harmonic();
  }
  return c;
}

TEST(OrbitEnergy, TheCasesCoverBothRestitutionsAndBothForceFamilies) {
  const Counts c = Count(ValidOrbits());
  EXPECT_EQ(c.all, kValidOrbits);
  EXPECT_EQ(c.elastic, 44);
  EXPECT_EQ(c.fourier, 38);
}

TEST(OrbitEnergy, MotorWorkEqualsFrictionPlusImpactLossesOverEveryValidOrbit) {
  int checked = 0;
  for (const ValidOrbit& v : ValidOrbits()) {
    const Energy en = OrbitEnergy(v.orbit);
    const double scale = std::abs(en.motor_work);
    EXPECT_TRUE(Near(en.motor_work, en.friction_loss + en.impact_loss, kBalanceRelTol * scale))
        << v.family << " phi0 = " << v.orbit.forcing.phi0();
    EXPECT_GT(en.motor_work, 0.0);
    EXPECT_GE(en.motor_work_positive, en.motor_work);
    ++checked;
  }
  EXPECT_EQ(checked, kValidOrbits);
}

TEST(OrbitEnergy, EachIntegralAgreesWithAdaptiveQuadrature) {
  int checked = 0;
  for (const ValidOrbit& v : ValidOrbits()) {
    const Orbit& o = v.orbit;
    const Energy en = OrbitEnergy(o);
    const auto power = [&o](double phi) { return o.forcing.F(phi) * o.dx(phi); };
    // The slide and the rest separately: x'' jumps at phi1.
    const double W = Quadrature(power, 0.0, o.phi1) + Quadrature(power, o.phi1, kTau);
    const double W_plus = PositivePart(power, 0.0, o.phi1) + PositivePart(power, o.phi1, kTau);
    const double friction =
        o.T0 * Quadrature([&o](double phi) { return std::abs(o.v(phi)); }, 0.0, o.phi1);
    const double tol = kQuadratureRelTol * en.motor_work_positive;
    EXPECT_TRUE(Near(en.motor_work, W, tol)) << v.family;
    EXPECT_TRUE(Near(en.motor_work_positive, W_plus, tol)) << v.family;
    EXPECT_TRUE(Near(en.friction_loss, friction, tol)) << v.family;
    EXPECT_TRUE(Near(en.friction_loss, o.T0 * o.I, kBalanceRelTol * en.friction_loss));
    // The impact loss from the kinetic energy (1-alpha) v^2/2 + alpha (v + x')^2/2 just
    // before (phi = tau, capsule at rest) and just after (phi = 0) the impact.
    const auto kinetic = [&o](double v, double dx) {
      return (1.0 - o.alpha) * v * v / 2.0 + o.alpha * (v + dx) * (v + dx) / 2.0;
    };
    const double jump = kinetic(o.v(kTau), o.dx(kTau)) - kinetic(o.v(0.0), o.dx(0.0));
    EXPECT_TRUE(Near(en.impact_loss, jump, kBalanceRelTol * en.motor_work)) << v.family;
    ++checked;
  }
  EXPECT_EQ(checked, kValidOrbits);
}

TEST(OrbitEnergy, PositivePartExceedsTheNetWorkByTheBrakingWork) {
  // W+ - W is the work the motor absorbs where F x' < 0 (it brakes the inner body): here a
  // valid orbit where it does, compared with the reference quadrature of that part.
  const Solution s = Solve(Forcing::Harmonic(0.05, 0.02, -2.5), Params{0.1, 0.5});
  ASSERT_TRUE(s.validity.valid());
  const Orbit& o = s.orbit;
  const Energy en = OrbitEnergy(o);
  const double negative =
      -PositivePart([&o](double phi) { return -o.forcing.F(phi) * o.dx(phi); }, 0.0, kTau);
  ASSERT_LT(negative, 0.0);
  EXPECT_TRUE(Near(en.motor_work_positive - en.motor_work, -negative,
                   kQuadratureRelTol * en.motor_work_positive));
}

TEST(OrbitEnergy, IsNotComputedWithoutAnOrbit) {
  const Orbit o = ComputeOrbit(Forcing::Harmonic(0.2, 0.03, 0.0), Params{});
  ASSERT_FALSE(o.ok());
  const Energy en = OrbitEnergy(o);
  EXPECT_TRUE(std::isnan(en.motor_work));
  EXPECT_TRUE(std::isnan(en.motor_work_positive));
  EXPECT_TRUE(std::isnan(en.friction_loss));
  EXPECT_TRUE(std::isnan(en.impact_loss));
}

}  // namespace
}  // namespace capsubot
