#pragma once
// Progress of long runs, on stderr (never on standard output). By default a one-line bar
// redrawn in place, only when stderr is a terminal (never into a log file); --progress asks
// for plain lines instead, also into a file (a Slurm log); --no-progress for none.

#include <CLI/CLI.hpp>
#include <string>

#include "capsubot/sweep/sweep.hpp"

namespace capsubot::cli {

/// Adds --progress and --no-progress to `cmd`; given, they choose how this process shows
/// progress (neither: the bar on a terminal, nothing otherwise).
void AddProgressOptions(CLI::App& cmd);

/// Whether progress is shown: --progress, or stderr is a terminal and no --no-progress.
bool ProgressShown();

/// The stage a long run is in ("optimize: 2/5 the fastest robust gait"), with how far it is
/// (`count`, "12 of at most 60 evaluations", may be empty): one line on stderr redrawn in
/// place on a terminal, ShowStage("") clearing it before the results. With --progress a line
/// of its own with the time elapsed since the start, when the stage changes and at least once
/// in kProgressLineSeconds ("" prints nothing).
void ShowStage(const std::string& text, const std::string& count = "");

/// On a terminal: "[#####.....]  42.0%  420/1000 points  1.2k points/s  00:01 elapsed  00:01
/// left", redrawn in place at most 10 times a second. With --progress: a plain line every
/// kProgressStep percent (and at least once a minute) with the time elapsed and left. The last
/// update (done >= total) ends the line. Nothing when progress is not shown.
class ProgressBar {
 public:
  /// `unit` names what is counted ("points", "periods").
  explicit ProgressBar(std::string unit) : unit_(std::move(unit)) {}
  /// `done` of `total` units after `seconds` of this run; `skipped` of the done units were
  /// not computed by this run (taken over from a checkpoint) and do not count in the rate.
  void Update(double done, double total, double seconds, double skipped = 0.0);

  /// Where a run is: the fraction done, the units done and in all, the time elapsed, the rate
  /// (units per second, resumed units left out) and the time left [s].
  struct Reading {
    double fraction, done, total, seconds, rate, left;
  };

 private:
  void Draw(const Reading& r);  // the bar on a terminal
  void Line(const Reading& r);  // a line of --progress

  std::string unit_;
  double drawn_ = -1.0;  // time of the last redraw or line
  int step_ = 0;         // --progress: the steps of kProgressStep percent printed
  bool ended_ = false;   // --progress: the last line is printed
};

/// --progress prints a line each time the run is this many percent further.
inline constexpr int kProgressStep = 5;
/// ... and at least once in this many seconds.
inline constexpr double kProgressLineSeconds = 60.0;

/// The progress of a grid run (sweep, design --grid) drawn on `bar`: points done of total,
/// the points resumed from a checkpoint left out of the rate; none (empty) when progress is
/// not shown. `bar` must outlive the run.
SweepProgressCallback GridProgress(ProgressBar& bar);

}  // namespace capsubot::cli
