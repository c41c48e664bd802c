#pragma once
// A force as JSON (docs/model.md sections 2 and 15): what every result that describes its force
// writes, in the names of the options that give it.

#include <nlohmann/json.hpp>

#include "capsubot/model/forcing.hpp"

namespace capsubot::json {

/// {"waveform": "sine", "A", "c", "phi0"} for the paper's family, {"waveform": "fourier",
/// "c", "cos": [a_1..a_K], "sin": [b_1..b_K], "phi0"} for a Fourier series, {"waveform":
/// "pulse", "levels": [L_1..L_N], "switches": [s_1..s_N], "phi0"} for a pulse force.
nlohmann::json ForcingJson(const Forcing& forcing);

/// `j`, the JSON object of a job's result, with the force it was run with: "force":
/// ForcingJson(forcing).
nlohmann::json WithForceJson(nlohmann::json j, const Forcing& forcing);

}  // namespace capsubot::json
