// Designing a robot in SI units (docs/model.md sections 2, 9, 11, 12): the map to the model
// against the formulas written out here, the scaling laws of the model, the cost of transport,
// and the example robot's best gait against an independent scan over m2.

#include "capsubot/design/design.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "capsubot/orbit/robot_orbits.hpp"
#include "design/example_robot.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::Near;
using testing::NearAbsBelowOne;

// Same computation in a different order of floating-point operations: a few ulps.
constexpr double kMapRelTol = 1e-13;
// The same orbit found by the robot-orbit search from scaled inputs: its roots are polished to
// ~1e-14 in phase; alpha(phi0) has slopes of order 1, I and u inherit that.
constexpr double kRootRelTol = 1e-9;
// The example robot's best m2 against the reference scan: within 1 % (the resolution a designer
// asks of an inner mass).
constexpr double kBestM2RelTol = 0.01;
// The reference scan: log-spaced, 0.1 % apart, over the range where the example has orbits.
constexpr int kReferenceScan = 2400;
constexpr double kReferenceLo = 0.05, kReferenceHi = 0.5;

// The example robot of docs/design.md with margins off (d = d_s = s = 0, rho_max = 1).
DesignInput Example() {
  DesignInput in = testing::ExampleRobot();
  in.margin = 0.0;
  in.margin_stroke = 0.0;
  in.stick_margin = 0.0;
  in.rho_max = 1.0;
  return in;
}

constexpr double kStableM2 = 0.22;  // an m2 of the example with a stable valid orbit (scan)

TEST(Design, MapsThePhysicalRobotToTheModelOfSections2And9) {
  const DesignInput in = Example();
  const double m2 = 0.3, f = 17.0;
  const DesignModel m = MapToModel(in, m2, f);
  const double w = 2.0 * M_PI * f;
  EXPECT_TRUE(NearAbsBelowOne(m.robot.params.T0, 0.3 * 9.81 / (w * w * 0.02), kMapRelTol));
  EXPECT_TRUE(
      NearAbsBelowOne(m.robot.forcing.amplitude(), 0.5 / ((0.2 + 0.3) * w * w * 0.02), kMapRelTol));
  EXPECT_TRUE(
      NearAbsBelowOne(m.robot.forcing.mean(), 0.1 / ((0.2 + 0.3) * w * w * 0.02), kMapRelTol));
  EXPECT_TRUE(NearAbsBelowOne(m.robot.alpha, 0.3 / 0.5, kMapRelTol));
  EXPECT_EQ(m.robot.params.e, 0.7);
}

TEST(Design, GaitOfAChosenMassIsTheOrbitThatSolveGivesForTheMappedParameters) {
  const DesignInput in = Example();
  const Gait g = EvaluateGait(in, kStableM2, 20.0);
  ASSERT_TRUE(g.ok()) << GaitStatusName(g.status);
  // Mapped by hand (section 9), then solved at the gait's impact phase.
  const double w = 2.0 * M_PI * 20.0, unit = (0.2 + kStableM2) * w * w * 0.02;
  const Params p{0.3 * 9.81 / (w * w * 0.02), 0.7};
  const Solution s =
      Solve(Forcing::Harmonic(0.5 / unit, 0.1 / unit, g.solution.orbit.forcing.phi0()), p);
  ASSERT_TRUE(s.validity.valid());
  EXPECT_TRUE(NearAbsBelowOne(g.solution.orbit.alpha, kStableM2 / (0.2 + kStableM2), kRootRelTol));
  EXPECT_TRUE(NearAbsBelowOne(g.solution.orbit.alpha, s.orbit.alpha, kMapRelTol));
  EXPECT_TRUE(NearAbsBelowOne(g.solution.orbit.phi1, s.orbit.phi1, kMapRelTol));
  EXPECT_TRUE(NearAbsBelowOne(g.solution.orbit.I, s.orbit.I, kMapRelTol));
  EXPECT_TRUE(NearAbsBelowOne(g.solution.orbit.u, s.orbit.u, kMapRelTol));
  // And in the user's units: speed omega L I / tau, step L I, impact velocity omega L u.
  EXPECT_TRUE(NearAbsBelowOne(g.speed_mm_s, 1e3 * w * 0.02 * s.orbit.I / kTau, kMapRelTol));
  EXPECT_TRUE(NearAbsBelowOne(g.displacement_mm, 1e3 * 0.02 * s.orbit.I, kMapRelTol));
  EXPECT_TRUE(NearAbsBelowOne(g.impact_velocity_m_s, w * 0.02 * s.orbit.u, kMapRelTol));
  // The gait is the fastest stable valid orbit among the robot's orbits.
  int robust = 0;
  for (const Solution& o : FindRobotOrbits(
           {Forcing::Harmonic(0.5 / unit, 0.1 / unit, 0.0), p, kStableM2 / (0.2 + kStableM2)})) {
    if (!o.validity.valid() || ComputeStability(o.orbit).spectral_radius > 1.0) continue;
    ++robust;
    EXPECT_LE(o.orbit.v_mean, g.solution.orbit.v_mean);
  }
  EXPECT_EQ(robust, 1);
}

