#include "capsubot/job/continue_settings.hpp"

namespace capsubot {

const SettingTable<ContinueJobOptions>& ContinueParamSettings() {
  static const SettingTable<ContinueJobOptions> table = {
      {"param", &ContinueJobOptions::param,
       "the parameter followed: A, c, alpha, T0, e, phi0, or a Fourier coefficient a1..a16, "
       "b1..b16"}};
  return table;
}

const SettingTable<ContinuationOptions>& ContinuationRangeSettings() {
  using C = ContinuationOptions;
  static const SettingTable<ContinuationOptions> table = {
      {"from", &C::from, "lower end of the range"}, {"to", &C::to, "upper end of the range"}};
  return table;
}

const SettingTable<FollowOptions>& FollowSettings() {
  using F = FollowOptions;
  static const SettingTable<FollowOptions> table = {
      {"param2", &F::param2,
       "also follow the branch's first located special point of the {follow} type in two "
       "parameters, this one the second (a parameter other than {param})"},
      {"from2", &F::from2, "lower end of the {param2} range"},
      {"to2", &F::to2, "upper end of the {param2} range"}};
  return table;
}

const SettingTable<ContinuationOptions>& ContinuationStepSettings() {
  using C = ContinuationOptions;
  static const SettingTable<ContinuationOptions> table = {
      {"max_points", &C::max_points,
       "points of the branch (and of the curve), both directions together"},
      {"initial_step", &C::initial_step, "first arclength step"},
      {"min_step", &C::min_step, "smallest arclength step: a failure there ends the branch (lost)"},
      {"max_step", &C::max_step, "largest arclength step"}};
  return table;
}

}  // namespace capsubot
