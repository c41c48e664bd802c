// The two front ends refuse the same settings with the same message, each in its own names.
// The cases are generated from the library's tables of which mode of a job uses which setting
// (OptimizeSettingUses, DesignSettingUses, SweepSettingUses): every setting given to every mode
// that does not use it, plus for optimize and sweep the rules beyond the table (settings that do
// not go together, given values that are not admissible). For each case the library's own refusal
// is computed here with the command line's flags and with the Python module's keywords; the program
// must print the first on stderr (exit status 2) and the module must raise ValueError with the
// second.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "apps/design_flags.hpp"
#include "apps/optimize_flags.hpp"
#include "apps/sweep_flags.hpp"
#include "capsubot/job/design_settings.hpp"
#include "capsubot/job/optimize_settings.hpp"
#include "capsubot/job/sweep_settings.hpp"
#include "python/design_keywords.hpp"
#include "python/optimize_keywords.hpp"
#include "python/sweep_keywords.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

// A setting given with a sample value: as typed on the command line (empty for a flag), as a
// Python literal, and as it lands in the job's settings.
template <class Settings>
struct GivenOf {
  std::string field;
  std::string flag_value;
  std::string keyword_value;
  std::function<void(Settings&)> set;
};
using Given = GivenOf<OptimizeSettings>;

// A sample value of every setting of the table (and of the settings of the rules beyond it).
// A setting added to the table without a sample here fails the test (SampleOf).
const std::map<std::string, Given>& Samples() {
  static const std::map<std::string, Given> samples = [] {
    std::map<std::string, Given> m;
    const auto add = [&m](Given g) { m[g.field] = std::move(g); };
    add({"A", "0.3", "0.3", [](OptimizeSettings& s) { s.A = 0.3; }});
    add({"c", "0.1", "0.1", [](OptimizeSettings& s) { s.c = 0.1; }});
    add({"harmonics", "2", "2", [](OptimizeSettings& s) { s.search.harmonics = 2; }});
    add({"hops", "3", "3", [](OptimizeSettings& s) { s.search.hops = 3; }});
    add({"starts", "5", "5", [](OptimizeSettings& s) { s.search.starts = 5; }});
    add({"bound", "0.5", "0.5", [](OptimizeSettings& s) { s.search.gait.force_bound = 0.5; }});
    add({"global_algorithm", "GN_ISRES", "'GN_ISRES'",
         [](OptimizeSettings& s) { s.search.global_algorithm = "GN_ISRES"; }});
    add({"local_algorithm", "LD_MMA", "'LD_MMA'",
         [](OptimizeSettings& s) { s.search.local_algorithm = "LD_MMA"; }});
    add({"global_evaluations", "500", "500",
         [](OptimizeSettings& s) { s.search.global_evaluations = 500; }});
    add({"alpha", "0.5", "0.5", [](OptimizeSettings& s) { s.alpha = 0.5; }});
    add({"T0_range", "0.5:1", "(0.5, 1.0)", [](OptimizeSettings& s) {
           s.T0_min = 0.5;
           s.T0_max = 1.0;
         }});
    add({"waveform", "pulse", "'pulse'", [](OptimizeSettings& s) { s.waveform = "pulse"; }});
    add({"pulse_levels", "4", "4", [](OptimizeSettings& s) { s.pulse_levels = 4; }});
    add({"reach_starts", "2x2", "'2x2'", [](OptimizeSettings& s) { s.reach_starts = "2x2"; }});
    add({"reach_evaluations", "10", "10",
         [](OptimizeSettings& s) { s.reach.global_evaluations = 10; }});
    add({"reach_local_evaluations", "5", "5",
         [](OptimizeSettings& s) { s.reach.local_evaluations = 5; }});
    add({"reach_seconds", "5", "5", [](OptimizeSettings& s) { s.reach.max_seconds = 5.0; }});
    add({"drive_evaluations", "10", "10",
         [](OptimizeSettings& s) { s.reach.drive_evaluations = 10; }});
    add({"drive_refine_evaluations", "20", "20",
         [](OptimizeSettings& s) { s.reach.drive_refine_evaluations = 20; }});
    add({"drive_screens", "4", "4", [](OptimizeSettings& s) { s.reach.drive_screens = 4; }});
    add({"drive_polishes", "3", "3", [](OptimizeSettings& s) { s.reach.drive_polishes = 3; }});
    add({"drive_local_evaluations", "50", "50",
         [](OptimizeSettings& s) { s.reach.drive_local_evaluations = 50; }});
    add({"band_levels", "0.9", "[0.9]", [](OptimizeSettings& s) { s.band_levels = {0.9}; }});
    return m;
  }();
  return samples;
}

