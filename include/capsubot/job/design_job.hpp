#pragma once
// The design job (docs/design.md): `capsubot design` and the Python module's design() in one
// call. One design is the fastest robust one-impact gait of a robot in SI units (part a,
// Design) and, when asked, the fastest motion reached from rest in each direction (part b,
// DesignFromRest); a grid is one design a point over the robot's inputs, one CSV row a point
// (RunDesignGrid).

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "capsubot/attract/gait_from_rest.hpp"
#include "capsubot/attract/start_grid.hpp"
#include "capsubot/design/design.hpp"
#include "capsubot/design/design_drive.hpp"
#include "capsubot/design/design_from_rest.hpp"
#include "capsubot/design/design_robustness.hpp"
#include "capsubot/job/stage_callback.hpp"
#include "capsubot/model/interrupt.hpp"
#include "capsubot/parallel/blocks.hpp"
#include "capsubot/sweep/design_grid.hpp"
#include "capsubot/sweep/grid_file.hpp"
#include "capsubot/sweep/sweep.hpp"

namespace capsubot {

/// Part (b) of one design: the fastest motion reached from rest in each direction, sized by
/// the parameters both front ends name alike (`--reach-evaluations` on the command line,
/// `reach_evaluations` in Python, and so on); the messages of Validate use these names.
struct DesignFromRestPart {
  /// Starts on which the best robots are re-checked and their attractors reported; each side
  /// 1..kMaxGridSide, at most kMaxRestStarts starts (ParseStartGrid). Default: those of
  /// DesignFromRestOptions.
  StartGrid from_rest_starts;
  StartGrid reach_starts;  ///< starts inside the search; the same ranges
  /// From-rest evaluations of the global stage per direction, 1..kMaxDesignFromRestEvaluations.
  int reach_evaluations = 0;
  /// From-rest evaluations of the local polish per direction, 0..kMaxDesignFromRestEvaluations.
  int reach_local_evaluations = 0;
  double reach_seconds = 0.0;  ///< wall-clock limit of the search stages [s], finite > 0
  /// Worker threads of the simulated starts (0: all cores); the result does not depend on it.
  int threads = 0;
  /// Asked by every from-rest evaluation (interrupt.hpp); empty: never.
  Interrupt interrupt;
  /// Told the stage of the search and its evaluations so far; empty: nobody is told.
  DesignFromRestProgress progress;

  /// The defaults of DesignFromRestOptions.
  DesignFromRestPart();
  /// Throws std::invalid_argument naming the bad parameter, its value and the rule.
  void Validate() const;
  /// The settings of DesignFromRest: the grids and threads of the search and of the re-check
  /// (which keeps its long record, kCheckRecord), the budgets and time limit; not the
  /// interrupt (RunDesignJob gives it to the run).
  DesignFromRestOptions Options() const;
};

/// One design of the robot DesignJobOptions::input.
struct DesignOneMode {
  /// Told the robots of part (a) evaluated so far (and asked on the calling thread: a front end
  /// may abandon the run from it by throwing); empty: nobody is told.
  DesignProgress progress;
  /// Asked by the continuations of the gait's robustness (interrupt.hpp); empty: never.
  Interrupt interrupt;
  std::optional<DesignFromRestPart> from_rest;  ///< part (b), when given
  /// The levels of the gait's speed bands in mu, e and m2 (SpeedBandOptions::levels); their
  /// starts are part (b)'s check from rest (from_rest_starts), or its default.
  std::vector<double> band_levels = {0.95};
};

/// One design a point of a grid over the robot's inputs, written as a sweep's CSV file
/// (GridFileOptions: comments, output, shard, resume, threads, checkpoints): the axes' values,
/// then the gait's status, its numbers in the user's units (those a gridded input does not
/// already give: m2_kg, frequency_hz) and dimensionless (gait_numbers.hpp), its orbits and
/// its binding limits (joined by ';').
struct DesignGridMode : GridFileOptions {
  /// The axes, first slowest; each parameter at most once, at least one. The robot of
  /// DesignJobOptions::input gives the inputs no axis varies (and must be valid as it is).
  std::vector<DesignGridAxis> axes;
  /// Told the points done; empty: nobody is told.
  SweepProgressCallback progress;
  /// Computes the blocks of rows: this process's threads, or other processes too.
  std::reference_wrapper<const BlockBackend> backend = LocalBlocks();
};

/// The fastest drive of the robot DesignJobOptions::input (design_drive.hpp): its waveform,
/// frequency and inner mass over the input's ranges; the input's motor force is not used.
struct DesignDriveMode {
  DriveDesignOptions options;
  /// Asked by every from-rest evaluation (interrupt.hpp); empty: never.
  Interrupt interrupt;
};

/// What the design job does and with what robot.
struct DesignJobOptions {
  /// The robot in SI units and what may be chosen (ranges of m2 and f, robust margins).
  DesignInput input;
  /// One design (its gait's robustness, with part (b) or without), or a grid of designs.
  std::variant<DesignOneMode, DesignGridMode, DesignDriveMode> mode;
  /// Told each stage of one design ("design: 1/2 the fastest robust one-impact gait", "design:
  /// 2/2 how far mu, e and m2 carry the gait" when there is a gait) and "" at its end; a grid
  /// tells its points to DesignGridMode::progress instead.
  StageCallback on_stage;

