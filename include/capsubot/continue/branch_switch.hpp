#pragma once
// Branch switching at a period doubling (docs/continuation.md): the branch of period 2p born
// where a branch of period p has a multiplier -1.

#include "capsubot/continue/continuation.hpp"

namespace capsubot {

/// The period-2p branch through the located period doubling `pd` of a period-p branch of
/// `family`. Predictor: the period-p motion at pd displaced by +-a along the eigenvector of the
/// multiplier -1 (the two points of the period-2p motion lie on either side of it, a distance
/// growing like the square root of lambda - lambda_pd), at parameters on both sides of pd;
/// corrector: Newton shooting with period 2p (ShootPeriodicMotion), kept when the result is not
/// a fixed point of the p-th iterate. From the first such motion, ContinueBranch over
/// [options.from, options.to] (options.start is set to its parameter, max_period to 2p).
/// Throws std::invalid_argument when `pd` is not a located period doubling or lies outside the
/// range; a branch with status kNoMotion when no trial converged to a period-2p motion.
Branch SwitchAtPeriodDoubling(const RobotFamily& family, const SpecialPoint& pd,
                              ContinuationOptions options);

}  // namespace capsubot