TEST(Design, EnergyInUserUnitsBalancesAndCostOfTransportIsAtLeastMu) {
  DesignInput in = Example();
  std::vector<Gait> rows;
  constexpr int kMasses = 25;  // m2 from 0.2 to 0.26 kg, log-spaced
  for (int i = 0; i < kMasses; ++i) {
    rows.push_back(DesignGait(in, 0.2 * std::pow(0.26 / 0.2, i / (kMasses - 1.0))));
  }
  int ok = 0, runs = 0;
  bool previous = false;
  for (const Gait& g : rows) {
    runs += g.ok() && !previous ? 1 : 0;
    previous = g.ok();
    if (!g.ok()) continue;
    ++ok;
    EXPECT_GE(g.cot, in.mu) << g.m2_kg;
    EXPECT_GT(g.efficiency, 0.0);
    EXPECT_LE(g.efficiency, 1.0);
    EXPECT_TRUE(NearAbsBelowOne(g.energy_mj, g.friction_loss_mj + g.impact_loss_mj, 1e-10));
    EXPECT_GE(g.power_positive_mw, g.power_mw);
    // COT from its definition W/((m1+m2) g |displacement|), in SI.
    EXPECT_TRUE(NearAbsBelowOne(
        g.cot, 1e-3 * g.energy_mj / ((in.m1 + g.m2_kg) * in.g * 1e-3 * g.displacement_mm),
        kMapRelTol));
    EXPECT_TRUE(NearAbsBelowOne(g.power_mw, g.energy_mj * 20.0, kMapRelTol));
  }
  // The range was chosen around the example's one window of robust gaits (from about 0.213 kg
  // to the end of its orbits near 0.25 kg): the gaits checked above form one run of masses.
  EXPECT_GE(ok, 2);
  EXPECT_EQ(runs, 1);
}

// The model of b equals a's (T0, A, c, alpha: the same numbers up to rounding), so every
// dimensionless result of its gait does (up to the robot-orbit search's root tolerance).
void ExpectSameDimensionlessGait(const Gait& a, const Gait& b) {
  const Orbit &oa = a.solution.orbit, &ob = b.solution.orbit;
  EXPECT_TRUE(NearAbsBelowOne(ob.T0, oa.T0, kMapRelTol));
  EXPECT_TRUE(NearAbsBelowOne(ob.forcing.amplitude(), oa.forcing.amplitude(), kMapRelTol));
  EXPECT_TRUE(NearAbsBelowOne(ob.forcing.mean(), oa.forcing.mean(), kMapRelTol));
  EXPECT_TRUE(NearAbsBelowOne(b.model.robot.alpha, a.model.robot.alpha, kMapRelTol));
  EXPECT_TRUE(NearAbsBelowOne(ob.alpha, oa.alpha, kRootRelTol));
  EXPECT_TRUE(NearAbsBelowOne(ob.forcing.phi0(), oa.forcing.phi0(), kRootRelTol));
  EXPECT_TRUE(NearAbsBelowOne(ob.I, oa.I, kRootRelTol));
  EXPECT_TRUE(
      NearAbsBelowOne(b.stability.spectral_radius, a.stability.spectral_radius, kRootRelTol));
  EXPECT_TRUE(NearAbsBelowOne(b.energy.motor_work, a.energy.motor_work, kRootRelTol));
}

// Multiplies the frequency by k and divides L by k^2: T0, A, c keep their values (omega^2 L
// does), so the dimensionless gait is the same and the speed omega L I/tau is divided by k.
TEST(Design, FrequencyTimesKAndGapOverKSquaredDivideTheSpeedByK) {
  for (const double k : {0.5, 3.0}) {
    DesignInput in = Example();
    const Gait a = EvaluateGait(in, kStableM2, 20.0);
    in.L /= k * k;
    const Gait b = EvaluateGait(in, kStableM2, 20.0 * k);
    ASSERT_TRUE(a.ok() && b.ok());
    ExpectSameDimensionlessGait(a, b);
    EXPECT_TRUE(NearAbsBelowOne(b.speed_mm_s, a.speed_mm_s / k, kRootRelTol));
    EXPECT_TRUE(NearAbsBelowOne(b.cot, a.cot, kRootRelTol));
  }
}

