#pragma once
// How an orbit is shown: one JSON object (for tools) or a table (for people), both the report
// stage's (the same for the Python module).

#include "capsubot/report/solution_json.hpp"
#include "capsubot/report/text.hpp"

namespace capsubot::app {

using json::AddEnergyJson;
using json::AddStabilityJson;
using json::SolutionJson;
using report::EnergyTable;
using report::ForceFormula;
using report::Num;
using report::NumFixed;
using report::SolutionTable;
using report::StabilityTable;

}  // namespace capsubot::app
