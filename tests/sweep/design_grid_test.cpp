// Designs over a grid of the robot's SI inputs (capsubot/sweep/design_grid.hpp): every row equals
// the library design of that robot computed here point by point, rho-max = inf is the design
// without a stability requirement, a resumed run gives the same bytes, and every bad grid is
// refused with a message naming the parameter, its value and the rule.

#include "capsubot/sweep/design_grid.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "capsubot/io/io.hpp"
#include "design/example_robot.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The result columns of these tests: what the design found, its numbers written as the CSV
// writes numbers (FormatNumber: shortest round trip), so that equal text is equal doubles;
// m2_kg only when m2 has no grid (else the grid's column is m2_kg).
DesignGridOptions Options(const std::string& output, bool m2_gridded) {
  DesignGridOptions o;
  o.input = testing::ExampleRobot();
  o.columns = {"status", "frequency_hz", "speed_mm_s", "power_mw", "orbits"};
  if (!m2_gridded) o.columns.insert(o.columns.begin() + 1, "m2_kg");
  o.row = [m2_gridded](const Gait& g) {
    return std::string(GaitStatusName(g.status)) + "," +
           (m2_gridded ? "" : FormatNumber(g.m2_kg) + ",") + FormatNumber(g.frequency_hz) + "," +
           FormatNumber(g.speed_mm_s) + "," + FormatNumber(g.power_mw) + "," +
           std::to_string(g.orbits);
  };
  o.output = output;
  o.threads = 2;
  return o;
}

std::string ReadAll(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The data rows of a file (after the comment and header lines).
std::vector<std::string> Rows(const std::filesystem::path& path, const std::string& header) {
  std::istringstream in(ReadAll(path));
  std::vector<std::string> rows;
  bool data = false;
  for (std::string line; std::getline(in, line);) {
    if (data) rows.push_back(line);
    if (line == header) data = true;
  }
  return rows;
}

std::string Expected(const std::vector<double>& grid, const Gait& g, bool m2_gridded) {
  std::string row;
  for (double v : grid) row += FormatNumber(v) + ",";
  return row + Options("", m2_gridded).row(g);
}

// A log grid over m2 (fixed inner mass at the fixed frequency: the robot's own gait,
// EvaluateGait) times a list over e: each row is that robot, computed here with the input
// changed by hand.
TEST(DesignGrid, TwoAxesOverM2AndRestitutionEqualTheRobotsComputedOneByOne) {
  const auto csv = testing::TempPath("design_grid_m2_e.csv");
  DesignGridOptions o = Options(csv.string(), true);
  o.axes = {ParseDesignGridAxis("m2=0.2:0.26:4:log"), ParseDesignGridAxis("e=0.5,0.7")};
  RunDesignGrid(o);
  // One column for the inner mass, the grid's: m2_kg.
  const std::vector<std::string> rows =
      Rows(csv, "m2_kg,e,status,frequency_hz,speed_mm_s,power_mw,orbits");
  ASSERT_EQ(rows.size(), 8U);
  const double m2s[] = {0.2, 0.2 * std::cbrt(1.3), 0.2 * std::cbrt(1.3 * 1.3), 0.26};
  int checked = 0, ok = 0;
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 2; ++j) {
      DesignInput in = testing::ExampleRobot();
      in.e = j == 0 ? 0.5 : 0.7;
      const Gait g = EvaluateGait(in, m2s[i], 20.0);
      const std::string& row = rows[static_cast<std::size_t>(2 * i + j)];
      // The grid's m2 is a log spacing through decimal logarithms: equal to 1e-15.
      const std::string tail = row.substr(row.find(',') + 1);
      EXPECT_TRUE(testing::NearAbsBelowOne(std::stod(row), m2s[i], 1e-15)) << row;
      const Gait exact = EvaluateGait(in, std::stod(row), 20.0);
      EXPECT_EQ(tail, Expected({in.e}, exact, true)) << row;
      EXPECT_EQ(g.status, exact.status) << row;
      ok += exact.ok() ? 1 : 0;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 8);
  EXPECT_GE(ok, 2);  // the grid crosses the stable window of the example (docs/design.md)
}

