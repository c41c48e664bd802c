#include "capsubot/model/detail/trig_roots.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace capsubot::detail {
namespace {

constexpr int kMaxDegree = 2 * kMaxHarmonics;  // degree 2K of the polynomial in t
constexpr double kEps = std::numeric_limits<double>::epsilon();
// Zeros closer than this are one zero; zeros this close outside [lo, hi] count as its ends.
constexpr double kDuplicateTol = 1e-11;
// Bound on the growth (1 + T)^(2K) of the rounding error of the polynomial on a chart
// |t| <= T relative to the series' coefficients (it sets how many charts a period needs).
constexpr double kMaxGrowth = 256.0;
// A piece with one known sign, the other coefficients unknown, and all of them at most this
// many noise bounds small is part of a region within noise of zero (see Isolate).
constexpr double kNoiseEdge = 4.0;
// Subdivision depth at which a chart of width 2T <= 2 is cut down to the spacing of doubles.
constexpr int kMaxDepth = 52;
// Bracketed Newton in t: stop when the step is below this (the step in phi finishes).
constexpr double kNewtonTolT = 1e-10;
constexpr int kNewtonMaxIter = 100;
// The final Newton step in phi is taken only when it is this small (the t-iterate converged).
constexpr double kPolishMaxStep = 1e-8;

// The series in the half-angle variable t = tan(theta/2) (docs/model.md section 2 gives the
// series): cos k theta = Re (1+it)^(2k) / (1+t^2)^k and sin k theta = Im (1+it)^(2k) / (1+t^2)^k,
// so (1+t^2)^K (c0 + sum_k a_k cos k theta + b_k sin k theta) = sum_{j=0..2K} p_j t^j with
// p_j = sum_{k=0..K} E(K, k, j) * (k = 0: c0; j even: a_k; j odd: b_k), E(K, k, j) the
// coefficient of t^j in [Re or Im, by the parity of j] (1+it)^(2k) * (1+t^2)^(K-k) (integers).
// Where the block of K starts in the table: sum_{q < K} (q + 1)(2q + 1).
constexpr int HalfAngleOffset(int K) {
  int o = 0;
  for (int q = 0; q < K; ++q) o += (q + 1) * (2 * q + 1);
  return o;
}

struct HalfAngleTable {
  std::array<double, HalfAngleOffset(kMaxHarmonics + 1)> e{};
  std::array<int, kMaxHarmonics + 1> offset{};  // HalfAngleOffset(K)
  // E(K, k, j) = Block(K)[k * (2K + 1) + j].
  const double* Block(int K) const { return e.data() + offset[K]; }
};

constexpr double Binomial(int n, int r) {
  double c = 1.0;
  for (int i = 1; i <= r; ++i) c = c * (n - r + i) / i;
  return c;
}

constexpr HalfAngleTable MakeHalfAngleTable() {
  HalfAngleTable table{};
  for (int K = 0; K <= kMaxHarmonics; ++K) {
    table.offset[K] = HalfAngleOffset(K);
    for (int k = 0; k <= K; ++k) {
      for (int j = 0; j <= 2 * K; ++j) {
        // (1+it)^(2k) = sum_i C(2k, i) i^i t^i: the real part has the even powers, the
        // imaginary part the odd ones, both with the sign (-1)^floor(i/2).
        double v = 0.0;
        for (int l = 0; 2 * l <= j && l <= K - k; ++l) {
          const int i = j - 2 * l;
          if (i > 2 * k) continue;
          const double sign = (i / 2) % 2 == 0 ? 1.0 : -1.0;
          v += Binomial(K - k, l) * Binomial(2 * k, i) * sign;
        }
        table.e[HalfAngleOffset(K) + k * (2 * K + 1) + j] = v;
      }
    }
  }
  return table;
}

constexpr HalfAngleTable kHalfAngle = MakeHalfAngleTable();

struct Series {
  double c0;
  const double* a;
  const double* b;
  int K;

