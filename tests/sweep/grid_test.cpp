// Grids of sweep parameters: `name=lo:hi:n` parsing, the values, and every rejection message.

#include "capsubot/grid.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace capsubot {
namespace {

// The message of the std::invalid_argument thrown by f ("" if none).
template <class Fn>
std::string Message(const Fn& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(Grid, ParsesNameBoundsAndCount) {
  const GridAxis axis = ParseGridAxis("c=0.01:0.5:50");
  EXPECT_EQ(axis.parameter, SweepParameter::kc);
  EXPECT_EQ(axis.lo, 0.01);
  EXPECT_EQ(axis.hi, 0.5);
  EXPECT_EQ(axis.n, 50);
}

TEST(Grid, AcceptsPiAsABound) {
  const GridAxis axis = ParseGridAxis("phi0=-pi:pi:3");
  EXPECT_EQ(axis.lo, -M_PI);
  EXPECT_EQ(axis.hi, M_PI);
  EXPECT_EQ(axis.Value(1), 0.0);
}

TEST(Grid, ValuesIncludeBothEndsExactly) {
  const GridAxis axis = ParseGridAxis("A=0.1:0.7:7");
  EXPECT_EQ(axis.Value(0), 0.1);
  EXPECT_EQ(axis.Value(6), 0.7);
  for (int i = 0; i < 7; ++i) EXPECT_NEAR(axis.Value(i), 0.1 + 0.1 * i, 1e-15) << i;
}

TEST(Grid, OnePointMeansLo) {
  const GridAxis axis = ParseGridAxis("T0=2:5:1");
  EXPECT_EQ(axis.Value(0), 2.0);
}

TEST(Grid, DescendingRangesAreAllowed) {
  const GridAxis axis = ParseGridAxis("e=1:0:3");
  EXPECT_EQ(axis.Value(1), 0.5);
  EXPECT_EQ(axis.Value(2), 0.0);
}

TEST(Grid, TwoAxesRunRowMajorWithTheLastFastest) {
  Grid g;
  g.axes = {ParseGridAxis("A=0:1:2"), ParseGridAxis("c=0.1:0.3:3")};
  g.Validate();
  ASSERT_EQ(g.size(), 6);
  EXPECT_EQ(g.Value(0, 0), 0.0);
  EXPECT_EQ(g.Value(2, 0), 0.0);
  EXPECT_EQ(g.Value(3, 0), 1.0);
  EXPECT_EQ(g.Value(3, 1), 0.1);
  EXPECT_EQ(g.Value(5, 1), 0.3);
  EXPECT_TRUE(g.Has(SweepParameter::kc));
  EXPECT_FALSE(g.Has(SweepParameter::kphi0));
}

struct BadSpec {
  const char* spec;
  const char* message;  // expected substring
};

class GridRejects : public ::testing::TestWithParam<BadSpec> {};

TEST_P(GridRejects, WithAMessageNamingTheOptionValueAndRule) {
  const BadSpec& bad = GetParam();
  const std::string message = Message([&] { ParseGridAxis(bad.spec); });
  EXPECT_EQ(message.rfind(std::string("--grid ") + bad.spec + " is invalid: ", 0), 0u) << message;
  EXPECT_NE(message.find("is invalid"), std::string::npos) << message;
  EXPECT_NE(message.find(bad.message), std::string::npos) << message;
}

INSTANTIATE_TEST_SUITE_P(
    BadSpecs, GridRejects,
    ::testing::Values(BadSpec{"x=0:1:3",
                              "unknown parameter 'x': expected one of A, c, phi0, T0, e, margin"},
                      BadSpec{"phi0", "expected name=lo:hi:n"},
                      BadSpec{"phi0=0:1", "three fields separated by ':'"},
                      BadSpec{"phi0=0:1:2:3", "three fields separated by ':'"},
                      BadSpec{"phi0=a:1:3", "lo = 'a' is not a number"},
                      BadSpec{"phi0=0::3", "hi = '' is not a number"},
                      BadSpec{"phi0=0:1:2.5", "n = '2.5' is not an integer"},
                      BadSpec{"phi0=0:1:0", "n = 0: expected n >= 1"},
                      BadSpec{"phi0=0:1:-4", "n = -4: expected n >= 1"},
                      BadSpec{"phi0=nan:1:3", "expected finite bounds"},
                      BadSpec{"c=0:inf:3", "expected finite bounds"},
                      BadSpec{"A=-0.1:1:3", "expected amplitudes A >= 0"},
                      BadSpec{"T0=0:1:3", "expected friction bounds T0 > 0"},
                      BadSpec{"e=0:1.5:3", "expected restitutions 0 <= e <= 1"},
                      BadSpec{"margin=0:0.5:3", "expected margins 0 <= margin < 0.5"},
                      BadSpec{"alpha=0:0.5:3", "expected mass ratios 0 < alpha < 1"}));

TEST(GridRejects, TheSpecItselfIsQuotedInTheMessage) {
  EXPECT_EQ(Message([] { ParseGridAxis("phi0=0:1:0"); }),
            "--grid phi0=0:1:0 is invalid: n = 0: expected n >= 1 points");
}

TEST(GridRejects, TheSameParameterTwice) {
  Grid g;
  g.axes = {ParseGridAxis("c=0:1:3"), ParseGridAxis("c=0:2:3")};
  const std::string message = Message([&] { g.Validate(); });
  EXPECT_NE(message.find("--grid c=0:2:3 is invalid: parameter c already has a grid"),
            std::string::npos)
      << message;
}

TEST(GridRejects, AlphaTogetherWithPhi0) {
  Grid g;
  g.axes = {ParseGridAxis("alpha=0.1:0.9:3"), ParseGridAxis("phi0=-pi:pi:3")};
  const std::string message = Message([&] { g.Validate(); });
  EXPECT_NE(message.find("--grid alpha together with --grid phi0 is invalid"), std::string::npos)
      << message;
}

TEST(GridRejects, NoneOrThreeAxes) {
  Grid g;
  EXPECT_NE(Message([&] { g.Validate(); }).find("expected 1 or 2 grids"), std::string::npos);
  g.axes = {ParseGridAxis("c=0:1:3"), ParseGridAxis("A=0:1:3"), ParseGridAxis("T0=1:2:3")};
  EXPECT_NE(Message([&] { g.Validate(); }).find("--grid given 3 times is invalid"),
            std::string::npos);
}

TEST(GridRejects, MoreThanTwoToThe53Points) {
  Grid g;
  g.axes = {ParseGridAxis("c=0:1:100000000"), ParseGridAxis("A=0:1:100000000")};
  EXPECT_NE(Message([&] { g.Validate(); }).find("expected at most 2^53 points"), std::string::npos);
}

}  // namespace
}  // namespace capsubot
