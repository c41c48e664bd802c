// The design job (capsubot/job/design_job.hpp): one call gives what the library's calls give
// made by hand (Design, DesignFromRest with the settings written out here, DesignGait at every
// point of a grid), tells its stages in order, and refuses bad options before any work with a
// message naming the parameter, its value and the rule.

#include "capsubot/job/design_job.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "capsubot/io/io.hpp"
#include "capsubot/simulate/simulator.hpp"
#include "design/example_robot.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

// Part (b) small enough for a test (about 0.1 s): 2 x 2 starts in the search, 3 x 3 in the
// re-check, 6 + 2 evaluations a direction, a time limit never reached (so that the result does
// not depend on the machine).
DesignFromRestPart SmallFromRest() {
  DesignFromRestPart part;
  part.from_rest_starts = {3, 3};
  part.reach_starts = {2, 2};
  part.reach_evaluations = 6;
  part.reach_local_evaluations = 2;
  part.reach_seconds = 1e6;
  part.threads = 2;
  return part;
}

// The same settings as SmallFromRest, written out on DesignFromRestOptions.
DesignFromRestOptions SmallFromRestOptions() {
  DesignFromRestOptions o;
  o.search.n_x = o.search.n_psi = 2;
  o.check.n_x = o.check.n_psi = 3;
  o.search.attractor.threads = o.check.attractor.threads = 2;
  o.global_evaluations = 6;
  o.local_evaluations = 2;
  o.max_seconds = 1e6;
  return o;
}

DesignJobOptions OneDesign(const std::optional<DesignFromRestPart>& from_rest) {
  DesignJobOptions o;
  o.input = testing::ExampleRobot();
  DesignOneMode one;
  one.from_rest = from_rest;
  o.mode = one;
  return o;
}

TEST(DesignJob, OneDesignIsTheLibrarysDesignAndTellsItsStages) {
  DesignJobOptions o = OneDesign(std::nullopt);
  std::vector<std::string> stages;
  o.on_stage = [&stages](const std::string& stage) { stages.push_back(stage); };
  const DesignJobResult r = RunDesignJob(o);
  const DesignResult expected = Design(testing::ExampleRobot());
  ASSERT_EQ(expected.status, DesignStatus::kOk);  // the example robot has a gait
  EXPECT_EQ(r.design.status, expected.status);
  EXPECT_EQ(r.design.message, expected.message);
  EXPECT_EQ(r.design.robots, expected.robots);
  EXPECT_EQ(r.design.one_impact.m2_kg, expected.one_impact.m2_kg);
  EXPECT_EQ(r.design.one_impact.speed_mm_s, expected.one_impact.speed_mm_s);
  EXPECT_EQ(r.design.one_impact.binding, expected.one_impact.binding);
  EXPECT_EQ(r.input.m1, 0.2);
  EXPECT_FALSE(r.from_rest.has_value());
  EXPECT_FALSE(r.grid.has_value());
  EXPECT_EQ(stages,
            (std::vector<std::string>{"design: 1/2 the fastest robust one-impact gait",
                                      "design: 2/2 how far mu, e and m2 carry the gait", ""}));
  // The gait's robustness is the library's, for the gait found.
  const GaitRobustness robustness =
      ComputeDesignRobustness(testing::ExampleRobot(), expected.one_impact);
  ASSERT_EQ(r.robustness.parameters.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    const ParameterRobustness& got = r.robustness.parameters[k];
    const ParameterRobustness& want = robustness.parameters[k];
    EXPECT_EQ(got.name, want.name);
    EXPECT_EQ(got.down.parameter, want.down.parameter) << want.name;
    EXPECT_EQ(got.up.parameter, want.up.parameter) << want.name;
  }
}

// At 1500 Hz the example robot's T0 is 1.7e-6: mu's range [mu/2, 2 mu] is narrower in T0 than
// the continuation's finite-difference step of 1e-6; mu is followed relative to its value and
// every part of the robustness is computed.
// testing::SmallRobot: most starts from rest never reach its gait (docs/design.md, "From
// rest"); they end with the inner body resting on a wall and the robot standing still.
using testing::SmallRobot;

// A start from rest run by the simulator alone for this many periods: long enough for the
// transients of this robot (they settle within 100 periods, docs/design.md).
constexpr double kDirectPeriods = 2000.0;

