// The pieces every report shares (text_format, forcing_json): numbers in tables with their
// digits and "-" for a missing one, and the force as a formula and as JSON, on forces built
// here so that each coefficient printed is known.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "capsubot/numerics/not_computed.hpp"
#include "capsubot/report/forcing_json.hpp"
#include "capsubot/report/text_format.hpp"
#include "report/report_text.hpp"

namespace capsubot {
namespace {

TEST(TextFormatReport, NumWritesSignificantDigitsAndADashForNaN) {
  EXPECT_EQ(text::Num(0.123456789012, 4), "0.1235");  // rounded at the 4th digit
  EXPECT_EQ(text::Num(1234567.0, 3), "1.23e+06");     // %g turns to an exponent past 3 digits
  EXPECT_EQ(text::Num(2.0 / 3.0), "0.6666666667");    // 10 digits by default
  EXPECT_EQ(text::Num(kNaN), "-");
  EXPECT_EQ(text::Num(kNaN, 3), "-");
}

TEST(TextFormatReport, NumFixedWritesDecimalsAndADashForNaN) {
  EXPECT_EQ(text::NumFixed(kTau / 2.0, 2), "3.14");
  EXPECT_EQ(text::NumFixed(-0.5, 3), "-0.500");
  EXPECT_EQ(text::NumFixed(kNaN, 6), "-");
}

TEST(TextFormatReport, XMaxWithoutAnInteriorMaximumIsTheImpact) {
  EXPECT_EQ(text::XMaxText(kNaN), "1 at the impact (no interior maximum)");
  EXPECT_EQ(text::XMaxText(0.87654321, 3), "0.877");
}

TEST(TextFormatReport, HarmonicForceWritesTheSignOfItsPhase) {
  EXPECT_EQ(text::ForceFormula(Forcing::Harmonic(0.5, 0.25, -2.9449)),
            "F(phi) = 0.5 sin(phi - 2.9449) + 0.25");
  // 6 significant digits: 1/3 is 0.333333.
  EXPECT_EQ(text::ForceFormula(Forcing::Harmonic(1.0 / 3.0, 0.5, 1.25)),
            "F(phi) = 0.333333 sin(phi + 1.25) + 0.5");
}

TEST(TextFormatReport, FourierForceListsEachHarmonicInTheMotorPhase) {
  const Forcing f = Forcing::Fourier(0.1, {0.2, -0.3}, {0.4, 0.5}, 1.0);
  EXPECT_EQ(text::ForceFormula(f),
            "F(phi) = 0.1 + 0.2 cos 1t + 0.4 sin 1t + -0.3 cos 2t + 0.5 sin 2t,  t = phi + 1");
}

TEST(TextFormatReport, PulseForceListsItsLevelsFromTheirSwitches) {
  const Forcing f = Forcing::Pulse({0.4, -0.2}, {0.0, 2.0}, 0.5);
  EXPECT_EQ(text::ForceFormula(f),
            "F(phi) = G(t), G = 0.4 from t = 0, -0.2 from t = 2,  t = phi + 0.5");
}

TEST(ForcingJsonReport, SineHasItsAmplitudeMeanAndPhase) {
  const nlohmann::json j = json::ForcingJson(Forcing::Harmonic(0.5, 0.25, -1.5));
  EXPECT_EQ(j["waveform"], "sine");
  EXPECT_EQ(j["A"].get<double>(), 0.5);
  EXPECT_EQ(j["c"].get<double>(), 0.25);
  EXPECT_EQ(j["phi0"].get<double>(), -1.5);
  EXPECT_FALSE(j.contains("cos"));
  EXPECT_FALSE(j.contains("levels"));
}

TEST(ForcingJsonReport, FourierHasOneCoefficientPerHarmonic) {
  const nlohmann::json j = json::ForcingJson(Forcing::Fourier(0.1, {0.2, -0.3}, {0.4, 0.5}, 1.0));
  EXPECT_EQ(j["waveform"], "fourier");
  EXPECT_EQ(j["c"].get<double>(), 0.1);
  ASSERT_EQ(j["cos"].size(), 2U);
  EXPECT_EQ(j["cos"][1].get<double>(), -0.3);
  EXPECT_EQ(j["sin"][0].get<double>(), 0.4);
  EXPECT_EQ(j["phi0"].get<double>(), 1.0);
  EXPECT_FALSE(j.contains("A"));
}

TEST(ForcingJsonReport, PulseHasItsLevelsAndSwitches) {
  const nlohmann::json j =
      json::ForcingJson(Forcing::Pulse({0.4, -0.2, 0.1}, {0.0, 2.0, 4.0}, 0.5));
  EXPECT_EQ(j["waveform"], "pulse");
  ASSERT_EQ(j["levels"].size(), 3U);
  EXPECT_EQ(j["levels"][1].get<double>(), -0.2);
  EXPECT_EQ(j["switches"][2].get<double>(), 4.0);
  EXPECT_EQ(j["phi0"].get<double>(), 0.5);
  EXPECT_FALSE(j.contains("c"));
}

}  // namespace
}  // namespace capsubot
