#pragma once
// The pieces of the plain-text reports: numbers in tables and the force as a formula.

#include <string>

#include "capsubot/model/forcing.hpp"

namespace capsubot::text {

/// A number in a text table with `digits` significant digits; a missing value (NaN) is "-"
/// everywhere (JSON writes it as null, CSV as an empty cell).
std::string Num(double value, int digits = 10);

/// The inner body's highest interior maximum x_max of an existing orbit with `digits` significant
/// digits; without one (NaN) x rises to the right wall at the impact: "1 at the impact (no
/// interior maximum)".
std::string XMaxText(double x_max, int digits = 10);

/// The same with `decimals` digits after the point (aligned columns); NaN is "-".
std::string NumFixed(double value, int decimals);

/// The force as a formula: "F(phi) = 0.5 sin(phi - 2.9449) + 0.5".
std::string ForceFormula(const Forcing& forcing);

}  // namespace capsubot::text
