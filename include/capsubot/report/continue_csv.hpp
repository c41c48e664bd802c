#pragma once
// The CSV table of `capsubot continue -o` (docs/continuation.md): the branch, or the curve when
// a special point was followed in two parameters. The command line writes it after its '#'
// provenance line.

#include <cstddef>
#include <string>

#include "capsubot/job/continue_job.hpp"

namespace capsubot::text {

/// A CSV table: the header line and one line per row.
struct CsvTable {
  std::string text;      ///< header and rows, each ending in '\n'
  std::size_t rows = 0;  ///< the rows (points)
};

/// The branch, one row per point: <param>, x, u, v, psi, period, impacts_right, impacts_left,
/// mean_velocity, spectral_radius, muK_re, muK_im (K = 1.. the largest dimension, empty where a
/// point has fewer), stable, label. With follow, the curve instead: <param>, <param2>, the same
/// columns up to the multipliers, stable, condition. Empty (no rows) when the branch, or the
/// curve, was not followed (status not ok).
CsvTable ContinueJobCsv(const ContinueJobResult& result);

/// The line the text report ends with when `table` (ContinueJobCsv(result)) was written to
/// `path`: "  written        N points to PATH", "N curve points" for a followed curve.
std::string ContinueCsvWritten(const ContinueJobResult& result, const CsvTable& table,
                               const std::string& path);

}  // namespace capsubot::text