// No m2 axis: at every point the design searches m2 over its range, as Design does for the
// robot with the point's friction and frequency.
TEST(DesignGrid, WithoutAnM2AxisEveryPointIsTheFullDesign) {
  const auto csv = testing::TempPath("design_grid_mu_f.csv");
  DesignGridOptions o = Options(csv.string(), false);
  o.axes = {ParseDesignGridAxis("mu=0.25,0.3"), ParseDesignGridAxis("frequency=18:20:2")};
  // The frequency's grid column is frequency_hz: the results leave theirs out.
  o.columns = {"status", "m2_kg", "speed_mm_s", "power_mw", "orbits"};
  o.row = [](const Gait& g) {
    return std::string(GaitStatusName(g.status)) + "," + FormatNumber(g.m2_kg) + "," +
           FormatNumber(g.speed_mm_s) + "," + FormatNumber(g.power_mw) + "," +
           std::to_string(g.orbits);
  };
  RunDesignGrid(o);
  const std::vector<std::string> rows =
      Rows(csv, "mu,frequency_hz,status,m2_kg,speed_mm_s,power_mw,orbits");
  ASSERT_EQ(rows.size(), 4U);
  int checked = 0;
  for (const double mu : {0.25, 0.3}) {
    for (const double f : {18.0, 20.0}) {
      DesignInput in = testing::ExampleRobot();
      in.mu = mu;
      in.frequency_min = in.frequency_max = f;
      EXPECT_EQ(rows[static_cast<std::size_t>(checked)],
                FormatNumber(mu) + "," + FormatNumber(f) + "," + o.row(Design(in).one_impact));
      ++checked;
    }
  }
  EXPECT_EQ(checked, 4);
}

// rho-max = inf in a list is the design with no stability requirement (DesignInput::rho_max
// infinite); 0.9 is the default robust requirement.
TEST(DesignGrid, RhoMaxInfinityIsTheDesignWithoutStabilityRequirement) {
  const auto csv = testing::TempPath("design_grid_rho.csv");
  DesignGridOptions o = Options(csv.string(), true);
  o.axes = {ParseDesignGridAxis("m2=0.2,0.25"), ParseDesignGridAxis("rho-max=0.9,inf")};
  RunDesignGrid(o);
  const std::vector<std::string> rows =
      Rows(csv, "m2_kg,rho-max,status,frequency_hz,speed_mm_s,power_mw,orbits");
  ASSERT_EQ(rows.size(), 4U);
  int checked = 0;
  for (const double m2 : {0.2, 0.25}) {
    for (const double rho : {0.9, kInfinity}) {
      DesignInput in = testing::ExampleRobot();
      in.rho_max = rho;
      EXPECT_EQ(rows[static_cast<std::size_t>(checked)],
                Expected({m2, rho}, EvaluateGait(in, m2, 20.0), true));
      ++checked;
    }
  }
  EXPECT_EQ(checked, 4);
  EXPECT_EQ(rows[1].rfind("0.2,inf,", 0), 0U) << rows[1];  // written as the grid is
}

struct Interrupt {};

// A run stopped part-way (the progress callback throws, as a kill would) keeps its partial
// file and checkpoint; the resume completes it byte for byte, rho-max = inf included.
TEST(DesignGrid, AResumedRunIsByteIdenticalToAnUninterruptedOne) {
  const auto whole = testing::TempPath("design_grid_whole.csv");
  DesignGridOptions o = Options(whole.string(), true);
  o.axes = {ParseDesignGridAxis("m2=0.18:0.3:6:log"), ParseDesignGridAxis("rho-max=0.9,inf")};
  o.comments = {"capsubot test design grid"};
  RunDesignGrid(o);
  const auto resumed = testing::TempPath("design_grid_resumed.csv");
  o.output = resumed.string();
  o.checkpoint_seconds = 0.0;
  o.threads = 1;
  EXPECT_THROW(RunDesignGrid(o,
                             [](const SweepProgress& p) {
                               if (p.points_done >= 5) throw Interrupt{};
                             }),
               Interrupt);
  ASSERT_FALSE(std::filesystem::exists(resumed));
  ASSERT_TRUE(std::filesystem::exists(resumed.string() + ".checkpoint"));
  o.resume = true;
  const SweepSummary s = RunDesignGrid(o);
  EXPECT_GE(s.points_resumed, 5);
  EXPECT_EQ(s.points, 12);
  EXPECT_EQ(ReadAll(resumed), ReadAll(whole));
  // A checkpoint of another grid is refused, not continued.
  o.axes[1] = ParseDesignGridAxis("rho-max=0.9,1");
  o.resume = false;
  o.output = testing::TempPath("design_grid_other.csv").string();
  EXPECT_THROW(RunDesignGrid(o, [](const SweepProgress&) { throw Interrupt{}; }), Interrupt);
  o.axes[1] = ParseDesignGridAxis("rho-max=0.9,inf");
  o.resume = true;
  try {
    RunDesignGrid(o);
    ADD_FAILURE() << "resumed another grid's checkpoint";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("checkpoint"), std::string::npos) << e.what();
  }
}

