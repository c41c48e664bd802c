// The strict number parser of every numeric input: accepted syntax, each rejection with its
// rule, and a bounded random test (random strings and random doubles written in many ways).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

#include "capsubot/io/io.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

// The message of ParseNumber/ParseInteger, or "" when it parsed.
std::string NumberError(const std::string& text) {
  try {
    ParseNumber(text, "--x");
    return "";
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
}

std::string IntegerError(const std::string& text, std::int64_t lo, std::int64_t hi) {
  try {
    ParseInteger(text, "--n", lo, hi);
    return "";
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
}

TEST(ParseNumber, AcceptsDecimalSyntaxAndRoundsToNearest) {
  const struct {
    const char* text;
    double value;
  } good[] = {{"0", 0.0},
              {"-0", -0.0},
              {"+4E2", 400.0},
              {".5", 0.5},
              {"5.", 5.0},
              {"-2.5e-3", -2.5e-3},
              {"1e-310", 1e-310},  // subnormal
              {"4.9406564584124654e-324", std::numeric_limits<double>::denorm_min()},
              {"1.7976931348623157e308", std::numeric_limits<double>::max()},
              {"0.1", 0.1},
              {"000012", 12.0}};
  int checked = 0;
  for (const auto& g : good) {
    EXPECT_EQ(ParseNumber(g.text, "--x"), g.value) << g.text;
    ++checked;
  }
  EXPECT_EQ(checked, 11);
  EXPECT_TRUE(std::signbit(ParseNumber("-0", "--x")));
}

TEST(ParseNumber, RejectsEverythingElseNamingTheRule) {
  const std::string syntax =
      "expected a decimal number such as 0.5, -2 or 1e-3 (no spaces, no hex)";
  const std::string range =
      "expected a number within the range of double: 0 or 4.94066e-324 "
      "<= |x| <= 1.79769e+308";
  const struct {
    const char* text;
    std::string message;
  } bad[] = {
      {"", "--x = '' is invalid: expected a number, not an empty string"},
      {" 1", "--x = ' 1' is invalid: " + syntax},
      {"1 ", "--x = '1 ' is invalid: " + syntax},
      {"0x1p-2", "--x = 0x1p-2 is invalid: " + syntax},
      {"1e", "--x = 1e is invalid: " + syntax},
      {".", "--x = . is invalid: " + syntax},
      {"+-1", "--x = +-1 is invalid: " + syntax},
      {"1,5", "--x = 1,5 is invalid: " + syntax},
      {"1\n", "--x = '1\\x0a' is invalid: " + syntax},
      {"nan", "--x = nan is invalid: expected a finite number"},
      {"-inf", "--x = -inf is invalid: expected a finite number"},
      {"Infinity", "--x = Infinity is invalid: expected a finite number"},
      {"1e309", "--x = 1e309 is invalid: " + range},
      {"-1e400", "--x = -1e400 is invalid: " + range},
      {"1e-400", "--x = 1e-400 is invalid: " + range},  // nonzero, rounds to 0
  };
  int checked = 0;
  for (const auto& b : bad) {
    EXPECT_EQ(NumberError(b.text), b.message) << b.text;
    ++checked;
  }
  EXPECT_EQ(checked, 15);
  EXPECT_EQ(NumberError("0e-400"), "");  // zero written with a tiny exponent is zero
}

TEST(ParseInteger, AcceptsWholeNumbersInRangeOnly) {
  EXPECT_EQ(ParseInteger("42", "--n", 1, 100), 42);
  EXPECT_EQ(ParseInteger("+7", "--n", 1, 100), 7);
  EXPECT_EQ(ParseInteger("2e1", "--n", 1, 100), 20);
  EXPECT_EQ(
      ParseInteger("-9223372036854775808", "--n", std::numeric_limits<std::int64_t>::min(), 0),
      std::numeric_limits<std::int64_t>::min());
  const std::string rule = "is invalid: expected an integer 2 <= n <= 10000000";
  int checked = 0;
  for (const char* text : {"", "1", "10000001", "2e9", "1.5", "0x10", " 3", "3 ", "+-3", "nan",
                           "99999999999999999999", "-99999999999999999999", "1e999"}) {
    EXPECT_EQ(IntegerError(text, 2, 10000000), "--n = " + QuoteForMessage(text) + " " + rule)
        << text;
    ++checked;
  }
  EXPECT_EQ(checked, 13);
}

// Random strings over the characters of numbers (and a few others): each parses to the value
// strtod gives for a string of the accepted grammar, or fails with a message naming the
// option; nothing else (no crash, no other exception). Random doubles written with printf in
// many formats parse back to the very same double.
TEST(ParseNumberFuzz, RandomTextParsesExactlyOrFailsCleanly) {
  std::mt19937_64 rng(20240611);  // fixed seed: the same cases on every run
  const std::string alphabet = "0123456789+-.eE xpXaInNf,\t";
  constexpr int kStrings = 40000;
  int parsed = 0, rejected = 0;
  for (int i = 0; i < kStrings; ++i) {
    std::string text;
    const int length = static_cast<int>(rng() % 12);
    for (int k = 0; k < length; ++k) text += alphabet[rng() % alphabet.size()];
    try {
      const double value = ParseNumber(text, "--x");
      // Accepted: only digits, sign, point, exponent; equal to the C library's reading.
      ASSERT_EQ(text.find_first_not_of("0123456789+-.eE"), std::string::npos) << text;
      ASSERT_EQ(value, std::strtod(text.c_str(), nullptr)) << text;
      ASSERT_TRUE(std::isfinite(value)) << text;
      ++parsed;
    } catch (const std::invalid_argument& e) {
      ASSERT_EQ(std::string(e.what()).rfind("--x = ", 0), 0U) << e.what();
      ++rejected;
    }
  }
  EXPECT_EQ(parsed + rejected, kStrings);
  EXPECT_GT(parsed, 200);  // the alphabet makes many valid numbers: the test sees both sides

  constexpr int kDoubles = 20000;
  const char* formats[] = {"%.17g", "%.17e", "%.16E", "%.25g", "%+.17g", "%.40f"};
  int round_trips = 0;
  for (int i = 0; i < kDoubles; ++i) {
    // Random bit patterns: every exponent, subnormals included; non-finite ones skipped.
    std::uint64_t bits = rng();
    double x = 0.0;
    std::memcpy(&x, &bits, sizeof x);
    if (!std::isfinite(x)) continue;
    for (const char* format : formats) {
      char buffer[512];
      std::snprintf(buffer, sizeof buffer, format, x);
      // 40 decimals hold 17 significant digits only from 1e-23 up.
      if (std::string(format) == "%.40f" && std::abs(x) < 1e-22 && x != 0.0) continue;
      ASSERT_EQ(ParseNumber(buffer, "--x"), x) << buffer;
    }
    ++round_trips;
  }
  EXPECT_GT(round_trips, kDoubles * 9 / 10);
}

TEST(ParseIntegerFuzz, RandomIntegersRoundTripAndOutOfRangeIsRejected) {
  std::mt19937_64 rng(7);
  constexpr int kCases = 20000;
  constexpr std::int64_t kLo = -1000000, kHi = 1000000000;
  int checked = 0;
  for (int i = 0; i < kCases; ++i) {
    const auto n = static_cast<std::int64_t>(rng());
    const std::string text = std::to_string(n);
    const std::string error = IntegerError(text, kLo, kHi);
    if (n >= kLo && n <= kHi) {
      ASSERT_EQ(ParseInteger(text, "--n", kLo, kHi), n);
    } else {
      ASSERT_NE(error.find("expected an integer -1000000 <= n <= 1000000000"), std::string::npos)
          << error;
    }
    ++checked;
  }
  EXPECT_EQ(checked, kCases);
}

TEST(ParsePhase, ReadsNumbersAndMultiplesOfPi) {
  const double pi = std::acos(-1.0);  // the double nearest pi, computed independently
  EXPECT_EQ(ParsePhase("0.5", "--phi0"), 0.5);
  EXPECT_EQ(ParsePhase("pi", "--phi0"), pi);
  EXPECT_EQ(ParsePhase("+pi", "--phi0"), pi);
  EXPECT_EQ(ParsePhase("-pi", "--phi0"), -pi);
  EXPECT_EQ(ParsePhase("-pi/2", "--phi0"), -pi / 2.0);
  EXPECT_EQ(ParsePhase("2*pi", "--phi0"), 2.0 * pi);
  EXPECT_EQ(ParsePhase("3*pi/4", "--phi0"), 3.0 * pi / 4.0);
  EXPECT_EQ(ParsePhase("1e0*pi/1e0", "--phi0"), pi);
}

TEST(ParsePhase, RefusesOtherTextNamingTheRule) {
  for (const char* text : {"pix", "2pi", "pi/", "pi/0", "pi/-2", "*pi", "-*pi", "pi*2", "pi pi",
                           " pi", "-2*-pi", "0*pi", "inf*pi", "PI", ""}) {
    const std::string message = testing::InvalidArgumentMessage([&] { ParsePhase(text, "--psi"); });
    EXPECT_EQ(message.rfind("--psi = ", 0), 0U) << text << ": " << message;
    EXPECT_NE(message.find("is invalid: expected"), std::string::npos) << text << ": " << message;
  }
}

}  // namespace
}  // namespace capsubot
