#pragma once
// The dimensionless parameters of the model besides the force (docs/model.md section 2).

namespace capsubot {

struct Params {
  double T0 = 1.0;      ///< friction bound mu*g/(omega^2*L), dimensionless; T0 > 0
  double e = 1.0;       ///< coefficient of restitution of the impacts; 0 <= e <= 1
  double margin = 0.0;  ///< clearance d required between inner body and walls; 0 <= d < 0.5

  /// Throws std::invalid_argument naming the first bad field, its value and the rule.
  void Validate() const;
};

}  // namespace capsubot
