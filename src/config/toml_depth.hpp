#pragma once
// The nesting of a TOML config file, checked before it is parsed: the parser descends once per
// level, so a file nested thousands deep would exhaust the stack.

#include <string>

namespace capsubot::detail {

// Nesting of a config file at the most: parts of a dotted key or table header, plus arrays
// and inline tables around a value. A robot's file needs 2.
constexpr int kMaxTomlDepth = 32;

// Refuses (std::invalid_argument naming the file `path` and the line) a TOML text nested
// deeper than kMaxTomlDepth, scanning it before it is parsed.
void RequireTomlDepth(const std::string& text, const std::string& path);

}  // namespace capsubot::detail
