// `capsubot design` end to end: the TOML file and the flags give the same design, the JSON keys,
// the grid CSV (and `solve` reproducing a row, shards merged), and every bad-input path (one line
// naming the parameter, its value and the rule; exit status 2; no file left).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::RunCli;
using testing::TempPath;

// JSON numbers are written with round-trip precision: a number read back is the same double.
constexpr double kSolveRelTol = 1e-12;  // `solve` from a CSV row: same orbit, same operations

const std::string kFlags =
    "--m1 0.2 --L 0.02 --mu 0.3 --e 0.7 --force-amplitude 0.5 --force-bias 0.1 --frequency 20";
const std::string kMarginsOff = " --margin 0 --margin-stroke 0 --stick-margin 0 --rho-max 1";

std::string ExampleConfig() { return std::string(CAPSUBOT_SOURCE_DIR) + "/examples/robot.toml"; }

std::filesystem::path WriteConfig(const std::string& name, const std::string& text) {
  const auto path = TempPath(name);
  std::ofstream(path) << text;
  return path;
}

TEST(DesignCli, ConfigFileAndFlagsGiveTheSameDesign) {
  const auto from_file = RunCli("design --config " + ExampleConfig() + kMarginsOff + " --json");
  const auto from_flags = RunCli("design " + kFlags + kMarginsOff + " --json");
  ASSERT_EQ(from_file.status, 0) << from_file.out;
  ASSERT_EQ(from_flags.status, 0) << from_flags.out;
  // The same design and the same provenance: the settings of the file are recorded as the
  // flags that give them, not as the file's name (whose content may change).
  const auto file_json = nlohmann::json::parse(from_file.out);
  const auto flags_json = nlohmann::json::parse(from_flags.out);
  EXPECT_FALSE(file_json["provenance"]["options"].contains("--config"));
  EXPECT_EQ(file_json["provenance"]["options"]["--m1"], nlohmann::json::array({"0.2"}));
  EXPECT_EQ(file_json, flags_json);
}

// Shards of one grid made from two contents of one --config file are of different runs: the
// provenance line holds the file's values (m1 = 0.4 in one of them), so merge refuses them.
TEST(DesignCli, GridShardsOfDifferentConfigContentsDoNotMerge) {
  const std::string grid =
      " --margin 0 --margin-stroke 0 --stick-margin 0 --rho-max 1 "
      "--grid e=0.5,0.7,0.9";
  std::vector<std::string> shards;
  for (int k = 0; k < 3; ++k) {
    const auto config = WriteConfig(
        "robot" + std::to_string(k) + ".toml",
        std::string("m1 = ") + (k == 1 ? "0.4" : "0.2") +
            "\nL = 0.02\nmu = 0.3\nforce-amplitude = 0.5\nforce-bias = 0.1\nfrequency = 20\n");
    shards.push_back(TempPath("config_shard" + std::to_string(k) + ".csv").string());
    const auto r = RunCli("design --config " + config.string() + grid + " --shard " +
                          std::to_string(k) + "/3 -o " + shards.back());
    ASSERT_EQ(r.status, 0) << r.out;
  }
  std::string first_line;
  std::ifstream shard(shards[1]);
  std::getline(shard, first_line);
  EXPECT_NE(first_line.find(" design --m1 0.4 --L 0.02 --mu 0.3 --g 9.81 --force-amplitude 0.5 "),
            std::string::npos)
      << first_line;
  const std::string out = TempPath("config_merged.csv").string();
  std::filesystem::remove(out);
  const auto r =
      RunCli("merge " + out + " " + shards[0] + " " + shards[1] + " " + shards[2] + " 2>&1");
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_NE(r.out.find("shard files " + shards[0] + " and " + shards[1] + " are of different"),
            std::string::npos)
      << r.out;
  EXPECT_FALSE(std::filesystem::exists(out));
}

