#pragma once
// Progress of long runs: a one-line bar on stderr, only when stderr is a terminal (never on
// standard output, never into a log file).

#include <string>

#include "capsubot/sweep.hpp"

namespace capsubot::app {

/// True when standard error is a terminal (progress is shown only then).
bool StderrIsTerminal();

/// The stage a long run is in ("optimize: 2/5 the fastest robust gait"), one line on stderr
/// redrawn in place when it is a terminal; ShowStage("") clears it before the results.
void ShowStage(const std::string& text);

/// "[#####.....]  42.0%  420/1000 points  1.2k points/s  00:01 elapsed  00:01 left", redrawn
/// in place at most 10 times a second; the last update (done >= total) ends the line.
class ProgressBar {
 public:
  /// `unit` names what is counted ("points", "periods").
  explicit ProgressBar(std::string unit) : unit_(std::move(unit)) {}
  /// `done` of `total` units after `seconds` of this run; `skipped` of the done units were
  /// not computed by this run (taken over from a checkpoint) and do not count in the rate.
  void Update(double done, double total, double seconds, double skipped = 0.0);

 private:
  std::string unit_;
  double drawn_ = -1.0;  // time of the last redraw
};

/// The progress of a grid run (sweep, design --grid) drawn on `bar`: points done of total,
/// the points resumed from a checkpoint left out of the rate; none (empty) when standard
/// error is not a terminal. `bar` must outlive the run.
SweepProgressCallback GridProgress(ProgressBar& bar);

}  // namespace capsubot::app