// The sample of `field` in `samples`.
template <class Settings>
GivenOf<Settings> SampleIn(const std::map<std::string, GivenOf<Settings>>& samples,
                           const std::string& field) {
  const auto it = samples.find(field);
  if (it == samples.end()) throw std::logic_error("no sample value of the setting " + field);
  return it->second;
}

Given SampleOf(const std::string& field) { return SampleIn(Samples(), field); }

// `field` given the number `value` (a bad value of a setting).
Given With(const std::string& field, const std::string& value,
           std::function<void(OptimizeSettings&)> set) {
  return {field, value, value, std::move(set)};
}

// `field` given the text `value`.
Given WithText(const std::string& field, const std::string& value,
               std::function<void(OptimizeSettings&)> set) {
  return {field, value, "'" + value + "'", std::move(set)};
}

struct Case {
  std::string problem;  // "" the main job
  std::vector<Given> given;
};

const std::vector<std::string> kProblems = {"", "phase", "forcing", "fourier", "reach"};

// Every setting of the table given to every problem that does not use it (the problem phase
// with its force shape, so that only the setting is wrong).
std::vector<Case> TableCases() {
  std::vector<Case> cases;
  for (const SettingUse& use : OptimizeSettingUses()) {
    for (const std::string& problem : kProblems) {
      if (use.UsedBy(problem)) continue;
      Case c{problem, {}};
      if (problem == "phase") c.given = {SampleOf("A"), SampleOf("c")};
      c.given.push_back(SampleOf(use.setting));
      cases.push_back(c);
    }
  }
  return cases;
}

// The rules beyond the table: settings that do not go together, values that are not admissible.
std::vector<Case> RuleCases() {
  std::vector<Case> cases;
  for (const char* budget : {"drive_evaluations", "drive_polishes", "drive_local_evaluations",
                             "drive_refine_evaluations", "drive_screens"}) {
    cases.push_back({"reach", {SampleOf(budget)}});
  }
  // A Fourier drive of one harmonic is the sine: no drive search, no drive budget.
  cases.push_back(
      {"reach",
       {WithText("waveform", "fourier", [](OptimizeSettings& s) { s.waveform = "fourier"; }),
        With("harmonics", "1", [](OptimizeSettings& s) { s.search.harmonics = 1; }),
        SampleOf("drive_evaluations")}});
  cases.push_back({"reach", {Given{"T0_range", "1:0.5", "(1.0, 0.5)", [](OptimizeSettings& s) {
                                     s.T0_min = 1.0;
                                     s.T0_max = 0.5;
                                   }}}});
  cases.push_back({"forcing", {SampleOf("global_evaluations")}});
  cases.push_back({"reach", {SampleOf("waveform"), SampleOf("harmonics")}});
  cases.push_back({"reach", {SampleOf("pulse_levels")}});
  cases.push_back({"reach",
                   {WithText("waveform", "sine", [](OptimizeSettings& s) { s.waveform = "sine"; }),
                    SampleOf("harmonics")}});
  cases.push_back({"phase", {SampleOf("A")}});
  cases.push_back(
      {"phase", {With("A", "-1", [](OptimizeSettings& s) { s.A = -1.0; }), SampleOf("c")}});
  cases.push_back({"forcing", {With("bound", "-1", [](OptimizeSettings& s) {
                     s.search.gait.force_bound = -1.0;
                   })}});
  cases.push_back({"", {With("starts", "0", [](OptimizeSettings& s) { s.search.starts = 0; })}});
  cases.push_back(
      {"forcing", {With("hops", "-1", [](OptimizeSettings& s) { s.search.hops = -1; })}});
  cases.push_back({"reach", {WithText("reach_starts", "0x3", [](OptimizeSettings& s) {
                     s.reach_starts = "0x3";
                   })}});
  return cases;
}

