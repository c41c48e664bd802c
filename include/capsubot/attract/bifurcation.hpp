#pragma once
// Bifurcation diagrams by brute force (docs/model.md section 13): one parameter is stepped from
// one end of a range to the other with the state carried from each value to the next (so
// coexisting attractors show as hysteresis between the up and down sweeps); at each value the
// motion is simulated for a transient, classified, its impacts recorded, and its largest
// multiplier found by Newton shooting (periodic.hpp). The analytic one-impact orbits of the
// same robots (robot_orbits.hpp) can be added for comparison.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "capsubot/attract/attractors.hpp"
#include "capsubot/model/model_parameter.hpp"
#include "capsubot/numerics/not_computed.hpp"
#include "capsubot/parallel/blocks.hpp"

namespace capsubot {

/// The most values of the second parameter of a study (BifurcationOptions::over_values): its
/// plan holds a few hundred bytes per value before the first row.
inline constexpr std::int64_t kMaxOverValues = 100000;

struct BifurcationOptions {
  /// The parameter stepped: a robot parameter (IsRobotParameter; A needs the harmonic force).
  ModelParameter param = ModelParameter::kT0;
  /// k of a_k (kCos) or b_k (kSin): 1 <= k <= the force's harmonics K; 0 for the others.
  int harmonic = 0;
  double from = kNaN;                      ///< first value (finite)
  double to = kNaN;                        ///< last value (finite; may be below `from`)
  int steps = 101;                         ///< values, both ends included; >= 2
  bool up = true;                          ///< sweep from `from` to `to`
  bool down = true;                        ///< sweep from `to` back to `from`
  MotionOptions motion;                    ///< transient, record, max_period, ... per value
  PhaseState start = RestStart(0.5, 0.0);  ///< state at the first value of each sweep
  bool multipliers = true;                 ///< largest multiplier of each periodic motion (Newton)
  bool analytic = true;                    ///< add the valid one-impact orbits of every value
  int threads = 0;  ///< the parts run in parallel (0: all cores); same result
  /// A two-parameter study: one diagram per value of a second parameter `over` (set to each
  /// of over_values in turn, the other inputs kept); empty: one diagram, no second parameter.
  /// At most kMaxOverValues values.
  std::vector<double> over_values;
  ModelParameter over = ModelParameter::kMean;  ///< the second parameter (not `param`)
  int over_harmonic = 0;                        ///< k of a_k, b_k when `over` is one, else 0
  /// Compute only shard `shard` of `shards` (0 <= shard < shards <= the continuations): the
  /// continuations q with q % shards = shard, q = i * D + d for over value i and direction d
  /// (D = 2 up and down, else 1; d = 0 up), with the analytic orbits of the values i whose
  /// continuation i * D it holds.
  int shard = 0;
  int shards = 1;

  /// Throws std::invalid_argument naming the first bad field, its value and the rule.
  void Validate() const;
};

/// The continuations of a diagram (up and down sweeps over every value of the second
/// parameter): the independent units of its work, hence of its shards.
int BifurcationContinuations(const BifurcationOptions& options);

/// The parts of the whole study (BifurcationDiagram::total_parts): per value of the second
/// parameter, its up sweep, down sweep and analytic orbits, those asked for.
int BifurcationParts(const BifurcationOptions& options);

enum class SweepDirection { kUp, kDown, kAnalytic };
/// "up", "down", "analytic".
const char* SweepDirectionName(SweepDirection direction);

/// One impact of a recorded motion.
struct ImpactPoint {
  double param = 0.0;
  SweepDirection direction = SweepDirection::kUp;
  int period_index = 0;   ///< forcing period of the record it happened in (0 = first)
  bool right = true;      ///< right wall (else left)
  double phase = 0.0;     ///< forcing phase psi at the impact, in [0, tau)
  double velocity = 0.0;  ///< relative velocity just before it
  double over = kNaN;     ///< second parameter (NaN: none)
  int part = 0;           ///< the part it belongs to (BifurcationDiagram::parts)
};

/// The long-run motion at one parameter value (or an analytic orbit).
struct BifurcationPoint {
  double param = kNaN;
  SweepDirection direction = SweepDirection::kUp;
  Motion motion;  ///< analytic rows: period 1, one right impact, the orbit's mean velocity
  /// Largest multiplier (by modulus) of the periodic motion: Newton shooting from the recorded
  /// state for sweeps, the impact map for analytic orbits; NaN when not found.
  double multiplier_re = kNaN;
  double multiplier_im = kNaN;
  double spectral_radius = kNaN;  ///< its modulus
  double over = kNaN;             ///< value of the second parameter (NaN: none)
  int part = 0;                   ///< the part it belongs to (BifurcationDiagram::parts)
};

struct BifurcationDiagram {
  /// Every recorded impact, up sweep then down: those of the record, or of one period p for a
  /// periodic motion found by the early stop (the others would repeat them).
  std::vector<ImpactPoint> impacts;
  std::vector<BifurcationPoint> summary;  ///< per value: up sweep, down sweep, analytic orbits
  /// The parts computed, in order: per value of the second parameter, its up sweep, down
  /// sweep and analytic orbits (those asked for), numbered 0 .. total_parts - 1 over the whole
  /// study; a shard holds some of them. Rows come part after part.
  std::vector<int> parts;
  int total_parts = 0;
};

/// The diagram for the robot (forcing, params, alpha) with options.param stepped (one per
/// value of options.over; the parts of shard options.shard only), its parts computed by
/// `backend` (this process's threads by default; the same rows). Throws
/// std::invalid_argument for bad inputs (a value of the range that makes the robot invalid
/// names the parameter and the value).
/// `progress` (optional) is told the parameter values simulated so far (up and down sweeps
/// together) of their total, in increasing order.
BifurcationDiagram ComputeBifurcation(const RobotModel& robot, const BifurcationOptions& options,
                                      const StartsProgress& progress = {},
                                      const BlockBackend& backend = LocalBlocks());

/// Throws what ComputeBifurcation throws for bad inputs, without computing anything (a writer
/// checks its inputs before it opens a file).
void ValidateBifurcation(const RobotModel& robot, const BifurcationOptions& options);

/// Receives one part of a diagram: its rows, parts = {its id}, total_parts.
using BifurcationPartSink = std::function<void(const BifurcationDiagram& part)>;

/// The parts of ComputeBifurcation from the `first`-th part of the shard on (0 <= first <= its
/// parts; the parts before are not computed: a resumed shard), computed by `backend` (one
/// part a block: this process's threads by default, or the ranks of an MPI job as well) and
/// each handed to `sink` as soon as it and those before it are done, in order, on the
/// calling thread; the rows do not depend on `first`, the backend or the threads.
/// `progress` counts the values of these parts (those of a part computed by another process
/// when it arrives). Throws std::invalid_argument for bad inputs before any call of `sink`;
/// what `sink` throws stops the run (no further call) and is rethrown once the parts being
/// computed end.
void StreamBifurcation(const RobotModel& robot, const BifurcationOptions& options, int first,
                       const BifurcationPartSink& sink, const StartsProgress& progress = {},
                       const BlockBackend& backend = LocalBlocks());

/// The computers of StreamBifurcation's blocks (blocks.hpp): unit k is the k-th part of the
/// shard, its bytes the values of its ImpactPoint and BifurcationPoint rows (processes of one
/// machine type exchange them). The arguments must outlive the computers; the study is
/// planned (and checked) by each computer. A distributed backend's workers compute with these.
BlockComputeFactory BifurcationBlocks(const RobotModel& robot, const BifurcationOptions& options);

}  // namespace capsubot
