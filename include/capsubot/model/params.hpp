#pragma once
// The dimensionless parameters of the model besides the force (docs/model.md section 2), with
// the design margins of a robust gait (docs/model.md section 12).

namespace capsubot {

struct Params {
  double T0 = 1.0;      ///< friction bound mu*g/(omega^2*L), dimensionless; T0 > 0
  double e = 1.0;       ///< coefficient of restitution of the impacts; 0 <= e <= 1
  double margin = 0.0;  ///< clearance d required between inner body and walls; 0 <= d < 0.5
  /// Clearance relative to the stroke d_s: the clearance from both walls is at least
  /// d_s * (x_max - x_min), x's range over the period; 0 <= d_s < 0.5.
  double margin_stroke = 0.0;
  /// Stick margin s: while the capsule rests, |F| <= (1 - s) T0; 0 <= s < 1.
  double stick_margin = 0.0;

  /// Throws std::invalid_argument naming the first bad field, its value and the rule.
  void Validate() const;
};

}  // namespace capsubot
