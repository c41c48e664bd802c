#pragma once
// The end of a branch at a wall (docs/continuation.md, Limits): where the walk cannot go on
// past its last point because a free flight of the motion comes to a wall, the grazing is
// located along the parameter by the flight's distance from the wall.

#include "continue/branch_system.hpp"

namespace capsubot::detail {

/// The grazing that ends a's motion beyond the point `a` of a branch, along a's tangent: the
/// flight of a's motion nearest to a wall (to `wall`, unless kNone), its grazing condition g
/// (wall_approach.hpp) at a's motion moved along the arclength, and the arclength where g
/// reaches 0, bracketed to `tolerance` between the last motion with a's events (g < 0) and the
/// first arclength without one (at most `limit` when that is a number: an arclength known to
/// lie beyond). The slope of g is first taken `back_step` back from a. True when that is a
/// grazing: *sp (type, parameter, accuracy, wall, motion, arclength from a's) and *end, the
/// completed point of the bracket's motion side. False when no flight turns back before the
/// wall or g at the bracket is not the wall's touch (the motion ends for another reason).
bool LocateWallEnd(BranchSystem& system, const Node& a, double back_step, double limit, Wall wall,
                   double tolerance, Node* end, SpecialPoint* sp);

}  // namespace capsubot::detail
