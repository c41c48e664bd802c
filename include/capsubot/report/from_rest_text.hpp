#pragma once
// What the robot reaches from rest, in the text reports (docs/model.md sections 12 and 13): a
// gait checked from rest in one line, the fastest motion from rest in a few.

#include <string>

#include "capsubot/attract/gait_from_rest.hpp"
#include "capsubot/reach/optimize_reach.hpp"

namespace capsubot::text {

/// "from rest        reached from rest in ..." (one line) after `indent` spaces.
std::string FromRestText(const GaitFromRest& report, int indent = 4);

/// The fastest motion from rest in a few indented lines: force, alpha, speed, attractors,
/// spread.
std::string ReachText(const ReachResult& reach);

}  // namespace capsubot::text
