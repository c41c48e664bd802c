#pragma once
// A sweep's CSV file drawn by gnuplot (`capsubot sweep --plot`): one column against the grid's
// axis, or as a map over its two axes.

#include <string>

#include "capsubot/sweep/sweep.hpp"

namespace capsubot::text {

/// The column a sweep's plot draws: `column`, or when it is empty the first of mean_velocity,
/// v_mean and I that the sweep writes. Throws std::invalid_argument naming the broken rule:
/// plot_column not among the sweep's columns (the message lists them), a grid of more than two
/// axes, the CSV written to standard output (the plot reads the file) or as a shard (the file
/// holds a part of the grid).
std::string SweepPlotColumn(const SweepOptions& sweep, const std::string& column);

/// A gnuplot script that reads the sweep's file sweep.output and draws `column` into `png`:
/// against the axis for a grid of one axis, as a map of coloured points over the two axes
/// (the first, slowest, axis upwards) for two; a log-spaced axis on a log scale. Empty cells
/// (no such quantity there) are left out.
std::string SweepPlotScript(const SweepOptions& sweep, const std::string& column,
                            const std::string& png);

}  // namespace capsubot::text
