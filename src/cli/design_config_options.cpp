#include "capsubot/cli/design_config_options.hpp"

namespace capsubot::cli {
namespace {

// The command line's names of the robot's settings: a flag given a value ("--m1"), the bare
// setting named alone ("settings frequency and frequency-range are both given as flags").
DesignConfigNames FlagNamesOfSettings() {
  return {[](const std::string& name) { return "--" + name; },
          [](const std::string& name) { return name; }, "as flags"};
}

}  // namespace

void AddDesignConfigOptions(CLI::App& cmd, DesignConfigOptions& o) {
  cmd.add_option("--config", o.config,
                 "TOML file with the robot: keys named like these flags without the dashes "
                 "(m1 = 0.2, force-sin = [0.5], frequency-range = [10, 40]); flags override it")
      ->type_name("FILE");
  const std::vector<DesignRobotSetting>& settings = DesignRobotSettings();
  o.values.assign(settings.size(), std::string());
  o.options.assign(settings.size(), nullptr);
  for (std::size_t i = 0; i < settings.size(); ++i) {
    o.options[i] =
        cmd.add_option("--" + std::string(settings[i].name), o.values[i], settings[i].help);
    o.options[i]->type_name(settings[i].syntax);
  }
}

DesignInput BuildDesignInput(const DesignConfigOptions& o, const std::vector<DesignGridAxis>& grid,
                             DesignSettingTexts* settings, bool motor_force) {
  DesignConfigInput input;
  input.config = o.config;
  input.grid = grid;
  input.motor_force = motor_force;
  const std::vector<DesignRobotSetting>& table = DesignRobotSettings();
  for (std::size_t i = 0; i < table.size(); ++i) {
    if (o.options[i]->count() > 0) input.given.emplace_back(table[i].name, o.values[i]);
  }
  const DesignInput in = capsubot::BuildDesignInput(input, FlagNamesOfSettings(), settings);
  if (settings != nullptr) {
    for (auto& setting : *settings) setting.first = "--" + setting.first;
  }
  return in;
}

void RequireDriveForceMax(double force_max) {
  capsubot::RequireDriveForceMax(force_max, FlagNamesOfSettings());
}

}  // namespace capsubot::cli
