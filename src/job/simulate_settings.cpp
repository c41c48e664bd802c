#include "capsubot/job/simulate_settings.hpp"

#include "capsubot/model/limits.hpp"

namespace capsubot {

const SettingTable<SimOptions>& SimulateRunSettings() {
  using S = SimOptions;
  static const SettingTable<SimOptions> table = {
      {"y0", &S::y0, "initial capsule position (units of L)"},
      {"periods", &S::periods,
       "forcing periods (2 pi each) recorded after the transient, 0 < N <= 1e8"},
      {"transient", &S::transient,
       "forcing periods run first and reported apart (JSON \"transient\"): the counts, v_mean "
       "and energy are over the {periods} after it, 0 <= N <= 1e8"},
      {"chatter_velocity", &S::chatter_velocity,
       "an impact slower than this (omega L) with the inner body pushed into the wall ends a "
       "chattering sequence: the body then rests on the wall"},
      {"max_events_per_period", &S::max_events_per_period,
       "work bound: the run stops (status event_limit) after this many events per period", 10,
       kMaxEventsPerPeriod}};
  return table;
}

const SettingTable<SimulateJobOptions>& SimulateJobSettings() {
  static const SettingTable<SimulateJobOptions> table = {
      {"samples_per_period", &SimulateJobOptions::samples_per_period,
       "grid of {trajectory}: samples per forcing period", 1, kMaxSamplesPerPeriod}};
  return table;
}

}  // namespace capsubot
