#pragma once
// The extended system of a two-parameter curve of special points (special_curve.hpp,
// docs/continuation.md): P^p(z; lambda, mu) - z = 0 and the defining condition g(y) = 0 in the
// unknowns y = (z, lambda, mu), its Jacobian by finite differences, the corrector with one
// linear condition a . y = b, the tangent and everything a curve point carries.

#include <Eigen/Dense>
#include <array>
#include <vector>

#include "capsubot/continue/special_curve.hpp"
#include "continue/branch_system.hpp"
#include "continue/wall_approach.hpp"

namespace capsubot::detail {

using Vec5 = std::array<double, 5>;  // (x, u, v, lambda, mu); fixed coordinates carry their value

/// A converged point of the curve with everything derived from it.
struct CurveNode {
  Vec5 y{};            ///< the point
  Vec5 t{};            ///< unit tangent (0 in the fixed coordinates)
  double s = 0.0;      ///< arclength from the start along its direction
  int iterations = 0;  ///< corrector iterations that found it
  /// [P_z, P_lambda, P_mu] over [g_z, g_lambda, g_mu]: (d + 1) x (d + 2).
  Eigen::MatrixXd J;
  double condition = 0.0;             ///< g(y)
  PeriodicMotion motion;              ///< state, impacts, mean velocity, multipliers
  std::vector<Recorder::Mark> marks;  ///< events over p periods from the section, in order
  std::vector<double> event_phases;   ///< their phases (mod tau)
};

/// One linear condition a . y = b that closes the extended system: the arclength condition
/// t_i . (y - y_i) = sigma, or one coordinate fixed.
using CurveClosure = LinearCondition<5>;

class CurveSystem {
 public:
  /// `options` must have been validated; `section` is the special point's.
  CurveSystem(const RobotSurface& surface, const CurveOptions& options, SpecialPointType type,
              int period, Section section);

  int dimension() const { return static_cast<int>(section_.free.size()); }

  /// For a grazing: finds the flight of the motion through y that comes nearest to a wall and
  /// keeps it as the one whose extremum the condition follows. False when there is none.
  bool Approach(const Vec5& y);
  const WallApproach& approach() const { return approach_; }

  /// Whether y lies in the box [from, to] x [from2, to2] of the parameters.
  bool InBox(const Vec5& y) const;

  enum class Outcome { kConverged, kFailed, kOutOfRange };
  /// Newton's method on the extended system closed by `closure`, from y (updated), starting
  /// with the Jacobian J of a nearby point (recomputed when the residual falls slowly).
  /// kOutOfRange when an iterate leaves the box [from, to] x [from2, to2]; kFailed when it does
  /// not converge, leaves [0, 1] in x, changes the mode at the section or hits the work bound.
  Outcome Correct(const CurveClosure& closure, Eigen::MatrixXd J, Vec5& y, int* iterations);

  /// Completes a corrected point: Jacobian, tangent (orient . t > 0), multipliers, impacts,
  /// mean velocity and events. False at the work bound.
  bool Complete(const Vec5& y, const Vec5& orient, CurveNode* node);

  /// Moves the section of `node` to the middle of the largest gap between its events when an
  /// event comes closer to it than a quarter of half that gap; the node is recomputed there
  /// with its tangent oriented by its parameter components. For a grazing, the flight nearest
  /// to the wall is looked for again at the node. True when the node is usable.
  bool Replace(CurveNode* node);

 private:
  RobotModel Robot(const Vec5& y) const { return surface_(y[3], y[4]); }
  PhaseState State(const Vec5& y) const { return {y[0], y[1], y[2], section_.psi}; }
  std::size_t Coordinate(int r) const;  // the index into y of unknown r (z's free ones, then 3, 4)
  double Step(int r, const Vec5& y, double base) const;
  int Side(int r, const Vec5& y, double h, const Eigen::RowVectorXd* away) const;
  bool Image(const Vec5& y, MapState* out, double* displacement = nullptr);
  bool MapColumns(const Vec5& y, int columns, const Eigen::RowVectorXd* away, Eigen::MatrixXd* P,
                  Eigen::VectorXd* grad);
  bool ConditionFrom(const Eigen::MatrixXd& P, const Eigen::VectorXd& grad, double* g) const;
  bool Condition(const Vec5& y, double* g);
  bool ConditionRow(const Vec5& y, Eigen::RowVectorXd* row);
  bool Jacobian(const Vec5& y, Eigen::MatrixXd* J, double* g);
  bool PullBack(const Eigen::MatrixXd& J, Vec5& y);

  const RobotSurface& surface_;
  const CurveOptions& options_;
  SpecialPointType type_;
  MotionOptions motion_;
  int p_;
  Section section_;
  WallApproach approach_;  // grazing only
  Recorder recorder_;
};

}  // namespace capsubot::detail