TEST(DesignJob, PartAsGaitIsCheckedFromRestAndTheAdviceFollowsFromIt) {
  DesignJobOptions o = OneDesign(std::nullopt);
  o.input = SmallRobot();
  const DesignJobResult r = RunDesignJob(o);
  ASSERT_TRUE(r.design.one_impact.ok()) << r.design.message;
  const GaitFromRest& fr = r.gait_from_rest;
  ASSERT_TRUE(fr.checked);
  EXPECT_EQ(fr.attractors.starts, 64);  // the 8 x 8 starts of the speed bands
  EXPECT_GT(fr.reached, 0);
  EXPECT_LT(2 * fr.reached, fr.attractors.starts);  // fewer than half reach the gait
  // The speed from rest is the speed bands' nominal speed, which the bands compute on their own.
  ASSERT_FALSE(r.robustness.parameters.empty());
  const Gait& g = r.design.one_impact;
  const double mm_s = 1e3 * g.model.omega * o.input.L;
  EXPECT_TRUE(testing::RelNear(GaitSpeedFromRest(r),
                               mm_s * r.robustness.parameters.front().band.nominal_speed, 1e-12));
  EXPECT_LT(GaitSpeedFromRest(r), 0.5 * g.speed_mm_s);
  // The most common motion: the inner body resting on a wall, the robot still. Checked on one
  // of its starts by the simulator alone: no impacts over the last periods, no displacement.
  const Attractor& top = fr.attractors.attractors.front();
  EXPECT_NE(NoImpactWords(top.motion), "");
  EXPECT_GT(2 * top.starts, fr.attractors.starts);
  const Orbit& orbit = g.solution.orbit;
  SimOptions so;
  so.alpha = orbit.alpha;
  so.x0 = top.example.x;
  so.u0 = top.example.u;
  so.v0 = top.example.v;
  so.transient = kDirectPeriods;
  so.periods = 100.0;
  const SimResult direct = Simulate(orbit.forcing.WithPhase(orbit.forcing.phi0() + top.example.psi),
                                    Params{orbit.T0, orbit.e}, so);
  ASSERT_EQ(direct.status, SimStatus::kOk) << direct.message;
  EXPECT_EQ(direct.impacts_right + direct.impacts_left, 0);
  EXPECT_LE(std::abs(direct.v_mean), 1e-12);
  // Without part (b) the advice is the gait, with the warning of its starts.
  EXPECT_EQ(ChooseDesign(r), DesignChoice::kGait);
}

// Progress counts against an upper bound while the searches run; their last report is the
// end (done = total), so that a bar ends full, not at "102/676 robots".
TEST(DesignJob, ProgressEndsWithTheWorkDone) {
  DesignJobOptions o = OneDesign(SmallFromRest());
  struct Report {
    std::int64_t done = -1, total = -1, reports = 0;
    bool within = true;
    void operator()(std::int64_t d, std::int64_t t) {
      within = within && d <= t;
      done = d;
      total = t;
      ++reports;
    }
  };
  auto robots = std::make_shared<Report>();
  auto evaluations = std::make_shared<Report>();
  auto& one = std::get<DesignOneMode>(o.mode);
  one.progress = [robots](std::int64_t d, std::int64_t t) { (*robots)(d, t); };
  one.from_rest->progress = [evaluations](const std::string&, std::int64_t d, std::int64_t t) {
    (*evaluations)(d, t);
  };
  const DesignJobResult r = RunDesignJob(o);
  ASSERT_TRUE(r.from_rest.has_value());
  EXPECT_GT(robots->reports, 1);
  EXPECT_TRUE(robots->within);
  EXPECT_EQ(robots->done, r.design.robots);
  EXPECT_EQ(robots->total, r.design.robots);
  EXPECT_GT(evaluations->reports, 1);
  EXPECT_TRUE(evaluations->within);
  EXPECT_EQ(evaluations->done, r.from_rest->evaluations);
  EXPECT_EQ(evaluations->total, r.from_rest->evaluations);
}

