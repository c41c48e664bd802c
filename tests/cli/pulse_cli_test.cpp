// A pulse force on the command line (docs/model.md section 15, docs/cli.md): --levels and
// --switches on every command that simulates. Each command's numbers are checked against the
// library's simulator run in the test on Forcing::Pulse (itself checked against an independent
// integration and the energy balance in simulator_pulse_test.cpp); the commands that need the
// analytic orbit refuse a pulse force with one line.

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "capsubot/model/forcing.hpp"
#include "capsubot/simulate/simulator.hpp"
#include "cli/cli_text.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::Near;
using testing::RunCli;

// The robot: a two-level drive, 0.3 for a motor phase in [0, 1.5), -0.05 for the rest of the
// period. From rest every start ends in one period-1 motion (1 right, 6 left impacts a period).
const std::vector<double> kLevels = {0.3, -0.05};
const std::vector<double> kSwitches = {0.0, 1.5};
constexpr double kT0 = 0.1, kE = 0.5, kAlpha = 0.3;
const std::string kPulse = "--levels 0.3,-0.05 --switches 0,1.5";
const std::string kModel = " --T0 0.1 --e 0.5 --alpha 0.3";
const std::string kRobot = kPulse + kModel;

// The same run in the program and in the test agrees to the last digits JSON keeps (17); the
// simulator is deterministic, so this only leaves room for the decimal round trip.
constexpr double kSameRunTol = 1e-12;
// A periodic motion found by shooting is closed to its residual (about 1e-12 here); one
// period simulated from its state returns to it within this.
constexpr double kClosedTol = 1e-8;

Forcing Pulse(double phi0 = 0.0) { return Forcing::Pulse(kLevels, kSwitches, phi0); }

Params Model(double T0 = kT0) {
  Params p;
  p.T0 = T0;
  p.e = kE;
  return p;
}

nlohmann::json Json(const std::string& args) {
  const auto r = RunCli(args);
  EXPECT_EQ(r.status, 0) << args << "\n" << r.out;
  return r.status == 0 ? nlohmann::json::parse(r.out) : nlohmann::json();
}

// From rest at (x0, psi): transient + record periods, as the attractor search runs a start.
SimResult FromRest(double x0, double psi, double transient, double record, double T0 = kT0) {
  SimOptions o = testing::StartAt(kAlpha, x0, 0.0, 0.0, record);
  o.transient = transient;
  return Simulate(Pulse().WithPhase(psi), Model(T0), o);
}

TEST(PulseCli, SimulateGivesTheLibrarysRunOfThePulseForce) {
  // Three periods after one: the start still shows (every start ends in the same motion).
  const auto j = Json("simulate " + kRobot +
                      " --x0 0.5 --u0 0 --v0 0 --phi0 0.4 --periods 3 "
                      "--transient 1 --json");
  SimOptions o = testing::StartAt(kAlpha, 0.5, 0.0, 0.0, 3.0);
  o.transient = 1.0;
  o.energy = true;
  const SimResult r = Simulate(Pulse(0.4), Model(), o);
  ASSERT_EQ(j["status"], "ok");
  EXPECT_TRUE(Near(j["displacement"].get<double>(), r.displacement, kSameRunTol));
  EXPECT_TRUE(Near(j["x"].get<double>(), r.final_state.x, kSameRunTol));
  EXPECT_TRUE(Near(j["u"].get<double>(), r.final_state.u, kSameRunTol));
  EXPECT_TRUE(Near(j["v"].get<double>(), r.final_state.v, kSameRunTol));
  EXPECT_EQ(j["impacts_right"], r.impacts_right);
  EXPECT_EQ(j["impacts_left"], r.impacts_left);
  EXPECT_GT(r.impacts_right + r.impacts_left, 0);  // the run is not trivial
  EXPECT_TRUE(Near(j["energy"]["motor_work"].get<double>(), r.energy.motor_work, kSameRunTol));
  // A phi0 of the wrong sign, or one dropped, gives another run.
  const SimResult other = Simulate(Pulse(-0.4), Model(), o);
  EXPECT_GT(std::abs(other.displacement - r.displacement), 1e-6);
}

