// The zeros of trigonometric polynomials (Bernstein subdivision on half-angle charts) against
// polynomials built from their roots, and against dense scans of random series.

#include "capsubot/model/detail/trig_roots.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <iomanip>
#include <random>
#include <vector>

#include "test_utils.hpp"

namespace capsubot {
namespace {

using Complex = std::complex<double>;

// A series c0 + sum_k (a_k cos k phi + b_k sin k phi) and the zeros it was built from.
struct Built {
  double c0 = 0.0;
  std::vector<double> a, b;
  std::vector<double> simple;  // zeros where it changes sign
  std::vector<double> touch;   // double zeros (it touches zero)
};

// What a factor C - cos(phi - mu) of the product contributes.
enum class Factor { kPair, kDouble, kNearPair, kNoRealZero };

// prod_i (C_i - cos(phi - mu_i)) times `gain`, expanded into its Fourier coefficients:
// C - cos(phi - mu) has the complex coefficients C at 0 and -exp(-+i mu)/2 at +-1, and a
// product is the convolution of the coefficient sequences. Its zeros are mu_i +- acos(C_i)
// for C_i <= 1 (a double zero at mu_i for C_i = 1) and none for C_i > 1.
Built Product(const std::vector<double>& C, const std::vector<double>& mu, double gain) {
  const int K = static_cast<int>(C.size());
  std::vector<Complex> h(2 * K + 1, 0.0);  // h[K + j]: coefficient of exp(i j phi)
  h[K] = gain;
  for (int f = 0; f < K; ++f) {
    std::vector<Complex> next(2 * K + 1, 0.0);
    const Complex up = -0.5 * std::exp(Complex(0.0, -mu[f]));
    for (int j = 0; j <= 2 * K; ++j) {
      if (h[j] == 0.0) continue;
      next[j] += C[f] * h[j];
      if (j + 1 <= 2 * K) next[j + 1] += up * h[j];
      if (j >= 1) next[j - 1] += std::conj(up) * h[j];
    }
    h = next;
  }
  Built s;
  s.c0 = h[K].real();
  for (int k = 1; k <= K; ++k) {
    s.a.push_back(2.0 * h[K + k].real());
    s.b.push_back(-2.0 * h[K + k].imag());
  }
  return s;
}

double Wrap(double phi) {
  double p = std::fmod(phi, kTau);
  return p < 0.0 ? p + kTau : p;
}

// Distance on the circle.
double CircleDistance(double x, double y) {
  const double d = std::abs(Wrap(x - y));
  return std::min(d, kTau - d);
}

// Random products of K factors whose centres are spread over the circle (at least
// tau/(2K) apart) and whose zero pairs are narrower than that, so that every zero is far from
// the other factors' zeros; each factor is a pair, a double zero, a near pair (zeros
// `near_gap` apart) or has no real zero.
Built RandomProduct(std::mt19937_64& rng, int K, double near_gap) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double spacing = kTau / K, offset = kTau * unit(rng);
  std::vector<double> C(K), mu(K);
  std::vector<Factor> kinds(K);
  for (int f = 0; f < K; ++f) {
    mu[f] = Wrap(offset + spacing * (f + 0.25 * unit(rng)));
    kinds[f] = static_cast<Factor>(std::uniform_int_distribution<int>(0, 3)(rng));
    switch (kinds[f]) {
      case Factor::kPair:
        C[f] = std::cos(0.5 * spacing * (0.1 + 0.4 * unit(rng)));  // half-gap acos C
        break;
      case Factor::kDouble:
        C[f] = 1.0;
        break;
      case Factor::kNearPair:
        C[f] = std::cos(0.5 * near_gap);
        break;
      case Factor::kNoRealZero:
        C[f] = 1.0 + 0.05 + unit(rng);
        break;
    }
  }
  Built s = Product(C, mu, 0.2 + 5.0 * unit(rng));
  for (int f = 0; f < K; ++f) {
    if (kinds[f] == Factor::kDouble) {
      s.touch.push_back(mu[f]);
    } else if (kinds[f] != Factor::kNoRealZero) {
      const double half = std::acos(C[f]);
      s.simple.push_back(Wrap(mu[f] - half));
      s.simple.push_back(Wrap(mu[f] + half));
    }
  }
  return s;
}

// How close a found zero is to the one built in: a simple zero is found to full precision; a
// double zero is the extremum, found by Newton on the derivative from inside the region
// where the series is within rounding of zero.
constexpr double kSimpleZeroTol = 1e-10;
constexpr double kDoubleZeroTol = 1e-7;

// Each built zero is matched by one found zero and nothing else is found.
::testing::AssertionResult FindsExactlyTheBuiltZeros(const Built& s, double lo, double hi) {
  const int K = static_cast<int>(s.a.size());
  const PhaseList x = detail::TrigRoots(s.c0, s.a.data(), s.b.data(), K, lo, hi);
  std::vector<double> expected;
  std::vector<double> tols;
  for (double r : s.simple) {
    const double in = lo + Wrap(r - lo);
    if (in <= hi) {
      expected.push_back(in);
      tols.push_back(kSimpleZeroTol);
    }
  }
  for (double r : s.touch) {
    const double in = lo + Wrap(r - lo);
    if (in <= hi) {
      expected.push_back(in);
      tols.push_back(kDoubleZeroTol);
    }
  }
  if (x.n != static_cast<int>(expected.size())) {
    auto failure = ::testing::AssertionFailure();
    failure << "found " << x.n << " zeros, built " << expected.size() << " (K = " << K
            << "); found:";
    for (int j = 0; j < x.n; ++j) failure << " " << x.phi[j];
    failure << "; built:";
    for (double r : expected) failure << " " << r;
    failure << "; c0 a b:" << std::setprecision(17) << " " << s.c0;
    for (int k = 0; k < K; ++k) failure << " " << s.a[k] << " " << s.b[k];
    return failure;
  }
  for (std::size_t i = 0; i < expected.size(); ++i) {
    double best = kTau;
    for (int j = 0; j < x.n; ++j) best = std::min(best, CircleDistance(x.phi[j], expected[i]));
    if (best > tols[i]) {
      return ::testing::AssertionFailure()
             << "built zero " << expected[i] << " found only " << best << " away (K = " << K << ")";
    }
  }
  return ::testing::AssertionSuccess();
}

TEST(TrigRoots, FindsEveryZeroOfRandomProductsIncludingDoubleAndNearDoubleZeros) {
  std::mt19937_64 rng(20261123);
  int checked = 0, doubles = 0, near_pairs = 0;
  for (int K = 2; K <= 8; ++K) {
    // Near pairs as close as the rounding of the polynomial resolves (it grows with K).
    const double near_gap = K <= 4 ? 1e-4 : 1e-3;
    for (int rep = 0; rep < 300; ++rep) {
      const Built s = RandomProduct(rng, K, near_gap);
      EXPECT_TRUE(FindsExactlyTheBuiltZeros(s, 0.0, kTau)) << "case " << rep;
      doubles += static_cast<int>(s.touch.size());
      near_pairs += static_cast<int>(std::count_if(
                        s.simple.begin(), s.simple.end(),
                        [&](double r) {
                          return std::any_of(s.simple.begin(), s.simple.end(), [&](double q) {
                            return q != r && CircleDistance(q, r) < 2.0 * near_gap;
                          });
                        })) /
                    2;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 7 * 300);
  EXPECT_GT(doubles, 1000);     // about a quarter of the 10,500 factors
  EXPECT_GT(near_pairs, 1000);  // likewise
}

TEST(TrigRoots, FindsTheZerosInsideSubintervals) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int checked = 0;
  for (int rep = 0; rep < 2000; ++rep) {
    const int K = 2 + rep % 5;
    const Built s = RandomProduct(rng, K, 1e-4);
    const double lo = -kTau + 2.0 * kTau * unit(rng), hi = lo + kTau * unit(rng);
    // Ends on a zero are decided within rounding: keep the ends away from the zeros.
    bool clear = true;
    for (const auto* list : {&s.simple, &s.touch}) {
      for (double r : *list) {
        clear = clear && CircleDistance(r, lo) > 1e-6 && CircleDistance(r, hi) > 1e-6;
      }
    }
    if (!clear) continue;
    EXPECT_TRUE(FindsExactlyTheBuiltZeros(s, lo, hi)) << "case " << rep;
    ++checked;
  }
  EXPECT_GT(checked, 1900);
}

// Random series (no structure) against the sign changes of a dense scan; where the scan's
// sign changes are closer than its step the count is not decided, and the case is skipped.
TEST(TrigRoots, MatchesTheSignChangesOfADenseScanOfRandomSeries) {
  constexpr int kScanPoints = 20000;
  constexpr double kValueTol = 1e-10;  // |series| at a found zero, relative to sum |coefficients|
  std::mt19937_64 rng(11);
  std::normal_distribution<double> normal(0.0, 1.0);
  int checked = 0;
  for (int rep = 0; rep < 500; ++rep) {
    const int K = 2 + rep % 15;
    std::vector<double> a(K), b(K);
    double scale = 0.0;
    for (int k = 0; k < K; ++k) {
      a[k] = normal(rng) / (1 + k);
      b[k] = normal(rng) / (1 + k);
      scale += std::abs(a[k]) + std::abs(b[k]);
    }
    const double c0 = 0.5 * scale * normal(rng);
    const auto f = [&](double phi) {
      double v = c0;
      for (int k = 1; k <= K; ++k) v += a[k - 1] * std::cos(k * phi) + b[k - 1] * std::sin(k * phi);
      return v;
    };
    const PhaseList x = detail::TrigRoots(c0, a.data(), b.data(), K, 0.0, kTau);
    int changes = 0;
    double prev = f(0.0), min_gap_value = std::abs(prev);
    for (int i = 1; i <= kScanPoints; ++i) {
      const double cur = f(kTau * i / kScanPoints);
      if ((prev < 0.0) != (cur < 0.0)) ++changes;
      min_gap_value = std::min(min_gap_value, std::abs(cur));
      prev = cur;
    }
    // Zeros closer than the scan's step could hide from it: only clear cases count.
    bool clear = true;
    for (int i = 0; i + 1 < x.n; ++i) clear = clear && x.phi[i + 1] - x.phi[i] > 1e-2;
    if (!clear) continue;
    EXPECT_EQ(x.n, changes) << "K = " << K << ", case " << rep;
    for (int i = 0; i < x.n; ++i) EXPECT_LE(std::abs(f(x.phi[i])), kValueTol * scale);
    ++checked;
  }
  EXPECT_GT(checked, 400);
}

TEST(TrigRoots, ReportsATouchOnceAndNothingJustBelowIt) {
  // -(1 - cos phi)(-0.5 - cos phi), a K = 2 series: a double zero at 0 (a minimum) and
  // simple zeros at +-2pi/3, outside [-1, 1].
  const Built s = Product({1.0, -0.5}, {0.0, 0.0}, -1.0);
  const PhaseList x = detail::TrigRoots(s.c0, s.a.data(), s.b.data(), 2, -1.0, 1.0);
  ASSERT_EQ(x.n, 1);
  EXPECT_TRUE(testing::Near(x.phi[0], 0.0, kDoubleZeroTol));
  // Raised by 1e-9 the series has no zero there; lowered, two.
  for (double shift : {1e-9, -1e-9}) {
    const PhaseList y = detail::TrigRoots(s.c0 + shift, s.a.data(), s.b.data(), 2, -1.0, 1.0);
    EXPECT_EQ(y.n, shift > 0.0 ? 0 : 2) << "shift " << shift;
  }
}

// The closed form for one harmonic reduces theta - delta into [lo, lo + tau) (by one
// subtraction of tau where that is exact, else by fmod): the same zeros whatever multiple of
// the period delta carries, from k = 0 (no reduction) to 4 periods either way.
TEST(HarmonicRoots, FindsTheSameZerosWhateverPeriodsThePhaseCarries) {
  constexpr double kShiftTol = 1e-12;  // delta + k tau rounds to a few ulp of 4 tau
  const double delta0 = 0.7, R = 0.05, c0 = 0.02;
  const double a = R * std::sin(delta0), b = R * std::cos(delta0);
  int found = 0;
  for (double lo : {-3.0, -0.5, 0.0, 1.0, 2.5, 5.0}) {
    const double hi = lo + 0.9 * kTau;
    const PhaseList ref = detail::HarmonicRoots(c0, a, b, R, delta0, lo, hi);
    for (int k = -4; k <= 4; ++k) {
      const PhaseList x = detail::HarmonicRoots(c0, a, b, R, delta0 + k * kTau, lo, hi);
      ASSERT_EQ(x.n, ref.n) << "lo " << lo << ", k " << k;
      for (int i = 0; i < x.n; ++i) {
        EXPECT_TRUE(testing::Near(x.phi[i], ref.phi[i], kShiftTol)) << "lo " << lo << ", k " << k;
        EXPECT_TRUE(
            testing::Near(c0 + a * std::cos(x.phi[i]) + b * std::sin(x.phi[i]), 0.0, kShiftTol));
      }
    }
    found += ref.n;
  }
  EXPECT_GE(found, 10);  // two zeros a period, 0.9 of a period searched from each lo
}

}  // namespace
}  // namespace capsubot
