#include "capsubot/config/design_config.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <set>
#include <stdexcept>

#include "config_file.hpp"
#include "robot_settings.hpp"

namespace capsubot {
namespace {

using detail::RobotSetting;
using detail::RobotSettings;
using detail::SettingKind;
using detail::SettingValue;

const char* Syntax(SettingKind kind) {
  switch (kind) {
    case SettingKind::kRange:
      return "MIN:MAX";
    case SettingKind::kBound:
      return "NUMBER|inf";
    case SettingKind::kList:
      return "X1,X2,...";
    case SettingKind::kInteger:
      return "INT";
    case SettingKind::kNumber:
      break;
  }
  return "NUMBER";
}

// Whether setting `name` or an alternative of it (ExclusiveRobotSettings) is among `names`.
bool NamedOrAlternative(const std::set<std::string>& names, const std::string& name) {
  if (names.count(name) > 0) return true;
  for (const auto& [a, b] : detail::ExclusiveRobotSettings()) {
    if ((name == a && names.count(b) > 0) || (name == b && names.count(a) > 0)) return true;
  }
  return false;
}

// No two alternatives from one source: `given` holds the names it set, `source` says where
// they come from ("in FILE", "as flags"), `named` writes a name.
void CheckExclusive(const std::set<std::string>& given, const std::string& source,
                    const std::function<std::string(const std::string&)>& named) {
  for (const auto& [a, b] : detail::ExclusiveRobotSettings()) {
    if (given.count(a) > 0 && given.count(b) > 0) {
      throw std::invalid_argument(
          fmt::format("settings {} and {} are both given {}: expected one of them", named(a),
                      named(b), source));
    }
  }
}

// The text given to the front end for `name` (it was given).
const std::string& GivenText(const DesignConfigInput& input, const std::string& name) {
  for (const auto& [setting, text] : input.given) {
    if (setting == name) return text;
  }
  throw std::logic_error("setting " + name + " was not given");
}

// A grid's axis gives its setting (added to `given`) the axis's first value, a valid one (the
// run sets each point's, DesignGridOptions); a setting given to the front end for it or an
// alternative of it (in `from_front_end`) is refused.
void SetFromGrid(const DesignGridAxis& axis, const DesignConfigInput& input,
                 const DesignConfigNames& names, const std::set<std::string>& from_front_end,
                 DesignInput& in, std::set<std::string>& given) {
  const int i = detail::FindRobotSetting(axis.name());
  // m2 is not a setting: its grid fixes what m2-range searches, so the two exclude each other.
  std::vector<std::string> settings = {i < 0 ? std::string("m2-range") : axis.name()};
  for (const auto& [a, b] : detail::ExclusiveRobotSettings()) {
    if (axis.name() == a) settings.emplace_back(b);
    if (axis.name() == b) settings.emplace_back(a);
  }
  for (const std::string& setting : settings) {
    if (from_front_end.count(setting) == 0) continue;
    throw std::invalid_argument(fmt::format(
        "{} = {} is invalid with {} {}: expected the value from only one of them",
        names.given(setting), GivenText(input, setting), names.given("grid"), axis.ToString()));
  }
  if (i < 0) return;
  SettingValue v;
  v.number = axis.Value(0);
  RobotSettings()[i].set(in, v);
  given.insert(axis.name());
}

// The settings given to the front end into `in`; returns their names.
std::set<std::string> SetFromFrontEnd(const DesignConfigInput& input,
                                      const DesignConfigNames& names, DesignInput& in) {
  std::set<std::string> from_front_end;
  for (const auto& [name, text] : input.given) {
    const int i = detail::FindRobotSetting(name);
    if (i < 0) throw std::logic_error("no setting " + name + " of the design's robot");
    const RobotSetting& s = RobotSettings()[i];
    s.set(in, detail::FromText(s, names.given(name), text));
    from_front_end.insert(name);
  }
  return from_front_end;
}

// A drive design chooses the force: none of its settings may be given.
void RejectForce(const std::set<std::string>& given, const DesignConfigNames& names) {
  for (const char* name : {"force-amplitude", "force-bias", "force-cos", "force-sin"}) {
    if (given.count(name) > 0) {
      throw std::invalid_argument(fmt::format(
          "setting {} is invalid with {}: expected no motor force (the drive search chooses it; "
          "give the motor's peak with {})",
          names.named(name), names.given("drive"), names.given("force-max")));
    }
  }
}

// "A", "A and B", "A, B and C".
std::string ListText(const std::vector<std::string>& items) {
  if (items.size() == 1) return items.front();
  return fmt::format("{} and {}", fmt::join(items.begin(), items.end() - 1, ", "), items.back());
}

// Every missing setting named at once: "setting L is missing: ..." or "settings L, mu and e
// are missing: give --L, --mu and --e (or L, mu and e in the --config file)".
void RequireGiven(const std::set<std::string>& given, bool motor_force,
                  const DesignConfigNames& names) {
  std::vector<std::string> missing, front_end, keys;
  for (const auto& group : detail::RequiredRobotSettings()) {
    if (!motor_force && std::string(group.front()).rfind("force", 0) == 0) continue;
    bool any = false;
    for (const char* name : group) any = any || given.count(name) > 0;
    if (any) continue;
    std::vector<std::string> alternatives;
    for (const char* name : group) alternatives.push_back(names.named(name));
    missing.push_back(fmt::format("{}", fmt::join(alternatives, " or ")));
    front_end.push_back(names.given(group.front()));
    keys.emplace_back(group.front());
  }
  if (missing.empty()) return;
  throw std::invalid_argument(fmt::format("setting{} {} {} missing: give {} (or {} in the {} file)",
                                          missing.size() == 1 ? "" : "s", ListText(missing),
                                          missing.size() == 1 ? "is" : "are", ListText(front_end),
                                          ListText(keys), names.given("config")));
}

// The value of every setting of `in`, without the grid's settings and their alternatives.
DesignSettingTexts SettingsOf(const DesignInput& in, const std::vector<DesignGridAxis>& grid) {
  // A grid gives its settings (m2: the range searched) at every point.
  std::set<std::string> gridded;
  for (const DesignGridAxis& axis : grid) {
    gridded.insert(detail::FindRobotSetting(axis.name()) < 0 ? std::string("m2-range")
                                                             : axis.name());
  }
  DesignSettingTexts settings;
  for (const RobotSetting& s : RobotSettings()) {
    SettingValue v;
    if (NamedOrAlternative(gridded, s.name) || !s.get(in, v)) continue;
    settings.emplace_back(s.name, detail::ToText(s, v));
  }
  return settings;
}

}  // namespace

const std::vector<DesignRobotSetting>& DesignRobotSettings() {
  static const std::vector<DesignRobotSetting> settings = [] {
    std::vector<DesignRobotSetting> out;
    for (const RobotSetting& s : RobotSettings()) out.push_back({s.name, s.help, Syntax(s.kind)});
    return out;
  }();
  return settings;
}

DesignInput BuildDesignInput(const DesignConfigInput& input, const DesignConfigNames& names,
                             DesignSettingTexts* settings) {
  DesignInput in;
  std::set<std::string> given = detail::ReadConfigFile(input.config, names.given("config"), in);
  CheckExclusive(given, "in " + input.config, [](const std::string& name) { return name; });
  const std::set<std::string> from_front_end = SetFromFrontEnd(input, names, in);
  CheckExclusive(from_front_end, names.source, names.named);
  given.insert(from_front_end.begin(), from_front_end.end());
  for (const DesignGridAxis& axis : input.grid) {
    SetFromGrid(axis, input, names, from_front_end, in, given);
  }
  if (!input.motor_force) {
    RejectForce(given, names);
    in.force = MotorForce{0.0, 0.0, {}, {}};
  }
  RequireGiven(given, input.motor_force, names);
  in.Validate();
  if (settings != nullptr) *settings = SettingsOf(in, input.grid);
  return in;
}

void RequireDriveForceMax(double force_max, const DesignConfigNames& names) {
  if (!std::isnan(force_max)) return;
  throw std::invalid_argument(
      fmt::format("setting {} is missing: {} needs the motor's peak force, give {}",
                  names.named("force-max"), names.given("drive"), names.given("force-max")));
}

}  // namespace capsubot
