#pragma once
// A grid of starts "NXxNPSI" (docs/model.md section 12): n_x starting positions of the inner
// body times n_psi starting forcing phases (or, in the x0-u0 plane of a basin map, n_psi
// starting relative velocities). One type and one parser for the command line and the Python
// module, with one set of limits.

#include <cstdint>
#include <string>

namespace capsubot {

/// Most cells along one side of a grid of starts.
inline constexpr int kMaxGridSide = 100000;

/// Most starts of a grid from rest (n_x * n_psi): a 2048 x 2048 map, about 0.5 GB of results.
inline constexpr std::int64_t kMaxRestStarts = 4194304;

/// The sizes of a grid of starts.
struct StartGrid {
  int n_x = 8;    ///< starting positions x0 = (i + 0.5)/n_x; 1 <= n_x <= kMaxGridSide
  int n_psi = 8;  ///< starting phases psi = tau j/n_psi (or velocities); 1 <= n_psi <= kMaxGridSide

  /// n_x * n_psi.
  std::int64_t Starts() const { return static_cast<std::int64_t>(n_x) * n_psi; }
  /// The grid as it is written, "NXxNPSI" ("8x8"): what ParseStartGrid reads.
  std::string Text() const { return std::to_string(n_x) + "x" + std::to_string(n_psi); }
  /// Throws std::invalid_argument naming the first bad size, its value and the rule (n_x,
  /// n_psi, and n_x * n_psi <= kMaxRestStarts).
  void Validate() const;
};

/// The grid written "NXxNPSI" (e.g. "8x8": decimal digits only, each size from 1 to
/// kMaxGridSide, at most kMaxRestStarts starts), given as the option or argument `name`.
/// Throws std::invalid_argument naming `name`, the text and the rule:
/// "--starts = 8by8 is invalid: expected NXxNPSI, two whole numbers from 1 to 100000 (e.g. 8x8)".
StartGrid ParseStartGrid(const std::string& name, const std::string& text);

}  // namespace capsubot