  // Value, first and second derivative at phi.
  void Eval(double phi, double& f, double& df, double& ddf) const {
    const double c1 = std::cos(phi), s1 = std::sin(phi);
    double ck = c1, sk = s1;
    f = c0;
    df = 0.0;
    ddf = 0.0;
    for (int k = 1; k <= K; ++k) {
      const double ak = a[k - 1], bk = b[k - 1];
      f += ak * ck + bk * sk;
      df += k * (bk * ck - ak * sk);
      ddf -= double(k) * k * (ak * ck + bk * sk);
      const double next = ck * c1 - sk * s1;
      sk = sk * c1 + ck * s1;
      ck = next;
    }
  }
};

// fmod(d, tau) for |d| >= tau, by one subtraction of tau where that is exact (tau <= |d| <= 2 tau,
// Sterbenz's lemma: the phases of the crossings lie within a few periods of the interval), so
// without the library call: the same number, bit for bit. Out of line: Inside stays small.
[[gnu::noinline]] double RemainderTau(double d) {
  if (d >= kTau && d < 2.0 * kTau) return d - kTau;
  if (d < -kTau && d > -2.0 * kTau) return d + kTau;
  return std::fmod(d, kTau);
}

// Maps phi to its representative in [lo, lo + tau); true if it lies in [lo, hi]. Then p is it,
// or the end of [lo, hi] it lies just outside of (moved is set).
bool Inside(double phi, double lo, double hi, double& p, bool& moved) {
  const double d = phi - lo;  // fmod(d, tau) is d itself for |d| < tau
  double r = lo + (std::abs(d) < kTau ? d : RemainderTau(d));
  if (r < lo) r += kTau;
  // A zero just below lo (rounding) is lo itself.
  p = lo + kTau - r < kDuplicateTol ? lo : std::min(r, hi);
  moved = p != r;
  return r <= hi + kDuplicateTol || p == lo;
}

// Appends phi's representative if it lies in [lo, hi].
void AddIfInside(double phi, double lo, double hi, PhaseList& out) {
  double p = 0.0;
  bool moved = false;
  if (Inside(phi, lo, hi, p, moved) && out.n < static_cast<int>(out.phi.size())) {
    out.phi[out.n++] = p;
  }
}

void SortUnique(PhaseList& out) {
  std::sort(out.phi.begin(), out.phi.begin() + out.n);
  int m = 0;
  for (int i = 0; i < out.n; ++i) {
    if (m == 0 || out.phi[i] - out.phi[m - 1] > kDuplicateTol) out.phi[m++] = out.phi[i];
  }
  out.n = m;
}

// Bernstein coefficients of degree n on one piece of a chart.
using Bernstein = std::array<double, kMaxDegree + 1>;

// The zeros found on the charts, in increasing phase, before they are mapped into [lo, hi].
// A run of pieces within rounding noise of zero is gathered and reported as one touch.
class Collector {
 public:
  Collector(const Series& s, double lo, double hi, PhaseList& out)
      : s_(s), lo_(lo), hi_(hi), out_(out) {}

  void Root(double phi) {
    Flush();
    AddIfInside(phi, lo_, hi_, out_);
  }
  void Noise(double from, double to) {
    if (has_noise_ && from <= noise_hi_ + kDuplicateTol) {
      noise_hi_ = std::max(noise_hi_, to);
      return;
    }
    Flush();
    has_noise_ = true;
    noise_lo_ = from;
    noise_hi_ = to;
  }
  // Reports the pending run of noise: at the extremum of the series inside it when Newton on
  // the derivative finds one there (a touch), else at its middle.
  void Flush() {
    if (!has_noise_) return;
    has_noise_ = false;
    double phi = 0.5 * (noise_lo_ + noise_hi_);
    for (int it = 0; it < 3; ++it) {
      double f = 0.0, df = 0.0, ddf = 0.0;
      s_.Eval(phi, f, df, ddf);
      const double next = phi - df / ddf;
      if (!(next >= noise_lo_ && next <= noise_hi_)) break;
      phi = next;
    }
    AddIfInside(phi, lo_, hi_, out_);
  }

 private:
  const Series& s_;
  double lo_, hi_;
  PhaseList& out_;
  bool has_noise_ = false;
  double noise_lo_ = 0.0, noise_hi_ = 0.0;
};

// One chart phi = m + 2 atan(t), |t| <= T, of the series: the polynomial in t (monomial
// coefficients p for evaluation, Bernstein coefficients for isolation) and the subdivision.
class Chart {
 public:
  Chart(const Series& s, Collector& collector) : s_(s), collector_(collector), n_(2 * s.K) {}

