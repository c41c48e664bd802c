#pragma once
// The value of a number that was not computed. Every result of the library starts its numbers
// at kNaN and every option that may be left out ("not given", "free") defaults to it, so that
// a number a run did not reach cannot be read as a value: NaN compares unequal to everything,
// and std::isnan tells it apart.

#include <limits>

namespace capsubot {

/// A quiet NaN: "not computed" in a result, "not given" in an option.
inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace capsubot
