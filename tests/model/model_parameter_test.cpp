// ModelParameter: names and their parse over every parameter and harmonic; SetParameter against
// the force built directly (Forcing::Harmonic, Fourier, WithPhase), bit for bit; the messages
// of the checks.

#include "capsubot/model/model_parameter.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::InvalidArgumentMessage;

constexpr ModelParameter kAll[] = {
    ModelParameter::kA,          ModelParameter::kMean,        ModelParameter::kPhi0,
    ModelParameter::kT0,         ModelParameter::kRestitution, ModelParameter::kMargin,
    ModelParameter::kAlpha,      ModelParameter::kCos,         ModelParameter::kSin,
    ModelParameter::kBound,      ModelParameter::kRhoMax,      ModelParameter::kMarginStroke,
    ModelParameter::kStickMargin};

// Two forces are the same numbers: the same series, phase and values at a few phases, bit for
// bit (memcmp: -0.0 and 0.0 differ).
::testing::AssertionResult SameForce(const Forcing& f, const Forcing& g) {
  const auto same = [](double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; };
  if (f.harmonics() != g.harmonics() || !same(f.mean(), g.mean()) || !same(f.phi0(), g.phi0())) {
    return ::testing::AssertionFailure()
           << "K " << f.harmonics() << " vs " << g.harmonics() << ", c " << f.mean() << " vs "
           << g.mean() << ", phi0 " << f.phi0() << " vs " << g.phi0();
  }
  for (int k = 1; k <= f.harmonics(); ++k) {
    if (!same(f.a(k), g.a(k)) || !same(f.b(k), g.b(k))) {
      return ::testing::AssertionFailure() << "harmonic " << k << ": a " << f.a(k) << " vs "
                                           << g.a(k) << ", b " << f.b(k) << " vs " << g.b(k);
    }
  }
  for (double phi : {0.0, 0.7, 2.9, 5.1}) {
    const ForceValues u = f.Values(phi), v = g.Values(phi);
    if (!same(u.F, v.F) || !same(u.Pi, v.Pi) || !same(u.Phi, v.Phi)) {
      return ::testing::AssertionFailure() << "at phi = " << phi << ": F " << u.F << " vs " << v.F
                                           << ", Pi " << u.Pi << " vs " << v.Pi;
    }
  }
  return ::testing::AssertionSuccess();
}

TEST(ModelParameter, EveryNameParsesBackToItsParameterAndHarmonic) {
  int checked = 0;
  for (ModelParameter p : kAll) {
    const std::vector<int> harmonics =
        IsFourierCoefficient(p) ? std::vector<int>{1, 2, 9, kMaxHarmonics} : std::vector<int>{0};
    for (int k : harmonics) {
      ModelParameter parsed = ModelParameter::kA;
      int harmonic = -1;
      ASSERT_TRUE(ParseModelParameter(ModelParameterName(p, k), parsed, harmonic))
          << ModelParameterName(p, k);
      EXPECT_EQ(parsed, p) << ModelParameterName(p, k);
      EXPECT_EQ(harmonic, k) << ModelParameterName(p, k);
      ++checked;
    }
  }
  EXPECT_EQ(checked, 11 + 2 * 4);
  EXPECT_EQ(ModelParameterName(ModelParameter::kCos, 3), "a3");
  EXPECT_EQ(ModelParameterName(ModelParameter::kSin), "b");
  EXPECT_EQ(ModelParameterNames(),
            "A, c, phi0, T0, e, margin, alpha, a1..a16, b1..b16, bound, rho_max, "
            "margin_stroke, stick_margin");
}

TEST(ModelParameter, NamesOutsideTheTableDoNotParse) {
  int checked = 0;
  for (const char* bad : {"mu", "a0", "b17", "a01", "a", "c1", "a+1", "A ", ""}) {
    ModelParameter parsed = ModelParameter::kBound;
    int harmonic = -1;
    EXPECT_FALSE(ParseModelParameter(bad, parsed, harmonic)) << bad;
    EXPECT_EQ(parsed, ModelParameter::kBound) << bad;  // left unchanged
    EXPECT_EQ(harmonic, -1) << bad;
    ++checked;
  }
  EXPECT_EQ(checked, 9);
}

