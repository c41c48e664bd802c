#pragma once
// The motor force F(phi) and its integrals Pi, Phi (docs/model.md sections 2 and 6).
//
// Every force is a truncated Fourier series in the phase s of the motor,
//     G(s) = c + sum_{k=1..K} (a_k cos(k s) + b_k sin(k s)),
// seen from the impact: F(phi) = G(phi + phi0), so that phi = 0 is the impact instant.
// The paper's family F = A sin(phi + phi0) + c is the series with K = 1, a_1 = 0, b_1 = A.
// One value type serves both families: the orbit, simulator and optimiser never ask which.
//
// A force may instead be piecewise constant (a pulse force, docs/model.md section 15): N
// levels on the intervals between N switching phases of the motor,
//     G(s) = L_j for s in [s_j, s_{j+1}),  j = 0..N-1,  s_N = s_0 + 2 pi,
// seen from the impact the same way: F(phi) = G(phi + phi0). Every member below answers for it
// too (F' = 0 between the switches) except those that name Fourier coefficients.

#include <array>
#include <cmath>
#include <vector>

namespace capsubot {
namespace detail {
class PulsePieces;
}

inline constexpr double kTau = 6.283185307179586476925286766559;  ///< the period 2*pi
inline constexpr int kMaxHarmonics = 16;    ///< largest K a Forcing holds (no allocation)
inline constexpr int kMaxPulseLevels = 16;  ///< largest N a pulse Forcing holds (no allocation)

/// Largest |phase| [rad] an input phase may have (the motor phase phi0 of a force, a range or
/// grid of phi0). A double phase is an angle only while its spacing is a small part of a turn:
/// 1.2e-10 rad at 1e6 rad, a whole turn beyond 3.5e16 rad, where 1e16 or 1e300 name no angle
/// at all. Larger phases are refused (RequirePhase), not wrapped.
inline constexpr double kMaxPhase = 1e6;

/// Throws std::invalid_argument unless `phi` is finite ("phi0 = nan is invalid: expected a
/// finite number") with |phi| <= kMaxPhase ("phi0 = 1e+300 is invalid: expected a phase
/// |phi0| <= 1e+06 rad (...)"), naming `name`.
void RequirePhase(const char* name, double phi);

/// The input phase `phi` (RequirePhase, naming `name`) reduced modulo 2 pi into [-pi, pi]:
/// unchanged when |phi| <= pi, otherwise phi - n 2 pi for the nearest whole n, with 2 pi
/// carried to 150 bits (three parts, Cody and Waite), so that the result is the exact
/// remainder of the double phi to within 2e-15 rad, not of the rounded 2 pi.
double ReduceInputPhase(const char* name, double phi);

/// Phases found in an interval, in increasing order (a fixed-size list: no allocation).
struct PhaseList {
  std::array<double, 2 * kMaxHarmonics + 2> phi{};  ///< the phases, phi[0..n)
  int n = 0;                                        ///< how many were found
};

/// cos tau and sin tau of the rounded period, as std::cos and std::sin return them (the force
/// is evaluated at phi = tau several times in every solve of the orbit).
inline constexpr double kCosTau = 1.0, kSinTau = -0x1.1a62633145c07p-52;

/// A phase with its cosine and sine. The force and its integrals at a phase need only these,
/// so a phase found in closed form (a crossing of a level by one harmonic) or reached by a
/// step from a known one costs no sincos. Make one with Of (no default values: lists of
/// angles are filled without zeroing the unused entries).
struct Angle {
  double phi;
  double cos;  ///< cos phi
  double sin;  ///< sin phi

  /// phi with its cosine and sine from one sincos (none at 0 and tau).
  static Angle Of(double phi) {
    if (phi == 0.0) return {0.0, 1.0, 0.0};
    if (phi == kTau) return {kTau, kCosTau, kSinTau};
    return {phi, std::cos(phi), std::sin(phi)};
  }

  /// The angle at `to`: by angle addition from this one when the step is at most 3/2 (a
  /// polynomial in the step instead of a sincos; within a few ulp of Of(to)), else Of(to).
  Angle Toward(double to) const {
    // Terms of the series below: for |d| <= 1/8 the first ones omitted, d^13/13! and
    // d^12/12!, are below a hundredth of an ulp of sin d and of 1 - cos d; for |d| <= 3/2,
    // d^25/25! and d^24/24! are.
    constexpr double kShortStep = 0.125, kLongStep = 1.5;
    const double d = to - phi;
    if (std::abs(d) <= kShortStep) return Rotated(to, d, Series<5>(d * d));
    if (std::abs(d) <= kLongStep) return Rotated(to, d, Series<11>(d * d));
    return Of(to);
  }

