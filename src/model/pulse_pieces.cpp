#include "capsubot/model/detail/pulse_pieces.hpp"

#include <algorithm>
#include <cmath>

namespace capsubot::detail {

void PulsePieces::Build(const double* levels, const double* switches, int n, double origin,
                        double snap) {
  // The switches' phases from the origin, in [0, tau): a rotation of an increasing list.
  std::array<double, kMaxPulseLevels> t{};
  int first = 0;
  for (int j = 0; j < n; ++j) {
    double d = switches[j] - origin;
    d -= kTau * std::floor(d / kTau);
    if (d >= kTau || d < snap || kTau - d < snap) d = 0.0;
    t[j] = d;
    if (d < t[first]) first = j;
  }
  origin_switch_ = t[first] == 0.0;
  n_ = 0;
  if (!origin_switch_) {  // the origin lies inside the piece of the switch before `first`
    start_[0] = 0.0;
    level_[0] = levels[(first + n - 1) % n];
    n_ = 1;
  }
  for (int m = 0; m < n; ++m) {
    const int j = (first + m) % n;
    if (n_ > 0 && t[j] <= start_[n_ - 1]) {  // a piece of no length (snapped): the later wins
      level_[n_ - 1] = levels[j];
      continue;
    }
    start_[n_] = t[j];
    level_[n_] = levels[j];
    ++n_;
  }
  pi_[0] = phi_[0] = 0.0;
  for (int i = 0; i < n_; ++i) {
    const double w = (i + 1 < n_ ? start_[i + 1] : kTau) - start_[i];
    const double pi = pi_[i] + level_[i] * w;
    const double phi = phi_[i] + w * (pi_[i] + 0.5 * level_[i] * w);
    if (i + 1 < n_) {
      pi_[i + 1] = pi;
      phi_[i + 1] = phi;
    } else {
      pi_tau_ = pi;
      phi_tau_ = phi;
    }
  }
}

PulsePieces::Turns PulsePieces::Reduce(double s) {
  if (s >= 0.0 && s < kTau) return {0.0, s};
  const double n = std::floor(s / kTau);
  const double r = s - n * kTau;
  if (r >= kTau) return {n + 1.0, 0.0};
  return {n, std::max(r, 0.0)};
}

int PulsePieces::Piece(double r) const {
  int i = n_ - 1;
  while (i > 0 && start_[i] > r) --i;
  return i;
}

ForceValues PulsePieces::Values(double s) const {
  const Turns t = Reduce(s);
  const int i = Piece(t.r);
  const double d = t.r - start_[i], L = level_[i];
  const double pi = pi_[i] + L * d;
  const double phi = phi_[i] + d * (pi_[i] + 0.5 * L * d);
  if (t.n == 0.0) return {L, pi, phi};
  // n whole periods first: Pi gains n Pi(tau); Phi gains n Phi(tau) + Pi(tau) tau n (n-1)/2
  // over them and n Pi(tau) r over the rest.
  const double n = t.n;
  return {L, n * pi_tau_ + pi,
          n * phi_tau_ + pi_tau_ * (kTau * 0.5 * n * (n - 1.0) + n * t.r) + phi};
}

PhaseList PulsePieces::Switches(double level, double lo, double hi, bool all) const {
  PhaseList out;
  const auto sign = [level](double f) { return f > level ? 1 : f < level ? -1 : 0; };
  const double m_last = std::floor(hi / kTau);
  for (double m = std::floor(lo / kTau); m <= m_last; m += 1.0) {
    for (int i = origin_switch_ ? 0 : 1; i < n_; ++i) {
      const double p = m * kTau + start_[i];
      if (p < lo || p > hi) continue;
      if (!all && sign(level_[i]) == sign(level_[(i + n_ - 1) % n_])) continue;
      if (out.n < static_cast<int>(out.phi.size())) out.phi[out.n++] = p;
    }
  }
  return out;
}

Range PulsePieces::Bounds(double lo, double hi) const {
  const double f_lo = F(lo), f_hi = F(hi);
  Range r{std::min(f_lo, f_hi), std::max(f_lo, f_hi)};
  const PhaseList inside = Switches(0.0, lo, hi, true);
  for (int i = 0; i < inside.n; ++i) {
    const double f = F(inside.phi[i]);
    r.min = std::min(r.min, f);
    r.max = std::max(r.max, f);
  }
  return r;
}

}  // namespace capsubot::detail
