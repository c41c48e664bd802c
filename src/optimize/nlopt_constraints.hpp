#pragma once
// The constraints of the optimisation problems (docs/model.md sections 5 and 7) as functions
// g_i <= 0, shared by P1, P2 and P3 and handed to NLopt as inequality constraints.
//
// Where the orbit does not exist (no phi1 or no alpha in (0, 1)) the orbit constraints are
// undefined; they then take the large positive value kNoOrbitConstraint, so that every
// optimiser sees such a point as clearly infeasible.

#include <array>
#include <limits>
#include <string>
#include <vector>

#include "capsubot/model/forcing.hpp"
#include "capsubot/model/params.hpp"
#include "capsubot/numerics/not_computed.hpp"
#include "capsubot/optimize/optimize_options.hpp"
#include "capsubot/orbit/validity.hpp"

namespace capsubot::detail {

/// The constraints g_i <= 0. Positions are in units of the length scale min(1, T0): an
/// orbit's size scales with T0 (docs/model.md section 6), so that at a small T0 the
/// constraints stay of order 1 for NLopt. Each row checks one validity condition (section 5,
/// with the margins of section 12) or one requirement of the problem.
enum ConstraintIndex {
  kLeftWallIndex,        ///< -x_min                                (left_wall)
  kRightWallIndex,       ///< x_max - 1; -1 without an interior maximum (right_wall)
  kClearanceLeftIndex,   ///< clearance - x_min                     (clearance)
  kClearanceRightIndex,  ///< x_max - (1 - clearance); -1 without an interior maximum
  kAlphaLowIndex,        ///< -alpha                                (mass_ratio)
  kAlphaHighIndex,       ///< alpha - 1                             (mass_ratio)
  kStickIndex,           ///< (max |F| on [phi1, tau] - (1 - s) T0) / T0   (stick)
  kForceBoundIndex,      ///< (force - force_bound) / T0; held up to rounding (WithinForceBound)
  kSeparationIndex,      ///< -e u / T0 for e > 0; x''(0+) / T0 for e = 0  (separation)
  kRhoMaxIndex,          ///< spectral radius - rho_max             (rho_max)
  kConstraintCount,
};

/// Value of the orbit constraints where the orbit does not exist.
inline constexpr double kNoOrbitConstraint = 10.0;

/// Name of constraint i: the validity condition it checks (ConditionName), kForceBoundName or
/// MarginName(Margin::kRhoMax).
const char* ConstraintName(int index);

/// What the constraints are measured against.
struct ConstraintSetup {
  Params params;  ///< T0, e
  /// Bound on max |F| (P2, P3), held up to rounding (WithinForceBound); infinity for none
  /// (P1: the force is given, and validity's force_below_friction already bounds it by T0).
  double force_bound = std::numeric_limits<double>::infinity();
  /// Largest admissible spectral radius; infinity: no stability requirement.
  double rho_max = std::numeric_limits<double>::infinity();
  /// Relative rounding allowed rho_max when a result found at another T0 is checked after
  /// scaling (docs/model.md section 6): 0 in the search itself.
  double rho_rel_tol = 0.0;
  /// The margins d, d_s, s (last: an aggregate initialised up to rho_rel_tol has none).
  Margins margins{};

  /// Whether row i is part of the problem: the walls without a clearance margin, the
  /// clearance rows with one (they imply the walls), the force bound and rho_max when set.
  bool Applies(int index) const;
  /// The unit of the position constraints: min(1, T0).
  double length() const;
};

/// One evaluated candidate.
struct Evaluation {
  Solution solution;
  double rho = kNaN;                         ///< spectral radius (if computed)
  std::array<double, kConstraintCount> g{};  ///< constraint values, <= 0 holds
  bool valid = false;  ///< every condition of section 5 holds (and stability if asked)
  /// Sum of max(g_i, 0) over the rows that apply
  double violation = std::numeric_limits<double>::infinity();
  /// The force held against the bound: max |F|, or the problem's own measure (P2: A + c).
  double force = kNaN;
  /// I if the orbit exists, else -infinity (so any orbit is better than none).
  double I = -std::numeric_limits<double>::infinity();
};

/// Solves the orbit of `forcing` and evaluates every constraint. `force`, unless NaN, replaces
/// max |F| in the force bound (P2: the linear A + c). Never throws for a force without orbit;
/// params must be valid.
Evaluation Evaluate(const Forcing& forcing, const ConstraintSetup& setup, double force = kNaN);

/// The spectral radius of the evaluated orbit (docs/model.md section 8): ev.rho if it was
/// computed, else computed now; NaN without orbit.
double SpectralRadius(const Evaluation& ev);

/// True if a is the better candidate: valid beats invalid, then larger I among valid ones,
/// smaller violation among invalid ones.
bool Better(const Evaluation& a, const Evaluation& b);

/// Names of the constraints that apply with -tol <= g_i <= tol, in index order, each once.
std::vector<std::string> ActiveConstraints(const Evaluation& ev, const ConstraintSetup& setup,
                                           double tol);

/// The design margins (docs/model.md section 12) among the active constraints: the clearance
/// by the margin that sets it (d or d_s * stroke), the stick margin when s > 0, rho_max.
std::vector<Margin> BindingMargins(const Evaluation& ev, const ConstraintSetup& setup, double tol);

/// The requirements beyond section 5 in words, for messages: "" without any, else e.g.
/// " (margins d = 0, d_s = 0.02, s = 0.02; spectral radius <= 0.9)".
std::string RequirementWords(const ConstraintSetup& setup);

/// Why an evaluated point is not valid: "left_wall (x_min = -0.31)", ... (empty if valid).
std::string DescribeViolations(const Evaluation& ev, const ConstraintSetup& setup);

}  // namespace capsubot::detail
