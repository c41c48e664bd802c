#pragma once
// The robot of `capsubot design` from flags and a TOML file: one flag per setting of the
// library's table (capsubot/config/design_config.hpp), named as the setting (--m1 for the key
// m1 = 0.2 of the file); a flag overrides the file.

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "capsubot/config/design_config.hpp"
#include "capsubot/design/design.hpp"
#include "capsubot/sweep/design_grid.hpp"

namespace capsubot::cli {

/// What the command line says about the robot: the config file and each setting's flag.
struct DesignConfigOptions {
  std::string config;                 ///< --config FILE (empty: none)
  std::vector<std::string> values;    ///< text of each setting's flag, by table index
  std::vector<CLI::Option*> options;  ///< each setting's flag
};

/// Adds --config and one flag per setting to `cmd`.
void AddDesignConfigOptions(CLI::App& cmd, DesignConfigOptions& options);

/// The input of the library's BuildDesignInput from --config, the flags given and the axes of
/// `grid`, its messages naming the flags (--m1). `settings` (if given) receives the value of
/// every setting the input has as the flag that gives it ({"--m1", "0.2"}). Without
/// `motor_force` (a drive design) the force settings are neither required nor accepted.
DesignInput BuildDesignInput(const DesignConfigOptions& options,
                             const std::vector<DesignGridAxis>& grid = {},
                             DesignSettingTexts* settings = nullptr, bool motor_force = true);

/// Refuses --drive without --force-max (`force_max` NaN), in flags.
void RequireDriveForceMax(double force_max);

}  // namespace capsubot::cli
