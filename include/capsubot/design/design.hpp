#pragma once
// Designing a real robot in SI units (docs/model.md sections 2, 9, 11 and 12): given the shell,
// the gap, the floor and the motor, find the inner mass m2 (and the motor frequency, when a
// range is given) of the fastest robust one-impact gait, with its speed, power and cost of
// transport.
//
// Mapping to the model: omega = 2 pi f, T0 = mu g/(omega^2 L), a motor force F_N [N] becomes
// F = F_N/((m1+m2) omega^2 L), alpha = m2/(m1+m2). A robot (m2, f) has the one-impact orbits
// of robot_orbits.hpp (the roots of alpha(phi0) = alpha); its gait is the fastest of them that
// is valid with the clearance margins and whose largest multiplier is at most rho_max.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "capsubot/model/energy.hpp"
#include "capsubot/model/forcing.hpp"
#include "capsubot/model/params.hpp"
#include "capsubot/model/robot_model.hpp"
#include "capsubot/numerics/not_computed.hpp"
#include "capsubot/optimize/optimize_options.hpp"
#include "capsubot/orbit/stability.hpp"
#include "capsubot/orbit/validity.hpp"

namespace capsubot {

/// Default work bound of the orbit search of one robot in a design (DesignInput::
/// orbit_evaluations): 32 times what the robots of the examples need. A robot whose friction
/// bound dwarfs its motor force (T0 = mu g/(omega^2 L) a million times max |F|: a huge mu or
/// g) leaves the search's rounding allowance, which grows with T0, wider than its orbits, and
/// its search would refine the whole circle to the bound.
inline constexpr std::int64_t kDesignOrbitEvaluations = 32768;

/// A design stops once this many robots' orbit searches have hit their work bound: the rest of
/// its ranges is not evaluated (DesignResult::complete false, the fastest gait met is kept).
inline constexpr int kDesignMaxUnresolvedRobots = 8;

/// The motor force in newtons, as a function of the motor phase s = omega t + const:
/// F_N(s) = bias + amplitude sin(s), or with Fourier coefficients
/// F_N(s) = bias + sum_k (cos[k-1] cos(k s) + sin[k-1] sin(k s)). The phase at the impact is
/// not an input: each orbit of the robot has its own.
struct MotorForce {
  double amplitude = kNaN;  ///< amplitude [N] of the harmonic force, >= 0 (unused with Fourier)
  double bias = kNaN;       ///< mean force [N], >= 0 (a one-impact gait needs > 0)
  std::vector<double> cos;  ///< Fourier cosine coefficients [N]; with `sin`, replaces amplitude
  std::vector<double> sin;  ///< Fourier sine coefficients [N], as many as `cos` (or cos empty)

  bool fourier() const { return !sin.empty() || !cos.empty(); }
  /// Throws std::invalid_argument naming the bad field, its value and the rule.
  void Validate() const;
};

/// A physical robot and what may be chosen: SI units throughout.
struct DesignInput {
  /// Shell mass [kg], > 0; with the default inner-mass range, small enough that 10 m1 is finite.
  double m1 = kNaN;
  double L = kNaN;   ///< free gap of the inner body between the walls [m], > 0
  double mu = kNaN;  ///< Coulomb friction coefficient of the shell on the floor, > 0
  double g = 9.81;   ///< gravity [m/s^2], > 0
  double e = kNaN;   ///< coefficient of restitution of the impacts, 0 <= e <= 1
  MotorForce force;  ///< the motor force [N]
  /// Motor frequency range [Hz], 0 < min <= max; min == max fixes the frequency.
  double frequency_min = kNaN;
  double frequency_max = kNaN;  ///< see frequency_min
  /// Inner mass range [kg], 0 < min < max; NaN means the default 0.01 m1 (min), 10 m1 (max).
  double m2_min = kNaN;
  double m2_max = kNaN;  ///< see m2_min

