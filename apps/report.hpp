#pragma once
// How an orbit is shown: one JSON object (for tools) or a table (for people). Both are the
// report stage's (src/report/), the same for the Python module.

#include <nlohmann/json.hpp>
#include <string>

#include "capsubot/report/solution_json.hpp"
#include "capsubot/report/solve_text.hpp"
#include "capsubot/report/text_format.hpp"

namespace capsubot::app {

using json::AddEnergyJson;
using json::AddStabilityJson;
using json::SolutionJson;
using text::EnergyTable;
using text::ForceFormula;
using text::Num;
using text::NumFixed;
using text::SolutionTable;
using text::StabilityTable;

}  // namespace capsubot::app