// Shards of one input given in other words (the default --g typed, a number written with
// another spelling, a setting in a file) name the same robot: they merge into the file of the
// whole grid.
TEST(DesignCli, GridShardsOfOneInputGivenInOtherWordsMerge) {
  const std::string robot =
      "design --L 0.02 --mu 0.3 --force-amplitude 0.5 --force-bias 0.1 --frequency 20 "
      "--margin 0 --margin-stroke 0 --stick-margin 0 --rho-max 1 --grid e=0.5,0.7,0.9";
  const auto config = WriteConfig("robot_m1.toml", "m1 = 0.2\n");
  const std::vector<std::string> words = {" --m1 0.2", " --m1 0.20 --g 9.81",
                                          " --config " + config.string()};
  const std::string merged_path = TempPath("words_merged.csv").string();
  std::string merge = "merge " + merged_path;
  for (std::size_t k = 0; k < words.size(); ++k) {
    const std::string shard = TempPath("words_shard" + std::to_string(k) + ".csv").string();
    const auto r = RunCli(robot + words[k] + " --shard " + std::to_string(k) + "/3 -o " + shard);
    ASSERT_EQ(r.status, 0) << r.out;
    merge += " " + shard;
  }
  const std::string whole = TempPath("words_whole.csv").string();
  ASSERT_EQ(RunCli(robot + " --m1 0.2 -o " + whole).status, 0);
  const auto r = RunCli(merge + " 2>&1");
  ASSERT_EQ(r.status, 0) << r.out;
  std::ifstream merged(merged_path), one(whole);
  const std::string merged_text((std::istreambuf_iterator<char>(merged)),
                                std::istreambuf_iterator<char>());
  const std::string whole_text((std::istreambuf_iterator<char>(one)),
                               std::istreambuf_iterator<char>());
  EXPECT_EQ(merged_text, whole_text);
  EXPECT_NE(whole_text.find(" --g 9.81 "), std::string::npos) << whole_text;
}

TEST(DesignCli, FlagsOverrideTheConfigFile) {
  const auto r =
      RunCli("design --config " + ExampleConfig() + " --frequency 25" + kMarginsOff + " --json");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_EQ(nlohmann::json::parse(r.out)["one_impact"]["frequency_hz"].get<double>(), 25.0);
  // A range given as a flag replaces the file's fixed frequency (the alternatives exclude
  // each other only within one source). Speed goes as 1/f here: the lowest frequency wins.
  const auto range = RunCli("design --config " + ExampleConfig() +
                            " --frequency-range 20:25 --scan-points 8 --m2-range 0.1:0.4" +
                            kMarginsOff + " --json");
  ASSERT_EQ(range.status, 0) << range.out;
  EXPECT_EQ(nlohmann::json::parse(range.out)["one_impact"]["frequency_hz"].get<double>(), 20.0);
}

TEST(DesignCli, JsonHoldsEveryKeyInTheUsersUnits) {
  const auto r = RunCli("design --config " + ExampleConfig() + kMarginsOff + " --json");
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["status"], "ok");
  const auto& g = j.at("one_impact");
  for (const char* key : {"m2_kg", "frequency_hz", "speed_mm_s", "displacement_mm",
                          "impact_velocity_m_s", "energy_mj", "power_mw", "power_positive_mw",
                          "friction_loss_mj", "impact_loss_mj", "cot", "efficiency"}) {
    EXPECT_TRUE(g.at(key).is_number()) << key;
  }
  for (const char* key : {"T0", "A", "c", "alpha", "phi0"}) {
    EXPECT_TRUE(g.at("dimensionless").at(key).is_number()) << key;
  }
  EXPECT_EQ(g["binding"], nlohmann::json::array({"rho_max"}));
  // The example of docs/design.md: near 0.21 kg, 1.3 mm/s, 2 mW (the library test checks m2
  // against an independent scan; here the units).
  EXPECT_NEAR(g["m2_kg"].get<double>(), 0.2128, 0.001);
  EXPECT_NEAR(g["speed_mm_s"].get<double>(), 1.31, 0.01);
  EXPECT_NEAR(g["power_mw"].get<double>(), 2.02, 0.01);
  EXPECT_GE(g["cot"].get<double>(), 0.3);
}

// Part (b): the fastest motion from rest in each direction, with the keys of the one-impact
// gait, the fractions of the starts and the attractors (the library test checks the numbers
// against the simulator).
TEST(DesignCli, JsonHoldsTheFastestMotionFromRestInEachDirection) {
  const auto r = RunCli("design --config " + ExampleConfig() + " --from-rest --json");
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out).at("from_rest_best");
  int directions = 0;
  for (const char* direction : {"forward", "backward"}) {
    const auto& b = j.at(direction);
    EXPECT_EQ(b["status"], "ok") << direction;
    for (const char* key : {"m2_kg", "frequency_hz", "speed_mm_s", "displacement_mm", "energy_mj",
                            "power_mw", "power_positive_mw", "friction_loss_mj", "impact_loss_mj",
                            "cot", "efficiency", "forward_fraction", "backward_fraction"}) {
      EXPECT_TRUE(b.at(key).is_number()) << direction << " " << key;
    }
    EXPECT_TRUE(b.contains("impact_velocity_m_s")) << direction;  // null: several impacts
    for (const char* key : {"T0", "A", "c", "alpha"}) {
      EXPECT_TRUE(b.at("dimensionless").at(key).is_number()) << direction << " " << key;
    }
    EXPECT_TRUE(b.at("dimensionless").at("phi0").is_null());  // the starts cover every phase
    double fractions = 0.0;
    for (const auto& a : b.at("attractors").at("attractors")) {
      for (const char* key :
           {"period", "impacts_right", "impacts_left", "mean_velocity", "speed_mm_s", "fraction"}) {
        EXPECT_TRUE(a.contains(key)) << direction << " " << key;
      }
      fractions += a["fraction"].get<double>();
    }
    EXPECT_NEAR(fractions, 1.0, 1e-12) << direction;
    ++directions;
  }
  EXPECT_EQ(directions, 2);
  // The example's light inner body drives the shell backward, faster than its forward gait.
  EXPECT_LT(j["backward"]["speed_mm_s"].get<double>(), -10.0);
  EXPECT_LT(j["backward"]["m2_kg"].get<double>(), 0.03);
  EXPECT_GT(j["forward"]["speed_mm_s"].get<double>(), 0.0);
  EXPECT_GT(j["evaluations"].get<int>(), 0);
}

