#pragma once
// The CSV files of `capsubot simulate --events, --trajectory` (docs/simulate.md), streamed as
// the run goes: the run is not stored. The command line writes them after its '#' provenance
// line.

#include <ostream>

#include "capsubot/simulate/simulator.hpp"

namespace capsubot::text {

/// An observer of the simulation that writes every event (phase, kind, x, u, v, y: the state
/// right after it, u_before, v_before, mode) to one stream and every sample (phi, x, u, v, y,
/// mode) to another, one CSV row each, numbers as FormatNumber writes them.
class SimulateCsv : public SimObserver {
 public:
  /// Writes the header line of each stream given; a null stream is not written.
  SimulateCsv(std::ostream* events, std::ostream* trajectory);
  void OnEvent(const SimEvent& event) override;
  void OnSample(const SimState& state) override;

 private:
  std::ostream* events_;
  std::ostream* trajectory_;
};

}  // namespace capsubot::text
