#pragma once
// The p-th iterate of the stroboscopic map of one robot as a function of the free coordinates
// at its section (docs/model.md section 13), with its Jacobian by central finite differences,
// its multipliers and the impacts and mean velocity of one period. Shared by the Newton
// shooting (periodic.cpp) and the continuation of periodic motions (src/continue/).

#include <Eigen/Dense>
#include <array>
#include <complex>
#include <functional>
#include <vector>

#include "capsubot/attract/detail/stroboscopic.hpp"
#include "capsubot/attract/periodic.hpp"

namespace capsubot::detail {

using Vec3 = std::array<double, 3>;  // (x, u, v)

inline Vec3 ToVec(const PhaseState& z) { return {z.x, z.u, z.v}; }

/// `base` with (x, u, v) replaced by z (the forcing phase kept).
PhaseState WithCoordinates(PhaseState base, const Vec3& z);

/// max |P^p(z) - z| over x, u, v, relative to the state's scale max(1, |x|, |u|, |v|): a state
/// is resolved only to its own rounding, which grows with it.
double Residual(const Vec3& z, const PhaseState& image);

/// Whether the state z of the robot is finite and within kMaxStateScale times its velocity
/// scale tau (max |F| + T0) / (alpha (1 - alpha)), the most force and friction change the
/// relative velocity in one period (docs/model.md section 3). Beyond it a period's change is
/// lost in the state's rounding, and a residual below any tolerance proves nothing: such a
/// state is no periodic motion the shooting or the continuation may report.
bool WithinScale(const RobotModel& robot, const Vec3& z);
inline constexpr double kMaxStateScale = 1e6;

/// The free coordinates (indices into (x, u, v)) of a section in mode `mode` with capsule
/// velocity v (periodic.hpp): at rest (x, u); sliding (x, u, v); on a wall v (none if v = 0).
std::vector<int> FreeCoordinates(SimMode mode, double v);

/// The simulator's settings of the shooting's runs.
MotionOptions SimulationOf(const ShootingOptions& options);

/// P^p of one robot. Holds references: the robot must outlive it.
class PeriodMap {
 public:
  PeriodMap(const RobotModel& robot, const MotionOptions& motion)
      : robot_(robot), motion_(motion) {}

  /// P^p(z) into *out; adds the capsule displacement to *displacement (if given); the recorder
  /// (if given) sees the run. False if the simulation hit the work bound.
  bool Map(const PhaseState& z, int p, MapState* out, double* displacement = nullptr,
           Recorder* recorder = nullptr) const;

  /// Moves s by `periods` (> 0, any real) forcing periods (the observer, if given, sees the
  /// run, sampled at whole periods with `sample`); false at the work bound.
  bool Shift(MapState& s, double periods, SimObserver* observer = nullptr,
             bool sample = false) const;

  const RobotModel& robot() const { return robot_; }

 private:
  const RobotModel& robot_;
  MotionOptions motion_;
};

/// Column `column` of a central difference: (plus - minus) / (2 h) in the free coordinates into
/// (*J)(., column), and the difference of the displacements into (*gradient)(column) when
/// `gradient` is given.
void DifferenceColumn(const MapState& plus, const MapState& minus, double displacement_plus,
                      double displacement_minus, const std::vector<int>& free, double h, int column,
                      Eigen::MatrixXd* J, Eigen::VectorXd* gradient = nullptr);

/// One run of P^p: its image, displacement and events.
struct MapRun {
  MapState image;
  double displacement = 0.0;
  Recorder recorder;  ///< impacts per period and the order of the events
  /// P^p from z; false at the work bound.
  bool Run(const PeriodMap& map, const PhaseState& z, int p);
  /// Same impacts per period and the same order of events as `o`.
  bool SameEvents(const MapRun& o) const;
};

/// Column `column` of the difference of P^p from the runs at +h and -h: central when both runs
/// have the same events; else (they straddle an impact that appears or a changed stick/slide
/// segment, where the map is not smooth) one-sided on the side whose run keeps the events of
/// the base run (made by `base` only then), or central when neither does.
bool DifferenceAcrossEvents(const MapRun& plus, const MapRun& minus,
                            const std::function<bool(MapRun*)>& base, const std::vector<int>& free,
                            double h, int column, Eigen::MatrixXd* J, Eigen::VectorXd* gradient);

/// The Jacobian of P^p at `at` (x, u, v; forcing phase of `base`) in the free coordinates by
/// central differences of step h (one-sided where they straddle a change of the events,
/// DifferenceAcrossEvents) into the first free.size() columns of *J (resized to at least
/// that), with the gradient of the displacement over p periods into *gradient (if given).
/// False at the work bound.
bool CentralJacobian(const PeriodMap& map, const PhaseState& base, const Vec3& at, int p,
                     const std::vector<int>& free, double h, Eigen::MatrixXd* J,
                     Eigen::VectorXd* gradient = nullptr);

/// The eigenvalues of J, largest modulus first.
std::vector<std::complex<double>> Multipliers(const Eigen::MatrixXd& J);

/// Sets the multipliers of `motion` and what follows from them (spectral radius, distances to
/// +1, -1 and the unit circle; the stability verdict needs a converged motion).
void SetMultipliers(std::vector<std::complex<double>> multipliers, PeriodicMotion* motion);

/// Impacts and mean velocity over one period p of the motion through motion->state (recorded
/// with `recorder`, whose events are then kept); false at the work bound.
bool MeasurePeriod(const PeriodMap& map, int p, Recorder& recorder, PeriodicMotion* motion);

}  // namespace capsubot::detail
