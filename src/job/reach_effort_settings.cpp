#include "capsubot/job/reach_effort_settings.hpp"

namespace capsubot {

const SettingTable<ReachEffort>& ReachEffortSettings() {
  using R = ReachEffort;
  static const SettingTable<ReachEffort> table = {
      {"reach_evaluations", &R::global_evaluations,
       "from-rest evaluations of the reach search's global stage (DIRECT-L), >= 1"},
      {"reach_local_evaluations", &R::local_evaluations,
       "from-rest evaluations of the reach search's local polish (Sbplx), >= 0"},
      {"reach_seconds", &R::max_seconds,
       "wall-clock limit of the reach search in seconds, looked at between two evaluations of "
       "its grid (the re-checks come on top); when it stops the search, the result depends on "
       "the machine's speed"},
      {"drive_evaluations", &R::drive_evaluations,
       "from-rest evaluations of the first global stage (Halton points of the box) of each "
       "Fourier drive K >= 2 ({harmonics}) and pulse drive, >= 1"},
      {"drive_polishes", &R::drive_polishes,
       "local polishes (Nelder-Mead) of each Fourier drive K >= 2, from its best distinct "
       "points, >= 1"},
      {"drive_local_evaluations", &R::drive_local_evaluations,
       "from-rest evaluations of each of those polishes, >= 0"},
      {"drive_refine_evaluations", &R::drive_refine_evaluations,
       "from-rest evaluations of the controlled random search (GN_CRS2_LM) after the Halton "
       "points, from the best of them, >= 0"},
      {"drive_screens", &R::drive_screens,
       "short local screens (Nelder-Mead, a quarter of a polish's evaluations each) before the "
       "polishes, from the best distinct points, >= 0"}};
  return table;
}

}  // namespace capsubot
