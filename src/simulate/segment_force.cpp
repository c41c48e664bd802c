#include "simulate/segment_force.hpp"

#include <algorithm>
#include <cmath>

#include "capsubot/model/detail/trig_roots.hpp"

namespace capsubot::detail {
namespace {

// Crossings closer than this are one (as TrigRoots merges them); a crossing this close below
// the start of the interval is its start.
constexpr double kSameCrossing = 1e-11;

// 1/k and 1/k^2 for k = 1..kMaxHarmonics (the same correctly rounded quotients as dividing
// per segment).
struct Inverse {
  double k1, k2;
};
constexpr std::array<Inverse, kMaxHarmonics> Inverses() {
  std::array<Inverse, kMaxHarmonics> inv{};
  for (int k = 1; k <= kMaxHarmonics; ++k) {
    inv[k - 1].k1 = 1.0 / k;
    inv[k - 1].k2 = 1.0 / (double(k) * k);
  }
  return inv;
}
constexpr std::array<Inverse, kMaxHarmonics> kInverse = Inverses();

}  // namespace

void SegmentForce::Prepare(const Forcing& motor, const double* levels, int n_levels, double tol) {
  n_levels_ = 0;
  tol_ = tol;
  if (motor.pulse()) return;  // its crossings are the switches (Crossings), its signs exact
  for (int i = 0; i < n_levels && n_levels_ < kMaxLevels; ++i) {
    LevelCrossings& entry = table_[n_levels_++];
    entry.level = levels[i];
    entry.t = motor.Crossings(levels[i], 0.0, kTau);
    const int n = entry.t.n;
    for (int k = 0; k < std::max(n, 1); ++k) {
      const double l = n == 0 ? 0.0 : entry.t.phi[k];
      const double r = n == 0 ? kTau : k + 1 < n ? entry.t.phi[k + 1] : entry.t.phi[0] + kTau;
      // F - level keeps its sign between crossings: its largest size on the piece decides, so
      // a point of the piece where F nearly touches the level cannot.
      const Range range = motor.Bounds(l, r);
      const double high = range.max - levels[i], low = range.min - levels[i];
      entry.sign[k] = high >= -low ? (high > tol ? 1.0 : 0.0) : (low < -tol ? -1.0 : 0.0);
    }
  }
}

double SegmentForce::PieceSign(double level, double l, double r) const {
  const LevelCrossings* entry = r - l >= kNearCut ? Find(level) : nullptr;
  if (entry == nullptr) {
    const double g = F(0.5 * (l + r)) - level;
    return g > tol_ ? 1.0 : g < -tol_ ? -1.0 : 0.0;
  }
  // The piece of the motor's period that holds the middle: the last crossing at or before it
  // (the one before the first crossing, wrapping around, is the last).
  double m = shift_ + 0.5 * (l + r);
  for (int turn = 0; turn < 3 && m >= kTau; ++turn) m -= kTau;
  int k = entry->t.n - 1;
  for (int i = 0; i < entry->t.n && entry->t.phi[i] <= m; ++i) k = i;
  return entry->sign[std::max(k, 0)];
}

void SegmentForce::Set(const Forcing& motor, double shift) {
  shift_ = shift;
  if (motor.pulse()) {
    std::array<double, kMaxPulseLevels> levels{}, switches{};
    for (int j = 0; j < motor.pulse_levels(); ++j) {
      levels[j] = motor.level(j);
      switches[j] = motor.switch_phase(j);
    }
    K_ = kPulse;
    c_ = motor.mean();
    pieces_.Build(levels.data(), switches.data(), motor.pulse_levels(), motor.phi0() + shift,
                  kSwitchSnap);
    f0_ = pieces_.F(0.0);
    return;
  }
  // a cos k(s+p) + b sin k(s+p) = (a cos kp + b sin kp) cos ks + (b cos kp - a sin kp) sin ks.
  const double p = motor.phi0() + shift;
  K_ = motor.harmonics();
  c_ = motor.mean();
  f0_ = 0.0;
  for (int k = 1; k <= K_; ++k) {
    const auto [ck, sk] = LocalCosSin(k * p);
    const double a = motor.a(k) * ck + motor.b(k) * sk;
    const double b = motor.b(k) * ck - motor.a(k) * sk;
    const double inv = kInverse[k - 1].k1, inv2 = kInverse[k - 1].k2;
    a_[k - 1] = a;
    b_[k - 1] = b;
    a1_[k - 1] = a * inv;
    b1_[k - 1] = b * inv;
    a2_[k - 1] = a * inv2;
    b2_[k - 1] = b * inv2;
    f0_ += a;
  }
  f0_ = c_ + f0_;
}

double SegmentForce::ManyF(double s) const {
  if (K_ == kPulse) return pieces_.F(s);
  const auto [c1, s1] = LocalCosSin(s);
  return c_ + SumF(c1, s1);
}

double SegmentForce::SumF(double c1, double s1) const {
  double ck = c1, sk = s1, sum = 0.0;
  for (int k = 0; k < K_; ++k) {
    sum += a_[k] * ck + b_[k] * sk;
    const double next = ck * c1 - sk * s1;
    sk = sk * c1 + ck * s1;
    ck = next;
  }
  return sum;
}

ForceJet SegmentForce::SumJet(const Angle& at, bool derivatives) const {
  if (K_ == kPulse) {  // F' = F'' = 0 inside a piece
    const ForceValues w = pieces_.Values(at.phi);
    return {w.F, 0.0, 0.0, w.Pi, w.Phi};
  }
  const double s = at.phi, c1 = at.cos, s1 = at.sin;
  double ck = c1, sk = s1, sF = 0.0, sdF = 0.0, sddF = 0.0, sPi = 0.0, sPhi = 0.0;
  for (int k = 0; k < K_; ++k) {
    const double one_minus_c = Versine(ck, sk), f = a_[k] * ck + b_[k] * sk, n = k + 1;
    sF += f;
    if (derivatives) {
      sdF += n * (b_[k] * ck - a_[k] * sk);
      sddF -= n * n * f;
    }
    sPi += a1_[k] * sk + b1_[k] * one_minus_c;
    sPhi += a2_[k] * one_minus_c + b2_[k] * (n * s - sk);
    const double next = ck * c1 - sk * s1;
    sk = sk * c1 + ck * s1;
    ck = next;
  }
  return {c_ + sF, sdF, sddF, c_ * s + sPi, 0.5 * c_ * s * s + sPhi};
}

CrossingList SegmentForce::Crossings(double level, double lo, double hi) const {
  const LevelCrossings* entry = Find(level);
  CrossingList out;
  if (K_ == kPulse) {
    const PhaseList switches = pieces_.Switches(level, lo, hi, true);
    std::copy(switches.phi.begin(), switches.phi.begin() + switches.n, out.phi.begin());
    out.n = switches.n;
    return out;
  }
  if (entry == nullptr) {
    const PhaseList roots = TrigRoots(c_ - level, a_.data(), b_.data(), K_, lo, hi);
    std::copy(roots.phi.begin(), roots.phi.begin() + roots.n, out.phi.begin());
    out.n = roots.n;
    return out;
  }
  // A motor crossing t is the segment's crossing t - shift, mapped to [lo, lo + tau).
  for (int i = 0; i < entry->t.n; ++i) {
    // (fmod returns a dividend smaller than tau unchanged: the usual case costs no call.)
    const double d = entry->t.phi[i] - shift_ - lo;
    double p = lo + (std::abs(d) < kTau ? d : std::fmod(d, kTau));
    if (p < lo) p += kTau;
    if (lo + kTau - p < kSameCrossing) p = lo;
    if (p > hi + kSameCrossing) continue;
    // Insert in order, merging a crossing within kSameCrossing of one already listed.
    p = std::min(p, hi);
    int j = out.n;
    while (j > 0 && out.phi[j - 1] > p) --j;
    if ((j > 0 && p - out.phi[j - 1] <= kSameCrossing) ||
        (j < out.n && out.phi[j] - p <= kSameCrossing)) {
      continue;
    }
    for (int m = out.n; m > j; --m) out.phi[m] = out.phi[m - 1];
    out.phi[j] = p;
    ++out.n;
  }
  return out;
}

}  // namespace capsubot::detail
