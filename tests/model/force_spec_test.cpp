// A force as a user describes it: the harmonic force by its amplitude, a Fourier series by its
// coefficients, and one message for each thing missing or contradictory, naming the parameter
// as the front end calls it.

#include "capsubot/model/force_spec.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace capsubot {
namespace {

// A front end that names the parameters by flags.
const FlagNames kFlags = {{"A", "--A"},           {"c", "--c"},
                          {"phi0", "--phi0"},     {"sin", "--sin"},
                          {"cos", "--cos"},       {"waveform", "--waveform"},
                          {"levels", "--levels"}, {"switches", "--switches"}};

std::string Refusal(const ForceSpec& spec, bool need_phase, const FlagNames& names) {
  try {
    spec.Build(need_phase, names);
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
  EXPECT_EQ(Refusal(no_phase, false, {}), "");
  EXPECT_EQ(Refusal(no_phase, true, {}), "phi0 is missing: give the impact phase phi0 [rad]");
  EXPECT_EQ(Refusal(no_phase, true, kFlags), "--phi0 is missing: give the impact phase phi0 [rad]");
  const ForceSpec nothing{std::nullopt, 0.2, 0.0, std::nullopt, std::nullopt};
  EXPECT_EQ(Refusal(nothing, true, kFlags),
            "--A is missing: give the amplitude A (or --sin/--cos)");
  const ForceSpec both{0.5, 0.2, 0.0, std::nullopt, std::vector<double>{0.1}};
  EXPECT_EQ(Refusal(both, true, {}).rfind("A and sin are exclusive", 0), 0U);
  const ForceSpec cos_alone{std::nullopt, 0.2, 0.0, std::vector<double>{0.1}, std::nullopt};
  EXPECT_EQ(Refusal(cos_alone, true, {}).rfind("cos needs sin", 0), 0U);
  const ForceSpec empty{std::nullopt, 0.2, 0.0, std::nullopt, std::vector<double>{}};
  EXPECT_EQ(Refusal(empty, true, {}).rfind("sin = [] is invalid", 0), 0U);
}

TEST(ForceSpec, BuildsAPulseForceFromItsLevelsAndSwitches) {
  ForceSpec spec;
  spec.levels = std::vector<double>{0.5, -0.2};
  spec.switches = std::vector<double>{0.0, 2.0};
  spec.phi0 = 0.3;
  const Forcing f = spec.Build();  // the waveform follows from the parts
  EXPECT_TRUE(f.pulse());
  EXPECT_EQ(f.pulse_levels(), 2);
  EXPECT_EQ(f.level(1), -0.2);
  EXPECT_EQ(f.switch_phase(1), 2.0);
  EXPECT_EQ(f.phi0(), 0.3);
  spec.waveform = "pulse";
  spec.phi0.reset();
  EXPECT_EQ(spec.Build(false).phi0(), 0.0);  // phi0 defaults to 0 as for a Fourier force
}

TEST(ForceSpec, NamesWhatAPulseForceMissesOrMayNotHave) {
  ForceSpec pulse;
  pulse.waveform = "pulse";
  pulse.levels = std::vector<double>{0.5};
  EXPECT_EQ(Refusal(pulse, true, kFlags),
            "--switches is missing: a pulse force needs --levels L_1,...,L_N and --switches "
            "s_1,...,s_N [rad]");
  pulse.switches = std::vector<double>{7.0};
  EXPECT_EQ(Refusal(pulse, true, kFlags),
            "--switches: s_1 = 7 is invalid: expected 0 <= s < 2 pi (phases in radians)");
  pulse.switches = std::vector<double>{1.0};
  pulse.c = 0.1;
  EXPECT_EQ(Refusal(pulse, true, {}),
            "c = 0.1 is invalid with waveform pulse: expected no c (the levels give the mean "
            "force)");
  pulse.c.reset();
  pulse.A = 0.3;
  EXPECT_EQ(Refusal(pulse, true, kFlags),
            "--waveform pulse takes --levels and --switches: --A is invalid with it");
  ForceSpec fourier{std::nullopt, 0.1, 0.0, std::nullopt, std::vector<double>{0.2}};
  fourier.levels = std::vector<double>{0.5};
  fourier.waveform = "fourier";
  EXPECT_EQ(Refusal(fourier, true, kFlags),
            "--levels is invalid with --waveform fourier: expected it only with --waveform pulse");
  fourier.waveform = "square";
  EXPECT_EQ(Refusal(fourier, true, {}),
            "waveform = 'square' is invalid: expected sine, fourier or pulse");
  const ForceSpec no_c{0.5, std::nullopt, 0.0, std::nullopt, std::nullopt};
  EXPECT_EQ(Refusal(no_c, true, kFlags), "--c is missing: give the mean force c");
}

TEST(ForceSpec, TheAnalyticOrbitRefusesAPulseForce) {
  const Forcing f = Forcing::Pulse({0.5, -0.2}, {0.0, 2.0}, 0.0);
  try {
    RefusePulse(f, "solve");
    FAIL() << "a pulse force was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("a pulse force is invalid for solve: expected a sine or "
                                          "Fourier force",
                                          0),
              0U);
  }
  RefusePulse(Forcing::Harmonic(0.5, 0.1, 0.0), "solve");  // a sine force passes
}

}  // namespace
}  // namespace capsubot
