#include "capsubot/job/motion_settings.hpp"

namespace capsubot {

const SettingTable<MotionOptions>& MotionSettings() {
  using M = MotionOptions;
  static const SettingTable<MotionOptions> table = {
      {"transient", &M::transient, "forcing periods simulated before the motion is recorded, >= 0"},
      {"record", &M::record,
       "forcing periods recorded (period, impacts, mean velocity), 2 {max_period} <= N <= 1e7 "
       "(about 50 bytes a period per thread)"},
      {"max_period", &M::max_period,
       "largest period searched, in forcing periods (0 is reported when none is found)"},
      {"state_tolerance", &M::state_tolerance,
       "two states of the stroboscopic map are the same when x, u, v differ by at most this"},
      {"converged_tolerance", &M::converged_tolerance,
       "early stop: a motion whose states already repeat to this tolerance is periodic (0: "
       "always run the whole transient and record)"},
      {"chatter_velocity", &M::chatter_velocity,
       "an impact slower than this (omega L) with the inner body pushed into the wall ends a "
       "chattering sequence: the body then rests on the wall"},
      {"max_events_per_period", &M::max_events_per_period,
       "work bound: a start needing more events per period ends as event_limit"}};
  return table;
}

}  // namespace capsubot