// Part (a)'s gait is checked from rest in the text and the JSON, and the summary says which
// answer to build. The small robot (docs/design.md, "From rest"): most of its starts end with
// the inner body resting on the right wall, the robot still, so the gait's promise is not what
// the robot does from rest; the JSON's speed from rest is the starts' mean of its attractors.
TEST(DesignCli, PartAsGaitIsCheckedFromRestAndTheSummarySaysWhatToBuild) {
  const std::string robot =
      "design --m1 0.03 --mu 0.3 --L 0.01 --e 0.7 --force-amplitude 0.05 --force-bias 0.05 "
      "--frequency 20";
  const auto text = RunCli(robot);
  ASSERT_EQ(text.status, 0) << text.out;
  EXPECT_NE(text.out.find("  from rest         the gait is reached from "), std::string::npos)
      << text.out;
  EXPECT_NE(text.out.find("no impacts, the inner body at rest against the right wall, 0 mm/s"),
            std::string::npos)
      << text.out;
  EXPECT_NE(text.out.find("\nWhich to build:\n  the gait of part (a). It promises "),
            std::string::npos)
      << text.out;
  EXPECT_NE(text.out.find("x_max = 1 at the impact (no interior maximum)"), std::string::npos);
  const auto r = RunCli(robot + " --json");
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("build"), "one_impact");
  const auto& g = j.at("one_impact");
  const auto& fr = g.at("from_rest");
  const int starts = fr.at("starts").get<int>();
  const int reached = fr.at("reached").get<int>();
  EXPECT_EQ(starts, 64);
  EXPECT_GT(reached, 0);
  EXPECT_LT(2 * reached, starts);
  double mean = 0.0;
  int counted = 0;
  for (const auto& a : fr.at("attractors")) {
    mean += a.at("fraction").get<double>() * a.at("speed_mm_s").get<double>();
    counted += a.at("starts").get<int>();
  }
  EXPECT_EQ(counted, starts);
  EXPECT_NEAR(g.at("speed_from_rest_mm_s").get<double>(), mean, 1e-9 * std::abs(mean));
  EXPECT_LT(g.at("speed_from_rest_mm_s").get<double>(), 0.5 * g.at("speed_mm_s").get<double>());
}

// The gait's robustness in the user's units: mu, e and m2 [kg] with their limits, each limit
// named by its parameter (the library test checks the limits against the design's own
// evaluation of the robot); null without a gait.
TEST(DesignCli, JsonHoldsTheRobustnessInMuEAndKilograms) {
  const auto r = RunCli("design --config " + ExampleConfig() + " --json");
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out).at("robustness");
  for (const char* name : {"mu", "e", "m2_kg"}) {
    const auto& p = j.at(name);
    EXPECT_EQ(p["status"], "ok") << name;
    for (const char* side : {"down", "up"}) {
      EXPECT_TRUE(p.at(side).at("type").is_string()) << name << " " << side;
      EXPECT_TRUE(p.at(side).at(name).is_number()) << name << " " << side;
    }
  }
  EXPECT_EQ(j["mu"]["value"].get<double>(), 0.3);
  EXPECT_EQ(j["m2_kg"]["value"], nlohmann::json::parse(r.out)["one_impact"]["m2_kg"]);
  // docs/design.md: the stable design's inner mass, 0.2128 kg, is the lower limit.
  EXPECT_EQ(j["m2_kg"]["down"]["type"], "period_doubling");
  EXPECT_NEAR(j["m2_kg"]["down"]["m2_kg"].get<double>(), 0.2128, 1e-4);
  const auto none = RunCli("design --config " + ExampleConfig() +
                           " --force-amplitude 5 --m2-range 0.01:1 --json");
  ASSERT_EQ(none.status, 0) << none.out;
  EXPECT_TRUE(nlohmann::json::parse(none.out).at("robustness").is_null());
}