  // Sets the chart up around phase m (cos m, sin m given) with half-width parameter T and
  // isolates its zeros.
  void Run(double cos_m, double sin_m, double m, double T) {
    m_ = m;
    T_ = T;
    // Coefficients of the series in theta = phi - m (angle addition, as in Forcing::Rotate).
    std::array<double, kMaxHarmonics + 1> ca, cb;
    double ck = cos_m, sk = sin_m;
    for (int k = 1; k <= s_.K; ++k) {
      ca[k] = s_.a[k - 1] * ck + s_.b[k - 1] * sk;
      cb[k] = s_.b[k - 1] * ck - s_.a[k - 1] * sk;
      const double next = ck * cos_m - sk * sin_m;
      sk = sk * cos_m + ck * sin_m;
      ck = next;
    }
    ca[0] = cb[0] = s_.c0;
    // Monomial coefficients and the sum of |terms| that bounds their rounding on |t| <= T.
    const int K = s_.K;
    const double* E = kHalfAngle.Block(K);
    double scale = 0.0, Tj = 1.0;
    for (int j = 0; j <= n_; ++j) {
      const double* coef = j % 2 == 0 ? ca.data() : cb.data();
      double v = 0.0, mag = 0.0;
      for (int k = 0; k <= K; ++k) {
        const double term = E[k * (n_ + 1) + j] * coef[k];
        v += term;
        mag += std::abs(term);
      }
      p_[j] = v;
      scale += mag * Tj;
      Tj *= T;
    }
    // Bernstein form on [-T, T] by Horner's rule, multiplying by t in Bernstein form (its
    // coefficients are -T, T; each step raises the degree by one): convex combinations, so
    // the rounding stays of the order of the scale.
    Bernstein bern;
    bern[0] = p_[n_];
    for (int j = n_ - 1, d = 0; j >= 0; --j, ++d) {
      const double inv = T / (d + 1);
      double prev = 0.0;  // B_{i-1} of degree d
      for (int i = 0; i <= d + 1; ++i) {
        const double cur = i <= d ? bern[i] : 0.0;
        bern[i] = (i * prev - (d + 1 - i) * cur) * inv + p_[j];
        prev = cur;
      }
    }
    // First-order rounding bound (unit roundoff kEps/2): K + 1 operations per monomial
    // coefficient, 4 per coefficient and degree of the Bernstein form, 2n for Horner's rule.
    const double noise = 0.5 * (K + 1 + 4 * n_) * kEps * scale;
    Isolate(bern, -T, T, noise, 0);
  }

 private:
  double Phase(double t) const { return m_ + 2.0 * std::atan(t); }

  // Value and derivative of the polynomial at t (Horner).
  void EvalT(double t, double& P, double& dP) const {
    P = p_[n_];
    dP = 0.0;
    for (int j = n_ - 1; j >= 0; --j) {
      dP = dP * t + P;
      P = P * t + p_[j];
    }
  }

