// The optimize job's settings (capsubot/job/optimize_settings.hpp): which settings do not shape
// the output of a problem, so that a record of the run leaves them out.

#include "capsubot/job/optimize_settings.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace capsubot {
namespace {

bool Lists(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

const char* const kDriveBudgets[] = {"drive_evaluations", "drive_polishes",
                                     "drive_local_evaluations", "drive_refine_evaluations",
                                     "drive_screens"};

TEST(OptimizeSettings, TheDriveBudgetsShapeOnlyADriveSearch) {
  OptimizeSettings sine;
  sine.problem = "reach";
  OptimizeSettings fourier = sine;  // K = 2 harmonics given: the Fourier drive
  fourier.search.harmonics = 2;
  fourier.given.insert("harmonics");
  OptimizeSettings pulse = sine;
  pulse.waveform = "pulse";
  pulse.given.insert("waveform");
  OptimizeSettings one = fourier;  // K = 1 is the sine
  one.search.harmonics = 1;
  const std::vector<std::string> unused_sine = UnusedOptimizeSettings(sine);
  const std::vector<std::string> unused_one = UnusedOptimizeSettings(one);
  const std::vector<std::string> unused_fourier = UnusedOptimizeSettings(fourier);
  const std::vector<std::string> unused_pulse = UnusedOptimizeSettings(pulse);
  for (const char* budget : kDriveBudgets) {
    EXPECT_TRUE(Lists(unused_sine, budget)) << budget;
    EXPECT_TRUE(Lists(unused_one, budget)) << budget;
    EXPECT_FALSE(Lists(unused_fourier, budget)) << budget;
    EXPECT_FALSE(Lists(unused_pulse, budget)) << budget;
  }
  EXPECT_TRUE(Lists(unused_sine, "pulse_levels"));
  EXPECT_TRUE(Lists(unused_fourier, "pulse_levels"));
  EXPECT_FALSE(Lists(unused_pulse, "pulse_levels"));
}

}  // namespace
}  // namespace capsubot
