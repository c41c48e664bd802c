// The report of one robot design (design_text, design_json; the drive design has its own test):
// a design built here by hand on the example robot, so that each number printed is known: the
// gait in the user's units, the `capsubot solve` command that reproduces its orbit, speeds in
// omega L turned into mm/s here (1e3 omega L per omega L), what a gait without an orbit leaves
// null, and which answer to build.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <string>

#include "capsubot/report/design_json.hpp"
#include "capsubot/report/design_text.hpp"
#include "design/example_robot.hpp"
#include "report/report_text.hpp"

namespace capsubot {
namespace {

using testing::Has;
using testing::Printed;

// The example robot (m1 = 0.2 kg, L = 20 mm at 20 Hz) with a gait at m2 = 0.05 kg.
DesignJobResult HandMadeDesign() {
  DesignJobResult r;
  r.input = testing::ExampleRobot();
  r.design.status = DesignStatus::kOk;
  r.design.message = "hand-made design";
  r.design.robots = 40;
  Gait& g = r.design.one_impact;
  g.status = GaitStatus::kOk;
  g.m2_kg = 0.05;
  g.frequency_hz = 20.0;
  g.speed_mm_s = 40.0;
  g.displacement_mm = 2.0;
  g.cot = 1.5;
  g.orbits = 2;
  g.binding = {"left_wall", "m2_max"};
  g.model.omega = kTau * 20.0;
  Orbit& o = g.solution.orbit;
  o.forcing = Forcing::Harmonic(0.7, 0.1, 0.3);
  o.T0 = 0.3;
  o.e = 0.7;
  o.alpha = 0.2;
  o.I = 0.1;
  g.solution.validity.x_min = 0.25;
  g.stability.spectral_radius = 0.5;
  g.energy.motor_work = 0.125;
  return r;
}

// Part (a)'s gait checked from rest: 48 of 64 starts end on it, mean velocity 0.002 omega L.
GaitFromRest CheckedFromRest() {
  GaitFromRest fr;
  fr.checked = true;
  fr.reached = 48;
  fr.attractors.starts = 64;
  fr.attractors.mean_velocity = 0.002;
  Attractor a;
  a.motion.status = MotionStatus::kPeriodic;
  a.motion.period = 1;
  a.motion.impacts_right = 1;
  a.fraction = 0.75;
  a.mean_velocity = 0.0025;
  fr.attractors.attractors = {a};
  return fr;
}

// mm/s per omega L of the example robot at 20 Hz: 1e3 * 2 pi 20 * 0.02.
constexpr double kMmPerS = 1e3 * kTau * 20.0 * 0.02;

TEST(DesignTextReport, GaitInTheUsersUnitsWithItsSolveCommand) {
  const std::string t = text::DesignJobText(HandMadeDesign());
  EXPECT_TRUE(Has(t,
                  "  robot             m1 = 0.2 kg, L = 20 mm, mu = 0.3, g = 9.81 m/s^2, e = "
                  "0.7\n"));
  EXPECT_TRUE(Has(t, "  motor             F_N = 0.5 sin(omega t + phase) + 0.1 N\n"));
  // The default range of m2: 0.01 m1 to 10 m1.
  EXPECT_TRUE(Has(t, "  searched          m2 in [0.002, 2] kg, f = 20 Hz\n"));
  EXPECT_TRUE(Has(t, "  status            ok: hand-made design\n"));
  EXPECT_TRUE(Has(t, "  inner mass        m2 = 0.05 kg   (alpha = m2/(m1+m2) = 0.2)\n"));
  EXPECT_TRUE(Has(t, "  mean speed        40 mm/s\n"));
  EXPECT_TRUE(Has(t, "  motor energy      - per period\n"));  // not given: NaN
  EXPECT_TRUE(Has(t, "  dimensionless     T0 = 0.3, A = 0.7, c = 0.1, alpha = 0.2, phi0 = 0.3\n"));
  EXPECT_TRUE(Has(t,
                  "x_min = 0.25, x_max = 1 at the impact (no interior maximum), spectral "
                  "radius = 0.5, 2 orbit(s)\n"));
  EXPECT_TRUE(Has(t, "  binding           left_wall, m2_max\n"));
  EXPECT_TRUE(Has(t,
                  "  check             capsubot solve --A 0.7 --c 0.1 --phi0 0.3 --T0 0.3 --e "
                  "0.7 --stability\n"));
  EXPECT_EQ(t.find("note"), std::string::npos);  // the search was complete
}

TEST(DesignTextReport, GaitFromRestAndTheAdviceInMillimetresPerSecond) {
  DesignJobResult r = HandMadeDesign();
  r.gait_from_rest = CheckedFromRest();
  const std::string t = text::DesignJobText(r);
  const std::string all = fmt::format("{:.6g} mm/s", kMmPerS * 0.002);
  EXPECT_TRUE(Has(t,
                  "  from rest         the gait is reached from 48 of 64 starts from rest (75 "
                  "%); over all starts the robot moves at " +
                      all + "\n"));
  EXPECT_TRUE(Has(t, fmt::format("    attractor 1     75 % of the starts: period 1: 1 right + 0 "
                                 "left impacts per period, {:.6g} mm/s\n",
                                 kMmPerS * 0.0025)));
  EXPECT_TRUE(Has(t,
                  "\nWhich to build:\n  the gait of part (a). It promises 40 mm/s, but only 48 "
                  "of 64 starts from rest end on it:\n  from rest the robot averages " +
                      all + ". --from-rest searches for a faster motion from rest.\n"));
}

TEST(DesignTextReport, NoGaitStopsAfterTheStatusAndAGridIsOneLine) {
  DesignJobResult r = HandMadeDesign();
  r.design.status = DesignStatus::kNoGait;
  r.design.complete = false;
  r.design.one_impact = Gait{};
  const std::string t = text::DesignJobText(r);
  EXPECT_TRUE(Has(t, "  status            no_gait: hand-made design\n"));
  EXPECT_TRUE(Has(t, "  note              an orbit search hit its work bound"));
  EXPECT_EQ(t.find("inner mass"), std::string::npos);
  EXPECT_TRUE(Has(t,
                  "\nWhich to build:\n  nothing: no robust one-impact gait; --from-rest "
                  "searches the motions from rest.\n"));
  r.grid = DesignGridWritten{"grid.csv", SweepSummary{12, 12, 0, 2, 1.23456}};
  EXPECT_EQ(text::DesignJobText(r), "12 points written to grid.csv in 1.235 s on 2 threads\n");
}

TEST(DesignJsonReport, GaitHasItsUnitsDimensionlessOrbitAndNulls) {
  DesignJobResult r = HandMadeDesign();
  r.gait_from_rest = CheckedFromRest();
  const nlohmann::json j = Printed(json::DesignJobJson(r));
  EXPECT_EQ(j["status"], "ok");
  EXPECT_EQ(j["robots"], 40);
  EXPECT_TRUE(j["robustness"].is_null());  // not computed
  const nlohmann::json& g = j["one_impact"];
  EXPECT_EQ(g["status"], "ok");
  EXPECT_EQ(g["m2_kg"].get<double>(), 0.05);
  EXPECT_EQ(g["cot"].get<double>(), 1.5);
  EXPECT_TRUE(g["energy_mj"].is_null());
  EXPECT_EQ(g["dimensionless"]["A"].get<double>(), 0.7);
  EXPECT_EQ(g["dimensionless"]["phi0"].get<double>(), 0.3);
  EXPECT_EQ(g["dimensionless"]["energy"]["motor_work"].get<double>(), 0.125);
  EXPECT_FALSE(g["dimensionless"].contains("cos"));  // a sine
  EXPECT_EQ(g["binding"], nlohmann::json({"left_wall", "m2_max"}));
  EXPECT_EQ(g["from_rest"]["reached"], 48);
  EXPECT_DOUBLE_EQ(g["from_rest"]["attractors"][0]["speed_mm_s"].get<double>(), kMmPerS * 0.0025);
  EXPECT_DOUBLE_EQ(g["speed_from_rest_mm_s"].get<double>(), kMmPerS * 0.002);
  EXPECT_EQ(j["build"], "one_impact");
  EXPECT_FALSE(j.contains("from_rest_best"));
}

TEST(DesignJsonReport, AGaitNotFoundHasNullNumbersAndNoEnergy) {
  DesignJobResult r = HandMadeDesign();
  r.design.status = DesignStatus::kNoGait;
  r.design.one_impact = Gait{};
  r.design.one_impact.status = GaitStatus::kNotRobust;
  const nlohmann::json j = Printed(json::DesignJobJson(r));
  EXPECT_EQ(j["one_impact"]["status"], "not_robust");
  EXPECT_TRUE(j["one_impact"]["speed_mm_s"].is_null());
  EXPECT_TRUE(j["one_impact"]["dimensionless"]["T0"].is_null());
  EXPECT_FALSE(j["one_impact"]["dimensionless"].contains("energy"));
  EXPECT_EQ(j["build"], "none");
}

TEST(DesignJsonReport, FromRestBestHasBothDirectionsAndTheFasterOneIsBuilt) {
  DesignJobResult r = HandMadeDesign();
  r.gait_from_rest = CheckedFromRest();
  DesignFromRestResult b;
  b.forward.status = FromRestStatus::kOk;
  b.forward.speed_mm_s = 1e3;  // faster than the gait's kMmPerS * 0.002 = 5.03 mm/s from rest
  b.forward.model.robot.forcing = Forcing::Harmonic(0.7, 0.1, 0.0);
  b.forward.model.robot.params.T0 = 0.3;
  b.forward.model.robot.alpha = 0.2;
  b.forward.model.omega = kTau * 20.0;
  b.forward.attractors = CheckedFromRest().attractors;
  b.backward.direction = Direction::kBackward;
  b.evaluations = 300;
  r.from_rest = b;
  const nlohmann::json j = Printed(json::DesignJobJson(r));
  const nlohmann::json& fwd = j["from_rest_best"]["forward"];
  EXPECT_EQ(fwd["status"], "ok");
  EXPECT_EQ(fwd["speed_mm_s"].get<double>(), 1e3);
  EXPECT_EQ(fwd["dimensionless"]["A"].get<double>(), 0.7);
  EXPECT_TRUE(fwd["dimensionless"]["phi0"].is_null());  // the starts cover every motor phase
  EXPECT_DOUBLE_EQ(fwd["attractors"]["attractors"][0]["speed_mm_s"].get<double>(),
                   kMmPerS * 0.0025);
  const nlohmann::json& back = j["from_rest_best"]["backward"];
  EXPECT_EQ(back["status"], "not_run");
  EXPECT_TRUE(back["dimensionless"]["T0"].is_null());
  EXPECT_EQ(j["from_rest_best"]["evaluations"], 300);
  EXPECT_FALSE(j["from_rest_best"]["max_time"].get<bool>());
  EXPECT_EQ(j["build"], "from_rest_forward");
}

}  // namespace
}  // namespace capsubot