  /// Throws std::invalid_argument naming the bad parameter, its value and the rule: the
  /// input's rules, those of part (b), those of the grid and its file.
  void Validate() const;
};

/// What a grid wrote.
struct DesignGridWritten {
  std::string output;    ///< the CSV file (DesignGridMode::output)
  SweepSummary summary;  ///< points, rows written by this run, threads, wall time
};

/// The outcome of the design job. One design: `design`, with a gait its `robustness` and,
/// with part (b), `from_rest`; a grid: `grid`.
struct DesignJobResult {
  DesignInput input;    ///< the robot designed (DesignJobOptions::input)
  DesignResult design;  ///< part (a); status kNotRun for a grid
  /// How far mu, e and m2 carry part (a)'s gait (ComputeDesignRobustness with the default
  /// RobustnessOptions); empty without a gait and for a grid.
  GaitRobustness robustness;
  /// Part (a)'s gait checked from rest (CheckGaitFromRest) on the starts of its speed bands
  /// (part (b)'s from_rest_starts, or 8 x 8): how many starts end on it and where the others
  /// go; checked = false without a gait and for a grid.
  GaitFromRest gait_from_rest;
  std::optional<DesignFromRestResult> from_rest;  ///< part (b), when asked
  /// How part (b) searched and checked (DesignFromRestPart::Options), when asked.
  DesignFromRestOptions from_rest_options;
  std::optional<DesignGridWritten> grid;   ///< what a grid wrote
  std::optional<DriveDesignResult> drive;  ///< the fastest drive (DesignDriveMode)
};

/// Which answer of one design to build: part (a)'s gait, unless part (b)'s forward motion is
/// faster from rest than the gait averaged over its starts from rest (or there is no gait).
enum class DesignChoice { kNone, kGait, kFromRestForward };

/// Stable identifier ("none", "one_impact", "from_rest_forward").
const char* DesignChoiceName(DesignChoice choice);

/// The choice for a result of one design (kNone for a grid).
DesignChoice ChooseDesign(const DesignJobResult& result);

/// The mean speed from rest [mm/s] of part (a)'s gait, averaged over its starts (NaN when not
/// checked).
double GaitSpeedFromRest(const DesignJobResult& result);

/// Runs the job: validates the options (std::invalid_argument before any work), then one
/// design or the grid. A grid's errors are RunDesignGrid's (IoError, SweepResumableError); an
/// exception of a callback or of the interrupt goes through, and no result is returned.
DesignJobResult RunDesignJob(const DesignJobOptions& options);

/// The grid options RunDesignJob runs for `mode` over `input` (its columns and rows): for the
/// workers of a distributed run, which compute its blocks (DesignGridBlocks). Validates
/// nothing.
DesignGridOptions DesignJobGrid(const DesignInput& input, const DesignGridMode& mode);

}  // namespace capsubot