TEST(Design, DoublingBothMassesAndTheMotorForceChangesNothingDimensionless) {
  DesignInput in = Example();
  const Gait a = EvaluateGait(in, kStableM2, 20.0);
  in.m1 *= 2.0;
  in.force.amplitude *= 2.0;
  in.force.bias *= 2.0;
  const Gait b = EvaluateGait(in, 2.0 * kStableM2, 20.0);
  ASSERT_TRUE(a.ok() && b.ok());
  ExpectSameDimensionlessGait(a, b);
  EXPECT_TRUE(NearAbsBelowOne(b.speed_mm_s, a.speed_mm_s, kRootRelTol));
  EXPECT_TRUE(
      NearAbsBelowOne(b.energy_mj, 2.0 * a.energy_mj, kRootRelTol));  // twice the mass moved
  EXPECT_TRUE(NearAbsBelowOne(b.cot, a.cot, kRootRelTol));
}

// The example robot (docs/design.md): the best stable one-impact gait against a plain loop over m2
// that solves the robot's orbits itself (no design code) and keeps the fastest stable valid one.
TEST(Design, ExampleRobotBestMassAgreesWithAnIndependentScan) {
  const DesignInput in = Example();
  const double w = 2.0 * M_PI * 20.0, T0 = 0.3 * 9.81 / (w * w * 0.02);
  double best_m2 = NAN, best_v = -1.0;
  for (int i = 0; i < kReferenceScan; ++i) {
    const double m2 =
        kReferenceLo * std::pow(kReferenceHi / kReferenceLo, i / (kReferenceScan - 1.0));
    const double unit = (0.2 + m2) * w * w * 0.02;
    for (const Solution& s : FindRobotOrbits(
             {Forcing::Harmonic(0.5 / unit, 0.1 / unit, 0.0), Params{T0, 0.7}, m2 / (0.2 + m2)})) {
      if (!s.validity.valid() || !ComputeStability(s.orbit).stable) continue;
      const double v = w * 0.02 * s.orbit.v_mean;  // m/s
      if (v > best_v) {
        best_v = v;
        best_m2 = m2;
      }
    }
  }
  ASSERT_GT(best_v, 0.0);
  const DesignResult r = Design(in);
  ASSERT_EQ(r.status, DesignStatus::kOk) << r.message;
  EXPECT_TRUE(NearAbsBelowOne(r.one_impact.m2_kg, best_m2, kBestM2RelTol));
  EXPECT_TRUE(NearAbsBelowOne(r.one_impact.speed_mm_s, 1e3 * best_v, kBestM2RelTol));
  // The scan's best is a sample; the refined optimum is at least as fast.
  EXPECT_GE(r.one_impact.speed_mm_s, 1e3 * best_v * (1.0 - 1e-12));
  // Its limit is stability: a multiplier at -1 (period doubling; `capsubot solve --stability`).
  EXPECT_EQ(r.one_impact.binding, std::vector<std::string>{"rho_max"});
  // The bound of Design: scan, bracketing budget of 8 robots a sample, 100 steps a window.
  EXPECT_LE(r.robots, 9 * in.scan_points + 100);
}

TEST(Design, FrequencyRangeFindsTheLowestFrequencyWhenTheStrokeFits) {
  // Same robot; at fixed m2 the gait keeps its shape when f changes (section 6 scaling:
  // A, c, T0 all scale by 1/f^2) and its speed goes as 1/f, so the best frequency of
  // [10, 40] Hz is 10 Hz (the stroke 1 - x_min = 0.02 at 20 Hz is then 0.08: it fits),
  // with the same m2 and twice the speed of the 20 Hz design.
  DesignInput in = Example();
  in.m2_min = 0.1;
  in.m2_max = 0.4;
  in.scan_points = 16;
  const DesignResult fixed = Design(in);
  in.frequency_min = 10.0;
  in.frequency_max = 40.0;
  const DesignResult ranged = Design(in);
  ASSERT_EQ(fixed.status, DesignStatus::kOk) << fixed.message;
  ASSERT_EQ(ranged.status, DesignStatus::kOk) << ranged.message;
  EXPECT_EQ(ranged.one_impact.frequency_hz, 10.0);
  EXPECT_TRUE(NearAbsBelowOne(ranged.one_impact.m2_kg, fixed.one_impact.m2_kg, 1e-6));
  EXPECT_TRUE(
      NearAbsBelowOne(ranged.one_impact.speed_mm_s, 2.0 * fixed.one_impact.speed_mm_s, 1e-6));
  EXPECT_EQ(ranged.one_impact.binding, (std::vector<std::string>{"rho_max", "frequency_min"}));
}

