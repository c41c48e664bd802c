// The fastest Fourier drive from rest, one harmonic at a time (docs/reach.md, "Drives").

#include "capsubot/reach/drive_ladder.hpp"

#include <cmath>
#include <stdexcept>

namespace capsubot {

DriveLadder ClimbDriveLadder(const Params& params, const OptimizeResult& seed,
                             const ReachResult& sine, const ReachOptions& options) {
  options.Validate();
  if (options.drive.waveform != Waveform::kFourier) {
    throw std::invalid_argument(
        "drive = sine is invalid for a ladder: expected a Fourier family (harmonics >= 1)");
  }
  DriveLadder ladder;
  ladder.steps.push_back(sine);
  ReachOptions step = options;
  for (int k = 2; k <= options.drive.harmonics; ++k) {
    step.drive = DriveFamily::Fourier(k);
    step.seeds.clear();
    for (const ReachResult& below : ladder.steps) {
      if (!std::isnan(below.mean_velocity)) {
        step.seeds.push_back({below.forcing, below.alpha, below.T0});
      }
    }
    ladder.steps.push_back(OptimizeReach(params, seed, step));
  }
  return ladder;
}

}  // namespace capsubot