// The force the result describes: the pulse, not a sine's A and c.
TEST(PulseCli, JsonDescribesThePulseForce) {
  const auto sim = Json("simulate " + kRobot + " --x0 0.5 --u0 0 --v0 0 --phi0 0.25 --json");
  const auto att = Json("attractors " + kRobot +
                        " --starts 2x2 --transient 40 --record 16 "
                        "--threads 1 --json");
  const auto per = Json("periodic " + kRobot + " --from-rest 0.5,0 --transient 100 --json");
  for (const auto* j : {&sim, &att, &per}) {
    const auto& f = (*j)["force"];
    EXPECT_EQ(f["waveform"], "pulse") << f.dump();
    EXPECT_EQ(f["levels"], nlohmann::json(kLevels)) << f.dump();
    EXPECT_EQ(f["switches"], nlohmann::json(kSwitches)) << f.dump();
    EXPECT_FALSE(f.contains("A") || f.contains("c") || f.contains("sin")) << f.dump();
  }
  EXPECT_EQ(sim["force"]["phi0"], 0.25);
  // A sine is described by its A and c.
  const auto sine = Json(
      "simulate --A 0.05 --c 0.02 --phi0 -2.842 --T0 0.1 --e 0.5 "
      "--alpha 0.28 --x0 1 --u0 0 --v0 0 --json")["force"];
  EXPECT_EQ(sine["waveform"], "sine");
  EXPECT_EQ(sine["A"], 0.05);
  EXPECT_EQ(sine["c"], 0.02);
  EXPECT_FALSE(sine.contains("levels"));
}

TEST(PulseCli, SwitchesTakeMultiplesOfPi) {
  const auto pi = Json("simulate --levels 0.3,-0.05 --switches 0,pi/2 " + kModel +
                       " --x0 0.5 --u0 0 --v0 0 --periods 3 --json");
  const SimResult r = Simulate(Forcing::Pulse(kLevels, {0.0, M_PI / 2}, 0.0), Model(),
                               testing::StartAt(kAlpha, 0.5, 0.0, 0.0, 3.0));
  EXPECT_TRUE(Near(pi["displacement"].get<double>(), r.displacement, kSameRunTol));
}

// Every start's motion, simulated again from rest in the test: the attractor's mean velocity.
TEST(PulseCli, AttractorsMeanVelocityIsThatOfItsStartsSimulatedFromRest) {
  const auto j = Json("attractors " + kRobot + " --starts 3x3 --threads 1 --json");
  ASSERT_EQ(j["attractors"].size(), 1U) << j.dump();
  const auto& a = j["attractors"][0];
  EXPECT_EQ(a["status"], "periodic");
  EXPECT_EQ(a["period"], 1);
  const SimResult r = FromRest(a["example_start"]["x0"].get<double>(),
                               a["example_start"]["psi"].get<double>(), 200.0, 100.0);
  // The attractor's figure is the mean over its starts, which differ by velocity_max - min.
  const double spread = a["velocity_max"].get<double>() - a["velocity_min"].get<double>();
  EXPECT_TRUE(
      Near(a["mean_velocity"].get<double>(), r.displacement / (100.0 * kTau), spread + 1e-9));
  EXPECT_GT(std::abs(r.displacement), 0.1);  // the robot moves
  EXPECT_EQ(a["impacts_right"], r.impacts_right / 100);
  EXPECT_EQ(a["impacts_left"], r.impacts_left / 100);
}

TEST(PulseCli, PeriodicMotionReturnsToItsStateWhenSimulated) {
  const auto j = Json("periodic " + kRobot + " --from-rest 0.5,0 --transient 100 --json");
  ASSERT_EQ(j["status"], "converged") << j.dump();
  const auto& s = j["state"];
  const int period = j["period"];
  ASSERT_GE(period, 1);
  const SimResult r = Simulate(Pulse().WithPhase(s["psi"].get<double>()), Model(),
                               testing::StartAt(kAlpha, s["x"].get<double>(), s["u"].get<double>(),
                                                s["v"].get<double>(), period));
  EXPECT_TRUE(Near(r.final_state.x, s["x"].get<double>(), kClosedTol));
  EXPECT_TRUE(Near(r.final_state.u, s["u"].get<double>(), kClosedTol));
  EXPECT_TRUE(Near(r.final_state.v, s["v"].get<double>(), kClosedTol));
  EXPECT_TRUE(Near(j["mean_velocity"].get<double>(), r.displacement / (period * kTau), kClosedTol));
}

