#pragma once
// The robot of `capsubot design` from flags and a TOML file: one table of settings whose
// names are both the flags (--m1) and the keys of the file (m1 = 0.2); a flag overrides the
// file.

#include <CLI/CLI.hpp>
#include <string>
#include <utility>
#include <vector>

#include "capsubot/design/design.hpp"
#include "capsubot/sweep/design_grid.hpp"

namespace capsubot::app {

/// What the command line says about the robot: the config file and each setting's flag.
struct DesignConfigOptions {
  std::string config;                 ///< --config FILE (empty: none)
  std::vector<std::string> values;    ///< text of each setting's flag, by table index
  std::vector<CLI::Option*> options;  ///< each setting's flag
};

/// Adds --config and one flag per setting to `cmd`.
void AddDesignConfigOptions(CLI::App& cmd, DesignConfigOptions& options);

/// The input: defaults, then the config file, then the flags given, then the first value of
/// each axis of `grid` (a gridded setting counts as given; the file's value is replaced, a
/// flag for it is an error). Throws std::invalid_argument (unknown key, wrong type, bad
/// text, a missing or doubly given setting; the message names the setting, its value and the
/// rule) or IoError (unreadable file). The input is validated (DesignInput::Validate).
/// `settings` (if given) receives the value of every setting the input has, however it was
/// given (the file, a flag or the default), as the flag that gives it ({"--m1", "0.2"},
/// {"--g", "9.81"}, in the table's order, numbers in shortest round-trip form), without the
/// settings of `grid` (and their alternatives): alone they make the same input, so two runs
/// of one input name it alike (`--g 9.81` typed or not, `--m1 0.20` or `m1 = 0.2` in a file).
/// Without `motor_force` (a drive design, which chooses the force) the force settings are
/// neither required nor accepted, and the input's force is zero.
DesignInput BuildDesignInput(const DesignConfigOptions& options,
                             const std::vector<DesignGridAxis>& grid = {},
                             std::vector<std::pair<std::string, std::string>>* settings = nullptr,
                             bool motor_force = true);

}  // namespace capsubot::app
