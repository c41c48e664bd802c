#pragma once
// The robot of the design job from its settings: one table of the robot's settings whose names
// are the keys of a TOML config file (m1 = 0.2, force-sin = [0.5]) and, as each front end
// writes them, its flags (--m1) and keyword arguments (m1=). The input is built in one order:
// the defaults, then the config file, then the settings the front end was given, then the
// first value of each axis of a design grid. Needs toml++: built with the front ends, not
// installed.

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "capsubot/design/design.hpp"
#include "capsubot/sweep/design_grid.hpp"

namespace capsubot {

/// One setting of the robot, as a front end declares it.
struct DesignRobotSetting {
  const char* name;    ///< the key of the config file ("m1", "force-amplitude")
  const char* help;    ///< what it is, its unit and its rule
  const char* syntax;  ///< its value as text: NUMBER, NUMBER|inf, INT, X1,X2,... or MIN:MAX
};

/// The robot's settings, in their order (the order of a provenance).
const std::vector<DesignRobotSetting>& DesignRobotSettings();

/// How a front end writes the robot's settings in its messages.
struct DesignConfigNames {
  /// A setting (or "config", "grid", "drive", "force-max") given a value: "--m1" or "m1".
  std::function<std::string(const std::string& name)> given;
  /// A setting named alone: "frequency-range" or "frequency_range".
  std::function<std::string(const std::string& name)> named;
  /// Where the front end's values come from: "as flags", "as keyword arguments".
  std::string source;
};

/// A (setting, text) pair: "m1" and "0.2"; a list "0.5,0.1", a range "10:40", a bound "inf".
using DesignSettingTexts = std::vector<std::pair<std::string, std::string>>;

/// What a front end was given about the robot.
struct DesignConfigInput {
  std::string config;        ///< the config file (empty: none)
  DesignSettingTexts given;  ///< the settings given to the front end, each once, by name
  /// The axes of a design grid: a gridded setting counts as given (the file's value is
  /// replaced; given to the front end too, it is refused).
  std::vector<DesignGridAxis> grid;
  /// Without it (a drive design, which chooses the force) the force settings are neither
  /// required nor accepted, and the input's force is zero.
  bool motor_force = true;
};

/// The input: defaults, then the config file, then the settings given, then the first value of
/// each axis of the grid. Throws std::invalid_argument (unknown key, wrong type, bad text, a
/// missing or doubly given setting; the message names the setting in `names`, its value and
/// the rule) or IoError (unreadable file). The input is validated (DesignInput::Validate).
/// `settings` (if given) receives the value of every setting the input has, however it was
/// given (the file, the front end or the default), in the table's order, numbers in shortest
/// round-trip form, without the settings of the grid (and their alternatives): alone they make
/// the same input, so two runs of one input name it alike (g = 9.81 given or not, 0.20 or 0.2).
DesignInput BuildDesignInput(const DesignConfigInput& input, const DesignConfigNames& names,
                             DesignSettingTexts* settings = nullptr);

/// Refuses (std::invalid_argument, in `names`) a drive design without the motor's peak force
/// (`force_max` NaN).
void RequireDriveForceMax(double force_max, const DesignConfigNames& names);

}  // namespace capsubot
