#include "capsubot/job/params_settings.hpp"

namespace capsubot {

const SettingTable<Params>& ParamsSettings() {
  static const SettingTable<Params> table = {
      {"T0", &Params::T0, "friction bound T0 = mu g/(omega^2 L), dimensionless, > 0"},
      {"e", &Params::e, "coefficient of restitution, 0 <= e <= 1"}};
  return table;
}

const SettingTable<RobotModel>& MassRatioSettings() {
  static const SettingTable<RobotModel> table = {
      {"alpha", &RobotModel::alpha, "mass ratio m2/(m1+m2) of the robot, 0 < alpha < 1"}};
  return table;
}

const SettingTable<Margins>& MarginsSettings() {
  static const SettingTable<Margins> table = {
      {"clearance", &Margins::clearance,
       "clearance d required between inner body and walls (fraction of L), 0 <= d < 0.5"},
      {"clearance_stroke", &Margins::clearance_stroke,
       "clearance relative to the stroke d_s: the clearance from both walls is at least max(d, "
       "d_s (x_max - x_min)), 0 <= d_s < 0.5 (docs/model.md section 12)"},
      {"stick", &Margins::stick,
       "stick margin s: while the capsule rests |F| <= (1 - s) T0, 0 <= s < 1 (docs/model.md "
       "section 12)"}};
  return table;
}

}  // namespace capsubot