 private:
  // (sin d - d)/(d^3) and (1 - cos d)/d^2 by their Taylor series to n terms each, in Horner
  // form in d2 = d^2 (multiplications only).
  struct SinVers {
    double sin_tail;
    double vers;
  };
  template <int n>
  static SinVers Series(double d2) {
    // s[i] = (-1)^(i+1)/(2i+3)!, v[i] = (-1)^i/(2i+2)!
    constexpr double s[] = {-1.0 / 6,
                            1.0 / 120,
                            -1.0 / 5040,
                            1.0 / 362880,
                            -1.0 / 39916800,
                            1.0 / 6227020800.0,
                            -1.0 / 1307674368000.0,
                            1.0 / 355687428096000.0,
                            -1.0 / 121645100408832000.0,
                            1.0 / 51090942171709440000.0,
                            -1.0 / 25852016738884976640000.0};
    constexpr double v[] = {1.0 / 2,
                            -1.0 / 24,
                            1.0 / 720,
                            -1.0 / 40320,
                            1.0 / 3628800,
                            -1.0 / 479001600.0,
                            1.0 / 87178291200.0,
                            -1.0 / 20922789888000.0,
                            1.0 / 6402373705728000.0,
                            -1.0 / 2432902008176640000.0,
                            1.0 / 1124000727777607680000.0};
    static_assert(n <= static_cast<int>(sizeof(s) / sizeof(s[0])));
    double ps = s[n - 1], pv = v[n - 1];
    for (int i = n - 2; i >= 0; --i) {
      ps = s[i] + d2 * ps;
      pv = v[i] + d2 * pv;
    }
    return {ps, pv};
  }
  // The angle at `to` = phi + d: cos(phi + d) = cos phi - (cos phi (1 - cos d) + sin phi sin d)
  // and likewise for the sine.
  Angle Rotated(double to, double d, const SinVers& t) const {
    const double d2 = d * d, sin_d = d + d * d2 * t.sin_tail, vers_d = d2 * t.vers;
    return {to, cos - (cos * vers_d + sin * sin_d), sin - (sin * vers_d - cos * sin_d)};
  }
};

/// Angles found in an interval, in increasing order of phi, angle[0..n) (fixed size: no
/// allocation; the unused entries are not zeroed).
struct AngleList {
  std::array<Angle, 2 * kMaxHarmonics + 2> angle;
  int n = 0;  ///< how many were found
};

/// F and its integrals at one phase.
struct ForceValues {
  double F = 0.0;
  double Pi = 0.0;
  double Phi = 0.0;
};

/// F with its first two derivatives and its integrals at one phase (what a root search in the
/// phase needs).
struct ForceJet {
  double F = 0.0;
  double dF = 0.0;   ///< F'
  double ddF = 0.0;  ///< F''
  double Pi = 0.0;
  double Phi = 0.0;
};

/// Smallest and largest value of F on an interval.
struct Range {
  double min = 0.0;
  double max = 0.0;
};

class Forcing {
 public:
  /// The zero force (a placeholder for results that were not computed).
  Forcing() = default;

  /// F = A sin(phi + phi0) + c: the paper's family (docs/model.md section 6).
  static Forcing Harmonic(double A, double c, double phi0);
  /// F = c + sum_k (a[k-1] cos(k (phi+phi0)) + b[k-1] sin(k (phi+phi0))); a and b have the
  /// same length K <= kMaxHarmonics. Throws std::invalid_argument naming the bad coefficient.
  /// phi0 is an input phase: |phi0| <= kMaxPhase, kept as phi0() reduced into [-pi, pi]
  /// (ReduceInputPhase), so that every phase added to it later keeps its digits.
  static Forcing Fourier(double c, const std::vector<double>& a, const std::vector<double>& b,
                         double phi0);

  /// Piecewise-constant force in the motor phase s: G(s) = levels[j] for s in
  /// [switches[j], switches[j+1]), j = 0..N-1, switches[N] = switches[0] + 2 pi; switches
  /// strictly increasing in [0, 2 pi), N = levels.size(), 1 <= N <= kMaxPulseLevels;
  /// F(phi) = G(phi + phi0) as for the Fourier series (phi0 reduced the same way). Throws
  /// std::invalid_argument naming the bad level or switch, its value and the rule.
  static Forcing Pulse(const std::vector<double>& levels, const std::vector<double>& switches,
                       double phi0);

  /// The same series with its mean c replaced, as Fourier(c, a, b, phi0()) builds it (phi0
  /// reduced) without the lists: no allocation. Throws std::invalid_argument for a c that is
  /// not finite. A pulse force: every level moved by the same amount, so that its mean is c.
  Forcing WithMean(double c) const;
  /// The same series with a_k (WithCosine) or b_k (WithSine) replaced, 1 <= k <= harmonics(),
  /// as Fourier builds it (phi0 reduced): no allocation. Throws std::invalid_argument for a
  /// coefficient that is not finite, a k out of range or a pulse force (it has no series).
  Forcing WithCosine(int k, double a_k) const;
  Forcing WithSine(int k, double b_k) const;

