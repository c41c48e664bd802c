// The grid of starts "NXxNPSI" and its limits.

#include "capsubot/attract/start_grid.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace capsubot {
namespace {

// One size of the grid: decimal digits only (no sign, no space, no exponent), 1 to
// kMaxGridSide; false otherwise.
bool GridSide(const std::string& part, int* value) {
  if (part.empty() || part.size() > 6 ||
      part.find_first_not_of("0123456789") != std::string::npos) {
    return false;
  }
  const long n = std::stol(part);
  if (n < 1 || n > kMaxGridSide) return false;
  *value = static_cast<int>(n);
  return true;
}

}  // namespace

void StartGrid::Validate() const {
  if (n_x < 1 || n_x > kMaxGridSide) {
    throw std::invalid_argument(fmt::format(
        "n_x = {} is invalid: expected 1 <= n_x <= {} starting positions", n_x, kMaxGridSide));
  }
  if (n_psi < 1 || n_psi > kMaxGridSide) {
    throw std::invalid_argument(fmt::format(
        "n_psi = {} is invalid: expected 1 <= n_psi <= {} starting phases", n_psi, kMaxGridSide));
  }
  if (Starts() > kMaxRestStarts) {
    throw std::invalid_argument(
        fmt::format("starts = {}x{} is invalid: expected n_x * n_psi <= {} starts", n_x, n_psi,
                    kMaxRestStarts));
  }
}

StartGrid ParseStartGrid(const std::string& name, const std::string& text) {
  const std::size_t x = text.find_first_of("xX");
  StartGrid grid;
  if (x == std::string::npos || !GridSide(text.substr(0, x), &grid.n_x) ||
      !GridSide(text.substr(x + 1), &grid.n_psi)) {
    throw std::invalid_argument(fmt::format(
        "{} = {} is invalid: expected NXxNPSI, two whole numbers from 1 to {} (e.g. 8x8)", name,
        text, kMaxGridSide));
  }
  if (grid.Starts() > kMaxRestStarts) {
    throw std::invalid_argument(
        fmt::format("{} = {} is invalid: expected at most {} starts", name, text, kMaxRestStarts));
  }
  return grid;
}

}  // namespace capsubot
