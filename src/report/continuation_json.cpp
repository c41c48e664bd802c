#include "capsubot/report/continuation_json.hpp"

#include <utility>

#include "capsubot/numerics/not_computed.hpp"

namespace capsubot::json {
namespace {

nlohmann::json Multipliers(const PeriodicMotion& m) {
  nlohmann::json j = nlohmann::json::array();
  for (const auto& l : m.multipliers) j.push_back({l.real(), l.imag()});
  return j;
}

// The motion of a point of a branch or curve: state, events, speed, multipliers.
nlohmann::json MotionPoint(const PeriodicMotion& m) {
  return {{"x", m.state.x},
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
          {"stable", m.stable}};
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

// One edge of a speed band: where it lies (the range's end when the speed stays above the
// level up to it) and its bracket.
nlohmann::json Edge(const BandEdge& e, const std::string& name) {
  return {{"within", e.within},
          {name, e.parameter},
          {"inside", e.inside},
          {"outside", e.outside},
          {"accuracy", e.accuracy},
          {"ratio_inside", e.ratio_inside},
          {"ratio_outside", e.ratio_outside}};
}

// A parameter's speed band (null when not computed) with the special points inside it.
nlohmann::json Band(const ParameterRobustness& p) {
  const SpeedBand& b = p.band;
  if (b.status == SpeedBandStatus::kNotRun) return nullptr;
  nlohmann::json levels = nlohmann::json::array();
  for (std::size_t i = 0; i < b.down.size() && i < b.up.size(); ++i) {
    levels.push_back({{"level", b.down[i].level},
                      {"down", Edge(b.down[i], p.name)},
                      {"up", Edge(b.up[i], p.name)}});
  }
  nlohmann::json inside = nlohmann::json::array();
  for (const SpecialPoint& sp : p.InBand()) {
    inside.push_back({{"type", SpecialPointTypeName(sp.type)}, {p.name, sp.parameter}});
  }
  return {{"status", SpeedBandStatusName(b.status)},
          {"nominal_speed", b.nominal_speed},
          {"starts", b.starts},
          {"unsettled_starts", b.unsettled_starts},
          {"evaluations", b.evaluations},
          {"levels", levels},
          {"special_points_inside", inside}};
}

// One end of a curve: how it ended and its last point.
nlohmann::json CurveEnd(BranchEnd end, const FollowResult& f, const std::string& name,
                        const CurvePoint* last) {
  const double nan = kNaN;
  return {{"end", BranchEndName(end)},
          {name, last != nullptr ? last->parameter : nan},
          {f.param2, last != nullptr ? last->parameter2 : nan}};
}

nlohmann::json FollowJson(const FollowResult& f, const std::string& name) {
  const Curve& c = f.curve;
  const bool any = !c.points.empty();
  return {{"type", SpecialPointTypeName(f.type)},
          {"parameter2", f.param2},
          {"status", ContinuationStatusName(c.status)},
          {"message", c.message},
          {"start", {{name, f.at ? f.at->parameter : kNaN}, {f.param2, f.value2}}},
          {"start_index", c.start_index},
          {"ends",
           {{"backward", CurveEnd(c.backward_end, f, name, any ? &c.points.front() : nullptr)},
            {"forward", CurveEnd(c.forward_end, f, name, any ? &c.points.back() : nullptr)}}}};
}

nlohmann::json CurveJson(const Curve& c, const std::string& name, const std::string& name2) {
  nlohmann::json j = nlohmann::json::array();
  for (const CurvePoint& p : c.points) {
    nlohmann::json point = MotionPoint(p.motion);
    point[name] = p.parameter;
    point[name2] = p.parameter2;
    point["arclength"] = p.arclength;
    point["condition"] = p.condition;
    j.push_back(std::move(point));
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
    nlohmann::json point = MotionPoint(p.motion);
    point[name] = p.parameter;
    point["arclength"] = p.arclength;
    point["label"] = p.label;
    j["points"].push_back(std::move(point));
  }
  j["special_points"] = nlohmann::json::array();
  for (const SpecialPoint& s : b.special_points) {
    const PeriodicMotion& m = s.motion;
    j["special_points"].push_back(
        {{"type", SpecialPointTypeName(s.type)},
         {name, s.parameter},
         {"located", s.located},
         {"accuracy", s.accuracy},
         {"wall", WallName(s.wall)},
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

nlohmann::json ContinueJobJson(const ContinueJobResult& r) {
  nlohmann::json j = BranchJson(r.branch, r.param);
  if (r.switched) {
    j["switched"] = r.switched->at ? BranchJson(r.switched->branch, r.param) : nlohmann::json();
  }
  if (r.follow) {
    j["follow"] = FollowJson(*r.follow, r.param);
    j["curve"] = CurveJson(r.follow->curve, r.param, r.follow->param2);
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
                 {"up", Limit(p.up, p.name)},
                 {"chatter_changes", p.chatter_changes},
                 {"band", Band(p)}};
  }
  return j;
}

}  // namespace capsubot::json