  // Subdivision of the piece [ta, tb] with Bernstein coefficients b, each within `noise` of
  // its exact value. The polynomial is a convex combination of b (so b of one sign exclude a
  // zero) and has at most as many zeros inside as b has sign variations, of the same parity
  // (Descartes' rule in the Bernstein basis).
  void Isolate(const Bernstein& b, double ta, double tb, double noise, int depth) {
    // Signs beyond the noise: +1, -1, or 0 (either sign).
    int first = -1, last = -1, variations = 0, prev_sign = 0, unknown_run = 0;
    double max_abs = 0.0;
    for (int i = 0; i <= n_; ++i) {
      max_abs = std::max(max_abs, std::abs(b[i]));
      const int sign = b[i] > noise ? 1 : b[i] < -noise ? -1 : 0;
      if (sign == 0) {
        ++unknown_run;
        continue;
      }
      if (first < 0) {
        first = i;
      } else {
        // Most variations the unknown run between two known signs can hold: the largest
        // count <= run + 1 with the parity of (signs differ).
        const int differ = sign != prev_sign ? 1 : 0;
        variations += (unknown_run + 1) - ((unknown_run + 1 - differ) % 2);
      }
      last = i;
      prev_sign = sign;
      unknown_run = 0;
    }
    if (first < 0) {  // the whole piece is within noise of zero
      collector_.Noise(Phase(ta), Phase(tb));
      return;
    }
    const bool whole = first == 0 && last == n_;
    if (whole && variations == 0) return;  // one sign throughout: no zero
    if (whole && variations == 1) {        // exactly one zero
      collector_.Root(SimpleRoot(b, ta, tb, first, b[first] > 0.0 ? 1.0 : -1.0));
      return;
    }
    // An unknown coefficient at a chart's end: the series is within noise of zero at that
    // end (a zero at a period's or interval's end is common: an event of the simulator).
    // Setting the unknown end coefficients to zero moves the polynomial by less than the noise
    // and leaves a zero at that end (reported as a touch) times a polynomial with the known
    // coefficients, which has `variations` zeros inside.
    const bool left_end = first > 0 && ta == -T_, right_end = last < n_ && tb == T_;
    if (variations <= 1 && (first == 0 || left_end) && (last == n_ || right_end)) {
      if (left_end) collector_.Noise(Phase(ta), Phase(ta));
      if (variations == 1) {
        collector_.Root(SimpleRoot(b, ta, tb, first, b[first] > 0.0 ? 1.0 : -1.0));
      }
      if (right_end) collector_.Noise(Phase(tb), Phase(tb));
      return;
    }
    // One known sign and the rest unknown, all a few noise units small: the edge of a region
    // where the series is within noise of zero (a touch).
    if ((variations == 0 && max_abs <= kNoiseEdge * noise) || depth >= kMaxDepth) {
      collector_.Noise(Phase(ta), Phase(tb));
      return;
    }
    // Split at the middle (de Casteljau); the new coefficients are means of the old ones.
    Bernstein left, right, w;
    std::copy(b.begin(), b.begin() + n_ + 1, w.begin());
    left[0] = w[0];
    right[n_] = w[n_];
    for (int r = 1; r <= n_; ++r) {
      for (int i = 0; i <= n_ - r; ++i) w[i] = 0.5 * (w[i] + w[i + 1]);
      left[r] = w[0];
      right[n_ - r] = w[n_ - r];
    }
    const double tm = 0.5 * (ta + tb);
    const double child_noise = noise + n_ * kEps * max_abs;
    Isolate(left, ta, tm, child_noise, depth + 1);
    Isolate(right, tm, tb, child_noise, depth + 1);
  }

  // The single zero inside [ta, tb], where the polynomial has the sign `left_sign` just right
  // of ta and the opposite one just left of tb: Newton's method kept inside a shrinking
  // bracket (bisection when a step would leave it), started where the Bernstein control
  // polygon crosses zero; then one Newton step on the series in phi for full precision.
  double SimpleRoot(const Bernstein& b, double ta, double tb, int first, double left_sign) const {
    int i = first;
    while (i < n_ && b[i + 1] * left_sign > 0.0) ++i;
    const double frac = i < n_ ? b[i] / (b[i] - b[i + 1]) : 0.5;
    double lo = ta, hi = tb;
    double t = ta + (tb - ta) * std::clamp((i + frac) / n_, 0.0, 1.0);
    for (int it = 0; it < kNewtonMaxIter; ++it) {
      double P = 0.0, dP = 0.0;
      EvalT(t, P, dP);
      const double f = left_sign * P;  // > 0 left of the zero
      if (f == 0.0) break;
      (f > 0.0 ? lo : hi) = t;
      double next = t - P / dP;
      if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
      const double step = next - t;
      t = next;
      if (std::abs(step) <= kNewtonTolT || hi - lo <= kNewtonTolT) break;
    }
    double phi = Phase(t), f = 0.0, df = 0.0, ddf = 0.0;
    s_.Eval(phi, f, df, ddf);
    const double step = f / df;
    if (std::abs(step) <= kPolishMaxStep) phi -= step;
    return phi;
  }

