#pragma once
// Basins of attraction as plain text and as a gnuplot figure (docs/model.md sections 12 and
// 13): what `capsubot basins` prints, and the script that draws its map.

#include <string>

#include "capsubot/attract/attractors.hpp"
#include "capsubot/job/basins_job.hpp"

namespace capsubot::text {

/// "56.7 %: period 12: 25 right + 0 left impacts per 12 periods, mean velocity 0.01034": the
/// line of an attractor in the report and in the figure's key.
std::string BasinLegend(const Attractor& attractor, int max_period);

/// What `capsubot basins` prints: the map (starts, grid, plane, the CSV) and its attractors
/// with their share of the starts; for a shard, its line (StartShardText).
std::string BasinsJobText(const BasinsJobResult& result);

/// The gnuplot script that draws the map of a whole-map run `result` (its CSV, read by gnuplot)
/// into the PNG file `png`: each start coloured by its attractor (the first ten in their own
/// colour, the others grey), the key naming them, the title naming the force and the robot in
/// gnuplot's typeset notation (T_0, {/Symbol a}), as the other figures of the project.
std::string BasinsPlotScript(const BasinsJobResult& result, const std::string& png);

}  // namespace capsubot::text
