#include "capsubot/orbit/orbit_energy.hpp"

#include <algorithm>
#include <array>
#include <tuple>

#include "orbit/velocity_pieces.hpp"

namespace capsubot {
namespace {

// Antiderivatives of F x' from phi = 0, with P = Pi(phi), Q = Phi(phi) (docs/model.md section 4):
//   slide, x' = -e u + T0 phi/(1-alpha) + P/(alpha (1-alpha)):
//     int F x' = -e u P + T0 (phi P - Q)/(1-alpha) + P^2/(2 alpha (1-alpha))
//   rest, x' = v+ - e u + P/alpha:
//     int F x' = (v+ - e u) P + P^2/(2 alpha)
// (using int phi F = phi P - Q and int F P = P^2/2).
struct MotorWork {
  const Orbit& o;
  double Slide(double phi) const {
    const double P = o.forcing.Pi(phi), Q = o.forcing.Phi(phi), a = o.alpha;
    return -o.e * o.u * P + o.T0 * (phi * P - Q) / (1.0 - a) + P * P / (2.0 * a * (1.0 - a));
  }
  double Rest(double phi) const {
    const double P = o.forcing.Pi(phi);
    return (o.v_plus - o.e * o.u) * P + P * P / (2.0 * o.alpha);
  }
  // integral of F x' over [lo, hi], a span inside the slide or inside the rest.
  double Over(double lo, double hi) const {
    return hi <= o.phi1 ? Slide(hi) - Slide(lo) : Rest(hi) - Rest(lo);
  }
};

// Every phase where F x' can change sign, plus 0, phi1 and tau: the ends of the monotone
// pieces of x', the zeros of x' inside them and the zeros of F. Fixed size (no allocation):
// each of the two walks of ForEachMonotonePiece gives at most kCrossings + 1 pieces, each
// piece at most two breaks, F at most kCrossings zeros.
constexpr int kCrossings = static_cast<int>(std::tuple_size<decltype(PhaseList::phi)>::value);
constexpr int kMaxBreaks = 2 * 2 * (kCrossings + 1) + kCrossings + 2;

}  // namespace

Energy OrbitEnergy(const Orbit& o) {
  Energy energy;
  if (!o.ok()) return energy;
  const MotorWork work{o};
  energy.motor_work = work.Slide(o.phi1) + work.Rest(kTau) - work.Rest(o.phi1);

  std::array<double, kMaxBreaks> breaks{};
  int n = 0;
  detail::ForEachMonotonePiece(o, [&](const Angle& lo, const Angle& hi, double dlo, double dhi) {
    breaks[n++] = lo.phi;
    if (dlo * dhi < 0.0) breaks[n++] = detail::VelocityZero(o, lo, hi, dlo, dhi).at.phi;
  });
  const PhaseList zeros = o.forcing.Crossings(0.0, 0.0, kTau);
  for (int i = 0; i < zeros.n; ++i) breaks[n++] = zeros.phi[i];
  breaks[n++] = o.phi1;
  breaks[n++] = kTau;
  std::sort(breaks.begin(), breaks.begin() + n);
  // F x' keeps its sign between neighbouring breaks: each span counts in full or not at all.
  double positive = 0.0;
  for (int i = 1; i < n; ++i) {
    if (breaks[i] > breaks[i - 1]) positive += std::max(0.0, work.Over(breaks[i - 1], breaks[i]));
  }
  energy.motor_work_positive = positive;
  // v > 0 on (0, phi1) (phi1 is the first zero of g) and v = 0 after: int |v| = I.
  energy.friction_loss = o.T0 * o.I;
  energy.impact_loss = o.alpha * (1.0 - o.alpha) * (1.0 - o.e * o.e) * o.u * o.u / 2.0;
  return energy;
}

}  // namespace capsubot
