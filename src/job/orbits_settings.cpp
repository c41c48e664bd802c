#include "capsubot/job/orbits_settings.hpp"

#include <fmt/format.h>

#include <string>

#include "capsubot/model/limits.hpp"

namespace capsubot {

const SettingTable<OrbitsJobOptions>& OrbitsSettings() {
  // The help states the default bound, which the search's constant sets.
  static const std::string max_evaluations = fmt::format(
      "work bound of the search: evaluations of the orbit equation while refining the circle "
      "(default {}, far above what the tested forces need); when it is hit, orbits may be "
      "missing: a note says so",
      kRobotOrbitsMaxEvaluations);
  static const SettingTable<OrbitsJobOptions> table = {
      {"max_evaluations", &OrbitsJobOptions::max_evaluations, max_evaluations.c_str(), 1,
       kMaxOrbitEvaluations}};
  return table;
}

}  // namespace capsubot
