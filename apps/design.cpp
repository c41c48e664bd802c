// capsubot design: a real robot in SI units; the inner mass (and motor frequency) of its
// fastest robust one-impact gait, with speed, power and cost of transport (library:
// capsubot/design.hpp).

#include "capsubot/design.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "capsubot/io.hpp"
#include "commands.hpp"
#include "design_config.hpp"
#include "json/design_json.hpp"
#include "provenance.hpp"
#include "report.hpp"

namespace capsubot::app {
namespace {

struct DesignCliOptions {
  DesignConfigOptions config;
  bool json = false;
  std::string sweep;
  std::string output;
};

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The gait's numbers for the table and the CSV are those of its JSON (src/json/).
using json::Dimensionless;
using json::UserUnits;

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

std::string Table(const DesignInput& in, const DesignResult& r) {
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
                  Num(g.solution.validity.x_min, ""), Num(g.solution.validity.x_max, ""),
                  Num(g.stability.spectral_radius, ""), g.orbits);
  t += fmt::format("  binding           {}\n", g.binding.empty()
                                                   ? "none (an interior maximum)"
                                                   : fmt::format("{}", fmt::join(g.binding, ", ")));
  t += fmt::format("  check             {}\n", SolveCommand(g));
  return t;
}

// A one-line count of the robots evaluated on stderr, redrawn at most 10 times a second.
DesignProgress ProgressLine() {
  if (::isatty(STDERR_FILENO) == 0) return {};
  auto last = std::make_shared<std::chrono::steady_clock::time_point>();
  return [last](std::int64_t done, std::int64_t total) {
    const auto now = std::chrono::steady_clock::now();
    if (now - *last < std::chrono::milliseconds(100)) return;
    *last = now;
    fmt::print(stderr, "\rdesign: {} robots evaluated (at most {}) ", done, total);
    std::fflush(stderr);
  };
}

void EndProgress(const DesignProgress& progress) {
  if (progress) fmt::print(stderr, "\r\033[K");
}

// "m2:0.01:2:50" -> variable, lo, hi, n.
struct SweepSpec {
  DesignSweepVariable variable = DesignSweepVariable::kM2;
  double lo = kNaN, hi = kNaN;
  int n = 0;
};

SweepSpec ParseSweep(const std::string& text) {
  const auto bad = [&text]() {
    return std::invalid_argument(fmt::format(
        "--sweep = {} is invalid: expected m2:M2MIN:M2MAX:N [kg] or frequency:FMIN:FMAX:N [Hz]",
        text));
  };
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (int i = 0; i < 4; ++i) {
    const std::size_t end = i < 3 ? text.find(':', start) : text.size();
    if (end == std::string::npos) throw bad();
    parts.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  SweepSpec s;
  if (parts[0] == "m2") {
    s.variable = DesignSweepVariable::kM2;
  } else if (parts[0] == "frequency") {
    s.variable = DesignSweepVariable::kFrequency;
  } else {
    throw bad();
  }
  try {
    std::size_t used = 0;
    s.lo = std::stod(parts[1], &used);
    if (used != parts[1].size()) throw bad();
    s.hi = std::stod(parts[2], &used);
    if (used != parts[2].size()) throw bad();
    s.n = std::stoi(parts[3], &used);
    if (used != parts[3].size()) throw bad();
  } catch (const std::logic_error&) {  // stod/stoi: no number or out of range
    throw bad();
  }
  return s;
}

void WriteSweep(const std::vector<Gait>& rows, const std::string& path) {
  AtomicFile file(path, "-o");
  auto& out = file.stream();
  std::vector<std::string> header = {"status"};
  for (const auto& [key, value] : UserUnits(Gait{})) header.emplace_back(key);
  for (const auto& [key, value] : Dimensionless(Gait{})) header.emplace_back(key);
  header.emplace_back("orbits");
  header.emplace_back("binding");
  out << fmt::format("{}\n", fmt::join(header, ","));
  for (const Gait& g : rows) {
    std::vector<std::string> cells = {GaitStatusName(g.status)};
    for (const auto& [key, value] : UserUnits(g)) cells.push_back(FormatNumber(value));
    for (const auto& [key, value] : Dimensionless(g)) cells.push_back(FormatNumber(value));
    cells.push_back(std::to_string(g.orbits));
    cells.push_back(fmt::format("{}", fmt::join(g.binding, ";")));
    out << fmt::format("{}\n", fmt::join(cells, ","));
  }
  file.Commit();
}

int Run(const DesignCliOptions& opt, const CLI::App& cmd) {
  const DesignInput input = BuildDesignInput(opt.config);
  const DesignProgress progress = ProgressLine();
  if (!opt.sweep.empty()) {
    const SweepSpec spec = ParseSweep(opt.sweep);
    if (opt.output.empty()) {
      throw std::invalid_argument("option -o is missing: --sweep writes its CSV to -o FILE");
    }
    const std::vector<Gait> rows =
        DesignSweep(input, spec.variable, spec.lo, spec.hi, spec.n, progress);
    EndProgress(progress);
    WriteSweep(rows, opt.output);
    return 0;
  }
  const DesignResult r = Design(input, progress);
  EndProgress(progress);
  if (opt.json) {
    nlohmann::json j = json::DesignJson(r);
    AddProvenanceJson(j, cmd);
    fmt::print("{}\n", j.dump());
  } else {
    fmt::print("{}", Table(input, r));
  }
  return 0;
}

}  // namespace

Command AddDesignCommand(CLI::App& app) {
  auto opt = std::make_shared<DesignCliOptions>();
  CLI::App* cmd = app.add_subcommand(
      "design",
      "Design a real robot in SI units: for the shell (m1, gap L, friction mu) and the motor "
      "force, find the inner mass m2 (and the frequency, with --frequency-range) of the fastest "
      "robust one-impact gait, with its speed, motor power, losses and cost of transport "
      "(docs/design.md). Exit status 0 whenever the search ran, gait found or not.");
  AddDesignConfigOptions(*cmd, opt->config);
  cmd->add_flag("--json", opt->json,
                "print one JSON object: status, message, one_impact {m2_kg, frequency_hz, "
                "speed_mm_s, displacement_mm, impact_velocity_m_s, energy_mj, power_mw, "
                "power_positive_mw, friction_loss_mj, impact_loss_mj, cot, efficiency, "
                "dimensionless {T0, A, c, alpha, phi0, ...}, binding}, robots, complete, "
                "provenance");
  cmd->add_option("--sweep", opt->sweep,
                  "instead of one design, one row per value: m2:M2MIN:M2MAX:N (the gait of each "
                  "m2) or frequency:FMIN:FMAX:N (the best m2 at each frequency), N log-spaced "
                  "values, to the CSV file -o")
      ->type_name("VAR:MIN:MAX:N");
  cmd->add_option("-o,--output", opt->output,
                  "CSV file of --sweep (written atomically; - for standard output)");
  return {cmd, [opt, cmd] { return Run(*opt, *cmd); }};
}

}  // namespace capsubot::app