TEST(DesignJob, AHighFrequencyDesignReportsItsRobustness) {
  DesignJobOptions o = OneDesign(std::nullopt);
  o.input.frequency_min = o.input.frequency_max = 1500.0;
  const DesignJobResult r = RunDesignJob(o);
  ASSERT_TRUE(r.design.one_impact.ok());
  ASSERT_EQ(r.robustness.parameters.size(), 3U);
  for (const ParameterRobustness& p : r.robustness.parameters) {
    EXPECT_EQ(p.status, ContinuationStatus::kOk) << p.name << ": " << p.message;
    EXPECT_NE(p.band.status, SpeedBandStatus::kNotRun) << p.name;
  }
}

// Without a gait there is nothing to continue: no robustness, and its stage is not told.
TEST(DesignJob, ADesignWithoutAGaitHasNoRobustness) {
  DesignJobOptions o = OneDesign(std::nullopt);
  o.input.force.amplitude = 5.0;  // the motor slides the shell by itself (docs/design.md)
  o.input.m2_min = 0.01;
  o.input.m2_max = 1.0;
  std::vector<std::string> stages;
  o.on_stage = [&stages](const std::string& stage) { stages.push_back(stage); };
  const DesignJobResult r = RunDesignJob(o);
  EXPECT_EQ(r.design.status, DesignStatus::kMotorSlidesShell);
  EXPECT_TRUE(r.robustness.parameters.empty());
  EXPECT_EQ(stages,
            (std::vector<std::string>{"design: 1/2 the fastest robust one-impact gait", ""}));
}

TEST(DesignJob, FromRestPartIsDesignFromRestWithTheSameSettings) {
  DesignJobOptions o = OneDesign(SmallFromRest());
  std::vector<std::string> stages;
  o.on_stage = [&stages](const std::string& stage) { stages.push_back(stage); };
  std::int64_t robots = 0, evaluations = 0;
  std::get<DesignOneMode>(o.mode).progress = [&robots](std::int64_t done, std::int64_t) {
    robots = done;
  };
  std::get<DesignOneMode>(o.mode).from_rest->progress =
      [&evaluations](const std::string&, std::int64_t done, std::int64_t) { evaluations = done; };
  const DesignJobResult r = RunDesignJob(o);
  const DesignFromRestResult expected =
      DesignFromRest(testing::ExampleRobot(), SmallFromRestOptions());
  ASSERT_TRUE(r.from_rest.has_value());
  for (const auto& [got, want] : {std::make_pair(&r.from_rest->forward, &expected.forward),
                                  std::make_pair(&r.from_rest->backward, &expected.backward)}) {
    EXPECT_EQ(got->status, want->status) << DirectionName(want->direction);
    EXPECT_EQ(got->m2_kg, want->m2_kg) << DirectionName(want->direction);
    EXPECT_EQ(got->speed_mm_s, want->speed_mm_s) << DirectionName(want->direction);
    EXPECT_EQ(got->attractors.attractors.size(), want->attractors.attractors.size());
  }
  EXPECT_EQ(r.from_rest->evaluations, expected.evaluations);
  EXPECT_EQ(r.design.one_impact.m2_kg, Design(testing::ExampleRobot()).one_impact.m2_kg);
  // The re-check keeps the long record of the from-rest design (a motion without a period is
  // averaged over it), whatever grid of starts it is given.
  EXPECT_EQ(r.from_rest_options.check.attractor.motion.record, kCheckRecord);
  EXPECT_EQ(r.from_rest_options.check.n_x, 3);
  EXPECT_EQ(stages, (std::vector<std::string>{"design: 1/3 the fastest robust one-impact gait",
                                              "design: 2/3 how far mu, e and m2 carry the gait",
                                              "design: 3/3 the fastest motion from rest", ""}));
  EXPECT_EQ(robots, r.design.robots);
  EXPECT_GT(evaluations, 0);
}

// The defaults of part (b) are those of the library's from-rest design.
TEST(DesignJob, FromRestDefaultsAreThoseOfDesignFromRestOptions) {
  const DesignFromRestOptions expected;
  const DesignFromRestOptions got = DesignFromRestPart().Options();
  EXPECT_EQ(got.search.n_x, expected.search.n_x);
  EXPECT_EQ(got.search.n_psi, expected.search.n_psi);
  EXPECT_EQ(got.check.n_x, expected.check.n_x);
  EXPECT_EQ(got.check.n_psi, expected.check.n_psi);
  EXPECT_EQ(got.global_evaluations, expected.global_evaluations);
  EXPECT_EQ(got.local_evaluations, expected.local_evaluations);
  EXPECT_EQ(got.max_seconds, expected.max_seconds);
}