TEST(ModelParameter, RobotParametersAreThoseThatChangeTheMotion) {
  int robot = 0;
  for (ModelParameter p : kAll) robot += IsRobotParameter(p) ? 1 : 0;
  EXPECT_EQ(robot, 8);  // A, c, alpha, T0, e, phi0, a_k, b_k
  for (ModelParameter p :
       {ModelParameter::kMargin, ModelParameter::kMarginStroke, ModelParameter::kStickMargin,
        ModelParameter::kBound, ModelParameter::kRhoMax}) {
    EXPECT_FALSE(IsRobotParameter(p)) << ModelParameterName(p);
  }
  int k = -1;
  EXPECT_EQ(ParseRobotParameter("b12", &k), ModelParameter::kSin);
  EXPECT_EQ(k, 12);
  EXPECT_EQ(ParseRobotParameter("phi0", &k), ModelParameter::kPhi0);
  EXPECT_EQ(k, 0);
  const std::string choices =
      " is invalid: expected one of A, c, alpha, T0, e, phi0, or a Fourier coefficient "
      "a1..a16, b1..b16";
  EXPECT_EQ(InvalidArgumentMessage([] { ParseRobotParameter("margin"); }),
            "parameter = margin" + choices);
  EXPECT_EQ(InvalidArgumentMessage([] { ParseRobotParameter("mu"); }), "parameter = mu" + choices);
}

TEST(ModelParameter, SetParameterBuildsTheForceAsItsConstructorsDo) {
  const double c = 0.02, phi0 = -2.842;
  const Forcing two = Forcing::Fourier(c, {0.01, -0.004}, {0.05, 0.003}, phi0);
  RobotModel r{two, Params{}, 0.3};
  SetParameter(r, ModelParameter::kMean, 0, 0.035);
  EXPECT_TRUE(SameForce(r.forcing, Forcing::Fourier(0.035, {0.01, -0.004}, {0.05, 0.003}, phi0)));
  SetParameter(r, ModelParameter::kCos, 2, 0.006);
  EXPECT_TRUE(SameForce(r.forcing, Forcing::Fourier(0.035, {0.01, 0.006}, {0.05, 0.003}, phi0)));
  SetParameter(r, ModelParameter::kSin, 1, -0.07);
  EXPECT_TRUE(SameForce(r.forcing, Forcing::Fourier(0.035, {0.01, 0.006}, {-0.07, 0.003}, phi0)));
  // phi0 is kept as given (WithPhase); a coefficient set afterwards reduces it, as Fourier does.
  SetParameter(r, ModelParameter::kPhi0, 0, 7.5);
  EXPECT_EQ(r.forcing.phi0(), 7.5);
  EXPECT_TRUE(SameForce(
      r.forcing, Forcing::Fourier(0.035, {0.01, 0.006}, {-0.07, 0.003}, 0.0).WithPhase(7.5)));
  SetParameter(r, ModelParameter::kMean, 0, 0.01);
  EXPECT_TRUE(SameForce(r.forcing, Forcing::Fourier(0.01, {0.01, 0.006}, {-0.07, 0.003}, 7.5)));
  EXPECT_LT(r.forcing.phi0(), 3.15);
  RobotModel h{Forcing::Harmonic(0.05, c, phi0), Params{}, 0.3};
  SetParameter(h, ModelParameter::kA, 0, 0.08);
  EXPECT_TRUE(SameForce(h.forcing, Forcing::Harmonic(0.08, c, phi0)));
  SetParameter(h, ModelParameter::kT0, 0, 0.4);
  SetParameter(h, ModelParameter::kRestitution, 0, 0.6);
  SetParameter(h, ModelParameter::kAlpha, 0, 0.7);
  EXPECT_EQ(h.params.T0, 0.4);
  EXPECT_EQ(h.params.e, 0.6);
  EXPECT_EQ(h.alpha, 0.7);
  EXPECT_TRUE(SameForce(h.forcing, Forcing::Harmonic(0.08, c, phi0)));  // the force kept
}