// The speed bands in the JSON: one pair of edges per level asked for, each edge's bracket
// around it; at 1500 Hz (T0 = 1.7e-6, narrower in mu than a fixed step) every part is computed.
TEST(DesignCli, JsonHoldsOneBandEdgePairPerLevel) {
  const auto r = RunCli("design --config " + ExampleConfig() + " --band-levels 0.95,0.9 --json");
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out).at("robustness");
  for (const char* name : {"mu", "e", "m2_kg"}) {
    const auto& band = j.at(name).at("band");
    ASSERT_EQ(band.at("status"), "ok") << name;
    ASSERT_EQ(band.at("levels").size(), 2U) << name;
    for (const auto& level : band["levels"]) {
      for (const char* side : {"down", "up"}) {
        const auto& edge = level.at(side);
        if (!edge.at("within").get<bool>()) continue;
        EXPECT_GE(edge.at("ratio_inside").get<double>(), level.at("level").get<double>());
        EXPECT_LT(edge.at("ratio_outside").get<double>(), level.at("level").get<double>());
      }
    }
  }
  const auto high = RunCli("design --config " + ExampleConfig() + " --frequency 1500 --json");
  ASSERT_EQ(high.status, 0) << high.out;
  for (const char* name : {"mu", "e", "m2_kg"}) {
    EXPECT_EQ(nlohmann::json::parse(high.out)["robustness"][name]["status"], "ok") << name;
  }
}

// Part (b) is asked for with --from-rest; without it the JSON is that of part (a) alone.
TEST(DesignCli, WithoutFromRestTheJsonHasNoFromRestBestAndRhoMaxTakesInf) {
  const auto r = RunCli("design --config " + ExampleConfig() + " --rho-max inf --json");
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_FALSE(j.contains("from_rest_best"));
  EXPECT_EQ(j["one_impact"]["status"], "ok");
}

TEST(DesignCli, TableShowsTheGaitAndHowToCheckIt) {
  const auto r = RunCli("design --config " + ExampleConfig() + " --from-rest");
  ASSERT_EQ(r.status, 0) << r.out;
  for (const char* text :
       {"inner mass", "mean speed", "mean motor power", "cost of transport", "binding",
        "capsubot solve", "robustness", "m2 = ", "the fastest motion reached from rest", "forward",
        "backward", "attractor 1", "from-rest evaluations"}) {
    EXPECT_NE(r.out.find(text), std::string::npos) << text << "\n" << r.out;
  }
}

// One CSV row of a grid over m2, solved again by `capsubot solve` from its dimensionless
// numbers: the design's orbit is exactly the orbit of the mapped parameters.
TEST(DesignCli, GridRowsAreReproducedBySolve) {
  const auto csv_path = TempPath("design_sweep.csv");
  const auto r = RunCli("design --config " + ExampleConfig() + kMarginsOff +
                        " --grid m2=0.18:0.3:7:log -o " + csv_path.string());
  ASSERT_EQ(r.status, 0) << r.out;
  const testing::CsvLines csv = testing::ReadCsv(csv_path);
  ASSERT_EQ(csv.comments.size(), 1U);
  const std::string& comment = csv.comments[0];
  EXPECT_EQ(comment.rfind("# capsubot ", 0), 0U) << comment;
  EXPECT_NE(comment.find(" design --m1 0.2 --L 0.02 "), std::string::npos) << comment;
  EXPECT_NE(comment.find(" --grid m2=0.18:0.3:7:log"), std::string::npos) << comment;
  // One column for the inner mass: the grid's, m2_kg, with its unit.
  EXPECT_EQ(csv.header,
            "m2_kg,status,frequency_hz,speed_mm_s,displacement_mm,impact_velocity_m_s,energy_mj,"
            "power_mw,power_positive_mw,friction_loss_mj,impact_loss_mj,cot,efficiency,T0,A,c,"
            "alpha,phi0,I,spectral_radius,x_min,x_max,orbits,binding");
  std::vector<std::vector<std::string>> rows;
  for (const std::string& line : csv.rows) {
    std::vector<std::string> cells;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) cells.push_back(cell);
    if (!line.empty() && line.back() == ',') cells.emplace_back();
    ASSERT_GE(cells.size(), 2U) << line;
    std::swap(cells[0], cells[1]);  // status, m2_kg, ...: the order of a design's gait
    rows.push_back(cells);
  }
  ASSERT_EQ(rows.size(), 7U);
  int ok = 0, blank = 0;
  for (const auto& row : rows) {
    ASSERT_EQ(row.size(), 24U);
    EXPECT_FALSE(row[1].empty());  // m2 is always there
    if (row[0] != "ok") {
      EXPECT_TRUE(row[3].empty() && row[13].empty());  // no gait: blank cells
      ++blank;
      continue;
    }
    ++ok;
    const auto s = RunCli("solve --A " + row[14] + " --c " + row[15] + " --phi0 " + row[17] +
                          " --T0 " + row[13] + " --e 0.7 --json");
    ASSERT_EQ(s.status, 0) << s.out;
    const auto j = nlohmann::json::parse(s.out);
    EXPECT_TRUE(j["valid"].get<bool>());
    EXPECT_TRUE(
        testing::NearAbsBelowOne(j["alpha"].get<double>(), std::stod(row[16]), kSolveRelTol));
    EXPECT_TRUE(testing::NearAbsBelowOne(j["I"].get<double>(), std::stod(row[18]), kSolveRelTol));
  }
  // m2 = 0.18, 0.196, 0.214, 0.233, 0.255, 0.278, 0.3 kg: the stable window of the example
  // starts at 0.2128 kg and its orbits end between 0.255 and 0.278 kg: 3 rows with a gait.
  EXPECT_EQ(ok, 3);
  EXPECT_EQ(blank, 4);
}

