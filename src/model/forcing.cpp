#include "capsubot/model/forcing.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "capsubot/model/detail/pulse_pieces.hpp"
#include "capsubot/model/detail/trig_roots.hpp"
#include "capsubot/numerics/not_computed.hpp"

namespace capsubot {
namespace {

void RequireFinite(const char* name, double value) {
  if (!std::isfinite(value)) {
    throw std::invalid_argument(
        fmt::format("{} = {} is invalid: expected a finite number", name, value));
  }
}

// 2 pi = kTwoPi1 + kTwoPi2 + kTwoPi3 + kTwoPi3t: the first three have 33 significant bits each
// (fdlibm's split of pi/2, times 4), so n kTwoPi1, n kTwoPi2 and n kTwoPi3 are exact for whole
// |n| < 2^20; kTwoPi3t is the rest, rounded.
constexpr double kTwoPi1 = 0x1.921fb544p+2;
constexpr double kTwoPi2 = 0x1.0b4611a6p-32;
constexpr double kTwoPi3 = 0x1.3198a2ep-67;
constexpr double kTwoPi3t = 0x1.b839a252049c1p-102;
constexpr double kPi = 0.5 * kTau;  // pi rounded down

}  // namespace

void RequirePhase(const char* name, double phi) {
  RequireFinite(name, phi);
  if (std::abs(phi) > kMaxPhase) {
    throw std::invalid_argument(fmt::format(
        "{} = {} is invalid: expected a phase |{}| <= {:g} rad (phases are in radians; a larger "
        "one carries no angle to the digits of a double)",
        name, phi, name, kMaxPhase));
  }
}

double ReduceInputPhase(const char* name, double phi) {
  RequirePhase(name, phi);
  if (std::abs(phi) <= kPi) return phi;
  // |n| <= kMaxPhase/(2 pi) < 2^18. phi and n kTwoPi1 are whole multiples of 2^-51 and differ
  // by less than 4, so their difference is exact; each later step rounds once, at the scale
  // of the result.
  const double n = std::nearbyint(phi / kTau);
  double r = phi - n * kTwoPi1;
  r -= n * kTwoPi2;
  r -= n * kTwoPi3;
  r -= n * kTwoPi3t;
  return r;
}

Forcing Forcing::Harmonic(double A, double c, double phi0) {
  RequireFinite("A", A);
  if (A < 0.0) {
    throw std::invalid_argument(fmt::format("A = {} is invalid: expected A >= 0", A));
  }
  const double a[] = {0.0}, b[] = {A};
  return Series(c, a, b, 1, phi0);
}

Forcing Forcing::Fourier(double c, const std::vector<double>& a, const std::vector<double>& b,
                         double phi0) {
  RequireFinite("c", c);  // the checks in the order of the arguments
  RequirePhase("phi0", phi0);
  if (a.size() != b.size()) {
    throw std::invalid_argument(fmt::format(
        "Fourier coefficients: {} cosine and {} sine terms given: expected as many of each",
        a.size(), b.size()));
  }
  if (a.size() > static_cast<std::size_t>(kMaxHarmonics)) {
    throw std::invalid_argument(
        fmt::format("harmonics K = {} is invalid: expected K <= {}", a.size(), kMaxHarmonics));
  }
  return Series(c, a.data(), b.data(), static_cast<int>(a.size()), phi0);
}

Forcing Forcing::Pulse(const std::vector<double>& levels, const std::vector<double>& switches,
                       double phi0) {
  const std::size_t n = levels.size();
  if (n < 1 || n > static_cast<std::size_t>(kMaxPulseLevels)) {
    throw std::invalid_argument(
        fmt::format("levels: N = {} is invalid: expected 1 <= N <= {} levels of the pulse force", n,
                    kMaxPulseLevels));
  }
  if (switches.size() != n) {
    throw std::invalid_argument(
        fmt::format("switches: {} phases given for {} levels: expected one switch phase per level",
                    switches.size(), n));
  }
  Forcing f;
  f.N_ = static_cast<int>(n);
  double sum = 0.0;
  for (std::size_t j = 0; j < n; ++j) {
    const double L = levels[j], s = switches[j], next = j + 1 < n ? switches[j + 1] : kTau;
    if (!std::isfinite(L)) {
      throw std::invalid_argument(
          fmt::format("levels: L_{} = {} is invalid: expected a finite number", j + 1, L));
    }
    if (!(s >= 0.0 && s < kTau)) {
      throw std::invalid_argument(fmt::format(
          "switches: s_{} = {} is invalid: expected 0 <= s < 2 pi (phases in radians)", j + 1, s));
    }
    if (j > 0 && !(s > switches[j - 1])) {
      throw std::invalid_argument(
          fmt::format("switches: s_{} = {} is invalid: expected it above s_{} = {} (switch "
                      "phases strictly increasing)",
                      j + 1, s, j, switches[j - 1]));
    }
    f.levels_[j] = L;
    f.switches_[j] = s;
    // The piece from s_j to s_{j+1} (to s_0 + 2 pi for the last one).
    sum += L * ((j + 1 < n ? next : switches[0] + kTau) - s);
  }
  f.c_ = sum / kTau;
  f.phi0_ = ReduceInputPhase("phi0", phi0);
  return f;
}

detail::PulsePieces Forcing::Pieces() const {
  detail::PulsePieces p;
  p.Build(levels_.data(), switches_.data(), N_, phi0_, 0.0);
  return p;
}

Forcing Forcing::Series(double c, const double* a, const double* b, int harmonics, double phi0) {
  RequireFinite("c", c);
  const double phase = ReduceInputPhase("phi0", phi0);
  Forcing f;
  f.c_ = c;
  f.phi0_ = phase;
  f.K_ = harmonics;
  for (int k = 0; k < f.K_; ++k) {
    if (!std::isfinite(a[k])) RequireFinite(fmt::format("a_{}", k + 1).c_str(), a[k]);
    if (!std::isfinite(b[k])) RequireFinite(fmt::format("b_{}", k + 1).c_str(), b[k]);
    f.a_[k] = a[k];
    f.b_[k] = b[k];
  }
  f.SetBase();
  f.Rotate();
  return f;
}

Forcing Forcing::WithMean(double c) const {
  if (N_ == 0) return Series(c, a_.data(), b_.data(), K_, phi0_);
  RequireFinite("c", c);
  Forcing f = *this;
  for (int j = 0; j < N_; ++j) f.levels_[j] += c - c_;
  f.c_ = c;
  return f;
}

Forcing Forcing::WithCoefficient(bool sine, int k, double value) const {
  if (N_ > 0) {
    throw std::invalid_argument(
        fmt::format("{}_{} is invalid for a pulse force: it has levels and switches, no Fourier "
                    "coefficients",
                    sine ? 'b' : 'a', k));
  }
  if (k < 1 || k > K_) {
    throw std::invalid_argument(fmt::format(
        "harmonic k = {} is invalid for {}_k: expected 1 <= k <= K = {}, the force's harmonics", k,
        sine ? 'b' : 'a', K_));
  }
  std::array<double, kMaxHarmonics> a = a_, b = b_;
  (sine ? b : a)[static_cast<std::size_t>(k - 1)] = value;
  return Series(c_, a.data(), b.data(), K_, phi0_);
}

Forcing Forcing::WithCosine(int k, double a_k) const { return WithCoefficient(false, k, a_k); }

Forcing Forcing::WithSine(int k, double b_k) const { return WithCoefficient(true, k, b_k); }

Forcing Forcing::WithPhase(double phi0) const {
  if (std::abs(phi0) > kMaxPhase) RequirePhase("phi0", phi0);  // NaN passes, as before
  Forcing f = *this;
  f.phi0_ = phi0;
  f.Rotate();
  return f;
}

Forcing Forcing::InImpactFrame() const {
  Forcing f = *this;
  if (N_ > 0) {  // the switches as phases from the impact, rotated to increase from 0
    const detail::PulsePieces p = Pieces();
    const PhaseList s = p.Switches(0.0, 0.0, std::nextafter(kTau, 0.0), true);
    for (int j = 0; j < s.n; ++j) {
      f.switches_[j] = s.phi[j];
      f.levels_[j] = p.F(s.phi[j]);
    }
    f.N_ = s.n;
    f.phi0_ = 0.0;
    return f;
  }
  f.a_ = ra_;
  f.b_ = rb_;
  f.phi0_ = 0.0;
  f.SetBase();
  f.Rotate();
  return f;
}

void Forcing::SetBase() {
  // a cos s + b sin s = R sin(s + atan2(a, b)) in the motor phase s: kept across the impact
  // phases (Rotate only adds phi0 to the phase).
  if (K_ == 1) {
    R_ = std::hypot(a_[0], b_[0]);
    base_delta_ = std::atan2(a_[0], b_[0]);
  }
}

void Forcing::Rotate() {
  // a cos k(phi+phi0) + b sin k(phi+phi0) = (a cos k phi0 + b sin k phi0) cos k phi
  //                                        + (b cos k phi0 - a sin k phi0) sin k phi.
  for (int k = 1; k <= K_; ++k) {
    const double ck = std::cos(k * phi0_), sk = std::sin(k * phi0_);
    ra_[k - 1] = a_[k - 1] * ck + b_[k - 1] * sk;
    rb_[k - 1] = b_[k - 1] * ck - a_[k - 1] * sk;
  }
  delta_ = base_delta_ + phi0_;  // ra cos phi + rb sin phi = R sin(phi + delta)
}

double Forcing::amplitude() const {
  if (N_ > 0) return kNaN;
  if (K_ == 1) return R_;  // hypot(a_1, b_1)
  return K_ == 0 ? 0.0 : std::hypot(a_[0], b_[0]);
}

namespace {

// Calls visit(k, cos k phi, sin k phi) for k = 1..K, with cos k phi and sin k phi from the
// angle's cosine and sine by the angle-addition recurrence. One harmonic (the hot path of the
// analytic solve) takes the loop's first step alone: with k a constant 1 the callers'
// divisions by k fold away, and the numbers are the loop's bit for bit.
template <class Visit>
void ForEachHarmonic(int K, const Angle& at, const Visit& visit) {
  const double c1 = at.cos, s1 = at.sin;
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
double SumHarmonics(int K, const Angle& at, const Term& term) {
  double sum = 0.0;
  ForEachHarmonic(K, at, [&](int k, double ck, double sk) { sum += term(k, ck, sk); });
  return sum;
}

}  // namespace

double Forcing::F(double phi) const {
  if (N_ > 0) return Pieces().F(phi);
  return F(Angle::Of(phi));
}

double Forcing::F(const Angle& at) const {
  if (N_ > 0) return Pieces().F(at.phi);
  return c_ + SumHarmonics(K_, at, [this](int k, double ck, double sk) {
           return ra_[k - 1] * ck + rb_[k - 1] * sk;
         });
}

double Forcing::dF(double phi) const {
  if (N_ > 0) return 0.0;  // between the switches
  return SumHarmonics(K_, Angle::Of(phi), [this](int k, double ck, double sk) {
    return k * (rb_[k - 1] * ck - ra_[k - 1] * sk);
  });
}

double Forcing::Pi(double phi) const {
  if (N_ > 0) return Pieces().Values(phi).Pi;
  // Pi = c phi + sum_k (ra_k sin k phi + rb_k (1 - cos k phi)) / k
  return c_ * phi + SumHarmonics(K_, Angle::Of(phi), [this](int k, double ck, double sk) {
           return (ra_[k - 1] * sk + rb_[k - 1] * (1.0 - ck)) / k;
         });
}

double Forcing::Phi(double phi) const {
  if (N_ > 0) return Pieces().Values(phi).Phi;
  // Phi = c phi^2/2 + sum_k (ra_k (1 - cos k phi) / k^2 + rb_k (phi/k - sin k phi / k^2))
  return 0.5 * c_ * phi * phi +
         SumHarmonics(K_, Angle::Of(phi), [this, phi](int k, double ck, double sk) {
           return (ra_[k - 1] * (1.0 - ck) + rb_[k - 1] * (k * phi - sk)) / (double(k) * k);
         });
}

ForceValues Forcing::Values(double phi) const {
  if (N_ > 0) return Pieces().Values(phi);
  return Values(Angle::Of(phi));
}

template <bool kWithDerivatives>
ForceJet Forcing::Sums(const Angle& at) const {
  // The sums of F, Pi and Phi above (and of dF), term by term in the same order, and of
  // F'' = -sum_k k^2 (ra_k cos k phi + rb_k sin k phi).
  const double phi = at.phi;
  if (N_ > 0) {  // F' = F'' = 0 between the switches
    const ForceValues w = Pieces().Values(phi);
    return {w.F, 0.0, 0.0, w.Pi, w.Phi};
  }
  double sF = 0.0, sdF = 0.0, sddF = 0.0, sPi = 0.0, sPhi = 0.0;
  ForEachHarmonic(K_, at, [&](int k, double ck, double sk) {
    const double a = ra_[k - 1], b = rb_[k - 1], f = a * ck + b * sk;
    sF += f;
    if (kWithDerivatives) {
      sdF += k * (b * ck - a * sk);
      sddF -= double(k) * k * f;
    }
    sPi += (a * sk + b * (1.0 - ck)) / k;
    sPhi += (a * (1.0 - ck) + b * (k * phi - sk)) / (double(k) * k);
  });
  return {c_ + sF, sdF, sddF, c_ * phi + sPi, 0.5 * c_ * phi * phi + sPhi};
}

ForceValues Forcing::Values(const Angle& at) const {
  const ForceJet j = Sums<false>(at);
  return {j.F, j.Pi, j.Phi};
}

ForceJet Forcing::Jet(const Angle& at) const { return Sums<true>(at); }

PhaseList Forcing::Crossings(double level, double lo, double hi) const {
  if (N_ > 0) return Pieces().Switches(level, lo, hi, false);
  if (K_ == 1) return detail::HarmonicRoots(c_ - level, ra_[0], rb_[0], R_, delta_, lo, hi);
  return detail::TrigRoots(c_ - level, ra_.data(), rb_.data(), K_, lo, hi);
}

namespace {

// The angles of the phases of a list (one sincos each).
AngleList AnglesOf(const PhaseList& phases) {
  AngleList out;
  out.n = phases.n;
  for (int i = 0; i < phases.n; ++i) out.angle[i] = Angle::Of(phases.phi[i]);
  return out;
}

}  // namespace

AngleList Forcing::CrossingAngles(double level, double lo, double hi) const {
  if (N_ > 0) return AnglesOf(Crossings(level, lo, hi));
  if (K_ == 1) return detail::HarmonicRootAngles(c_ - level, ra_[0], rb_[0], R_, delta_, lo, hi);
  return AnglesOf(detail::TrigRoots(c_ - level, ra_.data(), rb_.data(), K_, lo, hi));
}

Range Forcing::Bounds(double lo, double hi) const {
  if (N_ > 0) return Pieces().Bounds(lo, hi);
  return Bounds(Angle::Of(lo), Angle::Of(hi));
}

Range Forcing::Bounds(const Angle& lo, const Angle& hi) const {
  if (N_ > 0) return Pieces().Bounds(lo.phi, hi.phi);
  // The critical points of F: the zeros of dF = sum k rb_k cos k phi - k ra_k sin k phi; for one
  // harmonic rb cos phi - ra sin phi = R sin(phi + delta + pi/2).
  const AngleList critical = [&] {  // built in place (the list is 800 bytes)
    if (K_ == 1) {
      return detail::HarmonicRootAngles(0.0, rb_[0], -ra_[0], R_, delta_ + M_PI / 2.0, lo.phi,
                                        hi.phi);
    }
    std::array<double, kMaxHarmonics> da{}, db{};
    for (int k = 0; k < K_; ++k) {
      da[k] = (k + 1) * rb_[k];
      db[k] = -(k + 1) * ra_[k];
    }
    return AnglesOf(detail::TrigRoots(0.0, da.data(), db.data(), K_, lo.phi, hi.phi));
  }();
  const double f_lo = F(lo);
  Range r{f_lo, f_lo};
  auto include = [&r](double f) {
    r.min = std::min(r.min, f);
    r.max = std::max(r.max, f);
  };
  include(F(hi));
  for (int i = 0; i < critical.n; ++i) include(F(critical.angle[i]));
  return r;
}

double Forcing::MaxAbs() const {
  if (N_ > 0) {
    double m = 0.0;
    for (int j = 0; j < N_; ++j) m = std::max(m, std::abs(levels_[j]));
    return m;
  }
  if (K_ <= 1) return std::abs(c_) + amplitude();  // c + R sin(...) spans [c - R, c + R]
  const Range r = Bounds(0.0, kTau);
  return std::max(std::abs(r.min), std::abs(r.max));
}

}  // namespace capsubot
