// The fastest drive of a real robot in each direction (docs/design.md, "Part (c): the fastest
// drive"): the reach search with the frequency and the inner mass free over the designer's ranges
// and the force bound tied to both, mapped back to newtons, hertz and kilograms, then both
// directions checked from rest.

#include "capsubot/design/design_drive.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "capsubot/model/forcing.hpp"
#include "capsubot/reach/drive_ladder.hpp"

namespace capsubot {
namespace {

// The robot of a dimensionless winner: its inner mass, frequency and force unit.
struct Robot {
  double m2 = 0.0, frequency = 0.0, omega = 0.0, force_unit = 0.0;
};

Robot RobotOfWinner(const DesignInput& in, const ReachResult& r) {
  Robot robot;
  robot.m2 = r.alpha * in.m1 / (1.0 - r.alpha);
  robot.omega = std::sqrt(in.mu * in.g / (r.T0 * in.L));
  robot.frequency = robot.omega / kTau;
  robot.force_unit = (in.m1 + robot.m2) * robot.omega * robot.omega * in.L;
  return robot;
}

// The force F(phi) = G(phi + phi0) of the search over the motor phase s = phi + phi0, times
// `unit`: the phase at the start of a grid's run is psi (the starts' own phase).
DriveForce InNewtons(const Forcing& f, double unit) {
  DriveForce d;
  d.max_abs = unit * f.MaxAbs();
  d.mean = unit * f.mean();
  const double phi0 = f.phi0();
  if (f.pulse()) {
    const int n = f.pulse_levels();
    std::vector<int> order(static_cast<std::size_t>(n));
    std::iota(order.begin(), order.end(), 0);
    const auto shifted = [&](int j) {
      const double s = std::fmod(f.switch_phase(j) - phi0, kTau);
      return s < 0.0 ? s + kTau : s;
    };
    std::sort(order.begin(), order.end(), [&](int a, int b) { return shifted(a) < shifted(b); });
    for (int j : order) {
      d.levels.push_back(unit * f.level(j));
      d.switches.push_back(shifted(j));
    }
    return d;
  }
  for (int k = 1; k <= f.harmonics(); ++k) {
    const double c = std::cos(k * phi0), s = std::sin(k * phi0);
    d.cos.push_back(unit * (f.a(k) * c + f.b(k) * s));
    d.sin.push_back(unit * (f.b(k) * c - f.a(k) * s));
  }
  return d;
}

DriveForce Negated(DriveForce d) {
  d.mean = -d.mean;
  for (auto* v : {&d.cos, &d.sin, &d.levels}) {
    for (double& x : *v) x = -x;
  }
  return d;
}

// The dimensionless robot of the winner, its force negated for the backward drive.
DesignModel ModelOf(const DesignInput& in, const ReachResult& r, const Robot& robot, double sign) {
  DesignModel m;
  m.robot.forcing = ScaledDrive(r.forcing, sign);
  m.robot.params.T0 = r.T0;
  m.robot.params.e = in.e;
  m.robot.alpha = r.alpha;
  m.omega = robot.omega;
  return m;
}

// The ranges of the search in the model: alpha over the inner masses, T0 over the frequencies
// (T0 = mu g/(omega^2 L) falls as f rises), the robot at their geometric middle. The bound is
// the motor's peak, but never above the friction force mu (m1+m2) g (a larger force slides the
// shell by itself): it is given at an inner mass where the peak is below friction (the middle,
// or the lightest that is heavier), or is the friction force everywhere when none is.
ReachOptions ReachOptionsFor(const DesignInput& in, const DriveDesignOptions& o,
                             const DriveFamily& drive, Params& params) {
  const auto alpha_of = [&](double m2) { return m2 / (in.m1 + m2); };
  const auto T0_of = [&](double f) { return in.mu * in.g / ((kTau * f) * (kTau * f) * in.L); };
  const double slides_below = o.force_max / (in.mu * in.g) - in.m1;  // friction = peak there
  const double m2 = std::max(std::sqrt(in.M2Min() * in.M2Max()), slides_below);
  const double f = std::sqrt(in.frequency_min * in.frequency_max);
  params.T0 = T0_of(f);
  params.e = in.e;
  const bool capped = m2 > in.M2Max();
  const double bound =
      capped ? params.T0 : o.force_max / ((in.m1 + m2) * (kTau * f) * (kTau * f) * in.L);
  ReachOptions r = drive.sine() ? o.effort.Options(bound, kNaN, o.check)
                                : o.effort.DriveOptions(drive, bound, kNaN, o.check);
  r.alpha_min = alpha_of(in.M2Min());
  r.alpha_max = alpha_of(in.M2Max());
  r.widen_alpha_box = false;
  if (!capped) r.bound_alpha = alpha_of(m2);
  if (in.frequency_min < in.frequency_max) {
    r.T0_min = T0_of(in.frequency_max);
    r.T0_max = T0_of(in.frequency_min);
  }
  return r;
}

std::string Message(const DriveDesignOptions& o, const DriveDesignResult& r) {
  if (!r.found()) {
    return fmt::format("no drive ({}, max |F_N| <= {:g} N) moves the robot from rest: {}",
                       o.drive.Describe(), o.force_max, r.forward.message);
  }
  const FromRestBest& b = r.forward;
  return fmt::format(
      "fastest drive from rest ({}, max |F_N| <= {:g} N): {:.6g} mm/s forward at m2 = {:.6g} kg, "
      "f = {:.6g} Hz, {:.6g} mW, COT {:.4g}; backward the mirror image -F_N: {:.6g} mm/s",
      o.drive.Describe(), o.force_max, b.speed_mm_s, b.m2_kg, b.frequency_hz, b.power_mw, b.cot,
      r.backward.speed_mm_s);
}

}  // namespace

void DriveDesignOptions::Validate() const {
  if (!(std::isfinite(force_max) && force_max > 0.0)) {
    throw std::invalid_argument(fmt::format(
        "force_max = {} is invalid: expected the motor's peak force, a finite force_max > 0 [N]",
        force_max));
  }
  drive.Validate();
  effort.Validate();
  check.Validate();
}

DriveDesignResult DesignDrive(const DesignInput& input, const DriveDesignOptions& o) {
  o.Validate();
  DesignInput in = input;
  in.force = MotorForce{o.force_max, 0.0, {}, {}};  // the peak, for the input's range checks
  in.Validate();
  Params params;
  const ReachOptions sine = ReachOptionsFor(in, o, DriveFamily{}, params);
  DriveDesignResult out;
  out.ladder.push_back(OptimizeReach(params, sine));
  if (!o.drive.sine()) {
    const ReachOptions options = ReachOptionsFor(in, o, o.drive, params);
    const OptimizeResult& seed = out.ladder.front().seed.gait;
    if (o.drive.waveform == Waveform::kPulse) {
      out.ladder.push_back(OptimizeReach(params, seed, options));
    } else {
      out.ladder = ClimbDriveLadder(params, seed, out.ladder.front(), options).steps;
    }
  }
  const ReachResult& best = out.reach();
  if (std::isnan(best.mean_velocity)) {
    out.forward.status = out.backward.status = FromRestStatus::kEventLimit;
    out.forward.message = best.message;
    out.message = Message(o, out);
    return out;
  }
  const Robot robot = RobotOfWinner(in, best);
  out.force = InNewtons(best.forcing, robot.force_unit);
  out.backward_force = Negated(out.force);
  out.forward = EvaluateModelFromRest(in, ModelOf(in, best, robot, 1.0), robot.m2, robot.frequency,
                                      Direction::kForward, o.check);
  out.backward = EvaluateModelFromRest(in, ModelOf(in, best, robot, -1.0), robot.m2,
                                       robot.frequency, Direction::kBackward, o.check);
  out.message = Message(o, out);
  return out;
}

}  // namespace capsubot