struct BadCase {
  const char* name;
  std::string args;
  std::string message;
};

std::vector<BadCase> BadCases() {
  const std::string cfg = " --config " + ExampleConfig();
  return {
      {"m1", "--m1 0" + cfg, "shell mass m1 = 0 is invalid: expected a finite m1 > 0 [kg]"},
      {"L", "--L -0.01" + cfg, "gap L = -0.01 is invalid: expected a finite L > 0 [m]"},
      {"mu", "--mu 0" + cfg, "friction coefficient mu = 0 is invalid: expected a finite mu > 0"},
      {"g", "--g -9.81" + cfg, "gravity g = -9.81 is invalid: expected a finite g > 0 [m/s^2]"},
      {"e", "--e 2" + cfg, "restitution e = 2 is invalid: expected 0 <= e <= 1"},
      {"nan", "--m1 nan" + cfg, "--m1 = nan is invalid: expected a finite number"},
      {"amplitude", "--force-amplitude -0.5" + cfg,
       "motor force amplitude = -0.5 is invalid: expected a finite amplitude >= 0 [N]"},
      {"bias", "--force-bias -1" + cfg,
       "motor force bias = -1 is invalid: expected a finite bias >= 0 [N]"},
      {"not_a_number", "--m1 0.2kg" + cfg,
       "--m1 = 0.2kg is invalid: expected a decimal number such as 0.5, -2 or 1e-3"},
      {"not_an_integer", "--scan-points 3.5" + cfg,
       "--scan-points = 3.5 is invalid: expected an integer"},
      {"range_element", "--m2-range 0.1:x" + cfg,
       "--m2-range = 0.1:x is invalid: expected MIN:MAX with MIN < MAX"},
      {"reach_starts", "--from-rest --reach-starts 0x4" + cfg, "--reach-starts = 0x4 is invalid"},
      {"reach_evaluations", "--from-rest --reach-evaluations 0" + cfg,
       "--reach-evaluations = 0 is invalid: expected 1 <= reach_evaluations <= 100000"},
      {"frequency_range_inverted", "--frequency-range 30:20" + cfg,
       "--frequency-range = 30:20 is invalid: expected MIN:MAX with MIN < MAX"},
      {"frequency_range_empty", "--frequency-range 20:20" + cfg,
       "--frequency-range = 20:20 is invalid: expected MIN:MAX with MIN < MAX"},
      {"m2_range", "--m2-range 0.5:0.1" + cfg,
       "--m2-range = 0.5:0.1 is invalid: expected MIN:MAX with MIN < MAX"},
      {"m2_range_negative", "--m2-range -1:0.1" + cfg,
       "inner mass range m2 = -1:0.1 is invalid: expected 0 < M2MIN < M2MAX [kg]"},
      {"both_frequencies", kFlags + " --frequency-range 10:30",
       "settings frequency and frequency-range are both given as flags: expected one of them"},
      {"missing",
       "--m1 0.2 --L 0.02 --mu 0.3 --force-amplitude 0.5 --force-bias 0.1 "
       "--frequency 20",
       "setting e is missing: give --e (or e in the --config file)"},
      {"missing_several", "--m1 0.2 --e 0.7 --force-bias 0.1",
       "settings L, mu, force-amplitude or force-sin and frequency or frequency-range are "
       "missing: give --L, --mu, --force-amplitude and --frequency (or L, mu, force-amplitude "
       "and frequency in the --config file)"},
      {"rho_max", "--rho-max 0" + cfg, "rho_max = 0 is invalid: expected rho_max > 0"},
      {"grid_name", "--grid mass=1:2:3 -o x.csv" + cfg,
       "--grid mass=1:2:3 is invalid: unknown parameter 'mass': expected one of m1, L, mu, g, e, "
       "force-amplitude, force-bias, frequency, m2, margin, margin-stroke, stick-margin, "
       "rho-max"},
      {"grid_number", "--grid m2=0x1p-3:0.3:5 -o x.csv" + cfg,
       "--grid m2=0x1p-3:0.3:5 is invalid: lo = '0x1p-3' is not a number"},
      {"grid_domain", "--grid e=0.5,1.5 -o x.csv" + cfg,
       "--grid e=0.5,1.5 is invalid: expected restitutions 0 <= e <= 1"},
      {"grid_log", "--grid m2=0:0.3:5:log -o x.csv" + cfg,
       "--grid m2=0:0.3:5:log is invalid: expected lo > 0 and hi > 0 for a log grid"},
      {"grid_infinite", "--grid m1=0.2,inf -o x.csv" + cfg,
       "--grid m1=0.2,inf is invalid: expected finite values (not NaN or infinite)"},
      {"grid_rho_max", "--grid rho-max=0,inf -o x.csv" + cfg,
       "--grid rho-max=0,inf is invalid: expected spectral radius bounds rho-max > 0 (inf: no "
       "bound)"},
      {"grid_twice", "--grid e=0.5 --grid e=0.6 -o x.csv" + cfg,
       "grid e=0.6 is invalid: parameter e already has a grid (e=0.5): expected each parameter "
       "at most once"},
      {"grid_and_flag", "--grid e=0.5 --e 0.3 -o x.csv" + cfg,
       "--e = 0.3 is invalid with --grid e=0.5: expected the value from only one of them"},
      {"grid_and_alternative", "--grid force-amplitude=0.4,0.5 --force-sin 0.5 -o x.csv" + cfg,
       "--force-sin = 0.5 is invalid with --grid force-amplitude=0.4,0.5: expected the value "
       "from only one of them"},
      {"grid_output", "--grid m2=0.1:0.3:5" + cfg,
       "output is missing: --grid writes its CSV to -o FILE"},
      {"grid_shard", "--grid m2=0.1:0.3:5 --shard 1/1 -o x.csv" + cfg,
       "--shard = 1/1 is invalid: expected K/N with N >= 1 shards and 0 <= K < N"},
      {"grid_json", "--grid m2=0.1:0.3:5 --json -o x.csv" + cfg,
       "--json is invalid with --grid: expected --json only with one design (no --from-rest, "
       "no --grid) or --from-rest"},
      // -o of one design: its text or JSON, to a file that can be written.
      {"output_of_one_design_unwritable", "-o /no/such/dir/d.json" + cfg,
       "-o /no/such/dir/d.json cannot be written: No such file or directory"},
      // Options of another run would be silently ignored.
      {"harmonics_with_sine_drive", "--drive sine --force-max 1 --harmonics 3" + cfg,
       "--harmonics is invalid with --drive sine: expected --harmonics only with --drive "
       "fourier"},
      {"levels_with_fourier_drive", "--drive fourier --force-max 1 --pulse-levels 4" + cfg,
       "--pulse-levels is invalid with --drive fourier: expected --pulse-levels only with "
       "--drive pulse"},
      {"budget_with_sine_drive", "--drive sine --force-max 1 --drive-screens 4" + cfg,
       "--drive-screens is invalid with --drive sine: expected --drive-screens only with --drive "
       "fourier or --drive pulse"},
      {"reach_without_from_rest", "--reach-starts 2x2" + cfg,
       "--reach-starts is invalid with one design (no --from-rest, no --grid): expected "
       "--reach-starts only with --from-rest"},
      {"from_rest_starts_with_grid", "--grid m2=0.1:0.3:5 --from-rest-starts 2x2 -o x.csv" + cfg,
       "--from-rest-starts is invalid with --grid: expected --from-rest-starts only with "
       "--from-rest"},
      {"grid_from_rest", "--grid m2=0.1:0.3:5 --from-rest -o x.csv" + cfg,
       "--from-rest is invalid with --grid: expected one of them"},
      {"unreadable_config", "--config /nonexistent/robot.toml",
       "--config /nonexistent/robot.toml cannot be read: No such file or directory"},
      {"endless_config", "--config /dev/zero",
       "--config /dev/zero is invalid: expected a file of at most 1048576 bytes"},
      {"band_levels", "--band-levels 0.95,1.5" + cfg,
       "--band-levels = 1.5 is invalid: expected fractions of the speed in (0, 1)"},
      {"band_levels_grid", "--grid m2=0.1:0.3:5 --band-levels 0.9 -o x.csv" + cfg,
       "--band-levels is invalid with --grid"},
      {"drive_force", "--drive fourier --force-max 0.6" + cfg,
       "setting force-amplitude is invalid with --drive: expected no motor force"},
      {"drive_no_peak", "--drive fourier --m1 0.2 --L 0.02 --mu 0.3 --e 0.7 --frequency 20",
       "setting force-max is missing: --drive needs the motor's peak force, give --force-max"},
      {"drive_peak",
       "--drive sine --force-max -1 --m1 0.2 --L 0.02 --mu 0.3 --e 0.7 --frequency 20",
       "--force-max = -1 is invalid: expected the motor's peak force, a finite force_max > 0 [N]"},
      {"drive_from_rest",
       "--drive sine --from-rest --force-max 1 --m1 0.2 --L 0.02 --mu 0.3 --e 0.7 "
       "--frequency 20",
       "--from-rest is invalid with --drive: expected one of them"},
      {"drive_kind",
       "--drive square --force-max 1 --m1 0.2 --L 0.02 --mu 0.3 --e 0.7 --frequency 20",
       "--drive: square not in {sine,fourier,pulse}"},
      {"drive_harmonics",
       "--drive fourier --harmonics 17 --force-max 1 --m1 0.2 --L 0.02 --mu 0.3 "
       "--e 0.7 --frequency 20",
       "--harmonics = 17 is invalid: expected 1 <= harmonics <= 16"},
      {"drive_without", "--drive-screens 3" + cfg,
       "--drive-screens is invalid with one design (no --from-rest, no --grid): expected "
       "--drive-screens only with --drive"},
  };
}

