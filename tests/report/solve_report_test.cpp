// The one-impact orbit's report (solution_json, solve_text): an orbit built here by hand, so that
// every number printed is known, its text lines and JSON keys; a number that does not exist
// (NaN) is "-" in the text and null in the JSON; the stability and the check from rest appear
// only when asked, "not computed" without an orbit.

#include <gtest/gtest.h>

#include <string>

#include "capsubot/report/solution_json.hpp"
#include "capsubot/report/solve_text.hpp"
#include "report/report_text.hpp"

namespace capsubot {
namespace {

using testing::Has;
using testing::Printed;

// An orbit with round numbers; valid unless `violations` (bits of Condition) are set.
Solution HandMadeOrbit(unsigned violations = 0) {
  Solution s;
  Orbit& o = s.orbit;
  o.forcing = Forcing::Harmonic(0.5, 0.25, -2.5);
  o.T0 = 0.8;
  o.e = 0.9;
  o.status = OrbitStatus::kOk;
  o.phi1 = 1.5;
  o.alpha = 0.4;
  o.u = 0.75;
  o.v_plus = 0.125;
  o.I = 0.0625;
  o.v_mean = 0.0625 / kTau;
  Validity& v = s.validity;
  v.checked = true;
  v.violations = violations;
  v.x_min = 0.25;
  v.x_max = kNaN;  // x rises to the right wall at the impact
  v.stroke = 0.75;
  v.clearance = 0.0;
  return s;
}

unsigned Bit(Condition c) { return 1U << static_cast<unsigned>(c); }

TEST(SolutionJsonReport, HoldsTheOrbitWithNullForWhatDoesNotExist) {
  const nlohmann::json j = Printed(json::SolutionJson(HandMadeOrbit()));
  EXPECT_EQ(j["waveform"], "sine");
  EXPECT_EQ(j["A"].get<double>(), 0.5);
  EXPECT_EQ(j["T0"].get<double>(), 0.8);
  EXPECT_EQ(j["status"], "ok");
  EXPECT_EQ(j["phi1"].get<double>(), 1.5);
  EXPECT_EQ(j["alpha"].get<double>(), 0.4);
  EXPECT_EQ(j["I"].get<double>(), 0.0625);
  EXPECT_EQ(j["x_min"].get<double>(), 0.25);
  EXPECT_TRUE(j["x_max"].is_null());  // NaN: no interior maximum
  EXPECT_TRUE(j["valid"].get<bool>());
  EXPECT_TRUE(j["violations"].empty());
}

TEST(SolutionJsonReport, NamesTheViolatedConditionsAndAFourierForceHasNoAmplitude) {
  Solution s = HandMadeOrbit(Bit(Condition::kLeftWall) | Bit(Condition::kStick));
  s.orbit.forcing = Forcing::Fourier(0.25, {0.1, 0.0}, {0.5, 0.2}, 0.0);
  const nlohmann::json j = Printed(json::SolutionJson(s));
  EXPECT_FALSE(j["valid"].get<bool>());
  // In the order of the conditions: stick comes before left_wall.
  EXPECT_EQ(j["violations"], nlohmann::json({"stick", "left_wall"}));
  EXPECT_TRUE(j["A"].is_null());
  EXPECT_EQ(j["sin"][1].get<double>(), 0.2);
}

TEST(SolutionJsonReport, SolveJobAddsStabilityAndFromRestOnlyWhenAsked) {
  SolveJobResult r;
  r.solution = HandMadeOrbit();
  r.energy.motor_work = 0.5;  // the other figures stay NaN: null
  const nlohmann::json plain = Printed(json::SolveJobJson(r));
  EXPECT_EQ(plain["energy"]["motor_work"].get<double>(), 0.5);
  EXPECT_TRUE(plain["energy"]["impact_loss"].is_null());
  EXPECT_FALSE(plain.contains("multipliers"));
  EXPECT_FALSE(plain.contains("from_rest"));

  r.options.stability = FromRestOptions{};  // asked, but neither was computed
  const nlohmann::json asked = Printed(json::SolveJobJson(r));
  EXPECT_TRUE(asked["multipliers"].is_null());
  EXPECT_TRUE(asked["spectral_radius"].is_null());
  EXPECT_FALSE(asked["stable"].get<bool>());
  EXPECT_TRUE(asked["from_rest"].is_null());
}

TEST(SolutionJsonReport, StabilityHasItsMultipliers) {
  Stability st;
  st.computed = true;
  st.multipliers = {std::complex<double>(0.5, 0.25), std::complex<double>(0.5, -0.25)};
  st.spectral_radius = 0.6;
  st.stable = true;
  nlohmann::json j;
  json::AddStabilityJson(j, st);
  ASSERT_EQ(j["multipliers"].size(), 2U);
  EXPECT_EQ(j["multipliers"][1]["im"].get<double>(), -0.25);
  EXPECT_EQ(j["spectral_radius"].get<double>(), 0.6);
  EXPECT_TRUE(j["stable"].get<bool>());
}

TEST(SolveTextReport, TableWritesEachQuantityWithTenDigits) {
  const std::string t = text::SolutionTable(HandMadeOrbit(), Params{0.8, 0.9});
  EXPECT_TRUE(Has(t, "  force            F(phi) = 0.5 sin(phi - 2.5) + 0.25\n"));
  EXPECT_TRUE(Has(t, "  model            T0 = 0.8, e = 0.9, margin = 0\n"));
  EXPECT_TRUE(Has(t, "  status           ok\n"));
  EXPECT_TRUE(Has(t, "phi1   = 1.5\n"));
  // v_mean = I / 2 pi = 0.0625 / 6.283185307 = 0.009947183943 (10 significant digits).
  EXPECT_TRUE(Has(t, "v_mean = 0.009947183943   (omega L)"));
  EXPECT_TRUE(Has(t, "x_min  = 0.25, x_max = 1 at the impact (no interior maximum)"));
  EXPECT_TRUE(Has(t, "  valid            yes"));
  EXPECT_EQ(t.find("clearance"), std::string::npos);  // none required: no line
  EXPECT_EQ(t.find("margin_stroke"), std::string::npos);
}

TEST(SolveTextReport, TableNamesTheViolationsAndTheMarginsGiven) {
  Solution s = HandMadeOrbit(Bit(Condition::kLeftWall) | Bit(Condition::kClearance));
  s.validity.clearance = 0.015;
  const std::string t = text::SolutionTable(s, Params{0.8, 0.9}, Margins{0.0, 0.02, 0.05});
  EXPECT_TRUE(Has(t, "  valid            no: violated left_wall, clearance\n"));
  EXPECT_TRUE(Has(t, "margin = 0, margin_stroke = 0.02, stick_margin = 0.05\n"));
  EXPECT_TRUE(Has(t, "  clearance        0.015 required from both walls (stroke 0.75)\n"));
}

TEST(SolveTextReport, AnOrbitThatDoesNotExistHasDashes) {
  Solution s;
  s.orbit.status = OrbitStatus::kNoMassRatio;
  const std::string t = text::SolutionTable(s, Params{});
  EXPECT_TRUE(Has(t, "  status           no_mass_ratio\n"));
  EXPECT_TRUE(Has(t, "phi1   = -\n"));
  EXPECT_TRUE(Has(t, "x_min  = -, x_max = -"));  // no orbit: no impact to name either
  EXPECT_TRUE(Has(t, "  valid            no"));
}

TEST(SolveTextReport, StabilityTableWritesTheMultipliersWithTheirSign) {
  EXPECT_EQ(text::StabilityTable(Stability{}), "  stability        not computed (no orbit)\n");
  Stability st;
  st.computed = true;
  st.multipliers = {std::complex<double>(-1.25, 0.0), std::complex<double>(0.5, -0.25)};
  st.spectral_radius = 1.25;
  st.stable = false;
  const std::string t = text::StabilityTable(st);
  EXPECT_TRUE(Has(t, "  multiplier 1     -1.25 + 0i\n"));
  EXPECT_TRUE(Has(t, "  multiplier 2     0.5 - 0.25i\n"));
  EXPECT_TRUE(Has(t, "  spectral radius  1.25   (unstable, >= 1"));
}

TEST(SolveTextReport, JobAddsTheEnergyAndWithStabilityTheCheckFromRest) {
  SolveJobResult r;
  r.solution = HandMadeOrbit();
  r.options.params = Params{0.8, 0.9};
  r.energy = Energy{0.5, 0.75, 0.25, kNaN};
  const std::string plain = text::SolveJobText(r);
  EXPECT_TRUE(Has(plain, "  motor work       W = 0.5, positive part W+ = 0.75"));
  EXPECT_TRUE(Has(plain, "  losses           friction = 0.25, impacts = -   (per period"));
  EXPECT_EQ(plain.find("stability"), std::string::npos);
  r.options.stability = FromRestOptions{};
  r.from_rest.summary = "reached from rest in 3 of 4 starts";
  const std::string asked = text::SolveJobText(r);
  EXPECT_TRUE(Has(asked, "  stability        not computed (no orbit)\n"));
  EXPECT_TRUE(Has(asked, "\n  from rest        reached from rest in 3 of 4 starts\n"));
}

}  // namespace
}  // namespace capsubot
