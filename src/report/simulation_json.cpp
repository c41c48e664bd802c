#include "capsubot/report/simulation_json.hpp"

#include "capsubot/report/forcing_json.hpp"
#include "capsubot/report/solution_json.hpp"

namespace capsubot::json {
namespace {

// The figures of a span of the run (the record, or the transient) as keys of `j`.
void AddTallyJson(nlohmann::json& j, const SimTally& t) {
  j["displacement"] = t.displacement;
  j["v_mean"] = t.v_mean;
  j["impacts_right"] = t.impacts_right;
  j["impacts_left"] = t.impacts_left;
  j["stops"] = t.stops;
  j["breakaways"] = t.breakaways;
  j["sticks"] = t.sticks;
  j["releases"] = t.releases;
  j["events"] = t.events;
  AddEnergyJson(j, t.energy);
}

}  // namespace

nlohmann::json SimulationJson(const SimResult& r, const SimOptions& sim, const Solution* orbit) {
  const SimState& f = r.final_state;
  // The run's end: its status and final state.
  nlohmann::json j = {{"status", SimStatusName(r.status)},
                      {"message", r.message},
                      {"alpha", sim.alpha},
                      {"phi", f.phi},
                      {"x", f.x},
                      {"u", f.u},
                      {"v", f.v},
                      {"y", f.y},
                      {"mode", SimModeName(f.mode)}};
  AddTallyJson(j, r);
  if (sim.transient > 0.0) {
    nlohmann::json t;
    t["periods"] = sim.transient;
    AddTallyJson(t, r.transient);
    j["transient"] = t;
  }
  if (orbit != nullptr) j["orbit"] = SolutionJson(*orbit);
  return j;
}

nlohmann::json SimulateJobJson(const SimulateJobResult& result) {
  return WithForceJson(
      SimulationJson(result.run, result.sim, result.orbit ? &*result.orbit : nullptr),
      result.options.forcing);
}

}  // namespace capsubot::json
