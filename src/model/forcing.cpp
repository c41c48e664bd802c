#include "capsubot/forcing.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "numerics/trig_roots.hpp"

namespace capsubot {
namespace {

void RequireFinite(const char* name, double value) {
  if (!std::isfinite(value)) {
    throw std::invalid_argument(
        fmt::format("{} = {} is invalid: expected a finite number", name, value));
  }
}

}  // namespace

Forcing Forcing::Harmonic(double A, double c, double phi0) {
  RequireFinite("A", A);
  if (A < 0.0) {
    throw std::invalid_argument(fmt::format("A = {} is invalid: expected A >= 0", A));
  }
  return Fourier(c, {0.0}, {A}, phi0);
}

Forcing Forcing::Fourier(double c, const std::vector<double>& a, const std::vector<double>& b,
                         double phi0) {
  RequireFinite("c", c);
  RequireFinite("phi0", phi0);
  if (a.size() != b.size()) {
    throw std::invalid_argument(fmt::format(
        "Fourier coefficients: {} cosine and {} sine terms given: expected as many of each",
        a.size(), b.size()));
  }
  if (a.size() > static_cast<std::size_t>(kMaxHarmonics)) {
    throw std::invalid_argument(
        fmt::format("harmonics K = {} is invalid: expected K <= {}", a.size(), kMaxHarmonics));
  }
  Forcing f;
  f.c_ = c;
  f.phi0_ = phi0;
  f.K_ = static_cast<int>(a.size());
  for (int k = 0; k < f.K_; ++k) {
    if (!std::isfinite(a[k])) RequireFinite(fmt::format("a_{}", k + 1).c_str(), a[k]);
    if (!std::isfinite(b[k])) RequireFinite(fmt::format("b_{}", k + 1).c_str(), b[k]);
    f.a_[k] = a[k];
    f.b_[k] = b[k];
  }
  f.Rotate();
  return f;
}

Forcing Forcing::WithPhase(double phi0) const {
  Forcing f = *this;
  f.phi0_ = phi0;
  f.Rotate();
  return f;
}

Forcing Forcing::InImpactFrame() const {
  Forcing f = *this;
  f.a_ = ra_;
  f.b_ = rb_;
  f.phi0_ = 0.0;
  f.Rotate();
  return f;
}

void Forcing::Rotate() {
  // a cos k(phi+phi0) + b sin k(phi+phi0) = (a cos k phi0 + b sin k phi0) cos k phi
  //                                        + (b cos k phi0 - a sin k phi0) sin k phi.
  for (int k = 1; k <= K_; ++k) {
    const double ck = std::cos(k * phi0_), sk = std::sin(k * phi0_);
    ra_[k - 1] = a_[k - 1] * ck + b_[k - 1] * sk;
    rb_[k - 1] = b_[k - 1] * ck - a_[k - 1] * sk;
  }
  if (K_ == 1) {
    // ra cos phi + rb sin phi = R sin(phi + atan2(ra, rb)); its derivative
    // rb cos phi - ra sin phi = R sin(phi + atan2(rb, -ra)). The same numbers as TrigRoots'
    // closed form computes from these coefficients.
    R_ = std::hypot(ra_[0], rb_[0]);
    delta_ = std::atan2(ra_[0], rb_[0]);
    delta_dF_ = std::atan2(rb_[0], -ra_[0]);
  }
}

double Forcing::amplitude() const { return K_ == 0 ? 0.0 : std::hypot(a_[0], b_[0]); }

namespace {

// Calls visit(k, cos k phi, sin k phi) for k = 1..K, with cos k phi and sin k phi from one
// sincos by the angle-addition recurrence. One harmonic (the hot path of the analytic solve)
// takes the loop's first step alone: with k a constant 1 the callers' divisions by k fold
// away, and the numbers are the loop's bit for bit.
// cos tau and sin tau of the rounded period, as std::cos and std::sin return them (the force
// is evaluated at phi = tau several times in every solve of the orbit).
constexpr double kCosTau = 1.0, kSinTau = -0x1.1a62633145c07p-52;

template <class Visit>
void ForEachHarmonic(int K, double phi, const Visit& visit) {
  const bool at_tau = phi == kTau;
  const double c1 = at_tau ? kCosTau : std::cos(phi), s1 = at_tau ? kSinTau : std::sin(phi);
  if (K == 1) {
    visit(1, c1, s1);
    return;
  }
  double ck = c1, sk = s1;
  for (int k = 1; k <= K; ++k) {
    visit(k, ck, sk);
    const double next = ck * c1 - sk * s1;
    sk = sk * c1 + ck * s1;
    ck = next;
  }
}

// sum_{k=1..K} term(k, cos k phi, sin k phi).
template <class Term>
double SumHarmonics(int K, double phi, const Term& term) {
  double sum = 0.0;
  ForEachHarmonic(K, phi, [&](int k, double ck, double sk) { sum += term(k, ck, sk); });
  return sum;
}

}  // namespace

double Forcing::F(double phi) const {
  return c_ + SumHarmonics(K_, phi, [this](int k, double ck, double sk) {
           return ra_[k - 1] * ck + rb_[k - 1] * sk;
         });
}

double Forcing::dF(double phi) const {
  return SumHarmonics(K_, phi, [this](int k, double ck, double sk) {
    return k * (rb_[k - 1] * ck - ra_[k - 1] * sk);
  });
}

double Forcing::Pi(double phi) const {
  // Pi = c phi + sum_k (ra_k sin k phi + rb_k (1 - cos k phi)) / k
  return c_ * phi + SumHarmonics(K_, phi, [this](int k, double ck, double sk) {
           return (ra_[k - 1] * sk + rb_[k - 1] * (1.0 - ck)) / k;
         });
}

double Forcing::Phi(double phi) const {
  // Phi = c phi^2/2 + sum_k (ra_k (1 - cos k phi) / k^2 + rb_k (phi/k - sin k phi / k^2))
  return 0.5 * c_ * phi * phi + SumHarmonics(K_, phi, [this, phi](int k, double ck, double sk) {
           return (ra_[k - 1] * (1.0 - ck) + rb_[k - 1] * (k * phi - sk)) / (double(k) * k);
         });
}

ForceValues Forcing::Values(double phi) const {
  // The three sums of F, Pi and Phi above, term by term in the same order.
  double sF = 0.0, sPi = 0.0, sPhi = 0.0;
  ForEachHarmonic(K_, phi, [&](int k, double ck, double sk) {
    const double a = ra_[k - 1], b = rb_[k - 1];
    sF += a * ck + b * sk;
    sPi += (a * sk + b * (1.0 - ck)) / k;
    sPhi += (a * (1.0 - ck) + b * (k * phi - sk)) / (double(k) * k);
  });
  return {c_ + sF, c_ * phi + sPi, 0.5 * c_ * phi * phi + sPhi};
}

PhaseList Forcing::Crossings(double level, double lo, double hi) const {
  if (K_ == 1) return detail::HarmonicRoots(c_ - level, R_, delta_, lo, hi);
  return detail::TrigRoots(c_ - level, ra_.data(), rb_.data(), K_, lo, hi);
}

namespace {

// The critical points of F in [lo, hi]: the zeros of dF = sum k rb_k cos k phi - k ra_k sin k phi.
PhaseList CriticalPoints(int K, const std::array<double, kMaxHarmonics>& ra,
                         const std::array<double, kMaxHarmonics>& rb, double R, double delta_dF,
                         double lo, double hi) {
  if (K == 1) return detail::HarmonicRoots(0.0, R, delta_dF, lo, hi);
  std::array<double, kMaxHarmonics> da{}, db{};
  for (int k = 0; k < K; ++k) {
    da[k] = (k + 1) * rb[k];
    db[k] = -(k + 1) * ra[k];
  }
  return detail::TrigRoots(0.0, da.data(), db.data(), K, lo, hi);
}

}  // namespace

Range Forcing::Bounds(double lo, double hi) const {
  const PhaseList critical = CriticalPoints(K_, ra_, rb_, R_, delta_dF_, lo, hi);
  const double f_lo = F(lo);
  Range r{f_lo, f_lo};
  auto include = [&r](double f) {
    r.min = std::min(r.min, f);
    r.max = std::max(r.max, f);
  };
  include(F(hi));
  for (int i = 0; i < critical.n; ++i) include(F(critical.phi[i]));
  return r;
}

double Forcing::MaxAbs() const {
  if (K_ <= 1) return std::abs(c_) + amplitude();  // c + R sin(...) spans [c - R, c + R]
  const Range r = Bounds(0.0, kTau);
  return std::max(std::abs(r.min), std::abs(r.max));
}

}  // namespace capsubot