TEST(DesignCli, EveryBadInputIsOneLineNamingTheParameterAndExitsTwo) {
  const std::vector<BadCase> cases = BadCases();
  ASSERT_FALSE(cases.empty());
  std::size_t checked = 0;
  for (const BadCase& c : cases) {
    const auto r = RunCli("design " + c.args + " 2>&1");
    EXPECT_EQ(r.status, 2) << c.name << ": " << r.out;
    EXPECT_NE(r.out.find(c.message), std::string::npos) << c.name << ": " << r.out;
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << c.name << ": " << r.out;
    EXPECT_FALSE(std::filesystem::exists("x.csv")) << c.name;
    ++checked;
  }
  EXPECT_EQ(checked, cases.size());  // the loop has no early exit
}

TEST(DesignCli, TheFastestDriveInTheUsersUnitsForwardAndItsMirrorBackward) {
  // A small search (docs/design.md, "Part (c)"); the JSON against its own parts: the
  // drive's peak within the motor's, the robot within the ranges, the speed from the
  // dimensionless mean velocity (omega = 2 pi f), the mirror image's force.
  const auto r = RunCli(
      "design --m1 0.2 --L 0.02 --mu 0.3 --e 0.7 --frequency-range 10:20 --m2-range 0.05:0.5 "
      "--drive fourier --harmonics 2 --force-max 0.6 --reach-starts 2x2 --from-rest-starts 4x4 "
      "--reach-evaluations 30 --reach-local-evaluations 10 --drive-evaluations 40 "
      "--drive-refine-evaluations 40 --drive-screens 2 --drive-polishes 1 "
      "--drive-local-evaluations 20 --reach-seconds 1e6 --json");
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out)["drive_design"];
  ASSERT_EQ(j["status"], "ok") << j["message"];
  EXPECT_LE(j["force_n"]["max_abs"].get<double>(), 0.6 * (1.0 + 1e-12));
  const auto& f = j["forward"];
  const double m2 = f["m2_kg"], hz = f["frequency_hz"];
  EXPECT_TRUE(m2 >= 0.05 * (1 - 1e-12) && m2 <= 0.5 * (1 + 1e-12)) << m2;
  EXPECT_TRUE(hz >= 10.0 * (1 - 1e-12) && hz <= 20.0 * (1 + 1e-12)) << hz;
  const double omega_L_mm_s = 2e3 * M_PI * hz * 0.02;
  EXPECT_NEAR(f["speed_mm_s"].get<double>(),
              omega_L_mm_s * f["dimensionless"]["mean_velocity"].get<double>(), 1e-9);
  EXPECT_GT(f["speed_mm_s"].get<double>(), 0.0);
  EXPECT_LT(j["backward"]["speed_mm_s"].get<double>(), 0.0);
  EXPECT_EQ(j["backward_force_n"]["c"].get<double>(), -j["force_n"]["c"].get<double>());
  for (const char* part : {"cos", "sin"}) {
    const auto& forward = j["force_n"][part];
    ASSERT_EQ(forward.size(), 2U) << part;
    for (std::size_t k = 0; k < forward.size(); ++k) {
      EXPECT_EQ(j["backward_force_n"][part][k].get<double>(), -forward[k].get<double>()) << part;
    }
  }
  EXPECT_EQ(j["ladder"].size(), 2U);
}

