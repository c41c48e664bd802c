// The fastest drive of a real robot (docs/design.md, "Part (c)"): the SI answer
// against the dimensionless search it maps (units converted independently here), the force in
// newtons against the search's force over the motor phase, the peak bound, the ranges, the
// mirror image backward simulated from rest, bad options.

#include "capsubot/design/design_drive.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "design/example_robot.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

// Samples of one period for the peak and the waveform checks (the force has at most 3
// harmonics or 3 levels: far finer than its features).
constexpr int kSamples = 4096;
// The conversions to and from SI units are a few floating-point operations.
constexpr double kUnitsRelTol = 1e-12;
// The same robot re-checked on the same starts: its mean velocity to rounding of the force's
// coefficients (the same runs).
constexpr double kSameCheckRelTol = 1e-9;
// The mirror image simulated: a periodic motion's mirror has the same mean velocity to
// rounding; a motion without a period is a time average over the check's 100 periods, and its
// mirror image, rounded differently, averages another stretch of it (measured: 0.5 and 0.6 %
// for the two-harmonic and the pulse drive here).
constexpr double kMirrorPeriodicRelTol = 1e-9;
constexpr double kMirrorAverageRelTol = 0.03;

bool AllPeriodic(const Attractors& a) {
  for (const Attractor& m : a.attractors) {
    if (m.motion.status != MotionStatus::kPeriodic) return false;
  }
  return !a.attractors.empty();
}

// A small search: 2 x 2 starts, small budgets, the frequency over an octave, m2 over a decade.
DriveDesignOptions QuickDrive(const DriveFamily& drive) {
  DriveDesignOptions o;
  o.drive = drive;
  o.force_max = 0.6;
  o.effort.n_x = o.effort.n_psi = 2;
  o.effort.global_evaluations = 30;
  o.effort.local_evaluations = 10;
  o.effort.drive_evaluations = 40;
  o.effort.drive_polishes = 1;
  o.effort.drive_local_evaluations = 20;
  o.effort.max_seconds = HUGE_VAL;
  o.check.n_x = o.check.n_psi = 4;
  return o;
}

DesignInput Robot() {
  DesignInput in = testing::ExampleRobot();
  in.frequency_min = 10.0;
  in.frequency_max = 20.0;
  in.m2_min = 0.05;
  in.m2_max = 0.5;
  return in;
}

// F_N(s) of a drive in newtons.
double ForceAt(const DriveForce& d, double s) {
  if (!d.levels.empty()) {
    double value = d.levels.back();  // before the first switch: the last level, wrapped
    for (std::size_t j = 0; j < d.levels.size(); ++j) {
      if (s >= d.switches[j]) value = d.levels[j];
    }
    return value;
  }
  double value = d.mean;
  for (std::size_t k = 0; k < d.sin.size(); ++k) {
    const double n = static_cast<double>(k + 1);
    value += d.cos[k] * std::cos(n * s) + d.sin[k] * std::sin(n * s);
  }
  return value;
}

