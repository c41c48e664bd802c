#pragma once
// The bounds of the work and memory a caller sizes: the command line's options and the Python
// module's arguments are checked against these same numbers before any work starts.

#include <cstdint>

namespace capsubot {

/// Rows of a sampled trajectory at most: a --trajectory file of `solve` or `simulate` (about
/// 1 GB of CSV), the arrays of the Python module's trajectory() and simulate(trajectory=True)
/// (about 0.5 GB).
inline constexpr std::int64_t kMaxTrajectoryRows = 10'000'000;

/// Samples per forcing period of a simulated trajectory at most.
inline constexpr int kMaxSamplesPerPeriod = 1'000'000;

/// The simulator's work bound per period (SimOptions::max_events_per_period) at most.
inline constexpr std::int64_t kMaxEventsPerPeriod = 1'000'000'000;

/// The work bound of the orbit search of a given robot (FindRobotOrbits' max_evaluations) at
/// most: 250 times its default.
inline constexpr std::int64_t kMaxOrbitEvaluations = 1'000'000'000;

/// Worker threads a caller may ask for at most (0 asks for one per core): the --threads of the
/// commands, the threads of the library's options and of the Python module's arguments.
inline constexpr int kMaxThreads = 1024;

/// Worker threads per core at most: more only add overhead, and each thread of a long run
/// holds its own record (attractors.hpp, kMaxRecord).
inline constexpr int kThreadsPerCore = 4;

/// The most worker threads worth running on this machine: kThreadsPerCore x its cores, at most
/// kMaxThreads.
int MaxUsefulThreads();

/// `requested` worker threads (0: all cores, kept) lowered to MaxUsefulThreads(); the results
/// of every job do not depend on the threads.
int CapThreads(int requested);

/// Rows of a trajectory sampled `samples_per_period` times a period over `periods` periods
/// (the whole run: transient and record): floor(periods x samples_per_period) + 1.
double TrajectoryRows(double periods, double samples_per_period);

/// Throws std::invalid_argument when TrajectoryRows(periods, samples_per_period) exceeds
/// kMaxTrajectoryRows, naming the two arguments as the caller spells them: "samples_per_period
/// = 1000000 with transient + periods = 100000000 is invalid: expected at most 10000000 rows of
/// the trajectory (samples per period x periods + 1 = 100000000000001)".
void RequireTrajectoryRows(double periods, double samples_per_period, const char* samples_name,
                           const char* periods_name);

}  // namespace capsubot
