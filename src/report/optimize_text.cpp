#include "capsubot/report/optimize_text.hpp"

#include <fmt/format.h>

#include <cmath>
#include <string>
#include <vector>

#include "capsubot/orbit/scaling.hpp"
#include "capsubot/report/from_rest_text.hpp"
#include "capsubot/report/solve_text.hpp"
#include "capsubot/report/text_format.hpp"

namespace capsubot::text {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

std::string Join(const std::vector<std::string>& items, const char* none = "none") {
  std::string s;
  for (const auto& i : items) s += (s.empty() ? "" : ", ") + i;
  return s.empty() ? none : s;
}

std::vector<std::string> BindingNames(const OptimizeResult& r) {
  std::vector<std::string> names;
  for (Margin m : r.binding) names.emplace_back(MarginName(m));
  return names;
}

// What an active constraint or binding margin means for the gait.
const char* InPlainTerms(const std::string& name) {
  if (name == ConditionName(Condition::kLeftWall))
    return "the inner body just reaches the left wall";
  if (name == ConditionName(Condition::kRightWall)) {
    return "it just grazes the right wall before the impact";
  }
  if (name == ConditionName(Condition::kClearance)) {
    return "it comes exactly the required clearance close to a wall";
  }
  if (name == ConditionName(Condition::kStick)) {
    return "the force reaches its limit while the capsule rests";
  }
  if (name == ConditionName(Condition::kMassRatio)) return "alpha at its limit";
  if (name == kForceBoundName) return "the force uses its whole bound";
  if (name == MarginName(Margin::kRhoMax)) return "the spectral radius sits on rho_max";
  return "";
}

// A gait in plain terms, indented.
std::string GaitText(const OptimizeResult& r, double rho_max) {
  const Orbit& o = r.solution.orbit;
  const Validity& v = r.solution.validity;
  std::string t;
  t += fmt::format("    force            {}\n", ForceFormula(o.forcing));
  t += fmt::format("    inner mass ratio alpha = m2/(m1+m2) = {}\n", Num(o.alpha, 5));
  t +=
      fmt::format("    speed            I = {} gap lengths per period (mean velocity {} omega L)\n",
                  Num(o.I, 6), Num(o.v_mean, 5));
  t += fmt::format(
      "    impact           u = {} omega L, capsule kick v+ = {} omega L, slides "
      "until phi1 = {} rad\n",
      Num(o.u, 5), Num(o.v_plus, 5), Num(o.phi1, 5));
  t += fmt::format("    inner body       x from {} to {} (walls at 0 and 1){}\n", Num(v.x_min, 4),
                   std::isnan(v.x_max) ? "1 (at the impact)" : Num(v.x_max, 6),
                   v.clearance > 0.0 ? fmt::format(", clearance {}", Num(v.clearance, 4)) : "");
  t += fmt::format("    active           {}\n", Join(r.active_constraints));
  for (const auto& name : r.active_constraints) {
    const char* plain = InPlainTerms(name);
    if (*plain != '\0') t += fmt::format("                     - {}\n", plain);
  }
  if (r.found()) t += fmt::format("    margins binding  {}\n", Join(BindingNames(r)));
  if (!std::isnan(r.spectral_radius)) {
    const double rho = r.spectral_radius;
    // The stability requirement often binds: rho = rho_max up to the optimiser's tolerance.
    const bool boundary = std::isfinite(rho_max) && std::abs(rho - rho_max) <= 1e-6;
    t += fmt::format("    stability        spectral radius {} -> {}\n", Num(rho, 4),
                     boundary ? fmt::format("on the required bound rho_max = {:g}", rho_max)
                     : rho < 1.0
                         ? std::string("stable: a real robot settles on this gait")
                         : std::string("unstable: a real robot would drift away from this gait"));
  }
  t += fmt::format("    solver           {} ({} evaluations, status {})\n", r.algorithm,
                   r.evaluations, OptimizeStatusName(r.status));
  return t;
}

// How far T0, e and alpha can move: where a motion changes and where the robot's speed from
// rest leaves its band, in plain words.
std::string RobustnessText(const GaitRobustness& robustness, const char* motion) {
  return fmt::format(
             "    robustness       how far T0, e and alpha can move: where {} changes\n"
             "                     (its continuation, docs/continuation.md) and where the speed\n"
             "                     from rest leaves its band (simulation, docs/optimize.md):\n",
             motion) +
         robustness.Summary("                       ");
}

// Which gait to build, in plain words: the reach winner when it beats the robust gait from
// rest, else the robust gait.
std::string Advice(const OptimizeResult& robust, const ReachResult& reach) {
  const GaitFromRest& fr = reach.seed.from_rest;
  std::string t = "\nWhich to build:\n";
  if (std::isnan(reach.mean_velocity)) {
    return t + "  no motion from rest could be checked: see the messages above.\n";
  }
  const Attractor& top = reach.attractors.attractors.front();
  const std::string odds =
      top.fraction == 1.0
          ? std::string("every start from rest ends in it")
          : fmt::format("{:.0f} % of the starts from rest end in its most common motion",
                        100.0 * top.fraction);
  if (reach.seed_won) {
    return t + fmt::format(
                   "  the robust gait (2): it is also the fastest motion found from rest,\n"
                   "  {} omega L on average over the starts; {}.\n",
                   Num(reach.mean_velocity, 4), fr.summary);
  }
  t += fmt::format(
      "  the motion of 3 (A = {}, c = {}, alpha = {}): from rest the robot moves at {} omega L\n"
      "  on average over the starts; {}.\n",
      Num(reach.forcing.amplitude(), 4), Num(reach.forcing.mean(), 4), Num(reach.alpha, 4),
      Num(reach.mean_velocity, 4), odds);
  if (!reach.robust_to_settings) {
    t += "  Caution: under other numerical settings (see \"settings\" above) its starts hit the\n"
         "  work bound or its mean velocity moves by more than 1 %: check it with a finer\n"
         "  simulation before building.\n";
  }
  if (robust.found() && fr.checked) {
    t += fmt::format(
        "  The robust gait (2) promises {} omega L, but from rest the robot averages\n"
        "  {} omega L with it ({} of {} starts end on it).\n",
        Num(robust.solution.orbit.v_mean, 4), Num(fr.attractors.mean_velocity, 4), fr.reached,
        fr.attractors.starts);
  }
  return t;
}

// The header of the main job: the model, the requirements, the units.
std::string MainHeader(const MainJobResult& r) {
  const Params& p = r.params;
  std::string t;
  t += fmt::format(
      "capsubot optimize: the fastest gait of the capsule robot that the robot reaches "
      "(docs/model.md sections 7, 12, 13)\n"
      "model: T0 = {:g} (friction bound mu g/(omega^2 L)), e = {:g} (restitution)\n"
      "robust gait (docs/model.md section 12): clearance >= max(d = {:g}, d_s = {:g} x stroke), "
      "stick margin s = {:g}, spectral radius <= {:g}\n"
      "units: I = capsule displacement per forcing period in gap lengths L (the inner body's "
      "free gap); velocity in omega L\n"
      "(change them with --T0, --e, --margin, --margin-stroke, --stick-margin, --rho-max)\n\n",
      p.T0, p.e, r.gait.margins.clearance, r.gait.margins.clearance_stroke, r.gait.margins.stick,
      r.gait.rho_max);
  return t;
}

// 1. The paper's problem: its gait, or why there is none and what would fit.
std::string PaperText(const MainJobResult& r) {
  const Params& p = r.params;
  const OptimizeResult& paper = r.paper;
  std::string t;
  t += fmt::format(
      "1. The paper's problem (P1): force F = A sin(phi + phi0) + c with c = A = T0/2 = {:g},\n"
      "   best impact phase phi0 over the whole circle, valid orbits as the paper asks (no\n"
      "   margins: its force reaches the friction bound).\n",
      p.T0 / 2.0);
  if (paper.found()) {
    t += "   Result: a valid gait exists.\n" + GaitText(paper, kInf);
  } else {
    const Validity& v = paper.solution.validity;
    t += fmt::format(
        "   Result: NO valid gait (status {}). For every phi0 the constructed orbit breaks a\n"
        "   condition of docs/model.md section 5. Nearest to valid: phi0 = {}, I = {}, violating\n"
        "   {}.\n",
        OptimizeStatusName(paper.status), Num(paper.solution.orbit.forcing.phi0(), 6),
        Num(paper.solution.orbit.I, 6), Join(v.ViolationNames()));
    if (v.violations == (1U << static_cast<unsigned>(Condition::kLeftWall))) {
      // Scaling A, c, T0 by k scales 1 - x by k and leaves the other conditions unchanged
      // (docs/model.md section 6): the orbit fits once k (1 - x_min) <= 1.
      t += fmt::format(
          "   The inner body would have to reach x = {} (the shell spans 0..1): the force is\n"
          "   too strong for this shell. Orbit sizes scale with T0 (docs/model.md section 6): "
          "this\n"
          "   orbit would fit for T0 <= {} (a shorter shell or a faster motor). At T0 = {:g} a\n"
          "   weaker, differently shaped force is needed:\n",
          Num(v.x_min, 4), Num(LargestFittingT0(paper.solution, r.gait.margins.clearance), 4),
          p.T0);
    }
  }
  return t;
}

// 4. The fastest Fourier drives under the same bound, each simulated from every start.
std::string DrivesText(const std::vector<ReachResult>& drives, double bound) {
  if (drives.size() < 2) return "";
  std::string t = fmt::format(
      "\n4. The fastest drive: a motor makes any periodic force up to its peak, so the force\n"
      "   may be a Fourier series of K harmonics (each climbing from the winner of K - 1) or\n"
      "   piecewise constant, with max |F| <= {:g} (the bound of 3), simulated from every\n"
      "   start:\n",
      bound);
  const double sine = drives.front().mean_velocity;
  for (std::size_t k = 1; k < drives.size(); ++k) {
    const ReachResult& d = drives[k];
    t += fmt::format("   K = {}: mean velocity {} omega L, {} times the sine's {}{}\n",
                     d.drive.harmonics, Num(d.mean_velocity, 4),
                     fmt::format("{:.2f}", d.mean_velocity / sine), Num(sine, 4),
                     d.robust_to_settings ? "" : " (CAUTION: not robust to the settings)");
    t += fmt::format("    force            {}\n", ForceFormula(d.forcing));
    t += fmt::format("    inner mass ratio alpha = {}\n", Num(d.alpha, 5));
    t += fmt::format("    from rest        {}\n", d.summary);
  }
  return t;
}

// The fastest pulse drive under the same bound, against the sine.
std::string PulseText(const ReachResult& pulse, double sine) {
  if (std::isnan(pulse.mean_velocity)) return "";
  std::string t =
      fmt::format("   pulse, N = {} levels: mean velocity {} omega L, {} times the sine's{}\n",
                  pulse.drive.levels, Num(pulse.mean_velocity, 4),
                  fmt::format("{:.2f}", pulse.mean_velocity / sine),
                  pulse.robust_to_settings ? "" : " (CAUTION: not robust to the settings)");
  t += fmt::format("    force            {}\n", ForceFormula(pulse.forcing));
  t += fmt::format("    inner mass ratio alpha = {}\n", Num(pulse.alpha, 5));
  t += fmt::format("    from rest        {}\n", pulse.summary);
  return t +
         "   (a longer search: capsubot optimize --problem reach --harmonics K, or --waveform\n"
         "   pulse --pulse-levels N; docs/reach.md)\n";
}

// 2.-5. and the summary: the robust gait, the fastest motion from rest, the fastest drives, the
// exact optima.
std::string ResultsText(const MainJobResult& r) {
  const OptimizeResult& robust = r.robust;
  const OptimizeResult& fastest = r.fastest;
  const OptimizeResult& stable = r.stable;
  const ReachResult& reach = r.reach;
  const double bound = r.gait.force_bound;
  std::string t;
  t += fmt::format(
      "\n2. The fastest robust gait (P2): A, c and phi0 free, A + c <= {:g}, with the margins\n"
      "   above; checked from rest on {} starts.\n",
      bound, reach.seed.from_rest.attractors.starts);
  t += robust.found() ? GaitText(robust, r.gait.rho_max) + FromRestText(reach.seed.from_rest) +
                            RobustnessText(r.robustness, "this motion")
                      : fmt::format("   Result: none found ({})\n", robust.message);
  t += fmt::format(
      "\n3. The fastest motion from rest (any number of impacts, A + c <= {:g}, alpha free),\n"
      "   simulated from every start:\n",
      bound);
  t += ReachText(reach);
  if (!std::isnan(reach.mean_velocity)) {
    t += RobustnessText(r.reach_robustness, "its most common motion from rest");
  }
  t += DrivesText(r.drives, bound);
  if (!r.drives.empty()) t += PulseText(r.pulse, r.drives.front().mean_velocity);
  t += "\n5. For comparison, the exact optima without margins (they graze the walls: a robot\n"
       "   with slightly different parameters does something else).\n"
       "   The fastest valid gait:\n";
  t += fastest.found() ? GaitText(fastest, kInf)
                       : fmt::format("   Result: none found ({})\n", fastest.message);
  t += "   The fastest stable gait (spectral radius <= 1, docs/model.md section 8):\n";
  t += stable.found() ? GaitText(stable, 1.0)
                      : fmt::format("   Result: none found ({})\n", stable.message);
  if (robust.found() && fastest.found()) {
    t += fmt::format(
        "\nIn short: the fastest robust gait moves {} L per period with inner mass ratio {}\n"
        "({} of the exact, wall-grazing optimum {} L per period; margins binding: {}).\n",
        Num(robust.solution.orbit.I, 5), Num(robust.solution.orbit.alpha, 4),
        fmt::format("{:.1f}%", 100.0 * robust.solution.orbit.I / fastest.solution.orbit.I),
        Num(fastest.solution.orbit.I, 5), Join(BindingNames(robust)));
  }
  return t;
}

std::string Text(const MainJobResult& r) {
  return MainHeader(r) + PaperText(r) + ResultsText(r) + Advice(r.robust, r.reach);
}

// The best speed from rest for each number of harmonics, against the sine's.
std::string LadderText(const std::vector<ReachResult>& ladder) {
  if (ladder.empty()) return "";
  std::string t = "  best drive by number of harmonics (max |F| <= the same bound):\n";
  const double sine = ladder.front().mean_velocity;
  for (const ReachResult& step : ladder) {
    t += fmt::format(
        "    K = {:<2}          mean velocity {:.6g} omega L, {:.3g} times the sine; "
        "{}\n",
        step.drive.sine() ? 1 : step.drive.harmonics, step.mean_velocity, step.mean_velocity / sine,
        step.summary);
  }
  return t;
}

std::string Text(const ReachJobResult& r) {
  const Params& p = r.params;
  const Margins& m = r.gait.margins;
  const ReachResult& reach = r.reach;
  return fmt::format(
             "capsubot optimize --problem reach: T0 = {:g}, e = {:g}; seed: the robust gait "
             "(margins d = {:g}, d_s = {:g}, s = {:g}, spectral radius <= {:g})\n"
             "  status           {}\n"
             "  {}\n{}",
             p.T0, p.e, m.clearance, m.clearance_stroke, m.stick, r.gait.rho_max,
             OptimizeStatusName(reach.status), reach.message, ReachText(reach)) +
         LadderText(r.ladder);
}

std::string Text(const ProblemJobResult& pr) {
  const Params& p = pr.params;
  const Margins& m = pr.gait.margins;
  const OptimizeResult& r = pr.result;
  std::string t;
  t += fmt::format(
      "capsubot optimize --problem {}: T0 = {:g}, e = {:g}, margins d = {:g}, d_s = {:g}, "
      "s = {:g}, spectral radius <= {:g}\n",
      pr.problem, p.T0, p.e, m.clearance, m.clearance_stroke, m.stick, pr.gait.rho_max);
  t += fmt::format("  status           {}\n  {}\n", OptimizeStatusName(r.status), r.message);
  t += GaitText(r, pr.gait.rho_max) + FromRestText(pr.from_rest);
  if (pr.problem == "fourier") {
    t += fmt::format(
        "    gain over P2     {} (harmonic optimum I = {})\n",
        r.found() ? fmt::format("{:+.4g}%", 100.0 * (r.solution.orbit.I / r.baseline_I - 1.0))
                  : std::string("-"),
        Num(r.baseline_I, 8));
  }
  return t;
}

}  // namespace

std::string OptimizeJobText(const OptimizeJobResult& result) {
  return std::visit([](const auto& r) { return Text(r); }, result);
}

}  // namespace capsubot::text
