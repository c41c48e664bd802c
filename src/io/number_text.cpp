// Numbers as text: shortest round-trip formatting, and the strict parser every numeric
// input of the command line goes through.

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <system_error>

#include "capsubot/io/io.hpp"

namespace capsubot {
namespace {

bool IsDigit(char c) { return c >= '0' && c <= '9'; }

// The decimal grammar [+-]? (digits [. digits?] | . digits) ([eE] [+-]? digits)?, all of
// `text`. `nonzero` is set when a mantissa digit is not 0 (a nonzero number).
bool IsDecimal(std::string_view text, bool& nonzero) {
  std::size_t i = 0, digits = 0;
  nonzero = false;
  if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
  for (; i < text.size() && IsDigit(text[i]); ++i, ++digits) nonzero |= text[i] != '0';
  if (i < text.size() && text[i] == '.') {
    for (++i; i < text.size() && IsDigit(text[i]); ++i, ++digits) nonzero |= text[i] != '0';
  }
  if (digits == 0) return false;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
    std::size_t exponent_digits = 0;
    for (; i < text.size() && IsDigit(text[i]); ++i) ++exponent_digits;
    if (exponent_digits == 0) return false;
  }
  return i == text.size();
}

// "inf", "-Infinity", "nan": named so the message can say why they are refused.
bool IsNonFiniteWord(std::string_view text) {
  if (!text.empty() && (text[0] == '+' || text[0] == '-')) text.remove_prefix(1);
  std::string lower;
  for (char c : text.substr(0, 3))
    lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return lower == "inf" || lower == "nan";
}

[[noreturn]] void Reject(const std::string& name, std::string_view text, const std::string& rule) {
  throw std::invalid_argument(
      fmt::format("{} = {} is invalid: expected {}", name, QuoteForMessage(text), rule));
}

}  // namespace

char* WriteNumber(char* out, double value) {
  if (std::isnan(value)) return out;
  return std::to_chars(out, out + kMaxNumberChars, value).ptr;
}

std::string FormatNumber(double value) {
  char text[kMaxNumberChars];
  return std::string(text, WriteNumber(text, value));
}

std::string QuoteForMessage(std::string_view text) {
  bool plain = !text.empty();
  std::string shown;
  for (char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (std::isspace(u) || std::iscntrl(u) || c == '\'') plain = false;
    shown += std::iscntrl(u) ? fmt::format("\\x{:02x}", u) : std::string(1, c);
  }
  return plain ? shown : "'" + shown + "'";
}

double ParseNumber(std::string_view text, const std::string& name) {
  bool nonzero = false;
  if (!IsDecimal(text, nonzero)) {
    if (IsNonFiniteWord(text)) Reject(name, text, "a finite number");
    Reject(name, text,
           text.empty() ? "a number, not an empty string"
                        : "a decimal number such as 0.5, -2 or 1e-3 (no spaces, no hex)");
  }
  std::string_view digits = text;
  if (digits[0] == '+') digits.remove_prefix(1);  // from_chars takes no '+'
  double value = 0.0;
  const auto result = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (result.ec == std::errc::result_out_of_range || !std::isfinite(value) ||
      (value == 0.0 && nonzero)) {
    Reject(
        name, text,
        fmt::format("a number within the range of double: 0 or {:g} <= |x| <= {:g}",
                    std::numeric_limits<double>::denorm_min(), std::numeric_limits<double>::max()));
  }
  return value;
}

double ParsePhase(std::string_view text, const std::string& name) {
  const std::size_t pi = text.find("pi");
  if (pi == std::string_view::npos) return ParseNumber(text, name);
  const auto bad = [&]() {
    Reject(name, text,
           "a phase in radians: a decimal number such as 0.5 or -2, or a multiple of pi such as "
           "pi, -pi/2 or 2*pi (no spaces)");
  };
  std::string_view head = text.substr(0, pi), tail = text.substr(pi + 2);
  double sign = 1.0;
  if (!head.empty() && (head[0] == '+' || head[0] == '-')) {
    sign = head[0] == '-' ? -1.0 : 1.0;
    head.remove_prefix(1);
  }
  double factor = 1.0;
  if (!head.empty()) {
    if (head.back() != '*' || head.size() < 2 || head[0] == '+' || head[0] == '-') bad();
    head.remove_suffix(1);
    try {
      factor = ParseNumber(head, name);
    } catch (const std::invalid_argument&) {
      bad();
    }
  }
  double divisor = 1.0;
  if (!tail.empty()) {
    if (tail[0] != '/' || tail.size() < 2 || tail[1] == '+' || tail[1] == '-') bad();
    try {
      divisor = ParseNumber(tail.substr(1), name);
    } catch (const std::invalid_argument&) {
      bad();
    }
  }
  if (!(factor > 0.0) || !(divisor > 0.0)) bad();
  constexpr double kPi = 3.14159265358979323846;  // the double nearest pi
  const double value = sign * (factor * kPi) / divisor;
  if (!std::isfinite(value)) bad();
  return value;
}

std::int64_t ParseInteger(std::string_view text, const std::string& name, std::int64_t lo,
                          std::int64_t hi) {
  const std::string rule = fmt::format("an integer {} <= n <= {}", lo, hi);
  // [+-]? digits: exact, whatever the size (from_chars reports what int64 cannot hold).
  std::string_view unsigned_part = text;
  if (!unsigned_part.empty() && (unsigned_part[0] == '+' || unsigned_part[0] == '-')) {
    unsigned_part.remove_prefix(1);
  }
  if (!unsigned_part.empty() && std::all_of(unsigned_part.begin(), unsigned_part.end(), IsDigit)) {
    std::string_view digits = text[0] == '+' ? unsigned_part : text;  // from_chars takes no '+'
    std::int64_t n = 0;
    const auto result = std::from_chars(digits.data(), digits.data() + digits.size(), n);
    if (result.ec != std::errc() || n < lo || n > hi) Reject(name, text, rule);
    return n;
  }
  // "2e6", "1.5e3": a number in decimal syntax whose value is whole and in range (every bound
  // of an option is far below 2^53, where doubles hold every integer exactly).
  double value = 0.0;
  try {
    value = ParseNumber(text, name);
  } catch (const std::invalid_argument&) {
    Reject(name, text, rule);
  }
  if (!(value >= static_cast<double>(lo) && value <= static_cast<double>(hi)) ||
      value != std::floor(value) || std::abs(value) > 9007199254740992.0) {
    Reject(name, text, rule);
  }
  return static_cast<std::int64_t>(value);
}

std::vector<std::string> SplitText(const std::string& text, char separator) {
  std::vector<std::string> pieces;
  std::size_t start = 0;
  while (true) {
    const std::size_t end = std::min(text.find(separator, start), text.size());
    pieces.push_back(text.substr(start, end - start));
    if (end == text.size()) return pieces;
    start = end + 1;
  }
}

}  // namespace capsubot
