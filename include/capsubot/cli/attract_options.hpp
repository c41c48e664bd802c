#pragma once
// Options shared by the commands on long-run motions (attractors, basins, periodic,
// bifurcation, continue): the robot, the simulation lengths, the start grid, the start state.

#include <string>

#include "capsubot/attract/attractors.hpp"
#include "capsubot/attract/start_state_spec.hpp"
#include "capsubot/cli/force_options.hpp"
#include "capsubot/cli/setting_options.hpp"
#include "capsubot/cli/strict_values.hpp"
#include "capsubot/job/attractors_job.hpp"
#include "capsubot/numerics/not_computed.hpp"

namespace capsubot::cli {

/// The robot and how its motion is simulated: force, T0, e, alpha, transient, record, ...
struct RobotOptions {
  ForcingOptions forcing;
  RobotModel model;  ///< T0, e and alpha (its force is built from `forcing`)
  MotionOptions motion;

  /// The robot the options give (the force built: throws std::invalid_argument naming what is
  /// missing).
  RobotModel Model() const { return {forcing.Build(), model.params, model.alpha}; }
};

/// Adds the force, --T0, --e, --alpha (required), and with `with_motion` --transient, --record,
/// --max-period, --chatter-velocity, --max-events-per-period.
void AddRobotOptions(CLI::App& cmd, RobotOptions& options, bool with_motion = true);

/// The map job of `robot` (force, T0, e, alpha, motion options) over the grid `starts` (the
/// option --starts) with `threads` worker threads (as --threads gave them: AddThreadsOption).
/// Throws std::invalid_argument for a bad grid or force.
AttractorsJobOptions MapJobOptions(const RobotOptions& robot, const std::string& starts,
                                   int threads);

/// "0.5,1" -> RestStart(0.5, 1) for option `name`; throws std::invalid_argument naming it.
PhaseState ParseRestStart(const char* name, const std::string& text);

/// The flags of the long-run options (MotionOptions' fields, threads): for WithFlagNames.
const FlagNames& MotionFlagNames();

/// The flags of a start: the state's --x0, --u0, --v0, --psi and the other starts --from-rest,
/// --from-orbit (for StartStateSpec's messages).
inline const FlagNames kStartFlags = DashedFlags("x0 u0 v0 psi from_rest from_orbit");

/// The start state of a command given as --x0, --u0, --v0 and --psi (all four, or none when
/// another option gives the start).
struct StartStateOptions {
  PhaseState state;
  CLI::Option* options[4] = {};

  /// Adds the four options to `cmd`.
  void Add(CLI::App& cmd);
  /// The parts given, as the library reads a start state.
  StartStateSpec Spec() const;
};

/// A StartsProgress that shows the progress (ProgressBar, counting `what`, e.g. "starts") on
/// stderr when progress is shown (progress.hpp); none otherwise.
StartsProgress CountProgress(const char* what);

}  // namespace capsubot::cli