TEST(DesignCli, BadConfigFilesNameTheKeyItsValueAndTheRule) {
  const struct {
    const char* name;
    std::string text;
    std::string message;
  } cases[] = {
      {"unknown_key", "m1 = 0.2\nmass = 3\n",
       "mass = 3 in {} is invalid: unknown key, expected one of m1, L, mu"},
      {"wrong_type", "m1 = \"0.2\"\n", "m1 = '0.2' in {} is invalid: expected a number"},
      {"wrong_list", "force-sin = [0.5, \"x\"]\n",
       "force-sin = [0.5, 'x'] in {} is invalid: expected an array of numbers"},
      {"inverted_range", "m2-range = [0.5, 0.1]\n",
       "m2-range = [0.5, 0.1] in {} is invalid: expected MIN:MAX with MIN < MAX"},
      {"integer", "scan-points = 3.5\n", "scan-points = 3.5 in {} is invalid: expected an integer"},
      {"syntax", "m1 = \n", "config file {} line 1 is invalid"},
      {"both_in_file", "frequency = 20\nfrequency-range = [10, 30]\n",
       "settings frequency and frequency-range are both given in {}: expected one of them"},
  };
  int checked = 0;
  for (const auto& c : cases) {
    const auto path = WriteConfig(std::string("design_") + c.name + ".toml", c.text);
    const auto r = RunCli("design --config " + path.string() + " 2>&1");
    std::string message = c.message;
    message.replace(message.find("{}"), 2, path.string());
    EXPECT_EQ(r.status, 2) << c.name << ": " << r.out;
    EXPECT_NE(r.out.find(message), std::string::npos) << c.name << ": " << r.out;
    std::filesystem::remove(path);
    ++checked;
  }
  EXPECT_EQ(checked, 7);
}

