#pragma once
// The parameters a study varies: one vocabulary for every job that steps or grids a value
// (sweep grids, bifurcation diagrams, continuation). The robot's own parameters (the force,
// T0, e and the mass ratio alpha: docs/model.md sections 2, 6 and 8) change its motion; the
// requirements a gait must meet (the margins d, d_s, s, the force bound and rho_max: sections
// 7, 8 and 12) change only which motions count. Every parameter is one row of one table (its
// name and its domain); SetParameter is the one place that sets a robot parameter on a robot.

#include <string>

#include "capsubot/model/forcing.hpp"
#include "capsubot/model/robot_model.hpp"

namespace capsubot {

/// A parameter a study can vary (docs/model.md sections 2, 6, 7, 8 and 12 for the symbols).
/// kCos and kSin are the Fourier coefficients a_k and b_k of the force
/// F = c + sum_k (a_k cos k(phi+phi0) + b_k sin k(phi+phi0)) (forcing.hpp), with k given beside
/// them (the harmonic); the paper's family has a_1 = 0, b_1 = A.
enum class ModelParameter {
  kA,             ///< amplitude A of F = A sin(phi + phi0) + c (the sine coefficient b_1)
  kMean,          ///< mean force c
  kPhi0,          ///< motor phase at the impact phi0 [rad]
  kT0,            ///< friction bound T0
  kRestitution,   ///< restitution e
  kMargin,        ///< requirement: clearance d
  kAlpha,         ///< mass ratio alpha of the robot
  kCos,           ///< cosine coefficient a_k of the Fourier force
  kSin,           ///< sine coefficient b_k of the Fourier force
  kBound,         ///< requirement: force bound of problems P2 and P3, max |F| <= bound
  kRhoMax,        ///< requirement: largest admissible spectral radius (stability)
  kMarginStroke,  ///< requirement: clearance relative to the stroke d_s
  kStickMargin,   ///< requirement: stick margin s
};

/// Where a parameter's values may lie: [min, max], open ends excluded, and the rule a message
/// states ("" when every finite value is admissible); `infinite`: +infinity is a value too
/// (written `inf` in a list: a bound that is no bound, as rho_max = inf).
struct ParameterDomain {
  double min = 0.0;
  bool min_open = false;
  double max = 0.0;
  bool max_open = false;
  const char* rule = "";
  bool infinite = false;
};

/// The parameter's name ("A", "phi0", "rho_max", "a2"); `harmonic` is k for kCos and kSin
/// ("a" and "b" alone when it is 0).
std::string ModelParameterName(ModelParameter parameter, int harmonic = 0);

/// Every name, for messages: "A, c, phi0, T0, e, margin, alpha, a1..a16, b1..b16, ...".
std::string ModelParameterNames();

/// The parameter called `name` (ModelParameterName; a_k and b_k with 1 <= k <= kMaxHarmonics
/// written without a leading zero) into `parameter` and `harmonic` (k, else 0); false when no
/// parameter has that name (both left unchanged).
bool ParseModelParameter(const std::string& name, ModelParameter& parameter, int& harmonic);

/// The domain of the parameter's values (A >= 0, T0 > 0, 0 <= e <= 1, ...).
const ParameterDomain& ModelParameterDomain(ModelParameter parameter);

/// True for kCos and kSin, the parameters indexed by a harmonic k.
bool IsFourierCoefficient(ModelParameter parameter);

/// True for the parameters of the robot itself, which change its motion and which
/// SetParameter sets: A, c, alpha, T0, e, phi0, a_k, b_k.
bool IsRobotParameter(ModelParameter parameter);

/// The robot parameter called `name` into `harmonic` (if given; k of a_k and b_k, else 0).
/// Throws std::invalid_argument "parameter = <name> is invalid: expected one of A, c, alpha,
/// T0, e, phi0, or a Fourier coefficient a1..a16, b1..b16".
ModelParameter ParseRobotParameter(const std::string& name, int* harmonic = nullptr);

/// Throws std::invalid_argument unless `parameter` (with `harmonic`) is a robot parameter that can
/// be set on `forcing`: not A, a_k, b_k on a pulse force ("parameter = A is invalid for a pulse
/// force: ..."); A needs the harmonic family ("parameter = A is invalid for a Fourier force: ..."),
/// a_k and b_k a force with k harmonics ("parameter = a3 is invalid for this force: expected a_k
/// or b_k with 1 <= k <= K = 1, its harmonics").
void CheckRobotParameter(const Forcing& forcing, ModelParameter parameter, int harmonic = 0);

/// The value of robot parameter `parameter` (with `harmonic` k for a_k and b_k) of `robot`: A
/// is the amplitude of the first harmonic, phi0 the force's phase as kept (the inverse of
/// SetParameter). Checks CheckRobotParameter first.
double ParameterValue(const RobotModel& robot, ModelParameter parameter, int harmonic = 0);

/// Sets robot parameter `parameter` (with `harmonic` k for a_k and b_k) of `robot` to `value`,
/// the others kept: A makes the force A sin(phi + phi0) + c with its c and phi0 (Harmonic); c,
/// a_k, b_k rebuild the series with that coefficient (phi0 reduced, as Fourier does); phi0
/// moves the impact (WithPhase: phi0 kept as given); T0, e, alpha set the field. Checks
/// CheckRobotParameter first; throws std::invalid_argument for a value the force refuses (A < 0,
/// a coefficient or phase that is not finite). Allocates nothing.
void SetParameter(RobotModel& robot, ModelParameter parameter, int harmonic, double value);

}  // namespace capsubot