// The library's refusal of `c` in `names`, its lower stages' fields renamed by `renamed`;
// empty when it accepts the case.
std::string LibraryMessage(const Case& c, const SettingNames& names, const FlagNames& renamed) {
  OptimizeSettings s;
  s.problem = c.problem;
  for (const Given& g : c.given) {
    g.set(s);
    s.given.insert(g.field);
  }
  try {
    OptimizeJobFrom(s, names);
  } catch (const std::invalid_argument& e) {
    return WithFlagNames(e.what(), renamed);
  }
  return "";
}

std::string CommandLine(const Case& c) {
  std::string args = c.problem.empty() ? "optimize" : "optimize --problem " + c.problem;
  for (const Given& g : c.given) {
    args += " " + SettingNames{cli::kOptimizeFlags}.Name(g.field) + " " + g.flag_value;
  }
  return args;
}

std::string PythonCall(const Case& c) {
  std::string call = c.problem.empty() ? "run(" : "run(problem='" + c.problem + "', ";
  for (const Given& g : c.given) {
    call += SettingNames{python::kOptimizeKeywords}.Name(g.field) + "=" + g.keyword_value + ", ";
  }
  return call + ")\n";
}

// The messages of the Python module for the calls `calls` (each `run(...)` line), in order (""
// where it accepts one, "TypeError" where it has no such argument): one interpreter runs them.
std::vector<std::string> PythonMessages(const std::vector<std::string>& calls,
                                        const std::string& function) {
  const std::filesystem::path script = testing::TempPath("capsubot_refusals.py");
  {
    std::ofstream out(script);
    out << "import json, capsubot\nmessages = []\n"
        << "def run(**kw):\n"
        << "    try:\n        capsubot." << function << "(**kw)\n        messages.append('')\n"
        << "    except ValueError as e:\n        messages.append(str(e))\n"
        << "    except TypeError:\n        messages.append('TypeError')\n";
    for (const std::string& call : calls) out << call;
    out << "print(json.dumps(messages))\n";
  }
  const auto r = testing::RunShell("PYTHONPATH=" + std::string(CAPSUBOT_PYTHONPATH) + " " +
                                   CAPSUBOT_PYTHON + " " + script.string());
  std::filesystem::remove(script);
  EXPECT_EQ(r.status, 0) << r.out;
  return nlohmann::json::parse(r.out).get<std::vector<std::string>>();
}

TEST(OptimizeRefusals, BothFrontEndsRefuseWhatTheLibraryRefusesInTheirOwnNames) {
  std::vector<Case> cases = TableCases();
  const std::size_t table_cases = cases.size();
  for (const Case& c : RuleCases()) cases.push_back(c);
  // Every setting of the table is refused by at least one problem (the main job uses none of
  // A, c, alpha; phase none of the search's): the table yields cases for every setting.
  ASSERT_GE(table_cases, OptimizeSettingUses().size());

  const SettingNames flags{cli::kOptimizeFlags};
  const SettingNames keywords{python::kOptimizeKeywords, SettingNames::Style::kKeywords};
  std::vector<std::string> calls;
  for (const Case& c : cases) calls.push_back(PythonCall(c));
  const std::vector<std::string> python = PythonMessages(calls, "optimize");
  ASSERT_EQ(python.size(), cases.size());
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const Case& c = cases[k];
    const std::string args = CommandLine(c);
    const std::string cli_message = LibraryMessage(c, flags, cli::kOptimizeRenamedFields);
    const std::string python_message = LibraryMessage(c, keywords, keywords.flags);
    ASSERT_FALSE(cli_message.empty()) << "the library accepts " << args;
    // The two names of the first setting differ (a flag and a keyword) but the rule is one.
    EXPECT_NE(cli_message, python_message) << args;

    const auto r = testing::RunCli(args + " 2>&1 >/dev/null");
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_EQ(r.out, "capsubot optimize: error: " + cli_message + "\n") << args;
    EXPECT_EQ(python[k], python_message) << PythonCall(c);
  }
}

// The design job: one design, with the fastest motion from rest and the drive design (the runs
// both front ends have), every setting given to the one that does not use it; every setting of
// the drive design given to a waveform that does not use it; the drive with the motion from
// rest. The robot of examples/robot.toml.
const char* kDesignRobot =
    "m1=0.2, L=0.02, mu=0.3, e=0.7, force_amplitude=0.5, force_bias=0.1, "
    "frequency=20, ";

