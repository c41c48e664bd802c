#include "capsubot/report/design_text.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <vector>

#include "capsubot/continue/gait_robustness.hpp"
#include "capsubot/design/gait_numbers.hpp"
#include "capsubot/numerics/not_computed.hpp"
#include "capsubot/report/attractors_text.hpp"
#include "capsubot/report/text_format.hpp"

namespace capsubot::text {
namespace {

std::string Num(double value, const char* unit) {
  return std::isnan(value) ? "-" : fmt::format("{:.6g}{}", value, unit);
}

std::string MotorFormula(const MotorForce& f) {
  if (!f.fourier()) {
    return fmt::format("F_N = {:g} sin(omega t + phase) + {:g} N", f.amplitude, f.bias);
  }
  std::string s = fmt::format("F_N = {:g}", f.bias);
  for (std::size_t k = 0; k < f.sin.size(); ++k) {
    const double a = f.cos.empty() ? 0.0 : f.cos[k];
    s += fmt::format(" + {:g} cos {}s + {:g} sin {}s", a, k + 1, f.sin[k], k + 1);
  }
  return s + " N, s = omega t + phase";
}

// Shortest text that reads back as the same double ("0.7", not "0.69999999999999996").
std::string Shortest(double value) { return fmt::format("{}", value); }

// The `capsubot solve` command that reproduces the gait's orbit (round-trip numbers).
std::string SolveCommand(const Gait& g) {
  const Orbit& o = g.solution.orbit;
  const Forcing& f = o.forcing;
  std::string force;
  if (f.harmonic()) {
    force = fmt::format("--A {} --c {}", Shortest(f.amplitude()), Shortest(f.mean()));
  } else {
    std::vector<std::string> a, b;
    for (int k = 1; k <= f.harmonics(); ++k) {
      a.push_back(Shortest(f.a(k)));
      b.push_back(Shortest(f.b(k)));
    }
    force = fmt::format("--c {} --cos {} --sin {}", Shortest(f.mean()), fmt::join(a, ","),
                        fmt::join(b, ","));
  }
  return fmt::format("capsubot solve {} --phi0 {} --T0 {} --e {} --stability", force,
                     Shortest(f.phi0()), Shortest(o.T0), Shortest(o.e));
}

// Part (a): the robot, what was searched and the gait found.
std::string OneImpactText(const DesignInput& in, const DesignResult& r) {
  const Gait& g = r.one_impact;
  std::string t = "robot design: the fastest robust one-impact gait\n";
  t += fmt::format(
      "  robot             m1 = {:g} kg, L = {:g} mm, mu = {:g}, g = {:g} m/s^2, e = {:g}\n", in.m1,
      1e3 * in.L, in.mu, in.g, in.e);
  t += fmt::format("  motor             {}\n", MotorFormula(in.force));
  t += fmt::format("  searched          m2 in [{:g}, {:g}] kg, f {}\n", in.M2Min(), in.M2Max(),
                   in.frequency_min == in.frequency_max
                       ? fmt::format("= {:g} Hz", in.frequency_min)
                       : fmt::format("in [{:g}, {:g}] Hz", in.frequency_min, in.frequency_max));
  t += fmt::format("  robust gait       d = {:g}, d_s = {:g}, s = {:g}, rho_max = {:g}\n",
                   in.margin, in.margin_stroke, in.stick_margin, in.rho_max);
  t += fmt::format("  status            {}: {}\n", DesignStatusName(r.status), r.message);
  if (!r.complete)
    t += "  note              an orbit search hit its work bound: orbits may be missing\n";
  if (!g.ok()) return t;
  const Orbit& o = g.solution.orbit;
  t += fmt::format("  inner mass        m2 = {}   (alpha = m2/(m1+m2) = {:.6g})\n",
                   Num(g.m2_kg, " kg"), o.alpha);
  t += fmt::format("  frequency         f = {}\n", Num(g.frequency_hz, " Hz"));
  t += fmt::format("  mean speed        {}\n", Num(g.speed_mm_s, " mm/s"));
  t += fmt::format("  step per period   {}\n", Num(g.displacement_mm, " mm"));
  t += fmt::format("  impact velocity   {}   (inner body relative to the shell)\n",
                   Num(g.impact_velocity_m_s, " m/s"));
  t += fmt::format("  motor energy      {} per period\n", Num(g.energy_mj, " mJ"));
  t += fmt::format("  mean motor power  {} net, {} positive part\n", Num(g.power_mw, " mW"),
                   Num(g.power_positive_mw, " mW"));
  t += fmt::format("  losses            friction {}, impacts {} per period\n",
                   Num(g.friction_loss_mj, " mJ"), Num(g.impact_loss_mj, " mJ"));
  t += fmt::format("  cost of transport COT = {} (>= mu = {:g}), efficiency mu/COT = {}\n",
                   Num(g.cot, ""), in.mu, Num(g.efficiency, ""));
  const auto d = Dimensionless(g);
  t += fmt::format("  dimensionless     T0 = {}, A = {}, c = {}, alpha = {}, phi0 = {}\n",
                   Num(d[0].second, ""), Num(d[1].second, ""), Num(d[2].second, ""),
                   Num(d[3].second, ""), Num(d[4].second, ""));
  t +=
      fmt::format("  orbit             x_min = {}, x_max = {}, spectral radius = {}, {} orbit(s)\n",
                  Num(g.solution.validity.x_min, ""), XMaxText(g.solution.validity.x_max, 6),
                  Num(g.stability.spectral_radius, ""), g.orbits);
  t += fmt::format("  binding           {}\n", g.binding.empty()
                                                   ? "none (an interior maximum)"
                                                   : fmt::format("{}", fmt::join(g.binding, ", ")));
  t += fmt::format("  check             {}\n", SolveCommand(g));
  return t;
}

// A value of a robustness parameter with its unit and its change from the design's value in
// percent (none from a design's value of 0, e = 0: no relative change).
std::string ValueWithChange(double v, const char* unit, double value) {
  const std::string change =
      value == 0.0 ? "" : fmt::format(" ({:+.3g} %)", 100.0 * (v - value) / value);
  return fmt::format("{:.6g}{}{}", v, unit, change);
}

// How far mu, e and m2 carry the gait of a robot of length L [m]: the continuation's limits
// each way and the speed band.
std::string RobustnessText(const GaitRobustness& robustness, const Gait& g, double L) {
  std::string t =
      "  robustness        how far mu, e and m2 can move, the rest of the robot fixed: where the\n"
      "                    gait's motion changes (its continuation) and where the speed from\n"
      "                    rest leaves its band (simulation; docs/design.md):\n";
  const std::string indent = "                      ";
  // The band's speeds are in omega L: in mm/s, times 1e3 omega L.
  const double mm_s = 1e3 * g.model.omega * L;
  for (const ParameterRobustness& p : robustness.parameters) {
    const bool mass = p.name == "m2_kg";
    const std::string name = mass ? "m2" : p.name;
    const char* unit = mass ? " kg" : "";
    const auto value = [&](double v) { return ValueWithChange(v, unit, p.value); };
    t += fmt::format("{}{} = {:.6g}{}, searched in [{:.6g}, {:.6g}]{}:\n", indent, name, p.value,
                     unit, p.from, p.to, unit);
    if (p.status != ContinuationStatus::kOk) {
      t += fmt::format("{}  continuation: not followed ({})\n", indent, p.message);
    } else {
      t += fmt::format("{}  down: {}\n", indent, p.down.Text(name, value(p.down.parameter)));
      t += fmt::format("{}  up:   {}\n", indent, p.up.Text(name, value(p.up.parameter)));
    }
    ParameterRobustness named = p;
    named.name = name;
    t += named.BandText(value, fmt::format("{:.6g} mm/s", mm_s * p.band.nominal_speed),
                        indent + "  ");
  }
  return t;
}

// Attractors listed one by one in the text (the rest are summed).
constexpr std::size_t kListedAttractors = 4;

// The attractors of a motion from rest: the first kListedAttractors, then the rest summed;
// `mm_s` converts a mean velocity in omega L to mm/s.
std::string AttractorLines(const Attractors& attractors, double mm_s, int max_period) {
  std::string t;
  const auto& list = attractors.attractors;
  for (std::size_t k = 0; k < list.size() && k < kListedAttractors; ++k) {
    const Attractor& a = list[k];
    t += fmt::format("    attractor {:<5} {:.0f} % of the starts: {}, {}\n", k + 1,
                     100.0 * a.fraction, AttractorWords(a, max_period),
                     Num(mm_s * a.mean_velocity, " mm/s"));
  }
  if (list.size() > kListedAttractors) {
    double rest = 0.0;
    for (std::size_t k = kListedAttractors; k < list.size(); ++k) rest += list[k].fraction;
    t += fmt::format("    and             {} more attractors, {:.0f} % of the starts\n",
                     list.size() - kListedAttractors, 100.0 * rest);
  }
  return t;
}

// One direction of the from-rest design in lines of the table.
std::string FromRestLines(const DesignInput& in, const FromRestBest& b, int max_period) {
  std::string t = fmt::format("  {:<17} {}: {}\n", DirectionName(b.direction),
                              FromRestStatusName(b.status), b.message);
  if (!b.ok()) return t;
  const DesignModel& m = b.model;
  t += fmt::format("    inner mass      m2 = {}   (alpha = {:.6g}), f = {}\n", Num(b.m2_kg, " kg"),
                   m.robot.alpha, Num(b.frequency_hz, " Hz"));
  t += fmt::format("    mean speed      {} over the starts, {} per period\n",
                   Num(b.speed_mm_s, " mm/s"), Num(b.displacement_mm, " mm"));
  t += fmt::format("    impact velocity {}\n",
                   std::isnan(b.impact_velocity_m_s)
                       ? std::string("- (the most common motion has several impacts per period)")
                       : Num(b.impact_velocity_m_s, " m/s"));
  t +=
      fmt::format("    motor           {} per period, {} net, {} positive part\n",
                  Num(b.energy_mj, " mJ"), Num(b.power_mw, " mW"), Num(b.power_positive_mw, " mW"));
  t += fmt::format("    losses          friction {}, impacts {} per period\n",
                   Num(b.friction_loss_mj, " mJ"), Num(b.impact_loss_mj, " mJ"));
  t += fmt::format("    cost            COT = {}, efficiency mu/COT = {}\n", Num(b.cot, ""),
                   Num(b.efficiency, ""));
  t += fmt::format("    dimensionless   T0 = {}, A = {}, c = {}, alpha = {}\n",
                   Num(m.robot.params.T0, ""),
                   Num(m.robot.forcing.harmonic() ? m.robot.forcing.amplitude() : kNaN, ""),
                   Num(m.robot.forcing.mean(), ""), Num(m.robot.alpha, ""));
  return t + AttractorLines(b.attractors, 1e3 * b.model.omega * in.L, max_period);
}

// Part (b): the fastest motion from rest in each direction, checked with `options.check`.
std::string FromRestText(const DesignInput& in, const DesignFromRestOptions& options,
                         const DesignFromRestResult& r) {
  const int max_period = options.check.attractor.motion.max_period;
  std::string t = fmt::format(
      "robot design: the fastest motion reached from rest, each direction ({}x{} starts from "
      "rest)\n",
      options.check.n_x, options.check.n_psi);
  t += FromRestLines(in, r.forward, max_period);
  t += FromRestLines(in, r.backward, max_period);
  t += fmt::format(
      "  search            {} from-rest evaluations ({} rejected: event_limit), "
      "{:.1f} s{}\n",
      r.evaluations, r.rejected_evaluations, r.search_seconds,
      r.max_time ? "; the time limit (--reach-seconds) stopped a search stage" : "");
  return t;
}

// A drive in newtons as a formula of the phase s of the starts.
std::string DriveFormula(const DriveForce& d) {
  if (!d.levels.empty()) {
    std::vector<std::string> pieces;
    for (std::size_t j = 0; j < d.levels.size(); ++j) {
      pieces.push_back(fmt::format("{:.4g} N from s = {:.4g}", d.levels[j], d.switches[j]));
    }
    return fmt::format("F_N(s) = {}", fmt::join(pieces, ", "));
  }
  const auto term = [](double v) {
    return fmt::format(" {} {:.4g}", v < 0.0 ? '-' : '+', std::abs(v));
  };
  std::string s = fmt::format("F_N(s) = {:.4g}", d.mean);
  for (std::size_t k = 0; k < d.sin.size(); ++k) {
    s += fmt::format("{} cos {}s{} sin {}s", term(d.cos[k]), k + 1, term(d.sin[k]), k + 1);
  }
  return s + " N";
}

// The fastest drive: its waveform, the ladder of the search, both directions from rest.
std::string DriveText(const DesignInput& in, const DriveDesignResult& r, int max_period) {
  const ReachResult& best = r.reach();
  std::string t = fmt::format("robot design: the fastest drive from rest ({})\n  {}\n",
                              best.drive.Describe(), r.message);
  if (r.found()) {
    t += fmt::format("  forward drive     {} (s: the motor phase), max |F_N| = {}\n",
                     DriveFormula(r.force), Num(r.force.max_abs, " N"));
    t += fmt::format("  backward drive    {}: the mirror image\n", DriveFormula(r.backward_force));
  }
  for (const ReachResult& step : r.ladder) {
    t += fmt::format("  search            {:<16} speed {} sqrt(mu g L) at T0 = {}, alpha = {}{}\n",
                     step.drive.Describe(), Num(step.mean_velocity / std::sqrt(step.T0), ""),
                     Num(step.T0, ""), Num(step.alpha, ""),
                     step.robust_to_settings ? "" : " (not robust to the settings)");
  }
  t += FromRestLines(in, r.forward, max_period);
  t += FromRestLines(in, r.backward, max_period);
  return t;
}

}  // namespace

// Part (a)'s gait started from rest: how many starts end on it, the speed averaged over all
// starts, and where they go.
std::string GaitFromRestText(const DesignInput& in, const Gait& g, const GaitFromRest& fr,
                             int max_period) {
  const Attractors& a = fr.attractors;
  const double mm_s = 1e3 * g.model.omega * in.L;
  std::string t = fmt::format(
      "  from rest         the gait is reached from {} of {} starts from rest ({:.0f} %); over "
      "all starts the robot moves at {}\n",
      fr.reached, a.starts, 100.0 * static_cast<double>(fr.reached) / static_cast<double>(a.starts),
      Num(mm_s * a.mean_velocity, " mm/s"));
  return t + AttractorLines(a, mm_s, max_period);
}

// The advice of part (b)'s forward motion, with what part (a)'s gait does from rest.
std::string ForwardAdvice(const DesignJobResult& r) {
  const FromRestBest& b = r.from_rest->forward;
  const std::string t =
      fmt::format("  the forward motion of part (b): m2 = {} at {}, {} from rest averaged\n",
                  Num(b.m2_kg, " kg"), Num(b.frequency_hz, " Hz"), Num(b.speed_mm_s, " mm/s"));
  const double from_rest = GaitSpeedFromRest(r);
  if (std::isnan(from_rest)) return t + "  over the starts (part (a) has no gait).\n";
  return t + fmt::format(
                 "  over the starts; the gait of part (a) promises {} but averages {} from\n"
                 "  rest ({} of {} starts end on it).\n",
                 Num(r.design.one_impact.speed_mm_s, " mm/s"), Num(from_rest, " mm/s"),
                 r.gait_from_rest.reached, r.gait_from_rest.attractors.starts);
}

// The advice of part (a)'s gait: its promise and, when some starts miss it, what the robot
// does from rest.
std::string GaitAdvice(const DesignJobResult& r) {
  const GaitFromRest& fr = r.gait_from_rest;
  const Gait& g = r.design.one_impact;
  if (fr.reached == fr.attractors.starts) {
    return fmt::format("  the gait of part (a): every start from rest ends on it, at {}.\n",
                       Num(g.speed_mm_s, " mm/s"));
  }
  return fmt::format(
             "  the gait of part (a). It promises {}, but only {} of {} starts from rest end on "
             "it:\n"
             "  from rest the robot averages {}.",
             Num(g.speed_mm_s, " mm/s"), fr.reached, fr.attractors.starts,
             Num(GaitSpeedFromRest(r), " mm/s")) +
         (r.from_rest ? " Part (b) finds nothing faster forward from rest.\n"
                      : " --from-rest searches for a faster motion from rest.\n");
}

// Part (b)'s backward motion when it is faster from rest than `forward` [mm/s], else "".
std::string FasterBackward(const DesignJobResult& r, double forward) {
  if (!r.from_rest || !r.from_rest->backward.ok()) return "";
  const FromRestBest& b = r.from_rest->backward;
  if (!(std::abs(b.speed_mm_s) > forward)) return "";
  return fmt::format("  Backward the robot goes faster: part (b)'s m2 = {} at {}, {} from rest.\n",
                     Num(b.m2_kg, " kg"), Num(b.frequency_hz, " Hz"), Num(b.speed_mm_s, " mm/s"));
}

// Which answer to build, in plain words (ChooseDesign), and a faster backward motion.
std::string Advice(const DesignJobResult& r) {
  const std::string t = "\nWhich to build:\n";
  switch (ChooseDesign(r)) {
    case DesignChoice::kNone:
      return t + "  nothing: no robust one-impact gait" +
             (r.from_rest ? " and no motion forward from rest.\n" + FasterBackward(r, 0.0)
                          : std::string("; --from-rest searches the motions from rest.\n"));
    case DesignChoice::kFromRestForward:
      return t + ForwardAdvice(r) + FasterBackward(r, r.from_rest->forward.speed_mm_s);
    case DesignChoice::kGait:
      break;
  }
  return t + GaitAdvice(r) + FasterBackward(r, GaitSpeedFromRest(r));
}

std::string DesignJobText(const DesignJobResult& r) {
  if (r.grid) {
    const SweepSummary& s = r.grid->summary;
    return fmt::format("{} points written to {} in {:.3f} s on {} threads\n", s.points,
                       r.grid->output, s.seconds, s.threads);
  }
  const int max_period = r.from_rest_options.check.attractor.motion.max_period;
  if (r.drive) return DriveText(r.input, *r.drive, max_period);
  std::string t = OneImpactText(r.input, r.design);
  if (r.gait_from_rest.checked) {
    t += GaitFromRestText(r.input, r.design.one_impact, r.gait_from_rest, max_period);
  }
  if (!r.robustness.parameters.empty()) {
    t += RobustnessText(r.robustness, r.design.one_impact, r.input.L);
  }
  if (r.from_rest) t += FromRestText(r.input, r.from_rest_options, *r.from_rest);
  return t + Advice(r);
}

}  // namespace capsubot::text