// A branch in T0 from the periodic motion's state: every point is a motion of the pulse robot
// at its T0 (one period simulated returns to its state).
TEST(PulseCli, ContinueInT0FollowsMotionsOfThePulseRobot) {
  const auto p = Json("periodic " + kRobot + " --from-rest 0.5,0 --transient 100 --json");
  const auto& s = p["state"];
  std::ostringstream start;
  start.precision(17);
  start << " --x0 " << s["x"].get<double>() << " --u0 " << s["u"].get<double>() << " --v0 "
        << s["v"].get<double>() << " --psi " << s["psi"].get<double>();
  const auto j = Json("continue " + kRobot + start.str() +
                      " --param T0 --from 0.095 --to 0.105 --max-points 20 --json");
  const auto& points = j["points"];
  ASSERT_GE(points.size(), 3U) << j.dump();
  for (const auto& pt : {points.front(), points.back()}) {
    const double T0 = pt["T0"];
    const int period = pt["period"];
    const SimResult r =
        Simulate(Pulse().WithPhase(pt["psi"].get<double>()), Model(T0),
                 testing::StartAt(kAlpha, pt["x"].get<double>(), pt["u"].get<double>(),
                                  pt["v"].get<double>(), period));
    EXPECT_TRUE(Near(r.final_state.x, pt["x"].get<double>(), kClosedTol)) << "T0 = " << T0;
    EXPECT_TRUE(Near(r.final_state.v, pt["v"].get<double>(), kClosedTol)) << "T0 = " << T0;
    EXPECT_TRUE(
        Near(pt["mean_velocity"].get<double>(), r.displacement / (period * kTau), kClosedTol))
        << "T0 = " << T0;
  }
}

// One row of the basin map: its start simulated from rest in the test.
TEST(PulseCli, BasinsRowIsItsStartSimulatedFromRest) {
  const auto path = testing::TempPath("capsubot_pulse_basins.csv");
  const auto r = RunCli("basins " + kRobot +
                        " --starts 2x2 --threads 1 --converged-tolerance 0 "
                        "-o " +
                        path.string());
  ASSERT_EQ(r.status, 0) << r.out;
  const testing::CsvLines csv = testing::ReadCsv(path);
  ASSERT_EQ(csv.rows.size(), 4U);
  const auto header = testing::Lines(csv.header)[0];
  ASSERT_EQ(header.rfind("x0,psi,attractor,period,impacts_right,impacts_left,mean_velocity", 0), 0U)
      << header;
  std::istringstream row(csv.rows.back());
  std::vector<std::string> cells;
  for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
  ASSERT_EQ(cells.size(), 8U) << csv.rows.back();
  const SimResult sim = FromRest(std::stod(cells[0]), std::stod(cells[1]), 200.0, 100.0);
  EXPECT_TRUE(Near(std::stod(cells[6]), sim.displacement / (100.0 * kTau), kSameRunTol));
  std::filesystem::remove(path);
}

// The summary of a bifurcation diagram in T0: each value's motion from the diagram's start.
TEST(PulseCli, BifurcationSummaryIsTheRunFromItsStart) {
  const auto out = testing::TempPath("capsubot_pulse_bif.csv");
  const auto summary = testing::TempPath("capsubot_pulse_bif_summary.csv");
  const auto r = RunCli("bifurcation " + kPulse +
                        " --T0 0.1 --e 0.5 --alpha 0.3 --param T0 "
                        "--from 0.1 --to 0.12 --steps 2 --direction up --converged-tolerance 0 "
                        "--start 0.5,0 -o " +
                        out.string() + " --summary " + summary.string() + " --threads 1");
  ASSERT_EQ(r.status, 0) << r.out;
  const testing::CsvLines csv = testing::ReadCsv(summary);
  ASSERT_EQ(csv.rows.size(), 2U) << csv.header;
  ASSERT_EQ(csv.header.rfind("param,direction,period,impacts_right,impacts_left,mean_velocity", 0),
            0U)
      << csv.header;
  std::istringstream row(csv.rows.front());
  std::vector<std::string> cells;
  for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
  EXPECT_EQ(std::stod(cells[0]), 0.1);
  const SimResult sim = FromRest(0.5, 0.0, 200.0, 100.0, 0.1);
  EXPECT_TRUE(Near(std::stod(cells[5]), sim.displacement / (100.0 * kTau), kSameRunTol));
  std::filesystem::remove(out);
  std::filesystem::remove(summary);
}

struct BadPulse {
  const char* name;
  std::string args;
  const char* message;
  const char* output = "-o";  ///< the option that names the command's file ("" for none)
  friend void PrintTo(const BadPulse& b, std::ostream* os) { *os << b.name; }
};

class PulseCliBadInput : public ::testing::TestWithParam<BadPulse> {};

// One line naming the parameter, its value and the rule; exit status 2; no file written.
TEST_P(PulseCliBadInput, OneLineNamingTheFlagAndTheRule) {
  const auto path = testing::TempPath("capsubot_pulse_bad.csv");
  const BadPulse& b = GetParam();
  const std::string file =
      *b.output == '\0' ? "" : std::string(" ") + b.output + " " + path.string();
  const auto r = RunCli(b.args + file + " 2>&1");
  EXPECT_EQ(r.status, 2) << r.out;
  const std::string command = b.args.substr(0, b.args.find(' '));
  EXPECT_EQ(r.out, "capsubot " + command + ": error: " + b.message + "\n");
  EXPECT_FALSE(std::filesystem::exists(path));
}