// The settings of the design job's table with a sample value: as typed, as a Python literal.
const std::map<std::string, std::pair<std::string, std::string>> kDesignSamples = {
    {"from_rest_starts", {"4x4", "'4x4'"}},
    {"reach_starts", {"2x2", "'2x2'"}},
    {"reach_evaluations", {"10", "10"}},
    {"reach_local_evaluations", {"5", "5"}},
    {"reach_seconds", {"5", "5"}},
    {"threads", {"1", "1"}},
    {"force_max", {"1", "1.0"}},
    {"harmonics", {"2", "2"}},
    {"pulse_levels", {"3", "3"}},
    {"drive_evaluations", {"10", "10"}},
    {"drive_polishes", {"3", "3"}},
    {"drive_local_evaluations", {"50", "50"}},
    {"drive_refine_evaluations", {"20", "20"}},
    {"drive_screens", {"4", "4"}},
    {"band_levels", {"0.9", "[0.9]"}}};

// A case: the run ("", "from-rest" or "drive"), the drive's waveform, the setting given (a
// field of kDesignSamples, or "from_rest" with the drive), and the library's refusal in names.
struct DesignCase {
  std::string run, waveform, field;
  std::function<void(const SettingNames&, const ModeName&)> refuse;
};

// The library's refusal of `c` in `names` (runs named by `run_name`); empty when it accepts it.
std::string DesignRefusal(const DesignCase& c, const SettingNames& names,
                          const ModeName& run_name) {
  try {
    c.refuse(names, run_name);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

std::vector<DesignCase> DesignCases() {
  std::vector<DesignCase> cases;
  for (const SettingUse& use : DesignSettingUses()) {
    for (const std::string run : {"", "from-rest", "drive"}) {
      if (use.UsedBy(run)) continue;
      const std::string field = use.setting;
      cases.push_back({run, "sine", field, [run, field](const SettingNames& n, const ModeName& m) {
                         RejectUnusedSettings(DesignSettingUses(), {field}, run, m, n,
                                              "is invalid with");
                       }});
    }
  }
  for (const std::string waveform : {"sine", "fourier", "pulse"}) {
    for (const std::string field :
         {"harmonics", "pulse_levels", "drive_evaluations", "drive_polishes",
          "drive_local_evaluations", "drive_refine_evaluations", "drive_screens"}) {
      cases.push_back(
          {"drive", waveform, field, [waveform, field](const SettingNames& n, const ModeName&) {
             RejectUnusedDriveSettings(waveform, {field}, n);
           }});
    }
  }
  cases.push_back({"drive", "sine", "from_rest", [](const SettingNames& n, const ModeName&) {
                     RejectRunsWithDrive(true, false, n);
                   }});
  return cases;
}

// The case as the module's call and as the program's arguments.
std::string DesignCall(const DesignCase& c) {
  const std::string run = c.run == "drive"
                              ? "drive='" + c.waveform + "', force_max=1.0, "
                              : fmt::format("from_rest={}, ", c.run.empty() ? "False" : "True");
  const std::string given =
      c.field == "from_rest" ? "from_rest=True" : c.field + "=" + kDesignSamples.at(c.field).second;
  return "run(" + std::string(kDesignRobot) + run + given + ")\n";
}

std::string DesignArgs(const DesignCase& c) {
  const SettingNames flags{cli::kDesignFlags};
  std::string args = fmt::format("design --config {}/examples/robot.toml", CAPSUBOT_SOURCE_DIR);
  if (c.run == "from-rest") args += " --from-rest";
  if (c.run == "drive") args += " --drive " + c.waveform + " --force-max 1";
  if (c.field == "from_rest") return args + " --from-rest";
  return args + " " + flags.Name(c.field) + " " + kDesignSamples.at(c.field).first;
}

TEST(DesignRefusals, BothFrontEndsRefuseASettingTheRunDoesNotUseInTheirOwnNames) {
  const std::vector<DesignCase> cases = DesignCases();
  ASSERT_GE(cases.size(), DesignSettingUses().size());  // each setting is refused somewhere
  std::vector<std::string> calls;
  for (const DesignCase& c : cases) calls.push_back(DesignCall(c));
  const std::vector<std::string> python = PythonMessages(calls, "design");
  ASSERT_EQ(python.size(), cases.size());
  const SettingNames flags{cli::kDesignFlags};
  const ModeName run_flag = [&flags](const std::string& run) { return DesignRunName(run, flags); };
  std::size_t refused = 0;
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const DesignCase& c = cases[k];
    const std::string args = DesignArgs(c);
    const std::string cli_message = DesignRefusal(c, flags, run_flag);
    const std::string python_message =
        DesignRefusal(c, python::kDesignKeywords, python::DesignRunKeywords);
    if (cli_message.empty()) {  // a waveform that uses the setting
      EXPECT_EQ(python_message, "") << calls[k];
      continue;
    }
    ++refused;
    EXPECT_NE(cli_message, python_message) << args;  // a flag and a keyword, one rule
    const auto r = testing::RunCli(args + " 2>&1 >/dev/null");
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_EQ(r.out, "capsubot design: error: " + cli_message + "\n") << args;
    EXPECT_EQ(python[k], python_message) << calls[k];
  }
  EXPECT_GE(refused, DesignSettingUses().size());
}

// The sweep job: every setting given to every mode that does not read it, and the rules beyond
// the table (a value given both as a setting and by the grid, no evaluation budget under the
// multistart stage, no pulse force, a bad grid of starts, an unknown mode, the reach search's
// budgets). Each case sweeps a one-point grid over e unless it says otherwise.
using SweepGiven = GivenOf<SweepSettings>;

// A sample value of every setting of the sweep's table and of the model's parameters (which a
// grid may give too); a flag has no value on the command line.
const std::map<std::string, SweepGiven>& SweepSamples() {
  static const std::map<std::string, SweepGiven> samples = [] {
    std::map<std::string, SweepGiven> m;
    const auto add = [&m](SweepGiven g) { m[g.field] = std::move(g); };
    add({"A", "0.3", "0.3", [](SweepSettings& s) { s.A = 0.3; }});
    add({"c", "0.1", "0.1", [](SweepSettings& s) { s.c = 0.1; }});
    add({"phi0", "0.5", "0.5", [](SweepSettings& s) { s.phi0 = 0.5; }});
    add({"sin", "0.2", "[0.2]", [](SweepSettings& s) { s.sin = {0.2}; }});
    add({"cos", "0.1", "[0.1]", [](SweepSettings& s) { s.cos = {0.1}; }});
    add({"waveform", "sine", "'sine'", [](SweepSettings& s) { s.waveform = "sine"; }});
    add({"levels", "1,2", "[1.0, 2.0]", [](SweepSettings&) {}});
    add({"switches", "0,1", "[0.0, 1.0]", [](SweepSettings&) {}});
    add({"T0", "0.2", "0.2", [](SweepSettings& s) { s.params.T0 = 0.2; }});
    add({"e", "0.5", "0.5", [](SweepSettings& s) { s.params.e = 0.5; }});
    add({"margin", "0.1", "0.1", [](SweepSettings& s) { s.margins.clearance = 0.1; }});
    add({"margin_stroke", "0.1", "0.1",
         [](SweepSettings& s) { s.margins.clearance_stroke = 0.1; }});
    add({"stick_margin", "0.1", "0.1", [](SweepSettings& s) { s.margins.stick = 0.1; }});
    add({"stability", "", "True", [](SweepSettings& s) { s.stability = true; }});
    add({"rho_max", "0.9", "0.9", [](SweepSettings& s) { s.search.gait.rho_max = 0.9; }});
    add({"stable_only", "", "True", [](SweepSettings& s) { s.stable_only = true; }});
    add({"scan_points", "50", "50", [](SweepSettings& s) { s.scan_points = 50; }});
    add({"bound", "0.5", "0.5", [](SweepSettings& s) { s.search.gait.force_bound = 0.5; }});
    add({"harmonics", "2", "2", [](SweepSettings& s) { s.search.harmonics = 2; }});
    add({"starts", "5", "5", [](SweepSettings& s) { s.search.starts = 5; }});
    add({"hops", "3", "3", [](SweepSettings& s) { s.search.hops = 3; }});
    add({"global_algorithm", "GN_ISRES", "'GN_ISRES'",
         [](SweepSettings& s) { s.search.global_algorithm = "GN_ISRES"; }});
    add({"local_algorithm", "LD_MMA", "'LD_MMA'",
         [](SweepSettings& s) { s.search.local_algorithm = "LD_MMA"; }});
    add({"global_evaluations", "500", "500",
         [](SweepSettings& s) { s.search.global_evaluations = 500; }});
    add({"alpha", "0.5", "0.5", [](SweepSettings& s) { s.alpha = 0.5; }});
    add({"from_rest_starts", "2x2", "'2x2'", [](SweepSettings& s) { s.from_rest_starts = "2x2"; }});
    add({"reach_starts", "2x2", "'2x2'", [](SweepSettings& s) { s.reach_starts = "2x2"; }});
    add({"reach_evaluations", "10", "10", [](SweepSettings& s) { s.reach_evaluations = 10; }});
    add({"reach_local_evaluations", "5", "5",
         [](SweepSettings& s) { s.reach_local_evaluations = 5; }});
    return m;
  }();
  return samples;
}

SweepGiven SweepSampleOf(const std::string& field) { return SampleIn(SweepSamples(), field); }

// The settings of the command line's force that the Python module's sweep() does not have: it
// refuses them as unknown arguments (TypeError).
const std::set<std::string> kSweepCommandLineOnly = {"waveform", "levels", "switches"};

// The options the command line declares with `needs(--optimize)`: without --optimize its parser
// refuses them before the library sees them.
const std::set<std::string> kNeedsOptimize = {"rho_max", "stable_only", "scan_points"};

struct SweepCase {
  std::string mode;  // "" the orbit of the force
  std::vector<std::string> grid;
  std::vector<SweepGiven> given;
};

const std::vector<std::string> kSweepModes = {"", "phi0", "forcing", "fourier", "reach"};

// Every setting of the table given to every mode that does not read it. --cos needs --sin on
// the command line: its cases give both, and sin, before cos in the table, is the one refused.
std::vector<SweepCase> SweepTableCases() {
  std::vector<SweepCase> cases;
  for (const SettingUse& use : SweepSettingUses()) {
    for (const std::string& mode : kSweepModes) {
      if (use.UsedBy(mode)) continue;
      SweepCase c{mode, {"e=0.5"}, {}};
      if (use.setting == "cos") c.given.push_back(SweepSampleOf("sin"));
      c.given.push_back(SweepSampleOf(use.setting));
      cases.push_back(c);
    }
  }
  return cases;
}

// The first mode that reads `field` ("" for a setting every mode reads).
std::string ModeReading(const std::string& field) {
  for (const SettingUse& use : SweepSettingUses()) {
    if (use.setting == field) return use.modes.front();
  }
  return "";
}

std::vector<SweepCase> SweepRuleCases() {
  std::vector<SweepCase> cases;
  // Every setting a grid can give, given to a mode that reads it, with a grid over it.
  for (const char* field : {"A", "c", "phi0", "T0", "e", "margin", "margin_stroke", "stick_margin",
                            "alpha", "rho_max", "bound"}) {
    cases.push_back(
        {ModeReading(field), {std::string(field) + "=0.2,0.3"}, {SweepSampleOf(field)}});
  }
  cases.push_back({"forcing", {"rho_max=0.2,0.3"}, {SweepSampleOf("stable_only")}});
  cases.push_back({"forcing", {"e=0.5"}, {SweepSampleOf("global_evaluations")}});
  cases.push_back({"reach",
                   {"e=0.5"},
                   {SweepGiven{"global_algorithm", "multistart", "'multistart'",
                               [](SweepSettings& s) { s.search.global_algorithm = "multistart"; }},
                    SweepSampleOf("global_evaluations")}});
  cases.push_back({"", {"e=0.5"}, {SweepSampleOf("levels")}});
  cases.push_back({"phi0", {"e=0.5"}, {SweepSampleOf("switches")}});
  cases.push_back({"", {"e=0.5"}, {{"waveform", "pulse", "'pulse'", [](SweepSettings& s) {
                                      s.waveform = "pulse";
                                    }}}});
  cases.push_back({"reach", {"e=0.5"}, {{"from_rest_starts", "0x3", "'0x3'", [](SweepSettings& s) {
                                           s.from_rest_starts = "0x3";
                                         }}}});
  cases.push_back({"reach", {"e=0.5"}, {{"reach_starts", "2y2", "'2y2'", [](SweepSettings& s) {
                                           s.reach_starts = "2y2";
                                         }}}});
  cases.push_back({"reach", {"e=0.5"}, {{"reach_evaluations", "0", "0", [](SweepSettings& s) {
                                           s.reach_evaluations = 0;
                                         }}}});
  cases.push_back({"best", {"e=0.5"}, {}});
  return cases;
}

// The library's refusal of `c` in `names`, its lower stages' fields renamed by `renamed`;
// empty when it accepts the case.
std::string SweepLibraryMessage(const SweepCase& c, const SettingNames& names,
                                const FlagNames& renamed) {
  SweepSettings s;
  s.optimize = c.mode;
  for (const std::string& spec : c.grid) s.grid.axes.push_back(ParseGridAxis(spec));
  for (const SweepGiven& g : c.given) {
    g.set(s);
    s.given.insert(g.field);
  }
  s.file.output = "-";
  try {
    SweepJobFrom(s, names);
  } catch (const std::invalid_argument& e) {
    return WithFlagNames(e.what(), renamed);
  }
  return "";
}

std::string SweepCommandLine(const SweepCase& c) {
  std::string args = "sweep -o -";
  for (const std::string& spec : c.grid) args += " --grid " + spec;
  if (!c.mode.empty()) args += " --optimize " + c.mode;
  for (const SweepGiven& g : c.given) {
    args += " " + SettingNames{cli::kSweepFlags}.Name(g.field);
    if (!g.flag_value.empty()) args += " " + g.flag_value;
  }
  return args;
}

std::string SweepPythonCall(const SweepCase& c) {
  std::string call = "run(grid=[";
  for (const std::string& spec : c.grid) call += "'" + spec + "', ";
  call += "], ";
  if (!c.mode.empty()) call += "optimize='" + c.mode + "', ";
  for (const SweepGiven& g : c.given) {
    call += SettingNames{python::kSweepKeywords}.Name(g.field) + "=" + g.keyword_value + ", ";
  }
  return call + ")\n";
}

bool CommandLineOnly(const SweepCase& c) {
  for (const SweepGiven& g : c.given) {
    if (kSweepCommandLineOnly.count(g.field) > 0) return true;
  }
  return false;
}

TEST(SweepRefusals, BothFrontEndsRefuseWhatTheLibraryRefusesInTheirOwnNames) {
  std::vector<SweepCase> cases = SweepTableCases();
  // Every setting of the table is left out by at least one mode (none is read by all five).
  ASSERT_GE(cases.size(), SweepSettingUses().size());
  for (const SweepCase& c : SweepRuleCases()) cases.push_back(c);

  const SettingNames flags{cli::kSweepFlags};
  const SettingNames keywords{python::kSweepKeywords, SettingNames::Style::kKeywords};
  std::vector<std::string> calls;
  for (const SweepCase& c : cases) calls.push_back(SweepPythonCall(c));
  const std::vector<std::string> python = PythonMessages(calls, "sweep");
  ASSERT_EQ(python.size(), cases.size());
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const SweepCase& c = cases[k];
    const std::string args = SweepCommandLine(c);
    const std::string cli_message = SweepLibraryMessage(c, flags, cli::kSweepRenamedFields);
    const std::string python_message = SweepLibraryMessage(c, keywords, keywords.flags);
    ASSERT_FALSE(cli_message.empty()) << "the library accepts " << args;

    const auto r = testing::RunCli(args + " 2>&1 >/dev/null");
    EXPECT_EQ(r.status, 2) << args;
    const std::string& field = c.given.empty() ? std::string() : c.given.back().field;
    if (c.mode.empty() && kNeedsOptimize.count(field) > 0) {
      EXPECT_EQ(
          r.out,
          fmt::format("capsubot sweep: error: {} requires --optimize (see capsubot sweep --help)\n",
                      flags.Name(field)))
          << args;
    } else {
      EXPECT_EQ(r.out, "capsubot sweep: error: " + cli_message + "\n") << args;
    }
    if (CommandLineOnly(c)) {
      EXPECT_EQ(python[k], "TypeError") << calls[k];
    } else {
      EXPECT_NE(cli_message, python_message) << args;
      EXPECT_EQ(python[k], python_message) << calls[k];
    }
  }
}

}  // namespace
}  // namespace capsubot
