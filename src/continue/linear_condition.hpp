#pragma once
// The one linear condition a . y = b that closes the extended system of a walk
// (docs/continuation.md): in the N unknowns of a branch (x, u, v, lambda) or of a curve of
// special points (x, u, v, lambda, mu).

#include <array>
#include <cstddef>

namespace capsubot::detail {

template <std::size_t N>
struct LinearCondition {
  std::array<double, N> a{};
  double b = 0.0;

  /// The arclength condition t . (y' - y) = sigma: the point a step sigma along the tangent t
  /// from y.
  static LinearCondition Arclength(const std::array<double, N>& t, const std::array<double, N>& y,
                                   double sigma) {
    LinearCondition c;
    c.a = t;
    c.b = sigma;
    for (std::size_t i = 0; i < N; ++i) c.b += t[i] * y[i];
    return c;
  }

  /// Coordinate `index` of y' fixed at `value` (a parameter held at a value).
  static LinearCondition Fixed(std::size_t index, double value) {
    LinearCondition c;
    c.a[index] = 1.0;
    c.b = value;
    return c;
  }
};

}  // namespace capsubot::detail
