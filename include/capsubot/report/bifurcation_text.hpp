#pragma once
// What a bifurcation job wrote, as the line `capsubot bifurcation` prints.

#include <string>

#include "capsubot/job/bifurcation_job.hpp"

namespace capsubot::text {

/// "bifurcation diagram over T0 = 0.08 .. 0.12 (4 values, both) for 3 values of e: 558
/// impacts written to imp.csv, 40 summary rows to sum.csv\n"; for a shard ", shard 1/3 of 6
/// continuations" after the study, and how many of its parts were resumed, if any.
std::string BifurcationJobText(const BifurcationJobResult& result);

}  // namespace capsubot::text
