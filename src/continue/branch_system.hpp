#pragma once
// The extended system of the continuation (docs/continuation.md): the fixed-point equation
// P^p(z; lambda) - z = 0 in the free coordinates of a section, its Jacobian [P_z - I, P_lambda]
// by central differences, the corrector with one linear condition a . y = b, the tangent, and
// everything a branch point carries (multipliers, impacts, mean velocity, events, test
// functions).

#include <Eigen/Dense>
#include <array>
#include <complex>
#include <cstdint>
#include <vector>

#include "capsubot/attract/detail/period_map.hpp"
#include "capsubot/attract/detail/stroboscopic.hpp"
#include "capsubot/continue/continuation.hpp"
#include "continue/linear_condition.hpp"

namespace capsubot::detail {

using Vec4 = std::array<double, 4>;  // (x, u, v, lambda); fixed coordinates carry their value

/// The section of a branch: forcing phase, mode there and the free coordinates it leaves.
struct Section {
  double psi = 0.0;
  SimMode mode = SimMode::kRest;
  std::vector<int> free;  ///< indices into (x, u, v)
};

/// Whether an event of `phases` (mod tau) lies closer to the section (phase 0) than a quarter
/// of half the largest gap between them: then the section is moved to the middle of that gap.
bool EventNearSection(std::vector<double> phases);

/// A converged point of the branch with everything derived from it.
struct Node {
  Vec4 y{};                           ///< the point
  Vec4 t{};                           ///< unit tangent (0 in the fixed coordinates)
  double s = 0.0;                     ///< arclength from the start along its direction
  int iterations = 0;                 ///< corrector iterations that found it
  Eigen::MatrixXd J;                  ///< [P_z, P_lambda], d x (d + 1)
  Eigen::VectorXd grad;               ///< gradient of the displacement over p periods, d + 1
  PeriodicMotion motion;              ///< state, impacts, mean velocity, multipliers
  std::vector<Recorder::Mark> marks;  ///< events over p periods from the section, in order
  std::vector<double> event_phases;   ///< their phases (mod tau)
  double period_doubling = 0.0;       ///< det(P_z + I)
  double neimark_sacker = 0.0;        ///< prod over pairs (mu_i mu_j - 1) (1 when d < 2)
  double speed = 0.0;                 ///< d mean velocity / ds
  /// P^(p/2)(z) - z in (x, u, v) for an even period p (else 0): it passes through 0 where the
  /// branch meets the motion of half its period (the period doubling it is born at).
  Vec4 half{};
};

/// Same impacts per period and the same order of events.
inline bool SameEvents(const Node& a, const Node& b) {
  return a.motion.impacts_right == b.motion.impacts_right &&
         a.motion.impacts_left == b.motion.impacts_left && a.marks == b.marks;
}

/// One linear condition a . y = b that closes the extended system: the arclength condition
/// t_i . (y - y_i) = sigma, or the parameter fixed (Condition::Fixed(3, lambda)).
using Condition = LinearCondition<4>;

/// The Neimark-Sacker test function of multipliers mu: the product over pairs of
/// Re(mu_i mu_j - 1) (1 for fewer than two). It changes sign where a complex pair crosses the
/// unit circle (|mu|^2 = 1), and also where a real pair's product crosses 1.
double NeimarkSackerFunction(const std::vector<std::complex<double>>& mu);

/// What the search for special points (special_points.hpp) asks of the system of a branch:
/// the corrector, completed and measured points, a motion shot anew. BranchSystem is the
/// capsule's period map; any smooth map with a parameter can stand in for it.
class SmoothSystem {
 public:
  virtual ~SmoothSystem() = default;

  enum class Outcome { kConverged, kFailed, kOutOfRange };
  /// Newton's method on the extended system closed by `condition`, from y (updated), starting
  /// with the Jacobian J of a nearby point (recomputed when the residual falls slowly, unless
  /// `keep_jacobian`: then J alone, for a few iterations). kOutOfRange when an iterate leaves
  /// the parameter's range (y is that iterate); kFailed when it does not converge or leaves the
  /// map's domain.
  virtual Outcome Correct(const Condition& condition, Eigen::MatrixXd J, Vec4& y, int* iterations,
                          bool keep_jacobian) = 0;
  Outcome Correct(const Condition& condition, Eigen::MatrixXd J, Vec4& y, int* iterations) {
    return Correct(condition, std::move(J), y, iterations, false);
  }