TEST(DesignCli, AMotorThatSlidesTheShellIsReportedNotAnError) {
  const auto r = RunCli("design --config " + ExampleConfig() +
                        " --force-amplitude 5 --m2-range 0.01:1 --from-rest --json");
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["status"], "motor_slides_shell");
  EXPECT_EQ(j["one_impact"]["status"], "motor_slides_shell");
  EXPECT_TRUE(j["one_impact"]["speed_mm_s"].is_null());
  // The search from rest still runs: the shell slides, the design says where it goes fastest.
  EXPECT_TRUE(j["from_rest_best"]["forward"]["status"] == "ok" ||
              j["from_rest_best"]["backward"]["status"] == "ok");
}

TEST(DesignCli, AFailedGridLeavesNoFile) {
  const auto csv = TempPath("design_failed.csv");
  const auto r = RunCli("design --config " + ExampleConfig() + " --grid m2=0.3:-0.1:5 -o " +
                        csv.string() + " 2>&1");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("grid m2=0.3:-0.1:5 is invalid: expected inner masses m2 > 0 [kg]"),
            std::string::npos)
      << r.out;
  EXPECT_FALSE(std::filesystem::exists(csv));
  EXPECT_FALSE(std::filesystem::exists(csv.string() + ".partial"));
}

std::string ReadAll(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// A grid of 2 axes (a log grid over m2, a list over rho-max with inf: no stability
// requirement) in 3 shards merged is the file of one run, byte for byte, on any thread count.
TEST(DesignCli, GridShardsMergedAreByteIdenticalToOneRun) {
  const std::string run =
      "design --config " + ExampleConfig() + " --grid m2=0.18:0.3:5:log --grid rho-max=0.9,inf";
  const auto whole = TempPath("design_grid_whole.csv");
  ASSERT_EQ(RunCli(run + " --threads 1 -o " + whole.string()).status, 0);
  const auto threaded = TempPath("design_grid_threaded.csv");
  ASSERT_EQ(RunCli(run + " --threads 2 -o " + threaded.string()).status, 0);
  EXPECT_EQ(ReadAll(threaded), ReadAll(whole));
  constexpr int kShards = 3;
  std::string shards;
  for (int k = 0; k < kShards; ++k) {
    const auto shard = TempPath("design_grid_shard" + std::to_string(k) + ".csv");
    const auto r = RunCli(run + " --shard " + std::to_string(k) + "/3 -o " + shard.string());
    ASSERT_EQ(r.status, 0) << r.out;
    EXPECT_NE(ReadAll(shard).find("# shard " + std::to_string(k) + "/3 of 10 points\n"),
              std::string::npos);
    shards = " " + shard.string() + shards;  // merge takes them in any order
  }
  const auto merged = TempPath("design_grid_merged.csv");
  const auto m = RunCli("merge " + merged.string() + shards);
  ASSERT_EQ(m.status, 0) << m.out;
  const std::string text = ReadAll(whole);
  EXPECT_EQ(ReadAll(merged), text);
  // 1 comment line, the header, 10 rows; inf written in the rows as in the comment line.
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 12);
  EXPECT_NE(text.find("--grid rho-max=0.9,inf"), std::string::npos);
  EXPECT_NE(text.find("\n0.3,inf,"), std::string::npos) << text;
}

}  // namespace
}  // namespace capsubot