  /// The same motor with the impact at motor phase phi0 instead (cheap: O(K)). phi0 is kept
  /// as given (the simulator's shifts phi0 + psi stay within two turns and keep their bits);
  /// |phi0| > kMaxPhase throws std::invalid_argument (RequirePhase).
  Forcing WithPhase(double phi0) const;
  /// The same force F(phi) as a series in the phase seen from the impact: phi0 = 0, base
  /// coefficients = the rotated ones, so F, Pi, MaxAbs, ... give the same numbers (cheap: O(K));
  /// a pulse force with its switches moved to the phase from the impact.
  Forcing InImpactFrame() const;

  double phi0() const { return phi0_; }        ///< motor phase at the impact
  double mean() const { return c_; }           ///< c, the mean force: Pi(tau) = c*tau
  int harmonics() const { return K_; }         ///< K (0 for a pulse force)
  double a(int k) const { return a_[k - 1]; }  ///< base cosine coefficient a_k, k = 1..K
  double b(int k) const { return b_[k - 1]; }  ///< base sine coefficient b_k, k = 1..K
  /// True for the paper's family A sin(phi + phi0) + c (K <= 1 and a_1 = 0; not a pulse).
  bool harmonic() const { return N_ == 0 && (K_ == 0 || (K_ == 1 && a_[0] == 0.0)); }
  /// A of the paper's family: the amplitude of the first harmonic (NaN for a pulse force).
  double amplitude() const;
  bool pulse() const { return N_ > 0; }             ///< true for a piecewise-constant force
  int pulse_levels() const { return N_; }           ///< N (0 for a Fourier force)
  double level(int j) const { return levels_[j]; }  ///< L_j, j = 0..N-1
  double switch_phase(int j) const { return switches_[j]; }  ///< s_j [rad], j = 0..N-1

  double F(double phi) const;    ///< force at phase phi (phi = 0 is the impact)
  double dF(double phi) const;   ///< dF/dphi
  double Pi(double phi) const;   ///< integral_0^phi F
  double Phi(double phi) const;  ///< integral_0^phi Pi
  /// F, Pi and Phi at phi together (one sincos for all three; the same numbers, bit for bit,
  /// as F(phi), Pi(phi), Phi(phi)).
  ForceValues Values(double phi) const;
  /// Values at a phase whose cosine and sine are known (no sincos).
  ForceValues Values(const Angle& at) const;
  /// Values with F' and F'' at a phase whose cosine and sine are known (no sincos).
  ForceJet Jet(const Angle& at) const;

  /// Every phase in [lo, hi] where F crosses or touches `level`, sorted; needs
  /// hi - lo <= tau. Exact (closed form for K = 1, a certified subdivision otherwise).
  PhaseList Crossings(double level, double lo, double hi) const;
  /// Crossings with the cosine and sine of each phase (for one harmonic in closed form, with
  /// no sincos; otherwise one sincos per crossing).
  AngleList CrossingAngles(double level, double lo, double hi) const;
  /// Exact min and max of F on [lo, hi] (hi - lo <= tau), from the zeros of dF.
  Range Bounds(double lo, double hi) const;
  /// Bounds with the cosine and sine of the ends known.
  Range Bounds(const Angle& lo, const Angle& hi) const;
  /// max |F| over a whole period (max |L_j| for a pulse force).
  double MaxAbs() const;

 private:
  // The series c + sum_k a[k-1] cos k s + b[k-1] sin k s, K = `harmonics` terms, seen from
  // motor phase phi0 (checked and reduced): what every constructor builds.
  static Forcing Series(double c, const double* a, const double* b, int harmonics, double phi0);
  // This series with a_k (sine: b_k) replaced, rebuilt by Series.
  Forcing WithCoefficient(bool sine, int k, double value) const;
  void SetBase();  // R and the phase of one harmonic of the base series
  void Rotate();   // fill the coefficients seen from the impact phase
  double F(const Angle& at) const;
  template <bool kWithDerivatives>
  ForceJet Sums(const Angle& at) const;  // Jet, or only its F, Pi and Phi

  // The pulse force's pieces seen from the impact.
  detail::PulsePieces Pieces() const;

  double c_ = 0.0;  // for a pulse force: the mean of its levels over a period
  double phi0_ = 0.0;
  int N_ = 0;  // pulse levels (0: a Fourier series)
  std::array<double, kMaxPulseLevels> levels_{}, switches_{};
  int K_ = 0;
  std::array<double, kMaxHarmonics> a_{}, b_{};    // base series, motor phase s
  std::array<double, kMaxHarmonics> ra_{}, rb_{};  // F(phi) = c + sum ra cos k phi + rb sin k phi
  // One harmonic (K = 1): a cos s + b sin s = R sin(s + base_delta) in the motor phase s, so
  // F = c + R sin(phi + delta) with delta = base_delta + phi0 and F' = R cos(phi + delta),
  // kept for the closed-form crossings of every level.
  double R_ = 0.0, base_delta_ = 0.0, delta_ = 0.0;
};

}  // namespace capsubot