DesignJobOptions Grid(const std::string& output) {
  DesignJobOptions o;
  o.input = testing::ExampleRobot();
  DesignGridMode grid;
  grid.axes = {ParseDesignGridAxis("m2=0.2,0.25"), ParseDesignGridAxis("e=0.5,0.7")};
  grid.output = output;
  grid.threads = 2;
  o.mode = grid;
  return o;
}

// The cells of a CSV line.
std::vector<std::string> Cells(const std::string& line) {
  std::vector<std::string> cells;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= line.size(); ++i) {
    if (i == line.size() || line[i] == ',') {
      cells.push_back(line.substr(start, i - start));
      start = i + 1;
    }
  }
  return cells;
}

// The index of `column` in the CSV header `header`.
std::size_t Column(const std::string& header, const std::string& column) {
  const std::vector<std::string> names = Cells(header);
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i] == column) return i;
  }
  ADD_FAILURE() << column << " is not in " << header;
  return 0;
}

// Every row of a grid is the gait of its robot (DesignGait at that m2 and e), its numbers
// written as the CSV writes numbers (FormatNumber: shortest round trip): equal text is equal
// doubles.
TEST(DesignJob, GridRowsAreTheGaitsOfTheirPoints) {
  const auto csv = testing::TempPath("design_job_grid.csv");
  const DesignJobResult r = RunDesignJob(Grid(csv.string()));
  ASSERT_TRUE(r.grid.has_value());
  EXPECT_EQ(r.grid->output, csv.string());
  EXPECT_EQ(r.grid->summary.points, 4);
  EXPECT_EQ(r.design.status, DesignStatus::kNotRun);
  EXPECT_TRUE(r.robustness.parameters.empty());  // a grid continues no gait
  const testing::CsvLines file = testing::ReadCsv(csv);
  ASSERT_EQ(file.rows.size(), 4U);
  // The gridded m2 is the column m2_kg, once: the results leave theirs out.
  EXPECT_EQ(file.header.rfind("m2_kg,e,status,frequency_hz,speed_mm_s,", 0), 0U) << file.header;
  int ok = 0;
  for (std::size_t k = 0; k < 4; ++k) {
    DesignInput in = testing::ExampleRobot();
    in.e = k % 2 == 0 ? 0.5 : 0.7;
    const Gait g = DesignGait(in, k < 2 ? 0.2 : 0.25);
    const std::vector<std::string> cells = Cells(file.rows[k]);
    const auto cell = [&](const char* column) { return cells.at(Column(file.header, column)); };
    EXPECT_EQ(cell("status"), GaitStatusName(g.status)) << file.rows[k];
    EXPECT_EQ(cell("speed_mm_s"), FormatNumber(g.speed_mm_s)) << file.rows[k];
    EXPECT_EQ(cell("power_mw"), FormatNumber(g.power_mw)) << file.rows[k];
    EXPECT_EQ(cell("T0"), FormatNumber(g.ok() ? g.solution.orbit.T0 : kNaN));
    EXPECT_EQ(cell("orbits"), std::to_string(g.orbits)) << file.rows[k];
    ok += g.ok() ? 1 : 0;
  }
  EXPECT_GE(ok, 1);  // the grid crosses the stable window of the example (docs/design.md)
}

// The workers of a distributed grid compute the rows the job writes (DesignJobGrid).
TEST(DesignJob, GridBlocksOfTheWorkersAreTheRowsOfTheFile) {
  const auto csv = testing::TempPath("design_job_blocks.csv");
  const DesignJobOptions o = Grid(csv.string());
  RunDesignJob(o);
  const DesignGridOptions grid = DesignJobGrid(o.input, std::get<DesignGridMode>(o.mode));
  std::string bytes;
  EXPECT_EQ(DesignGridBlocks(grid)()(0, 4, bytes), 4);
  std::string rows;
  for (const std::string& row : testing::ReadCsv(csv).rows) rows += row + "\n";
  EXPECT_EQ(bytes, rows);
}

struct BadOptions {
  const char* name;
  std::function<void(DesignJobOptions&)> spoil;
  const char* message;
  friend void PrintTo(const BadOptions& b, std::ostream* os) { *os << b.name; }
};

