#include "capsubot/job/basins_settings.hpp"

namespace capsubot {

const SettingTable<VelocityPlane>& VelocityPlaneSettings() {
  using V = VelocityPlane;
  static const SettingTable<VelocityPlane> table = {
      // An angle [rad]: the kind "PHASE" tells the front ends to read it as a forcing phase.
      {"psi", &V::psi, "forcing phase of the starts in the x0-u0 plane", 0, 0, "PHASE"},
      {"u_min", &V::u_min, "smallest u0 of the x0-u0 plane"},
      {"u_max", &V::u_max, "largest u0 of the x0-u0 plane"}};
  return table;
}

}  // namespace capsubot
