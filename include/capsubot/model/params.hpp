#pragma once
// The dimensionless parameters of the robot besides the force and the mass ratio
// (docs/model.md section 2). What a gait must keep (the margins) is apart, in
// gait_requirements.hpp.

namespace capsubot {

struct Params {
  double T0 = 1.0;  ///< friction bound mu*g/(omega^2*L), dimensionless; T0 > 0
  double e = 1.0;   ///< coefficient of restitution of the impacts; 0 <= e <= 1

  /// Throws std::invalid_argument naming the first bad field, its value and the rule.
  void Validate() const;
};

}  // namespace capsubot
