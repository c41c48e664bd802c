#pragma once
// A long-run motion from rest in words (docs/model.md sections 12 and 13), as the text reports
// of the commands show each attractor.

#include <string>

#include "capsubot/attract/attractors.hpp"

namespace capsubot {

/// "period 1: 3 right + 1 left impacts per period", or for an irregular attractor the range of
/// its starts' mean velocities and whether their records are long enough (periods searched up
/// to `max_period`).
std::string AttractorWords(const Attractor& attractor, int max_period);

}  // namespace capsubot
