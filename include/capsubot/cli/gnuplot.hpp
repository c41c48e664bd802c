#pragma once
// A PNG drawn by gnuplot from a script, for the commands' --plot.

#include <functional>
#include <string>

namespace capsubot::cli {

/// Runs gnuplot on script(temp), a script that writes the PNG `temp`, a temporary file beside
/// `path`, then renames it to `path` (written in place when `path` is a symlink or special
/// file, never replaced). Throws IoError naming --plot when gnuplot is missing or fails.
void DrawPng(const std::function<std::string(const std::string& png)>& script,
             const std::string& path);

}  // namespace capsubot::cli