TEST(DesignGrid, BadGridsAreRefusedNamingTheParameterItsValueAndTheRule) {
  const struct {
    const char* spec;
    const char* message;
  } parse_cases[] = {
      {"m3=1:2:3",
       "grid m3=1:2:3 is invalid: unknown parameter 'm3': expected one of m1, L, mu, g, e, "
       "force-amplitude, force-bias, frequency, m2, margin, margin-stroke, stick-margin, "
       "rho-max"},
      {"rho_max=0.9", "unknown parameter 'rho_max'"},  // the sweep's name, not the design's
      {"L=0:0.02:3", "grid L=0:0.02:3 is invalid: expected gaps L > 0 [m]"},
      {"frequency=10:20:3:log:x", "expected name=lo:hi:n or name=lo:hi:n:log"},
      {"margin=0.1,0.5", "grid margin=0.1,0.5 is invalid: expected margins 0 <= margin < 0.5"},
      {"force-bias=0.1,inf", "expected finite values (not NaN or infinite)"},
      {"rho-max=0.9,-inf", "value 2 = '-inf' is not a number"},
      {"m2", "grid m2 is invalid: expected name=lo:hi:n, name=lo:hi:n:log or name=v1,v2,..."},
  };
  int checked = 0;
  for (const auto& c : parse_cases) {
    const std::string message =
        testing::InvalidArgumentMessage([&] { ParseDesignGridAxis(c.spec); });
    EXPECT_NE(message.find(c.message), std::string::npos) << c.spec << ": " << message;
    ++checked;
  }
  EXPECT_EQ(checked, 8);

  DesignGridOptions o = Options(testing::TempPath("design_grid_bad.csv").string(), true);
  EXPECT_EQ(testing::InvalidArgumentMessage([&] { o.Validate(); }),
            "grid is missing: expected at least one axis (name=lo:hi:n, name=lo:hi:n:log or "
            "name=v1,v2,...)");
  o.axes = {ParseDesignGridAxis("e=0.5"), ParseDesignGridAxis("e=0.6")};
  EXPECT_EQ(testing::InvalidArgumentMessage([&] { o.Validate(); }),
            "grid e=0.6 is invalid: parameter e already has a grid (e=0.5): expected each "
            "parameter at most once");
  o.axes = {ParseDesignGridAxis("force-amplitude=0.4,0.5")};
  o.input.force.sin = {0.5};
  EXPECT_NE(testing::InvalidArgumentMessage([&] {
              o.Validate();
            }).find("grid force-amplitude=0.4,0.5 is invalid with a Fourier motor force"),
            std::string::npos);
  o.input = testing::ExampleRobot();
  o.input.m2_min = 0.1;
  o.input.m2_max = 0.3;
  o.axes = {ParseDesignGridAxis("m2=0.2")};
  // The inner mass has one column, the grid's: a result column of that name is refused.
  o.columns = Options(o.output, false).columns;
  EXPECT_EQ(testing::InvalidArgumentMessage([&] { o.Validate(); }),
            "columns are invalid: m2_kg is the column of grid m2=0.2: expected each column once "
            "(the grid's value)");
  o.columns = Options(o.output, true).columns;
  o.threads = -1;
  EXPECT_EQ(testing::InvalidArgumentMessage([&] { o.Validate(); }),
            "threads = -1 is invalid: expected 1 <= threads <= 1024 (0: all cores)");
  o.threads = 1;
  o.shards = 2;
  o.shard = 0;
  EXPECT_EQ(testing::InvalidArgumentMessage([&] { o.Validate(); }),
            "shard = 0/2 is invalid: the grid has only 1 points: expected at most as many shards "
            "as points");
  EXPECT_FALSE(std::filesystem::exists(o.output));
}

}  // namespace
}  // namespace capsubot