TEST(Design, AMotorThatSlidesTheShellIsAStatusNotAnError) {
  DesignInput in = Example();
  // max |F_N| = 0.6 N slides the shell while mu (m1+m2) g < 0.6 N: m2 < 0.0039 kg.
  EXPECT_EQ(EvaluateGait(in, 0.003, 20.0).status, GaitStatus::kMotorSlidesShell);
  EXPECT_NE(EvaluateGait(in, 0.005, 20.0).status, GaitStatus::kMotorSlidesShell);
  in.force.amplitude = 5.0;  // slides the shell for every m2 below 1.84 kg
  in.m2_min = 0.01;
  in.m2_max = 1.0;
  const DesignResult r = Design(in);
  EXPECT_EQ(r.status, DesignStatus::kMotorSlidesShell);
  EXPECT_NE(r.message.find("slides the shell"), std::string::npos) << r.message;
  EXPECT_TRUE(std::isnan(r.one_impact.speed_mm_s));
}

TEST(Design, AFourierMotorWithOneSineTermIsTheHarmonicMotor) {
  DesignInput in = Example();
  const Gait a = EvaluateGait(in, kStableM2, 20.0);
  in.force.amplitude = NAN;
  in.force.sin = {0.5};
  in.force.cos = {0.0};
  const Gait b = EvaluateGait(in, kStableM2, 20.0);
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_TRUE(NearAbsBelowOne(b.speed_mm_s, a.speed_mm_s, kRootRelTol));
  EXPECT_TRUE(NearAbsBelowOne(b.solution.orbit.forcing.phi0(), a.solution.orbit.forcing.phi0(),
                              kRootRelTol));
}

struct BadInput {
  const char* name;
  void (*spoil)(DesignInput&);
  const char* message;
};

const BadInput kBadInputs[] = {
    {"m1", [](DesignInput& in) { in.m1 = 0.0; },
     "shell mass m1 = 0 is invalid: expected a finite m1 > 0 [kg]"},
    {"m1_default_m2_range", [](DesignInput& in) { in.m1 = 1e308; },
     "shell mass m1 = 1e+308 kg is invalid: expected m1 <= 1.7976931348623158e+307 kg, so that "
     "the default inner mass range 0.01 m1:10 m1 is finite (or give the inner mass range)"},
    {"L", [](DesignInput& in) { in.L = -0.02; },
     "gap L = -0.02 is invalid: expected a finite L > 0 [m]"},
    {"mu", [](DesignInput& in) { in.mu = NAN; },
     "friction coefficient mu = nan is invalid: expected a finite mu > 0"},
    {"g", [](DesignInput& in) { in.g = 0.0; },
     "gravity g = 0 is invalid: expected a finite g > 0 [m/s^2]"},
    {"e", [](DesignInput& in) { in.e = 1.5; },
     "restitution e = 1.5 is invalid: expected 0 <= e <= 1"},
    {"amplitude", [](DesignInput& in) { in.force.amplitude = -0.5; },
     "motor force amplitude = -0.5 is invalid: expected a finite amplitude >= 0 [N]"},
    {"bias", [](DesignInput& in) { in.force.bias = -0.1; },
     "motor force bias = -0.1 is invalid: expected a finite bias >= 0 [N]"},
    {"fourier_sizes",
     [](DesignInput& in) {
       in.force.sin = {0.5, 0.1};
       in.force.cos = {0.1};
     },
     "motor force cos = 1 coefficients is invalid: expected as many as sin (2)"},
    {"fourier_nan",
     [](DesignInput& in) {
       in.force.sin = {0.5, NAN};
     },
     "motor force sin[2] = nan is invalid: expected a finite coefficient [N]"},
    {"frequency", [](DesignInput& in) { in.frequency_min = in.frequency_max = 0.0; },
     "frequency f = 0 is invalid: expected a finite f > 0 [Hz]"},
    {"frequency_range",
     [](DesignInput& in) {
       in.frequency_min = 30.0;
       in.frequency_max = 20.0;
     },
     "frequency range = 30:20 is invalid: expected finite FMIN <= FMAX [Hz]"},
    {"m2_range",
     [](DesignInput& in) {
       in.m2_min = 0.5;
       in.m2_max = 0.5;
     },
     "inner mass range m2 = 0.5:0.5 is invalid: expected 0 < M2MIN < M2MAX [kg]"},
    {"margin", [](DesignInput& in) { in.margin = 0.5; },
     "margin d = 0.5 is invalid: expected 0 <= d < 0.5"},
    {"margin_stroke", [](DesignInput& in) { in.margin_stroke = -0.1; },
     "stroke margin d_s = -0.1 is invalid: expected 0 <= d_s < 0.5"},
    {"stick_margin", [](DesignInput& in) { in.stick_margin = 1.0; },
     "stick margin s = 1 is invalid: expected 0 <= s < 1"},
    {"rho_max", [](DesignInput& in) { in.rho_max = 0.0; },
     "rho_max = 0 is invalid: expected rho_max > 0"},
    {"scan_points", [](DesignInput& in) { in.scan_points = 2; },
     "scan_points = 2 is invalid: expected 3 <= scan_points <= 100000"},
    {"orbit_evaluations", [](DesignInput& in) { in.orbit_evaluations = 0; },
     "orbit_evaluations = 0 is invalid: expected 1 <= orbit_evaluations <= 1000000000"},
};

