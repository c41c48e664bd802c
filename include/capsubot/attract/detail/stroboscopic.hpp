#pragma once
// The stroboscopic map of docs/model.md section 13 on top of the simulator: advance a state by
// a number of forcing periods, record what happens, place a section away from every event and
// read a period off the recorded section states. Shared by the long-run classification, the
// Newton shooting and the bifurcation diagram.

#include <cstdint>
#include <vector>

#include "capsubot/attract/attractors.hpp"
#include "capsubot/attract/periodic.hpp"
#include "capsubot/simulate/simulator.hpp"

namespace capsubot::detail {

/// A state of the stroboscopic map with its mode (the mode follows from the state except on a
/// switch; it is kept to compare states).
struct MapState {
  PhaseState z;
  SimMode mode = SimMode::kRest;
};

/// Records a run: the state at every whole period (samples[k] at phase k tau, k = 0..periods),
/// the impacts per period, and the phases (mod tau) of every event. Buffers are reused: after
/// the first runs of a given length nothing is allocated.
class Recorder : public SimObserver {
 public:
  /// Clears the record for a run of `periods` whole periods; `samples`, `events` and `impacts`
  /// say what to keep (per-period impact counts are always kept).
  void Start(int periods, bool samples, bool events, bool impacts = false, double psi0 = 0.0,
             double origin = 0.0);
  void OnEvent(const SimEvent& event) override;
  void OnSample(const SimState& state) override;

  std::vector<SimState> samples;          ///< state at phase k tau, k = 0..periods
  std::vector<std::int32_t> right, left;  ///< impacts in period k, k = 0..periods-1
  std::vector<double> event_phases;       ///< phase mod tau of every event (at most kMaxEvents)
  /// The kind of every event of event_phases and the mode after it, in the order of the run.
  struct Mark {
    EventKind kind;
    SimMode mode;
    bool operator==(const Mark& o) const { return kind == o.kind && mode == o.mode; }
  };
  std::vector<Mark> event_marks;
  /// An impact: phase since the start of the run, wall, velocity before it, period index.
  struct Impact {
    double phase;
    bool right;
    double u_before;
    int period;
  };
  std::vector<Impact> impacts;  ///< every impact (when kept)
  /// Forcing phase (mod tau) at the start of period 0 of the record: impact phases are
  /// measured from it.
  double psi0 = 0.0;
  /// Phase since the start of the simulation at which period 0 of the record starts; events
  /// before it are not recorded.
  double origin = 0.0;
  static constexpr std::size_t kMaxEvents = 4096;

 private:
  int periods_ = 0;
  bool keep_samples_ = false, keep_events_ = false, keep_impacts_ = false;
};

/// The simulator's options for a run from state z (its forcing phase aside) with the settings
/// of `options`.
SimOptions RunOptions(const MotionOptions& options, double alpha, const PhaseState& z);

/// The shooting's options with the simulator settings of `options` (periodic.cpp).
ShootingOptions ShootingOf(const MotionOptions& options);

/// Simulates `periods` (> 0, any real) forcing periods from s, updates s (state, phase, mode)
/// and adds the capsule displacement to *displacement (if given). The observer gets phases
/// measured from s.z.psi; with `sample` the samples are at whole periods.
SimResult Advance(const RobotModel& robot, const MotionOptions& options, MapState& s,
                  double periods, double* displacement, SimObserver* observer = nullptr,
                  bool sample = false);

/// The phase shift in [0, tau) to the middle of the largest gap between the event phases
/// (mod tau) of `phases` (sorted in place); 0 when there is no event.
double SectionShift(std::vector<double>& phases);

/// True when every phase of `phases` (mod tau) is farther than `clearance` from phase 0.
bool SectionClear(const std::vector<double>& phases, double clearance);

/// Same state of the map: same mode and |dx|, |du|, |dv| <= tol.
bool SameState(const SimState& a, const SimState& b, double tol);

/// Smallest p in 1..max_period such that the last p samples each equal the one p before
/// (SameState with tol); 0 if none (or fewer than 2p + 1 samples).
int DetectPeriod(const std::vector<SimState>& samples, int max_period, double tol);

/// The motion from s (the whole of LongRunMotion after validation), reusing `recorder`. With
/// `keep_impacts`, the recorder holds the impacts of the record afterwards (phases from the
/// section's phase); it holds none when the early stop skipped the record.
Motion ClassifyMotion(const RobotModel& robot, const MotionOptions& options, MapState s,
                      Recorder& recorder, bool keep_impacts = false);

/// The periodic motion of period p (or a divisor of it) through the state s (periodic.cpp):
/// the section is moved off the events of the next p periods from s, then Newton's method on
/// the p-th iterate with the simulator settings of `options`; the period is the smallest
/// divisor of p whose iterate returns to the fixed point. The reported state lies at that
/// section. *moved receives s at that section (the start of the Newton iteration).
PeriodicMotion RefinePeriodicMotion(const RobotModel& robot, const MotionOptions& options,
                                    MapState s, int p, MapState* moved);

}  // namespace capsubot::detail
