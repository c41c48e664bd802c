#pragma once
// What the tests of the report stage share: the JSON as it is printed (read back), and a check
// that a text holds a line, printing the text when it does not.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

namespace capsubot::testing {

/// `j` as `--json` prints it, read back: a NaN or infinity the library put in is null here,
/// as a reader of the output sees it.
inline nlohmann::json Printed(const nlohmann::json& j) { return nlohmann::json::parse(j.dump()); }

/// `text` contains `part`; on failure prints both.
inline ::testing::AssertionResult Has(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "missing \"" << part << "\" in:\n" << text;
}

}  // namespace capsubot::testing
