// Grids of sweep parameters: linear, log and list axes, any number of them, the values, every
// rejection message, and a bounded random (fuzz) test of the parser.

#include "capsubot/sweep/grid.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "test_utils.hpp"

namespace capsubot {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

TEST(Grid, ParsesNameBoundsAndCount) {
  const GridAxis axis = ParseGridAxis("c=0.01:0.5:50");
  EXPECT_EQ(axis.parameter, ModelParameter::kMean);
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
  EXPECT_TRUE(g.Has(ModelParameter::kMean));
  EXPECT_FALSE(g.Has(ModelParameter::kPhi0));
}

struct BadSpec {
  const char* spec;
  const char* message;  // expected substring
};

class GridRejects : public ::testing::TestWithParam<BadSpec> {};

TEST_P(GridRejects, WithAMessageNamingTheOptionValueAndRule) {
  const BadSpec& bad = GetParam();
  const std::string message = testing::InvalidArgumentMessage([&] { ParseGridAxis(bad.spec); });
  EXPECT_EQ(message.rfind(std::string("grid ") + bad.spec + " is invalid: ", 0), 0u) << message;
  EXPECT_NE(message.find("is invalid"), std::string::npos) << message;
  EXPECT_NE(message.find(bad.message), std::string::npos) << message;
}

INSTANTIATE_TEST_SUITE_P(
    BadSpecs, GridRejects,
    ::testing::Values(BadSpec{"x=0:1:3",
                              "unknown parameter 'x': expected one of A, c, phi0, T0, e, margin"},
                      BadSpec{"phi0", "expected name=lo:hi:n, name=lo:hi:n:log or name=v1,v2"},
                      BadSpec{"phi0=0:1", "fields separated by ':'"},
                      BadSpec{"phi0=0:1:2:3", "fields separated by ':'"},
                      BadSpec{"phi0=0:1:2:lin", "fields separated by ':'"},
                      BadSpec{"c=0:1:3:log", "expected lo > 0 and hi > 0 for a log grid"},
                      BadSpec{"c=-1:1:3:log", "expected lo > 0 and hi > 0 for a log grid"},
                      BadSpec{"c=0.1,,0.3", "value 2 = '' is not a number"},
                      BadSpec{"c=0.1,x", "value 2 = 'x' is not a number"},
                      BadSpec{"c=0.1,inf", "expected finite values"},
                      BadSpec{"e=0.5,1.5", "expected restitutions 0 <= e <= 1"},
                      BadSpec{"A=0x1p-2:1:3", "lo = '0x1p-2' is not a number"},
                      BadSpec{"A= 1:2:3", "lo = ' 1' is not a number"},
                      BadSpec{"A=1e999:2:3", "lo = '1e999' is not a number"},
                      BadSpec{"phi0=0:1:1e3", "n = '1e3' is not an integer"},
                      BadSpec{"phi0=0:1:1000000001", "expected n <= 1000000000 points"},
                      BadSpec{"phi0=0:1:99999999999999999999", "is not an integer number"},
                      BadSpec{"phi0=-1.7e308:1.7e308:5", "the bounds are too large for 5 points"},
                      BadSpec{"A=0:1e308:10", "the bounds are too large for 10 points"},
                      BadSpec{"a0=0:1:3", "unknown parameter 'a0'"},
                      BadSpec{"a17=0:1:3", "unknown parameter 'a17'"},
                      BadSpec{"b01=0:1:3", "unknown parameter 'b01'"},
                      BadSpec{"bound=0:1:3", "expected force bounds bound > 0"},
                      BadSpec{"rho_max=0,1", "expected spectral radius bounds rho_max > 0"},
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
                      BadSpec{"alpha=0:0.5:3", "expected mass ratios 0 < alpha < 1"},
                      // Infinity is a value of rho_max only (no bound), spelled inf, in a list.
                      BadSpec{"bound=1,inf", "expected finite values (not NaN or infinite)"},
                      BadSpec{"rho_max=0.5,Infinity", "value 2 = 'Infinity' is not a number"},
                      BadSpec{"rho_max=0.5,-inf", "value 2 = '-inf' is not a number"},
                      BadSpec{"rho_max=0.5,nan", "expected finite values or inf"},
                      BadSpec{"rho_max=0.5:inf:3", "expected finite bounds"}));

TEST(Grid, RhoMaxListAcceptsInfinityAsNoBoundAndWritesItAsInf) {
  const GridAxis axis = ParseGridAxis("rho_max=0.9,inf");
  ASSERT_EQ(axis.size(), 2);
  EXPECT_EQ(axis.Value(0), 0.9);
  EXPECT_EQ(axis.Value(1), kInfinity);
  EXPECT_EQ(axis.ToString(), "rho_max=0.9,inf");  // as the CSV writes it (WriteNumber)
  EXPECT_NO_THROW(axis.Validate());
}

TEST(GridRejects, TheSpecItselfIsQuotedInTheMessage) {
  EXPECT_EQ(testing::InvalidArgumentMessage([] { ParseGridAxis("phi0=0:1:0"); }),
            "grid phi0=0:1:0 is invalid: n = 0: expected n >= 1 points");
}

TEST(GridRejects, TheSameParameterTwice) {
  Grid g;
  g.axes = {ParseGridAxis("c=0:1:3"), ParseGridAxis("c=0:2:3")};
  const std::string message = testing::InvalidArgumentMessage([&] { g.Validate(); });
  EXPECT_NE(message.find("grid c=0:2:3 is invalid: parameter c already has a grid"),
            std::string::npos)
      << message;
}

TEST(GridRejects, AlphaTogetherWithPhi0) {
  Grid g;
  g.axes = {ParseGridAxis("alpha=0.1:0.9:3"), ParseGridAxis("phi0=-pi:pi:3")};
  const std::string message = testing::InvalidArgumentMessage([&] { g.Validate(); });
  EXPECT_EQ(message.rfind("grid alpha together with grid phi0 is invalid", 0), 0u) << message;
}

TEST(GridRejects, NoAxis) {
  Grid g;
  EXPECT_EQ(testing::InvalidArgumentMessage([&] {
              g.Validate();
            }).rfind("grid is missing: expected at least one axis", 0),
            0u);
}

TEST(GridRejects, AAndB1Together) {
  Grid g;
  g.axes = {ParseGridAxis("A=0:1:3"), ParseGridAxis("b1=0:2:3")};
  EXPECT_EQ(testing::InvalidArgumentMessage([&] {
              g.Validate();
            }).rfind("grid A together with grid b1 is invalid", 0),
            0u);
}

TEST(GridRejects, MoreThanTheMaximumNumberOfPoints) {
  Grid g;
  g.axes = {ParseGridAxis("c=0:1:100000"), ParseGridAxis("A=0:1:100000")};
  EXPECT_NE(testing::InvalidArgumentMessage([&] {
              g.Validate();
            }).find("more than 1000000000 points: expected at most 1000000000 points"),
            std::string::npos);
  g.axes = {ParseGridAxis("c=0:1:1000"), ParseGridAxis("A=0:1:1000"), ParseGridAxis("e=0:1:1000")};
  EXPECT_EQ(testing::InvalidArgumentMessage([&] { g.Validate(); }), "");  // exactly the maximum
  EXPECT_EQ(g.size(), kMaxGridPoints);
}

TEST(Grid, LogAxisHasEqualRatiosAndExactDecades) {
  const GridAxis axis = ParseGridAxis("T0=1e-3:1:4:log");
  EXPECT_EQ(axis.spacing, GridSpacing::kLog);
  ASSERT_EQ(axis.size(), 4);
  // Decades come out exactly: log10 and pow(10, integer) are exact in IEEE arithmetic.
  EXPECT_EQ(axis.Value(0), 1e-3);
  EXPECT_EQ(axis.Value(1), 1e-2);
  EXPECT_EQ(axis.Value(2), 1e-1);
  EXPECT_EQ(axis.Value(3), 1.0);
  const GridAxis odd = ParseGridAxis("c=2:50:7:log");
  constexpr double kRatioTol = 1e-14;  // a few ulps of pow
  const double ratio = std::pow(25.0, 1.0 / 6.0);
  for (int i = 1; i < 7; ++i) {
    EXPECT_NEAR(odd.Value(i) / odd.Value(i - 1), ratio, kRatioTol) << i;
  }
  EXPECT_EQ(odd.Value(6), 50.0);
  EXPECT_EQ(odd.ToString(), "c=2:50:7:log");
}

TEST(Grid, ListAxisKeepsItsOrderAndValues) {
  const GridAxis axis = ParseGridAxis("c=1,0.2,pi,0.5");
  EXPECT_EQ(axis.spacing, GridSpacing::kList);
  EXPECT_EQ(axis.size(), 4);
  EXPECT_EQ(axis.Value(0), 1.0);
  EXPECT_EQ(axis.Value(1), 0.2);
  EXPECT_EQ(axis.Value(2), M_PI);
  EXPECT_EQ(axis.Value(3), 0.5);
  EXPECT_EQ(axis.Min(), 0.2);
  EXPECT_EQ(axis.Max(), M_PI);
  EXPECT_EQ(testing::InvalidArgumentMessage([] { ParseGridAxis("e=1,0.2,pi,0.5"); }),
            "grid e=1,0.2,pi,0.5 is invalid: expected restitutions 0 <= e <= 1");
  const GridAxis one = ParseGridAxis("A=0.25");  // one value: a list of one
  EXPECT_EQ(one.size(), 1);
  EXPECT_EQ(one.Value(0), 0.25);
  EXPECT_EQ(ParseGridAxis("c=0.1,2.5e-3").ToString(), "c=0.1,0.0025");
}

TEST(Grid, NumbersAreDecimalSubnormalsIncluded) {
  EXPECT_EQ(ParseGridAxis("c=5e-324,+1").Value(0), 5e-324);
  EXPECT_EQ(ParseGridAxis("c=5e-324,+1").Value(1), 1.0);
  EXPECT_EQ(ParseGridAxis("phi0=+pi:-pi:2").Value(1), -M_PI);
}

TEST(Grid, FourierCoefficientsBoundAndRhoMaxAreParameters) {
  const GridAxis a3 = ParseGridAxis("a3=-0.1:0.1:3");
  EXPECT_EQ(a3.parameter, ModelParameter::kCos);
  EXPECT_EQ(a3.harmonic, 3);
  EXPECT_EQ(a3.name(), "a3");
  const GridAxis b16 = ParseGridAxis("b16=0,0.01");
  EXPECT_EQ(b16.parameter, ModelParameter::kSin);
  EXPECT_EQ(b16.harmonic, 16);
  EXPECT_EQ(ParseGridAxis("bound=0.05:0.1:2").parameter, ModelParameter::kBound);
  EXPECT_EQ(ParseGridAxis("rho_max=0.9,1").parameter, ModelParameter::kRhoMax);
  Grid g;
  g.axes = {ParseGridAxis("a1=0:1:2"), ParseGridAxis("a2=0:1:2"), ParseGridAxis("b1=0:1:2")};
  EXPECT_EQ(testing::InvalidArgumentMessage([&] { g.Validate(); }),
            "");  // different harmonics are different parameters
  EXPECT_TRUE(g.Has(ModelParameter::kCos));
  EXPECT_TRUE(g.Has(ModelParameter::kCos, 2));
  EXPECT_FALSE(g.Has(ModelParameter::kSin, 2));
}

TEST(Grid, ThreeAxesRunRowMajorWithTheFirstSlowest) {
  Grid g;
  g.axes = {ParseGridAxis("A=0:1:2"), ParseGridAxis("c=0.1,0.2,0.3"), ParseGridAxis("e=1:0.5:2")};
  g.Validate();
  ASSERT_EQ(g.size(), 12);
  int checked = 0;
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 3; ++j) {
      for (int k = 0; k < 2; ++k) {
        const std::int64_t point = (i * 3 + j) * 2 + k;
        EXPECT_EQ(g.Value(point, 0), g.axes[0].Value(i)) << point;
        EXPECT_EQ(g.Value(point, 1), g.axes[1].Value(j)) << point;
        EXPECT_EQ(g.Value(point, 2), g.axes[2].Value(k)) << point;
        ++checked;
      }
    }
  }
  EXPECT_EQ(checked, 12);
}

