#pragma once
// Branch switching (docs/continuation.md): at a period doubling, the branch of period 2p born
// where a branch of period p has a multiplier -1; at a grazing, the branch of the motion with
// other impacts per period that exists beyond it.

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

/// The branch of the motion with other impacts per period just beyond the grazing `grazing` of
/// `branch` (one of its special points, located or not), on the side of the parameter that the
/// branch was heading to when it met the grazing. Trials: the parameters lambda_g +- 1e-5, 1e-4,
/// 1e-3 (times max(1, |lambda_g|); the sign is that side; only offsets wider than the
/// grazing's accuracy and inside [options.from, options.to]), nearest first; at each, Newton
/// shooting from the grazing's state (FindPeriodicMotion, which finds the period up to
/// options.shooting.max_period), and when that finds no such motion the same after 50 periods
/// of the simulator from that state. A motion is kept when it converged, its impacts per
/// period differ from the grazing's motion's, and it passes within sqrt(offset) of the
/// grazing's state at the grazing's phase (a motion born at the grazing lies that close: the
/// impacting side depends on the parameter like a square root). From the first kept motion,
/// ContinueBranch over [options.from, options.to] (options.start is set to its parameter,
/// max_period to its period). Throws std::invalid_argument when `grazing` is not a grazing of
/// `branch`; a branch with status kNoMotion (the message says the motion ends at the grazing)
/// when no trial kept a motion.
Branch SwitchAtGrazing(const RobotFamily& family, const Branch& branch, const SpecialPoint& grazing,
                       ContinuationOptions options);

}  // namespace capsubot
