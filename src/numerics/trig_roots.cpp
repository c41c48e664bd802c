#include "numerics/trig_roots.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <complex>

namespace capsubot::detail {
namespace {

// A zero of the polynomial in z counts as real when | |z| - 1 | is below this (double zeros
// split off the circle by about sqrt(machine epsilon)).
constexpr double kUnitCircleTol = 1e-5;
// A polished candidate is kept when |f| is below this fraction of the coefficients' scale.
constexpr double kResidualTol = 1e-9;
// Candidates closer than this are one zero.
constexpr double kDuplicateTol = 1e-11;

struct Series {
  double c0;
  const double* a;
  const double* b;
  int K;

  // Value and derivative at phi.
  void Eval(double phi, double& f, double& df) const {
    const double c1 = std::cos(phi), s1 = std::sin(phi);
    double ck = c1, sk = s1;
    f = c0;
    df = 0.0;
    for (int k = 1; k <= K; ++k) {
      f += a[k - 1] * ck + b[k - 1] * sk;
      df += k * (b[k - 1] * ck - a[k - 1] * sk);
      const double next = ck * c1 - sk * s1;
      sk = sk * c1 + ck * s1;
      ck = next;
    }
  }
};

// Maps phi to its representative in [lo, lo + tau) and appends it if it lies in [lo, hi].
void AddIfInside(double phi, double lo, double hi, PhaseList& out) {
  double p = lo + std::fmod(phi - lo, kTau);
  if (p < lo) p += kTau;
  // A zero just below lo (rounding) is lo itself.
  if (lo + kTau - p < kDuplicateTol) p = lo;
  if (p <= hi + kDuplicateTol && out.n < static_cast<int>(out.phi.size())) {
    out.phi[out.n++] = std::min(p, hi);
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

void ClosedFormK1(const Series& s, double lo, double hi, PhaseList& out) {
  // c0 + a cos phi + b sin phi = c0 + R sin(phi + delta), R = hypot(a, b), delta = atan2(a, b).
  const double R = std::hypot(s.a[0], s.b[0]);
  if (R == 0.0 || std::abs(s.c0) > R) return;
  const double delta = std::atan2(s.a[0], s.b[0]);
  const double q = std::asin(std::clamp(-s.c0 / R, -1.0, 1.0));
  AddIfInside(q - delta, lo, hi, out);
  AddIfInside(M_PI - q - delta, lo, hi, out);
}

void Companion(const Series& s, double lo, double hi, PhaseList& out) {
  // z^K f = sum_j h_j z^j, h_{K+k} = (a_k - i b_k)/2, h_{K-k} = (a_k + i b_k)/2, h_K = c0.
  const int K = s.K, n = 2 * K;
  using C = std::complex<double>;
  Eigen::VectorXcd h(n + 1);
  h(K) = s.c0;
  for (int k = 1; k <= K; ++k) {
    h(K + k) = C(s.a[k - 1], -s.b[k - 1]) / 2.0;
    h(K - k) = C(s.a[k - 1], s.b[k - 1]) / 2.0;
  }
  Eigen::MatrixXcd companion = Eigen::MatrixXcd::Zero(n, n);
  for (int i = 1; i < n; ++i) companion(i, i - 1) = 1.0;
  for (int i = 0; i < n; ++i) companion(i, n - 1) = -h(i) / h(n);
  Eigen::ComplexEigenSolver<Eigen::MatrixXcd> solver(companion, /*computeEigenvectors=*/false);
  double scale = std::abs(s.c0);
  for (int k = 0; k < K; ++k) scale += std::abs(s.a[k]) + std::abs(s.b[k]);
  for (int i = 0; i < n; ++i) {
    const C z = solver.eigenvalues()(i);
    if (std::abs(std::abs(z) - 1.0) > kUnitCircleTol) continue;
    double phi = std::arg(z), f = 0.0, df = 0.0;
    for (int it = 0; it < 4; ++it) {
      s.Eval(phi, f, df);
      if (df == 0.0) break;
      const double step = f / df;
      if (std::abs(step) > 1e-3) break;  // Newton is leaving: keep the eigenvalue's phase
      phi -= step;
    }
    s.Eval(phi, f, df);
    if (std::abs(f) <= kResidualTol * scale) AddIfInside(phi, lo, hi, out);
  }
}

}  // namespace

PhaseList TrigRoots(double c0, const double* a, const double* b, int K, double lo, double hi) {
  while (K > 0 && a[K - 1] == 0.0 && b[K - 1] == 0.0) --K;  // effective degree
  PhaseList out;
  const Series s{c0, a, b, K};
  if (K == 0 || hi < lo) return out;
  if (K == 1) {
    ClosedFormK1(s, lo, hi, out);
  } else {
    Companion(s, lo, hi, out);
  }
  SortUnique(out);
  return out;
}

}  // namespace capsubot::detail
