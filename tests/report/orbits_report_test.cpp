// The report of every orbit of a robot (orbits_text, and RobotOrbitsJson of solution_json): one
// row per orbit with its phases, speed, stability and validity. The orbits are solved here (one
// Solve each: a stability of the report's own computing needs a real orbit); the numbers the
// rows must show are computed here from them and formatted as the report says it formats them.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "capsubot/orbit/stability.hpp"
#include "capsubot/report/orbits_text.hpp"
#include "capsubot/report/solution_json.hpp"
#include "report/report_text.hpp"

namespace capsubot {
namespace {

using testing::Has;
using testing::Printed;

// The paper's force at T0 = 1, e = 1 with two impact phases; the robot's own orbit search is
// not run: the report only reads the list.
OrbitsJobResult TwoOrbits() {
  OrbitsJobResult r;
  r.options.robot.forcing = Forcing::Harmonic(0.5, 0.5, 0.0);
  r.options.robot.params = Params{};
  r.options.robot.alpha = 0.25;
  for (const double phi0 : {-2.9449, -2.0}) {
    r.orbits.push_back(Solve(Forcing::Harmonic(0.5, 0.5, phi0), r.options.robot.params));
  }
  return r;
}

TEST(OrbitsTextReport, OneRowPerOrbitWithItsStabilityAndValidity) {
  const OrbitsJobResult r = TwoOrbits();
  const std::string t = text::OrbitsJobText(r, "--max-evaluations");
  EXPECT_TRUE(Has(t, "one-impact orbits of the robot with alpha = 0.25\n"));
  EXPECT_TRUE(Has(t, "  force   F(phi) = 0.5 sin(phi + 0) + 0.5   (phi0 = impact phase"));
  EXPECT_TRUE(Has(t, "  model   T0 = 1, e = 1, margins d = 0, d_s = 0, s = 0\n"));
  EXPECT_TRUE(Has(t, "  2 orbit(s)\n"));
  EXPECT_EQ(t.find("note:"), std::string::npos);  // complete
  OrbitsJobResult margins = r;  // each margin the validity was judged with is said
  margins.options.margins = Margins{0.05, 0.02, 0.1};
  EXPECT_TRUE(Has(text::OrbitsJobText(margins, "--max-evaluations"),
                  "  model   T0 = 1, e = 1, margins d = 0.05, d_s = 0.02, s = 0.1\n"));
  ASSERT_EQ(r.orbits.size(), 2U);
  for (const Solution& s : r.orbits) {
    ASSERT_TRUE(s.orbit.ok());
    const Stability st = ComputeStability(s.orbit);
    // The row's first cells: phi0 with 10 decimals, phi1 with 6, v_mean with 8 digits.
    const std::string row = fmt::format("{:.10f}  {:>10.6f}  {:>14}", s.orbit.forcing.phi0(),
                                        s.orbit.phi1, fmt::format("{:.8g}", s.orbit.v_mean));
    EXPECT_TRUE(Has(t, row));
    EXPECT_TRUE(Has(t, fmt::format("{:>15}  {:>8}", fmt::format("{:.6g}", st.spectral_radius),
                                   st.stable ? "yes" : "no")));
  }
  EXPECT_TRUE(Has(t, "-2.9449000000"));  // the phase as given, 10 decimals
}

TEST(OrbitsTextReport, AnIncompleteSearchSaysSoWithTheBoundsName) {
  OrbitsJobResult r;
  r.options.robot.alpha = 0.5;
  r.complete = false;
  const std::string t = text::OrbitsJobText(r, "max_evaluations");
  EXPECT_TRUE(Has(t, "  0 orbit(s)\n"));
  EXPECT_TRUE(Has(t,
                  "  note: the search stopped at its work bound (max_evaluations): orbits "
                  "may be missing\n"));
  EXPECT_EQ(t.find("spectral_radius"), std::string::npos);  // no rows: no header
}

TEST(OrbitsTextReport, AnInvalidOrbitNamesItsViolations) {
  OrbitsJobResult r = TwoOrbits();
  Solution& s = r.orbits.front();
  s.validity.violations = 1U << static_cast<unsigned>(Condition::kRightWall);
  EXPECT_TRUE(Has(text::OrbitsJobText(r, "b"), "no: right_wall\n"));
}

TEST(RobotOrbitsJsonReport, EachOrbitHasItsEnergyStabilityAndCompleteness) {
  const OrbitsJobResult r = TwoOrbits();
  const nlohmann::json j = Printed(json::RobotOrbitsJson(r.orbits, false));
  ASSERT_EQ(j.size(), 2U);
  for (std::size_t k = 0; k < 2; ++k) {
    const Stability st = ComputeStability(r.orbits[k].orbit);
    EXPECT_EQ(j[k]["phi0"].get<double>(), r.orbits[k].orbit.forcing.phi0());
    EXPECT_EQ(j[k]["spectral_radius"].get<double>(), st.spectral_radius);
    EXPECT_EQ(j[k]["stable"].get<bool>(), st.stable);
    EXPECT_TRUE(j[k]["energy"]["motor_work"].is_number());  // an orbit has its budget
    EXPECT_FALSE(j[k]["complete"].get<bool>());
  }
  EXPECT_TRUE(json::RobotOrbitsJson({}, true).empty());
}

}  // namespace
}  // namespace capsubot