TEST(Design, EveryBadInputIsRejectedNamingTheParameterItsValueAndTheRule) {
  for (const BadInput& b : kBadInputs) {
    DesignInput in = Example();
    b.spoil(in);
    try {
      in.Validate();
      ADD_FAILURE() << b.name << ": accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(b.message), std::string::npos)
          << b.name << ": " << e.what();
    }
    EXPECT_THROW(Design(in), std::invalid_argument) << b.name;
  }
}

TEST(Design, GaitOfAGivenInnerMassRejectsABadMass) {
  const DesignInput in = Example();
  for (const double m2 : {-0.1, 0.0, std::numeric_limits<double>::infinity()}) {
    try {
      DesignGait(in, m2);
      ADD_FAILURE() << "accepted m2 = " << m2;
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()).rfind("inner mass m2 = ", 0), 0u) << e.what();
      EXPECT_NE(std::string(e.what()).find("expected a finite m2 > 0 [kg]"), std::string::npos);
    }
  }
}

// A friction bound that dwarfs the motor force (huge mu or g): the orbit searches cannot resolve
// the robot's orbits, and the design stops after a bounded number of robots instead of refining
// every circle to the search's bound (a minute or more per design).
struct FrictionCase {
  const char* name;
  double mu, g;
};

TEST(Design, HugeFrictionStopsAfterABoundedNumberOfUnresolvedRobots) {
  for (const FrictionCase& c :
       {FrictionCase{"mu = 1e6", 1e6, 9.81}, FrictionCase{"g = 1e7", 0.3, 1e7},
        FrictionCase{"g = 1e10", 0.3, 1e10}, FrictionCase{"g = 1e300", 0.3, 1e300}}) {
    const char* name = c.name;
    DesignInput in = testing::ExampleRobot();
    in.mu = c.mu;
    in.g = c.g;
    const DesignResult r = Design(in);
    EXPECT_EQ(r.unresolved_robots, kDesignMaxUnresolvedRobots) << name;
    EXPECT_LE(r.robots, 2 * kDesignMaxUnresolvedRobots) << name;
    EXPECT_FALSE(r.complete) << name;
    EXPECT_NE(r.message.find("the search stopped after"), std::string::npos) << name << r.message;
  }
}

// The work bound of each orbit search is a cost knob: a thousand times more changes nothing for
// the example robot, whose searches all end far below it.
TEST(Design, OrbitEvaluationsBoundChangesTheCostNotTheAnswer) {
  DesignInput in = testing::ExampleRobot();
  const DesignResult base = Design(in);
  in.orbit_evaluations = 1000 * kDesignOrbitEvaluations;
  const DesignResult more = Design(in);
  ASSERT_EQ(base.status, DesignStatus::kOk);
  EXPECT_TRUE(base.complete);
  EXPECT_EQ(base.unresolved_robots, 0);
  EXPECT_EQ(base.robots, more.robots);
  EXPECT_EQ(base.one_impact.m2_kg, more.one_impact.m2_kg);
  EXPECT_EQ(base.one_impact.speed_mm_s, more.one_impact.speed_mm_s);
  EXPECT_EQ(base.message, more.message);
}

}  // namespace
}  // namespace capsubot