  const Series& s_;
  Collector& collector_;
  int n_;
  double m_ = 0.0, T_ = 0.0;
  std::array<double, kMaxDegree + 1> p_;
};

// Largest chart parameter T for K harmonics: (1 + T)^(2K) <= kMaxGrowth, and T <= 1 (a chart
// of at most half a period).
double MaxChartT(int K) { return std::min(1.0, std::pow(kMaxGrowth, 0.5 / K) - 1.0); }

void Subdivided(const Series& s, double lo, double hi, PhaseList& out) {
  // The arc searched: [lo, hi] widened by the duplicate tolerance (a zero just outside counts
  // as the end), or one whole period.
  double from = lo - kDuplicateTol, width = hi - lo + 2.0 * kDuplicateTol;
  if (width >= kTau) {
    from = lo;
    width = kTau;
  }
  // Charts of width theta = 4 atan(T) each, as few as the growth bound allows.
  static const std::array<double, kMaxHarmonics + 1> kMaxTheta = [] {
    std::array<double, kMaxHarmonics + 1> theta{};
    for (int K = 1; K <= kMaxHarmonics; ++K) theta[K] = 4.0 * std::atan(MaxChartT(K));
    return theta;
  }();
  const int charts = std::max(1, static_cast<int>(std::ceil(width / kMaxTheta[s.K])));
  const double theta = width / charts, T = std::tan(0.25 * theta);
  const double m0 = from + 0.5 * theta;
  const double cos_step = std::cos(theta), sin_step = std::sin(theta);
  double cos_m = std::cos(m0), sin_m = std::sin(m0);
  Collector collector(s, lo, hi, out);
  Chart chart(s, collector);
  for (int c = 0; c < charts; ++c) {
    chart.Run(cos_m, sin_m, m0 + c * theta, T);
    const double next = cos_m * cos_step - sin_m * sin_step;
    sin_m = sin_m * cos_step + cos_m * sin_step;
    cos_m = next;
  }
  collector.Flush();
}

}  // namespace

PhaseList TrigRoots(double c0, const double* a, const double* b, int K, double lo, double hi) {
  while (K > 0 && a[K - 1] == 0.0 && b[K - 1] == 0.0) --K;  // effective degree
  PhaseList out;
  const Series s{c0, a, b, K};
  if (K == 0 || hi < lo) return out;
  if (K == 1) {
    return HarmonicRoots(c0, a[0], b[0], std::hypot(a[0], b[0]), std::atan2(a[0], b[0]), lo, hi);
  }
  Subdivided(s, lo, hi, out);
  SortUnique(out);
  return out;
}

AngleList HarmonicRootAngles(double c0, double a, double b, double R, double delta, double lo,
                             double hi) {
  AngleList out;
  if (hi < lo || R == 0.0 || std::abs(c0) > R) return out;
  // The zeros are phi = theta - delta with sin theta = -c0/R: theta = q (cos theta >= 0) and
  // pi - q (cos theta <= 0). With sin delta = a/R and cos delta = b/R,
  //   cos phi = (b cos theta + a sin theta)/R,  sin phi = (b sin theta - a cos theta)/R.
  const double sin_theta = std::clamp(-c0 / R, -1.0, 1.0), q = std::asin(sin_theta);
  const double cos_q = std::sqrt((1.0 - sin_theta) * (1.0 + sin_theta));
  const double theta[2] = {q, M_PI - q}, cos_theta[2] = {cos_q, -cos_q};
  for (int i = 0; i < 2; ++i) {
    double p = 0.0;
    bool moved = false;
    if (!Inside(theta[i] - delta, lo, hi, p, moved)) continue;
    // A zero moved onto an end of [lo, hi] takes that end's cosine and sine.
    out.angle[out.n++] = moved ? Angle::Of(p)
                               : Angle{p, (b * cos_theta[i] + a * sin_theta) / R,
                                       (b * sin_theta - a * cos_theta[i]) / R};
  }
  if (out.n == 2) {  // sorted, a touch (two equal zeros) once
    if (out.angle[1].phi < out.angle[0].phi) std::swap(out.angle[0], out.angle[1]);
    if (!(out.angle[1].phi - out.angle[0].phi > kDuplicateTol)) out.n = 1;
  }
  return out;
}

PhaseList HarmonicRoots(double c0, double a, double b, double R, double delta, double lo,
                        double hi) {
  const AngleList angles = HarmonicRootAngles(c0, a, b, R, delta, lo, hi);
  PhaseList out;
  out.n = angles.n;
  for (int i = 0; i < angles.n; ++i) out.phi[i] = angles.angle[i].phi;
  return out;
}

}  // namespace capsubot::detail
