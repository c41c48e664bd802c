// The grid of starts "NXxNPSI" (capsubot/attract/start_grid.hpp): one parser and one set of
// limits for the command line and the Python module.

#include "capsubot/attract/start_grid.hpp"

#include <gtest/gtest.h>

#include <string>

#include "capsubot/attract/attractors.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::InvalidArgumentMessage;

TEST(StartGrid, ParsesTwoWholeNumbersAroundAnX) {
  const StartGrid a = ParseStartGrid("--starts", "8x6");
  EXPECT_EQ(a.n_x, 8);
  EXPECT_EQ(a.n_psi, 6);
  EXPECT_EQ(a.Starts(), 48);
  const StartGrid b = ParseStartGrid("starts", "100000X1");  // either case, the largest side
  EXPECT_EQ(b.n_x, 100000);
  EXPECT_EQ(b.n_psi, 1);
  EXPECT_EQ(ParseStartGrid("starts", "2048x2048").Starts(), kMaxRestStarts);
}

TEST(StartGrid, RefusesAnythingElseNamingTheArgumentAndTheRule) {
  const std::string rule =
      " is invalid: expected NXxNPSI, two whole numbers from 1 to 100000 (e.g. 8x8)";
  for (const char* text : {"8by8", "0x8", "8x0", " 2x2", "+2x2", "2x-2", "2x2e0", "100001x1", "2x",
                           "x2", "", "1000000x1", "99999999999x1"}) {
    EXPECT_EQ(InvalidArgumentMessage([&] { ParseStartGrid("starts", text); }),
              std::string("starts = ") + text + rule)
        << text;
  }
  EXPECT_EQ(InvalidArgumentMessage([&] { ParseStartGrid("--starts", "3000x3000"); }),
            "--starts = 3000x3000 is invalid: expected at most 4194304 starts");
}

TEST(StartGrid, ValidateHasTheParsersLimitsAndFromRestOptionsUseThem) {
  EXPECT_EQ(InvalidArgumentMessage([] {
              StartGrid{0, 8}.Validate();
            }),
            "n_x = 0 is invalid: expected 1 <= n_x <= 100000 starting positions");
  EXPECT_EQ(InvalidArgumentMessage([] {
              StartGrid{8, 100001}.Validate();
            }),
            "n_psi = 100001 is invalid: expected 1 <= n_psi <= 100000 starting phases");
  EXPECT_EQ(InvalidArgumentMessage([] {
              StartGrid{3000, 3000}.Validate();
            }),
            "starts = 3000x3000 is invalid: expected n_x * n_psi <= 4194304 starts");
  FromRestOptions o;
  o.n_x = 3000;
  o.n_psi = 3000;
  EXPECT_EQ(InvalidArgumentMessage([&] { o.Validate(); }),
            "starts = 3000x3000 is invalid: expected n_x * n_psi <= 4194304 starts");
  EXPECT_EQ(InvalidArgumentMessage([] { StartGrid{}.Validate(); }), "");
}

}  // namespace
}  // namespace capsubot