  /// d mean velocity / ds at the node with the finite-difference step times `step_factor`: a
  /// sign that changes with the step is an artefact of the differences. A map whose Jacobian
  /// is exact returns the node's.
  virtual double SpeedWithStep(const Node& node, double step_factor) {
    (void)step_factor;
    return node.speed;
  }

  /// Completes a corrected point: Jacobian, tangent oriented along `orient`, multipliers,
  /// impacts, mean velocity, events and test functions. False at the work bound.
  virtual bool Complete(const Vec4& y, const Vec4& orient, Node* node) = 0;

  /// Impacts, mean velocity and events of the motion through y (into node->motion, marks and
  /// event_phases). False at the work bound.
  virtual bool Measure(const Vec4& y, Node* node) = 0;

  /// The motion through `state` at `lambda`, shot anew (Newton from `state`) with the
  /// Jacobians' finite-difference step times `step_factor`: its multipliers tell a bifurcation
  /// from an artefact of the differences.
  virtual PeriodicMotion Reshoot(double lambda, const PhaseState& state,
                                 double step_factor) const = 0;
};

class BranchSystem : public SmoothSystem {
 public:
  BranchSystem(const RobotFamily& family, const ContinuationOptions& options, int period,
               Section section);

  const Section& section() const { return section_; }
  int period() const { return p_; }
  int dimension() const { return static_cast<int>(section_.free.size()); }
  const MotionOptions& motion() const { return motion_; }
  RobotModel Robot(double lambda) const { return family_(lambda); }
  /// The state of the point y at the section.
  PhaseState State(const Vec4& y) const { return {y[0], y[1], y[2], section_.psi}; }

  /// The corrector (SmoothSystem::Correct). kOutOfRange when an iterate leaves [from, to] in the
  /// parameter (the robots there may not exist); kFailed when it does not converge within the
  /// options' iterations, leaves [0, 1] in x, changes the mode at the section or hits the work
  /// bound; `keep_jacobian`: J alone, for up to kChordIterations iterations.
  using SmoothSystem::Correct;
  Outcome Correct(const Condition& condition, Eigen::MatrixXd J, Vec4& y, int* iterations,
                  bool keep_jacobian) override;

  bool Complete(const Vec4& y, const Vec4& orient, Node* node) override;

  bool Measure(const Vec4& y, Node* node) override;

  /// Moves the section of `node` to the middle of the largest gap between its events when an
  /// event lies closer to the section than a quarter of half that gap: the node is recomputed
  /// at the new section, its tangent carried along by the flow. True when the node is usable
  /// (moved or not).
  bool Replace(Node* node);

  /// The motion of period p through `state` of the robot at `lambda`, shot anew with the
  /// options' finite-difference step times `step_factor` (SmoothSystem::Reshoot).
  PeriodicMotion Reshoot(double lambda, const PhaseState& state, double step_factor) const override;

  /// d mean velocity / ds at the node, from the Jacobian with the finite-difference step of the
  /// options times `step_factor` (the tangent oriented along the node's): a sign that changes
  /// with the step is an artefact of the differences. NaN at the work bound.
  double SpeedWithStep(const Node& node, double step_factor) override;

 private:
  // P^p at y; displacement over the p periods into *displacement (if given).
  bool Image(const Vec4& y, MapState* out, double* displacement = nullptr);
  // P^p at y with its events.
  bool Run(const Vec4& y, MapRun* run);
  bool Jacobian(const Vec4& y, Eigen::MatrixXd* J, Eigen::VectorXd* grad, double step_factor = 1.0);
  double LambdaStep(double lambda) const;
  // The unit tangent of J (null vector of [P_z - I, P_lambda]) oriented along `orient`, in
  // (x, u, v, lambda); false when it is not defined.
  bool Tangent(const Eigen::MatrixXd& J, const Vec4& orient, Vec4* t) const;
  // d mean velocity / ds: the displacement's gradient along the tangent over p periods.
  double Speed(const Eigen::VectorXd& grad, const Vec4& t) const;

  const RobotFamily& family_;
  const ContinuationOptions& options_;
  MotionOptions motion_;
  int p_;
  Section section_;
  Recorder recorder_;
};

}  // namespace capsubot::detail