const std::string kAttr = "attractors --T0 0.1 --alpha 0.3 --starts 1x1 ";

INSTANTIATE_TEST_SUITE_P(
    EveryRule, PulseCliBadInput,
    ::testing::Values(
        BadPulse{"Unsorted", kAttr + "--levels 1,2 --switches 2,1",
                 "--switches: s_2 = 1 is invalid: expected it above s_1 = 2 (switch phases "
                 "strictly increasing)"},
        BadPulse{"OutsideTheTurn", kAttr + "--levels 1,2 --switches 0,7",
                 "--switches: s_2 = 7 is invalid: expected 0 <= s < 2 pi (phases in radians)"},
        BadPulse{"Negative", kAttr + "--levels 1,2 --switches -1,2",
                 "--switches: s_1 = -1 is invalid: expected 0 <= s < 2 pi (phases in radians)"},
        BadPulse{"Lengths", kAttr + "--levels 1,2,3 --switches 0,1",
                 "--switches: 2 phases given for 3 levels: expected one switch phase per level"},
        BadPulse{"NoSwitches", kAttr + "--levels 1,2",
                 "--switches is missing: a pulse force needs --levels L_1,...,L_N and "
                 "--switches s_1,...,s_N [rad]"},
        BadPulse{"WithA", kAttr + "--levels 1,2 --switches 0,1 --A 0.5",
                 "--waveform pulse takes --levels and --switches: --A is invalid with it"},
        BadPulse{"WithC", kAttr + "--levels 1,2 --switches 0,1 --c 0.5",
                 "--c = 0.5 is invalid with --waveform pulse: expected no --c (the levels give "
                 "the mean force)"},
        BadPulse{"SineWithLevels", kAttr + "--waveform sine --A 1 --c 0 --phi0 0 --levels 1",
                 "--levels is invalid with --waveform sine: expected it only with --waveform "
                 "pulse"},
        // --c is no longer required by the parser: the force's rules ask for it.
        BadPulse{"SineWithoutC", kAttr + "--A 0.5 --phi0 0",
                 "--c is missing: give the mean force c"},
        BadPulse{"BadSwitchText", kAttr + "--levels 1,2 --switches 0,x",
                 "--switches = 0,x is invalid: expected comma-separated phases (numbers or "
                 "multiples of pi) (element 2 is 'x')"},
        BadPulse{"SolveRefuses", "solve " + kRobot.substr(0, kRobot.find(" --alpha")),
                 "a pulse force is invalid for solve: expected a sine or Fourier force (the "
                 "analytic one-impact orbit needs one; simulate, attractors, periodic, continue, "
                 "basins and bifurcation take a pulse force)",
                 "--trajectory"},
        BadPulse{"OrbitsRefuses", "orbits " + kRobot,
                 "a pulse force is invalid for orbits: expected a sine or Fourier force (the "
                 "analytic one-impact orbit needs one; simulate, attractors, periodic, continue, "
                 "basins and bifurcation take a pulse force)",
                 ""},
        BadPulse{"SweepRefuses", "sweep --grid T0=0.1:0.2:2 " + kPulse,
                 "a pulse force is invalid for sweep: expected a sine or Fourier force (the "
                 "analytic one-impact orbit needs one; simulate, attractors, periodic, continue, "
                 "basins and bifurcation take a pulse force)"},
        BadPulse{"FromOrbitRefuses", "simulate " + kPulse + " --T0 0.1 --from-orbit",
                 "a pulse force is invalid for from_orbit (a start on the analytic one-impact "
                 "orbit): expected a sine or Fourier force (the analytic one-impact orbit needs "
                 "one; simulate, attractors, periodic, continue, basins and bifurcation take a "
                 "pulse force)",
                 "--trajectory"},
        BadPulse{"ContinueInA",
                 "continue " + kRobot +
                     " --x0 0.5 --u0 0 --v0 0 --psi 0 "
                     "--param A --from 0 --to 1",
                 "parameter = A is invalid for a pulse force: expected c (every level moved), "
                 "phi0, T0, e or alpha"},
        BadPulse{"BifurcationInB1", "bifurcation " + kRobot + " --param b1 --from 0 --to 1",
                 "parameter = b1 is invalid for a pulse force: expected c (every level moved), "
                 "phi0, T0, e or alpha"}),
    [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace capsubot
