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

#include "capsubot/forcing.hpp"
#include "capsubot/params.hpp"
#include "capsubot/validity.hpp"

namespace capsubot::detail {

enum ConstraintIndex {
  kLeftWallIndex,    ///< margin - x_min                       (units of L)
  kRightWallIndex,   ///< x_max - (1 - margin); -1 without an interior maximum
  kAlphaLowIndex,    ///< -alpha
  kAlphaHighIndex,   ///< alpha - 1
  kStickIndex,       ///< (max |F| on [phi1, tau] - T0) / T0
  kForceBoundIndex,  ///< (max |F| - force_bound) / T0; holds up to rounding (WithinForceBound)
  kSeparationIndex,  ///< -e u for e > 0; x''(0+) for e = 0
  kStabilityIndex,   ///< spectral radius - rho_max (0 when stability is not required)
  kConstraintCount,
};

/// Value of the orbit constraints where the orbit does not exist.
inline constexpr double kNoOrbitConstraint = 10.0;

/// Name of constraint i (capsubot::constraint_names).
const char* ConstraintName(int index);

/// What the constraints are measured against.
struct ConstraintSetup {
  Params params;  ///< T0, e, margin
  /// Bound on max |F| (P2, P3), held up to rounding (WithinForceBound); infinity for none
  /// (P1: the force is given, and validity's force_below_friction already bounds it by T0).
  double force_bound = std::numeric_limits<double>::infinity();
  bool stable = false;  ///< require spectral radius <= rho_max
  double rho_max = 1.0;
};

/// One evaluated candidate.
struct Evaluation {
  Solution solution;
  double rho = std::numeric_limits<double>::quiet_NaN();  ///< spectral radius (if computed)
  std::array<double, kConstraintCount> g{};               ///< constraint values, <= 0 holds
  bool valid = false;  ///< every condition of section 5 holds (and stability if asked)
  double violation = std::numeric_limits<double>::infinity();  ///< sum of max(g_i, 0)
  /// The force held against the bound: max |F|, or the problem's own measure (P2: A + c).
  double force = std::numeric_limits<double>::quiet_NaN();
  /// I if the orbit exists, else -infinity (so any orbit is better than none).
  double I = -std::numeric_limits<double>::infinity();
};

/// Solves the orbit of `forcing` and evaluates every constraint. `force`, unless NaN, replaces
/// max |F| in the force bound (P2: the linear A + c). Never throws for a force without orbit;
/// params must be valid.
Evaluation Evaluate(const Forcing& forcing, const ConstraintSetup& setup,
                    double force = std::numeric_limits<double>::quiet_NaN());

/// The spectral radius of the evaluated orbit (docs/model.md section 8): ev.rho if it was
/// computed, else computed now; NaN without orbit.
double SpectralRadius(const Evaluation& ev);

/// True if a is the better candidate: valid beats invalid, then larger I among valid ones,
/// smaller violation among invalid ones.
bool Better(const Evaluation& a, const Evaluation& b);

/// Names of the constraints with -tol <= g_i <= tol (and g_i defined), in index order; the
/// force bound only when setup.force_bound is finite.
std::vector<std::string> ActiveConstraints(const Evaluation& ev, const ConstraintSetup& setup,
                                           double tol);

/// Why an evaluated point is not valid: "left_wall (x_min = -0.31)", ... (empty if valid).
std::string DescribeViolations(const Evaluation& ev, const ConstraintSetup& setup);

}  // namespace capsubot::detail