DesignFromRestPart& Part(DesignJobOptions& o) { return *std::get<DesignOneMode>(o.mode).from_rest; }
DesignGridMode& GridOf(DesignJobOptions& o) { return std::get<DesignGridMode>(o.mode); }

class DesignJobRefuses : public ::testing::TestWithParam<BadOptions> {};

// Refused before any work: no robot evaluated, no file written.
TEST_P(DesignJobRefuses, NamingTheParameterItsValueAndTheRule) {
  const auto csv = testing::TempPath("design_job_refused.csv");
  const bool grid = std::string(GetParam().name).rfind("grid", 0) == 0;
  DesignJobOptions o = grid ? Grid(csv.string()) : OneDesign(SmallFromRest());
  std::int64_t calls = 0;
  if (!grid) std::get<DesignOneMode>(o.mode).progress = [&calls](auto, auto) { ++calls; };
  GetParam().spoil(o);
  try {
    RunDesignJob(o);
    ADD_FAILURE() << "accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind(GetParam().message, 0), 0U) << e.what();
  }
  EXPECT_EQ(calls, 0);
  EXPECT_FALSE(std::filesystem::exists(csv));
}

INSTANTIATE_TEST_SUITE_P(
    BadOptions, DesignJobRefuses,
    ::testing::Values(
        BadOptions{"restitution", [](DesignJobOptions& o) { o.input.e = 1.3; },
                   "restitution e = 1.3 is invalid: expected 0 <= e <= 1"},
        BadOptions{"reach_evaluations", [](DesignJobOptions& o) { Part(o).reach_evaluations = 0; },
                   "reach_evaluations = 0 is invalid: expected 1 <= reach_evaluations <= 100000"},
        BadOptions{"reach_local_evaluations",
                   [](DesignJobOptions& o) { Part(o).reach_local_evaluations = -1; },
                   "reach_local_evaluations = -1 is invalid: expected 0 <= "
                   "reach_local_evaluations <= 100000"},
        BadOptions{"reach_seconds", [](DesignJobOptions& o) { Part(o).reach_seconds = 0.0; },
                   "reach_seconds = 0 is invalid: expected a finite time > 0 [s]"},
        BadOptions{"band_levels",
                   [](DesignJobOptions& o) {
                     std::get<DesignOneMode>(o.mode).band_levels = {0.9, 0.9};
                   },
                   "band_levels = 0.9 is invalid: expected distinct levels"},
        BadOptions{"reach_starts",
                   [](DesignJobOptions& o) {
                     Part(o).reach_starts = {0, 4};
                   },
                   "reach_starts = 0x4 is invalid: expected NXxNPSI, two whole numbers from 1 to "
                   "100000 (e.g. 8x8)"},
        BadOptions{"from_rest_starts",
                   [](DesignJobOptions& o) {
                     Part(o).from_rest_starts = {3000, 3000};
                   },
                   "from_rest_starts = 3000x3000 is invalid: expected at most 4194304 starts"},
        BadOptions{"threads", [](DesignJobOptions& o) { Part(o).threads = -1; },
                   "threads = -1 is invalid: expected 1 <= threads <= "},
        BadOptions{"grid_missing", [](DesignJobOptions& o) { GridOf(o).axes.clear(); },
                   "grid is missing: expected at least one axis"},
        BadOptions{
            "grid_twice",
            [](DesignJobOptions& o) { GridOf(o).axes.push_back(ParseDesignGridAxis("e=0.6")); },
            "grid e=0.6 is invalid: parameter e already has a grid (e=0.5,0.7): expected "
            "each parameter at most once"},
        BadOptions{"grid_output", [](DesignJobOptions& o) { GridOf(o).output.clear(); },
                   "output is missing: expected the path of the CSV file to write"},
        BadOptions{"grid_shard",
                   [](DesignJobOptions& o) {
                     GridOf(o).shard = 2;
                     GridOf(o).shards = 2;
                   },
                   "shard = 2/2 is invalid: expected K/N with N >= 1 shards and 0 <= K < N"}),
    [](const ::testing::TestParamInfo<BadOptions>& info) { return info.param.name; });

}  // namespace
}  // namespace capsubot