void ExpectTheSearchInUserUnits(const DriveDesignResult& r, const DesignInput& in,
                                const DriveDesignOptions& o) {
  ASSERT_TRUE(r.found()) << r.message;
  const ReachResult& best = r.reach();
  // The robot, converted here: alpha = m2/(m1+m2), T0 = mu g/((2 pi f)^2 L).
  const double m2 = r.forward.m2_kg, f = r.forward.frequency_hz, w = kTau * f;
  EXPECT_NEAR(m2 / (in.m1 + m2), best.alpha, kUnitsRelTol);
  EXPECT_NEAR(in.mu * in.g / (w * w * in.L) / best.T0, 1.0, kUnitsRelTol);
  EXPECT_GE(m2, in.m2_min * (1.0 - kUnitsRelTol));
  EXPECT_LE(m2, in.m2_max * (1.0 + kUnitsRelTol));
  EXPECT_GE(f, in.frequency_min * (1.0 - kUnitsRelTol));
  EXPECT_LE(f, in.frequency_max * (1.0 + kUnitsRelTol));
  // The speed: the same starts, the same robot, the mean velocity in units of omega L.
  EXPECT_NEAR(r.forward.mean_velocity / best.mean_velocity, 1.0, kSameCheckRelTol) << r.message;
  EXPECT_NEAR(r.forward.speed_mm_s / (1e3 * w * in.L * best.mean_velocity), 1.0, kSameCheckRelTol);
  // The force in newtons at the phase s of the starts is the search's force F(s), times the
  // unit (m1+m2) omega^2 L; its peak is within the motor's.
  const double unit = (in.m1 + m2) * w * w * in.L;
  double peak = 0.0;
  for (int i = 0; i < kSamples; ++i) {
    const double s = kTau * (i + 0.5) / kSamples;
    const double newtons = ForceAt(r.force, s);
    EXPECT_NEAR(newtons, unit * best.forcing.F(s), 1e-9 * o.force_max) << "s = " << s;
    EXPECT_DOUBLE_EQ(ForceAt(r.backward_force, s), -newtons);
    peak = std::max(peak, std::abs(newtons));
  }
  EXPECT_LE(peak, o.force_max * (1.0 + 1e-12));
  EXPECT_LE(r.force.max_abs, o.force_max * (1.0 + 1e-12));
  // Backward: the mirror image drives the same robot back at the same speed, simulated.
  ASSERT_TRUE(r.backward.ok()) << r.backward.message;
  const bool periodic = AllPeriodic(r.forward.attractors) && AllPeriodic(r.backward.attractors);
  EXPECT_NEAR(r.backward.speed_mm_s / -r.forward.speed_mm_s, 1.0,
              periodic ? kMirrorPeriodicRelTol : kMirrorAverageRelTol);
  EXPECT_GT(r.forward.power_mw, 0.0);
  EXPECT_GE(r.forward.cot, in.mu * (1.0 - kUnitsRelTol));  // the motor pays at least friction
}

TEST(DesignDrive, TheSineSearchInUserUnits) {
  const DesignInput in = Robot();
  const DriveDesignOptions o = QuickDrive(DriveFamily{});
  const DriveDesignResult r = DesignDrive(in, o);
  ASSERT_EQ(r.ladder.size(), 1U);
  ExpectTheSearchInUserUnits(r, in, o);
}

TEST(DesignDrive, TwoHarmonicsInUserUnitsAtLeastTheSine) {
  const DesignInput in = Robot();
  const DriveDesignOptions o = QuickDrive(DriveFamily::Fourier(2));
  const DriveDesignResult r = DesignDrive(in, o);
  ASSERT_EQ(r.ladder.size(), 2U);
  ExpectTheSearchInUserUnits(r, in, o);
  // The ladder starts from the sine: the physical speed never falls below it.
  const auto speed = [](const ReachResult& s) { return s.mean_velocity / std::sqrt(s.T0); };
  EXPECT_GE(speed(r.ladder[1]), speed(r.ladder[0]) * (1.0 - 1e-12));
}

TEST(DesignDrive, APulseDriveInUserUnits) {
  const DesignInput in = Robot();
  const DriveDesignOptions o = QuickDrive(DriveFamily::Pulse(2));
  const DriveDesignResult r = DesignDrive(in, o);
  ExpectTheSearchInUserUnits(r, in, o);
  EXPECT_EQ(r.force.levels.size(), 2U);
}

TEST(DesignDrive, BadOptionsAreNamed) {
  DriveDesignOptions o = QuickDrive(DriveFamily{});
  o.force_max = -1.0;
  try {
    DesignDrive(Robot(), o);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()),
              "force_max = -1 is invalid: expected the motor's peak force, a finite force_max > 0 "
              "[N]");
  }
  o.force_max = 0.6;
  DesignInput in = Robot();
  in.mu = -0.3;
  EXPECT_THROW(DesignDrive(in, o), std::invalid_argument);
}

}  // namespace
}  // namespace capsubot
