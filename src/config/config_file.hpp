#pragma once
// The robot's settings in a TOML config file (design_config.hpp): keys named as the settings.

#include <set>
#include <string>

#include "capsubot/design/design.hpp"

namespace capsubot::detail {

// The settings of the config file `path` (none when empty) into `in`; returns their names.
// Throws std::invalid_argument (a file nested too deep or not TOML, an unknown key, a value of
// the wrong type, two alternatives given) and IoError (an unreadable file), naming the file as
// the option `option` ("--config FILE cannot be read: ...").
std::set<std::string> ReadConfigFile(const std::string& path, const std::string& option,
                                     DesignInput& in);

}  // namespace capsubot::detail
