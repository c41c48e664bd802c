#pragma once
// The long-run motions from rest as plain text (docs/model.md sections 12 and 13): what
// `capsubot attractors` prints, and the words and lines shared with the other reports of
// attractors (basins, a gait checked from rest).

#include <string>

#include "capsubot/attract/attractors.hpp"
#include "capsubot/attract/gait_from_rest.hpp"
#include "capsubot/job/attractors_job.hpp"

namespace capsubot::text {

/// "period 1: 3 right + 1 left impacts per period", or for an irregular attractor the range of
/// its starts' mean velocities and whether their records are long enough.
std::string AttractorWords(const Attractor& attractor, int max_period);

/// The line of a map run as one shard (`command`: "attractors", "basins"): "attractors: shard
/// 1/2: 3 of 6 starts written to FILE" (and how many were resumed from the checkpoint).
std::string StartShardText(const char* command, const AttractorsJobResult& result);

/// What `capsubot attractors` prints: the run, the force and model, each attractor with an
/// example start, the mean velocity over the starts (and the CSV written); for a shard, its
/// line (StartShardText).
std::string AttractorsJobText(const AttractorsJobResult& result);

}  // namespace capsubot::text
