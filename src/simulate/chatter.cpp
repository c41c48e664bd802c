#include "simulate/chatter.hpp"

#include <cmath>

#include "capsubot/numerics/not_computed.hpp"

namespace capsubot::detail {
namespace {

// Records one estimate uses, and the degrees of the series it eliminates.
constexpr int kPoints = ChatterSequence::kImpacts - 1;
constexpr int kDegrees = kPoints - 1;

// The limit of Q from its values Q_j at kPoints successive impacts, when
// Q_k - Q* = sum over d = 1..kDegrees of a_d r^(d k) (increments of degree d in the scale of
// the sequence, docs/model.md section 14). The shift E: k -> k+1 maps r^(d k) to r^d r^(d k),
// so p(E) = prod_d (E - r^d) annihilates every series and leaves p(1) Q*:
//   Q* = sum_j c_j Q_j / p(1),   c_j the coefficients of p,
// written as Q_last + sum_j w_j (Q_j - Q_last), w_j = c_j / p(1), so that a constant Q stays
// exact. A purely geometric Q gives Q_last + (Q_last - Q_before) r/(1 - r).
struct Extrapolation {
  double w[kPoints];

  explicit Extrapolation(double r) {
    double c[kPoints] = {1.0};  // p(E) = 1, then times (E - r^d): c[j] the coefficient of E^j
    double p1 = 1.0, rd = 1.0;
    for (int d = 1; d <= kDegrees; ++d) {
      rd *= r;
      p1 *= 1.0 - rd;
      for (int j = d; j >= 0; --j) c[j] = (j > 0 ? c[j - 1] : 0.0) - rd * c[j];
    }
    for (int j = 0; j < kPoints; ++j) w[j] = c[j] / p1;
  }

  template <typename Get>
  double operator()(const ChatterRecord* rec, Get get) const {
    const double last = get(rec[kPoints - 1]);
    double sum = 0.0;
    for (int j = 0; j < kPoints - 1; ++j) sum += w[j] * (get(rec[j]) - last);
    return last + sum;
  }
};

struct Estimate {
  bool valid = false;
  double ratio = 0.0;
  ChatterRecord at;
};

// The accumulation point from kPoints successive impacts. The ratios of the last three speeds,
// rho1 and rho2, drift towards the limit r as rho_k - r = g r^k (the force changes along the
// sequence), so r = rho2 (1 - rho1)/(1 - rho2); then every tallied quantity by Extrapolation with
// that r.
Estimate FromPoints(const ChatterRecord* rec) {
  Estimate est;
  const ChatterRecord &a = rec[kPoints - 3], &b = rec[kPoints - 2], &c = rec[kPoints - 1];
  for (int j = 0; j < kPoints; ++j) {
    if (!(rec[j].speed > 0.0)) return est;
  }
  for (int j = 1; j < kPoints; ++j) {
    if (!(rec[j].speed < rec[j - 1].speed)) return est;
  }
  const double rho1 = b.speed / a.speed, rho2 = c.speed / b.speed;
  const double r = rho2 * (1.0 - rho1) / (1.0 - rho2);
  if (!(r > 0.0 && r < 1.0)) return est;
  est.valid = true;
  est.ratio = r;
  const Extrapolation lim(r);
  est.at.phase = lim(rec, [](const ChatterRecord& x) { return x.phase; });
  est.at.speed = 0.0;
  est.at.v = lim(rec, [](const ChatterRecord& x) { return x.v; });
  est.at.y = lim(rec, [](const ChatterRecord& x) { return x.y; });
  if (std::isnan(c.energy.motor_work)) return est;  // no energy budget
  Energy& en = est.at.energy;
  en.motor_work = lim(rec, [](const ChatterRecord& x) { return x.energy.motor_work; });
  en.motor_work_positive =
      lim(rec, [](const ChatterRecord& x) { return x.energy.motor_work_positive; });
  en.friction_loss = lim(rec, [](const ChatterRecord& x) { return x.energy.friction_loss; });
  en.impact_loss = lim(rec, [](const ChatterRecord& x) { return x.energy.impact_loss; });
  return est;
}

}  // namespace

ChatterLimit ChatterSequence::Add(const ChatterRecord& record) {
  if (n_ == kImpacts) {
    for (int i = 1; i < kImpacts; ++i) rec_[i - 1] = rec_[i];
    --n_;
  }
  rec_[n_++] = record;
  ChatterLimit limit;
  limit.previous_phase_error = error_;
  error_ = kNaN;
  if (n_ < kImpacts) return limit;
  const Estimate last = FromPoints(&rec_[1]);
  const Estimate before = FromPoints(&rec_[0]);
  if (!last.valid || !before.valid) return limit;
  limit.valid = true;
  limit.ratio = last.ratio;
  limit.ratio_spread = std::abs(last.ratio - before.ratio) / (1.0 - last.ratio);
  const double r3 = last.ratio * last.ratio * last.ratio;
  limit.phase_error = std::abs(last.at.phase - before.at.phase) * r3 / (1.0 - r3);
  error_ = limit.phase_error;
  limit.at = last.at;
  return limit;
}

}  // namespace capsubot::detail