TEST(ModelParameter, ParameterValueReadsBackEveryRobotParameterSet) {
  RobotModel r{Forcing::Fourier(0.02, {0.0, 0.01}, {0.05, 0.003}, -2.0), Params{}, 0.3};
  RobotModel h{Forcing::Harmonic(0.05, 0.02, -2.0), Params{}, 0.3};
  int checked = 0;
  for (ModelParameter p : kAll) {
    if (!IsRobotParameter(p)) continue;
    RobotModel& robot = p == ModelParameter::kA ? h : r;
    const int k = IsFourierCoefficient(p) ? 2 : 0;
    const double value = p == ModelParameter::kPhi0 ? 7.25 : 0.375;  // exact in binary
    SetParameter(robot, p, k, value);
    EXPECT_EQ(ParameterValue(robot, p, k), value) << ModelParameterName(p, k);
    ++checked;
  }
  EXPECT_EQ(checked, 8);
  EXPECT_EQ(InvalidArgumentMessage([&] { ParameterValue(r, ModelParameter::kRhoMax); }),
            "parameter = rho_max is invalid: expected one of A, c, alpha, T0, e, phi0, or a "
            "Fourier coefficient a1..a16, b1..b16");
}

TEST(ModelParameter, SetParameterRefusesWhatTheRobotCannotTake) {
  RobotModel fourier{Forcing::Fourier(0.02, {0.01}, {0.05}, 0.0), Params{}, 0.3};
  const RobotModel before = fourier;
  EXPECT_EQ(InvalidArgumentMessage([&] { SetParameter(fourier, ModelParameter::kA, 0, 0.1); }),
            "parameter = A is invalid for a Fourier force: expected the harmonic family");
  EXPECT_EQ(InvalidArgumentMessage([&] { SetParameter(fourier, ModelParameter::kCos, 3, 0.1); }),
            "parameter = a3 is invalid for this force: expected a_k or b_k with 1 <= k <= K = 1, "
            "its harmonics");
  EXPECT_EQ(InvalidArgumentMessage([&] { SetParameter(fourier, ModelParameter::kBound, 0, 1.0); }),
            "parameter = bound is invalid: expected one of A, c, alpha, T0, e, phi0, or a Fourier "
            "coefficient a1..a16, b1..b16");
  RobotModel harmonic{Forcing::Harmonic(0.05, 0.02, 0.0), Params{}, 0.3};
  EXPECT_EQ(InvalidArgumentMessage([&] { SetParameter(harmonic, ModelParameter::kA, 0, -1.0); }),
            "A = -1 is invalid: expected A >= 0");
  EXPECT_EQ(InvalidArgumentMessage([&] { SetParameter(harmonic, ModelParameter::kMean, 0, NAN); }),
            "c = nan is invalid: expected a finite number");
  EXPECT_TRUE(SameForce(fourier.forcing, before.forcing));  // a refused value changes nothing
}

TEST(ModelParameter, ForceCoefficientSettersCheckTheirHarmonic) {
  const Forcing f = Forcing::Fourier(0.02, {0.01}, {0.05}, 0.0);
  EXPECT_EQ(InvalidArgumentMessage([&] { (void)f.WithCosine(0, 0.1); }),
            "harmonic k = 0 is invalid for a_k: expected 1 <= k <= K = 1, the force's harmonics");
  EXPECT_EQ(InvalidArgumentMessage([&] { (void)f.WithSine(2, 0.1); }),
            "harmonic k = 2 is invalid for b_k: expected 1 <= k <= K = 1, the force's harmonics");
  EXPECT_EQ(InvalidArgumentMessage([&] { (void)f.WithSine(1, INFINITY); }),
            "b_1 = inf is invalid: expected a finite number");
}

}  // namespace
}  // namespace capsubot