  // Robust gaits (docs/model.md section 12): what a gait must keep; by default the robust gait
  // of the optimiser.
  double margin = 0.0;  ///< clearance d from both walls [units of L], 0 <= d < 0.5
  /// Clearance d_s [units of the stroke x_max - x_min], >= 0.
  double margin_stroke = kRobustMarginStroke;
  double stick_margin =
      kRobustStickMargin;  ///< stick margin s: |F| <= (1-s) T0 at rest, 0 <= s < 1
  /// Largest admissible modulus of a multiplier (docs/model.md section 8), > 0; infinity means
  /// no stability requirement.
  double rho_max = kRobustRhoMax;

  /// Samples of each variable's scan (log-spaced) before the bracketing of windows, >= 3.
  int scan_points = 64;
  /// Work bound of each robot's orbit search (FindRobotOrbits' max_evaluations),
  /// 1 <= orbit_evaluations <= kMaxOrbitEvaluations. It sets the cost of a design, not its
  /// answer, except where a search hits it (Gait::complete false).
  std::int64_t orbit_evaluations = kDesignOrbitEvaluations;

  /// m2_min and m2_max with their defaults applied.
  double M2Min() const;
  double M2Max() const;  ///< see M2Min
  /// Throws std::invalid_argument naming the bad parameter, its value and the rule.
  void Validate() const;
};

/// The dimensionless model of one robot (docs/model.md sections 2 and 9).
struct DesignModel {
  /// The robot: F in units of (m1+m2) omega^2 L, phi0 = 0 (the orbits choose theirs); T0, e;
  /// alpha = m2/(m1+m2).
  RobotModel robot;
  Margins margins;      ///< the margins d, d_s, s its gaits must keep
  double omega = kNaN;  ///< 2 pi f [rad/s]
};

/// Maps the robot with inner mass m2 [kg] at motor frequency f [Hz] to the model. Validates
/// nothing (call DesignInput::Validate first).
DesignModel MapToModel(const DesignInput& input, double m2, double frequency);

/// Why a robot has no gait, or that it has one.
enum class GaitStatus {
  kNotRun,            ///< not computed
  kOk,                ///< a robust one-impact gait exists
  kMotorSlidesShell,  ///< max |F_N| >= mu (m1+m2) g: the motor alone slides the shell, so no
                      ///< one-impact gait (the capsule never rests between impacts)
  kNoOrbit,           ///< the robot has no one-impact orbit (alpha(phi0) = alpha has no root)
  kNotRobust,         ///< orbits exist, none valid with the margins and stable with rho_max
};

/// Stable identifier of a status ("ok", "motor_slides_shell", "no_orbit", "not_robust").
const char* GaitStatusName(GaitStatus status);

/// A gait in the user's units, with the dimensionless orbit it comes from.
struct Gait {
  GaitStatus status = GaitStatus::kNotRun;
  double m2_kg = kNaN;         ///< inner mass [kg]
  double frequency_hz = kNaN;  ///< motor frequency [Hz]
  // Below: NaN unless status == kOk.
  double speed_mm_s = kNaN;           ///< mean speed of the shell [mm/s]
  double displacement_mm = kNaN;      ///< displacement per period L I [mm]
  double impact_velocity_m_s = kNaN;  ///< relative velocity at the impact omega L u [m/s]
  double energy_mj = kNaN;            ///< motor work per period [mJ]
  double power_mw = kNaN;             ///< mean motor power [mW]
  double power_positive_mw = kNaN;    ///< mean power of a drive that cannot recover energy [mW]
  double friction_loss_mj = kNaN;     ///< friction loss per period [mJ]
  double impact_loss_mj = kNaN;       ///< impact loss per period [mJ]
  double cot = kNaN;                  ///< cost of transport W/((m1+m2) g |displacement|), >= mu
  double efficiency = kNaN;           ///< mu/COT = friction loss / motor work, in (0, 1]
  /// The robot's orbits (valid or not, robust or not) found for this m2 and frequency.
  int orbits = 0;
  /// False when the orbit search hit its work bound: orbits may be missing.
  bool complete = true;

