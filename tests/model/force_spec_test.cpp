// A force as a user describes it: the harmonic force by its amplitude, a Fourier series by its
// coefficients, and one message for each thing missing or contradictory, naming the parameter
// as the front end calls it.

#include "capsubot/model/force_spec.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace capsubot {
namespace {

std::string Refusal(const ForceSpec& spec, bool need_phase, const std::string& prefix) {
  try {
    spec.Build(need_phase, prefix);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(ForceSpec, BuildsTheHarmonicForceAndTheSeries) {
  const Forcing h = ForceSpec{0.5, 0.2, 1.0, std::nullopt, std::nullopt}.Build();
  EXPECT_TRUE(h.harmonic());
  EXPECT_EQ(h.amplitude(), 0.5);
  EXPECT_EQ(h.mean(), 0.2);
  EXPECT_EQ(h.phi0(), 1.0);
  const Forcing f =
      ForceSpec{std::nullopt, 0.1, std::nullopt, std::nullopt, std::vector<double>{0.3, 0.1}}.Build(
          false);
  EXPECT_FALSE(f.harmonic());
  EXPECT_EQ(f.harmonics(), 2);
  EXPECT_EQ(f.a(1), 0.0);  // cos absent: zeros
  EXPECT_EQ(f.b(2), 0.1);
  EXPECT_EQ(f.phi0(), 0.0);  // the phase left to the command
}

TEST(ForceSpec, NamesWhatIsMissingOrContradictoryInTheFrontEndsTerms) {
  const ForceSpec no_phase{0.5, 0.2, std::nullopt, std::nullopt, std::nullopt};
  EXPECT_EQ(Refusal(no_phase, false, ""), "");
  EXPECT_EQ(Refusal(no_phase, true, ""), "phi0 is missing: give the impact phase phi0 [rad]");
  EXPECT_EQ(Refusal(no_phase, true, "--"), "--phi0 is missing: give the impact phase phi0 [rad]");
  const ForceSpec nothing{std::nullopt, 0.2, 0.0, std::nullopt, std::nullopt};
  EXPECT_EQ(Refusal(nothing, true, "--"), "--A is missing: give the amplitude A (or --sin/--cos)");
  const ForceSpec both{0.5, 0.2, 0.0, std::nullopt, std::vector<double>{0.1}};
  EXPECT_EQ(Refusal(both, true, "").rfind("A and sin are exclusive", 0), 0U);
  const ForceSpec cos_alone{std::nullopt, 0.2, 0.0, std::vector<double>{0.1}, std::nullopt};
  EXPECT_EQ(Refusal(cos_alone, true, "").rfind("cos needs sin", 0), 0U);
  const ForceSpec empty{std::nullopt, 0.2, 0.0, std::nullopt, std::vector<double>{}};
  EXPECT_EQ(Refusal(empty, true, "").rfind("sin = [] is invalid", 0), 0U);
}

}  // namespace
}  // namespace capsubot