// Bounded random test of the parser: specs generated from the grammar (names, numbers, counts,
// spacings), half of them then mutated by random character edits, either parse to an axis
// that validates, whose values are finite (or inf for rho_max) and inside its range, or are
// rejected with a
// message that quotes them; nothing else (no crash, no other exception). 20,000 specs: well
// under a second.
TEST(GridFuzz, EveryStringParsesToAValidAxisOrIsRejectedWithItsMessage) {
  const std::vector<std::string> names = {"A",  "c",  "phi0", "T0",  "e",     "margin",  "alpha",
                                          "a1", "b2", "a16",  "a17", "bound", "rho_max", "x"};
  const std::vector<std::string> numbers = {"0",   "1",    "0.5",   "-0.25",  "pi",
                                            "-pi", "2e-3", "1e308", "-1e308", "5e-324",
                                            "nan", "inf",  "+0.1",  ""};
  const std::vector<std::string> counts = {"1", "2", "7", "1000", "0", "-3", "1000000001", "2.5"};
  const std::string alphabet = "0123456789.,:=+-e pilogxnaA";
  std::mt19937 rng(12);
  const auto pick = [&rng](const auto& list) {
    return list[std::uniform_int_distribution<std::size_t>(0, list.size() - 1)(rng)];
  };
  const auto chance = [&rng](int n) {
    return std::uniform_int_distribution<int>(0, n - 1)(rng) == 0;
  };
  int parsed = 0, rejected = 0;
  constexpr int kCases = 20000;
  for (int i = 0; i < kCases; ++i) {
    std::string spec = pick(names) + "=";
    if (chance(3)) {
      const int n = std::uniform_int_distribution<int>(1, 4)(rng);
      for (int j = 0; j < n; ++j) spec += (j > 0 ? "," : "") + pick(numbers);
    } else {
      spec += pick(numbers) + ":" + pick(numbers) + ":" + pick(counts) + (chance(3) ? ":log" : "");
    }
    if (chance(2)) {  // random edits
      const int edits = std::uniform_int_distribution<int>(1, 3)(rng);
      for (int j = 0; j < edits && !spec.empty(); ++j) {
        const std::size_t at = std::uniform_int_distribution<std::size_t>(0, spec.size() - 1)(rng);
        const char ch =
            alphabet[std::uniform_int_distribution<std::size_t>(0, alphabet.size() - 1)(rng)];
        if (chance(3)) {
          spec.erase(at, 1);
        } else if (chance(2)) {
          spec.insert(at, 1, ch);
        } else {
          spec[at] = ch;
        }
      }
    }
    try {
      const GridAxis axis = ParseGridAxis(spec);
      axis.Validate();
      ASSERT_GE(axis.size(), 1) << spec;
      ASSERT_LE(axis.size(), kMaxGridPoints) << spec;
      for (std::int64_t k : {std::int64_t{0}, axis.size() / 2, axis.size() - 1}) {
        const double v = axis.Value(k);
        const bool no_bound = axis.parameter == ModelParameter::kRhoMax && v == kInfinity;
        ASSERT_TRUE(std::isfinite(v) || no_bound) << spec << " value " << k;
        ASSERT_GE(v, axis.Min()) << spec;
        ASSERT_LE(v, axis.Max()) << spec;
      }
      ++parsed;
    } catch (const std::invalid_argument& e) {
      ASSERT_EQ(std::string(e.what()).rfind("grid " + spec + " is invalid: ", 0), 0u) << e.what();
      ++rejected;
    }
  }
  EXPECT_EQ(parsed + rejected, kCases);
  EXPECT_GT(parsed, 100);  // the generator reaches the valid grammar too
  EXPECT_GT(rejected, 100);
}

}  // namespace
}  // namespace capsubot