  DesignModel model;    ///< the dimensionless robot (T0, A, c, alpha, omega)
  Solution solution;    ///< the gait's orbit (phi0, phi1, u, I, x_min, ...) and validity
  Stability stability;  ///< its multipliers
  Energy energy;        ///< its energy budget, dimensionless (docs/model.md section 11)
  /// Robustness limits the gait sits on (slack below the search's resolution), in a fixed
  /// order: left_wall, right_wall, stick, force_bound, stability (constraint_names of
  /// optimize_result.hpp) and the ends of a searched range: m2_min, m2_max, frequency_min,
  /// frequency_max. Filled by Design and DesignGait.
  std::vector<std::string> binding;

  bool ok() const { return status == GaitStatus::kOk; }
};

/// The robust gait of the robot with inner mass m2 [kg] at frequency f [Hz]: its fastest
/// one-impact orbit that is valid with the margins and has spectral radius <= rho_max. The
/// input must be valid (throws std::invalid_argument otherwise). Deterministic; ~1 ms.
Gait EvaluateGait(const DesignInput& input, double m2, double frequency);

/// Outcome of a design search.
enum class DesignStatus {
  kNotRun,            ///< not computed
  kOk,                ///< the fastest robust one-impact gait was found
  kMotorSlidesShell,  ///< the motor slides the shell by itself for every m2 in the range
  kNoGait,            ///< no robust one-impact gait for any m2 (and frequency) of the ranges
};

/// Stable identifier of a status ("ok", "motor_slides_shell", "no_gait").
const char* DesignStatusName(DesignStatus status);

struct DesignResult {
  DesignStatus status = DesignStatus::kNotRun;
  std::string message;  ///< one readable sentence: what was found, or why nothing was
  /// (a) The fastest robust one-impact gait over the ranges (status kOk), else the reason
  /// of its absence in `status` with the other fields NaN.
  Gait one_impact;
  std::int64_t robots = 0;  ///< robots (m2, f) evaluated
  bool complete = true;     ///< false if an orbit search hit its work bound somewhere
  /// Robots whose orbit search hit its work bound (DesignInput::orbit_evaluations); at
  /// kDesignMaxUnresolvedRobots the design stops there and says so in `message`.
  std::int64_t unresolved_robots = 0;
};

/// Reports the robots evaluated so far (done of total, total an upper bound that the search
/// raises when its windows hold more than one maximum of the speed; the last report, at the
/// end of the search, has total = done); must be cheap.
using DesignProgress = std::function<void(std::int64_t done, std::int64_t total)>;

/// The fastest robust one-impact gait over m2 in [M2Min, M2Max] (and f in the frequency range).
/// The windows of m2 with a gait are bracketed first: a scan of scan_points log-spaced values,
/// then, within a budget of 8 robots per scan sample, the gaps between samples where the
/// robot's orbit count changes (a fold: bisected to 1e-3 in log m2), where the gait appears or
/// disappears (bisected to 1e-6) and beside an infeasible sample whose feasibility measure
/// (the largest over the robot's orbits of the smallest slack of the limits of a robust gait)
/// is a local maximum (golden section on the measure to 1e-6). Then the speed is maximised in
/// each window by golden section from each local maximum of its samples (to 1e-9 relative, at
/// most 100 steps) and the fastest is kept. With a frequency range the same search runs over f,
/// each point an m2 search whose measure is the largest it met (docs/design.md, "How the search
/// works"). Work is bounded by B = 9 scan_points + 100 M robots for a fixed frequency (M the local
/// maxima of the speed among the samples of the windows; one in the examples) and B_f * B_m2 with a
/// range, each of at most orbit_evaluations evaluations, and it stops after
/// kDesignMaxUnresolvedRobots robots whose search hit that bound. Throws std::invalid_argument for
/// invalid input.
DesignResult Design(const DesignInput& input, const DesignProgress& progress = {});

/// The gait the design finds for a robot whose inner mass is m2 [kg], or is searched over the
/// range when m2 is NaN (then Design(input).one_impact): at a fixed frequency the robot's own
/// gait (EvaluateGait), with a frequency range the fastest over it as in Design. The gait's
/// `binding` lists the limits it sits on. Throws std::invalid_argument for invalid input or
/// an m2 that is not NaN and not finite > 0.
Gait DesignGait(const DesignInput& input, double m2);

}  // namespace capsubot
