#include "capsubot/job/orbits_settings.hpp"

#include "capsubot/model/limits.hpp"

namespace capsubot {

const SettingTable<OrbitsJobOptions>& OrbitsSettings() {
  using O = OrbitsJobOptions;
  static const SettingTable<OrbitsJobOptions> table = {
      {"max_evaluations", &O::max_evaluations,
       "work bound of the search: evaluations of the orbit equation while refining the circle "
       "(default 4000000, far above what the tested forces need); when it is hit, orbits may be "
       "missing: a note says so",
       1, kMaxOrbitEvaluations}};
  return table;
}

}  // namespace capsubot
