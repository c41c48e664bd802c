#include "capsubot/report/continuation_json.hpp"

namespace capsubot::json {
namespace {

nlohmann::json Multipliers(const PeriodicMotion& m) {
  nlohmann::json j = nlohmann::json::array();
  for (const auto& l : m.multipliers) j.push_back({l.real(), l.imag()});
  return j;
}

nlohmann::json End(BranchEnd end, const std::string& name, double lambda) {
  return {{"end", BranchEndName(end)}, {name, lambda}};
}

nlohmann::json Limit(const MotionLimit& l, const std::string& name) {
  nlohmann::json j = {{"type", l.Name()}, {name, l.parameter}, {"located", l.located}};
  if (l.special) {
    j["accuracy"] = l.accuracy;
    j["multipliers"] = Multipliers(l.motion);
  }
  return j;
}

}  // namespace

nlohmann::json BranchJson(const Branch& b, const std::string& name) {
  nlohmann::json j;
  j["parameter"] = name;
  j["status"] = ContinuationStatusName(b.status);
  j["message"] = b.message;
  j["start_index"] = b.start_index;
  j["ends"] = {{"lower", End(b.backward_end, name, b.backward_parameter)},
               {"upper", End(b.forward_end, name, b.forward_parameter)}};
  j["points"] = nlohmann::json::array();
  for (const BranchPoint& p : b.points) {
    const PeriodicMotion& m = p.motion;
    j["points"].push_back({{name, p.parameter},
                           {"arclength", p.arclength},
                           {"x", m.state.x},
                           {"u", m.state.u},
                           {"v", m.state.v},
                           {"psi", m.state.psi},
                           {"mode", SimModeName(m.mode)},
                           {"period", m.period},
                           {"impacts_right", m.impacts_right},
                           {"impacts_left", m.impacts_left},
                           {"mean_velocity", m.mean_velocity},
                           {"spectral_radius", m.spectral_radius},
                           {"multipliers", Multipliers(m)},
                           {"stable", m.stable},
                           {"label", p.label}});
  }
  j["special_points"] = nlohmann::json::array();
  for (const SpecialPoint& s : b.special_points) {
    const PeriodicMotion& m = s.motion;
    j["special_points"].push_back(
        {{"type", SpecialPointTypeName(s.type)},
         {name, s.parameter},
         {"located", s.located},
         {"accuracy", s.accuracy},
         {"mean_velocity", m.mean_velocity},
         {"period", m.period},
         {"impacts_right", m.impacts_right},
         {"impacts_left", m.impacts_left},
         {"state", {{"x", m.state.x}, {"u", m.state.u}, {"v", m.state.v}, {"psi", m.state.psi}}},
         {"multipliers", Multipliers(m)},
         {"stable", m.stable}});
  }
  return j;
}

nlohmann::json RobustnessJson(const GaitRobustness& robustness) {
  nlohmann::json j = nlohmann::json::object();
  for (const ParameterRobustness& p : robustness.parameters) {
    j[p.name] = {{"value", p.value},
                 {"from", p.from},
                 {"to", p.to},
                 {"status", ContinuationStatusName(p.status)},
                 {"message", p.message},
                 {"down", Limit(p.down, p.name)},
                 {"up", Limit(p.up, p.name)}};
  }
  return j;
}

}  // namespace capsubot::json
