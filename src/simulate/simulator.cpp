#include "capsubot/simulate/simulator.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <stdexcept>
#include <utility>

#include "capsubot/model/detail/enum_names.hpp"
#include "capsubot/model/detail/phase_root.hpp"
#include "capsubot/numerics/not_computed.hpp"
#include "capsubot/numerics/safe_newton.hpp"
#include "simulate/chatter.hpp"
#include "simulate/cycle_memo.hpp"
#include "simulate/segment_force.hpp"

namespace capsubot {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Cuts (crossings of F with a level) closer than this to the start of a segment are dropped:
// a function that changes its monotonicity within 1e-13 in phase of the start cannot hide an
// event there (the state moves by at most 1e-13 times a velocity).
constexpr double kMinCut = 1e-13;
// |F - level| below this fraction of the force scale counts as "on the level" when a mode is
// chosen at a phase where F may be crossing T0, -T0 or a contact level (rounding of events).
constexpr double kLevelTol = 1e-12;
// Chattering safety bound: more consecutive impacts on one wall than this, each within
// kChatterSpan in phase of the previous one, end the sequence as an impact slower than the
// cut-off does.
constexpr int kMaxChatterImpacts = 10000;
constexpr double kChatterSpan = 1e-3;
// A sequence is extrapolated to its accumulation point only while the ratio of successive
// speeds is steady: its two estimates (ChatterLimit::ratio_spread) differ by at most this
// fraction of 1 - r. Early in a sequence, while the impact map has not yet settled on its
// geometric rate, they differ by more.
constexpr double kChatterRatioSpread = 1e-3;
// A sequence whose estimated error of the accumulation phase stops shrinking within this factor
// of SimOptions::chatter_tolerance has reached the rounding of its estimates (about 1e-10 in
// phase for the impacts of a sequence near speeds of 1e-4) and ends there.
constexpr double kChatterRoundingFactor = 100.0;
// Below the cut-off, a sequence whose ratio is above 1 - this (or that does not shrink at all)
// is not contracting: at e = 1 without loss the speeds repeat to rounding.
constexpr double kMinChatterContraction = 1e-6;
// Points at which ReachOnPiece evaluates a concave piece while it bounds its maximum (Newton
// steps on f', a few near a smooth maximum; this many only guard against rounding loops).
constexpr int kMaxTangentCuts = 100;
// A probe for an event predicted by the parabola of its function at a segment's origin goes
// this far beyond the prediction (relative to the distance from the origin), so a good
// prediction lands just past the event and brackets it.
constexpr double kProbeReach = 1.01;
// More consecutive events than this without any progress in phase: report, never hang.
constexpr int kMaxStalledEvents = 1000;

void Require(bool ok, const char* name, double value, const char* rule) {
  if (!ok) {
    throw std::invalid_argument(fmt::format("{} = {} is invalid: expected {}", name, value, rule));
  }
}

// Which wall the inner body meets or rests on, and which way the capsule slides (kNone: at
// rest). The closed forms below use their signs: +1 right wall / forward slide, -1 left wall /
// backward slide, 0 rest.
enum class Wall { kLeft, kRight };
enum class Slide { kNone, kForward, kBackward };

double Sign(Wall wall) { return wall == Wall::kRight ? 1.0 : -1.0; }
double Position(Wall wall) { return wall == Wall::kRight ? 1.0 : 0.0; }
double Sign(Slide slide) {
  return slide == Slide::kForward ? 1.0 : slide == Slide::kBackward ? -1.0 : 0.0;
}
Slide SlideOf(double v) {
  return v > 0.0 ? Slide::kForward : v < 0.0 ? Slide::kBackward : Slide::kNone;
}
EventKind ImpactKind(Wall wall) {
  return wall == Wall::kRight ? EventKind::kImpactRight : EventKind::kImpactLeft;
}

// The motion inside one mode in closed form (docs/model.md section 3), in the local phase s
// measured from the segment's origin; f is the force seen from there: f.F(s) = F(origin + s).
//   free modes:  x'' = kx (F + b),  kx = 1/alpha (rest) or 1/(alpha (1-alpha)) (slide),
//                b = sgn alpha T0 (sgn = Sign(slide));
//                (1-alpha) v' = -(sgn T0 + F) while sliding.
//   on a wall:   x, u = 0 fixed; the capsule and the inner body move together: v' = -sgn T0.
struct Segment {
  detail::SegmentForce f;
  SimMode mode = SimMode::kRest;
  Slide slide = Slide::kNone;
  double alpha = 0.0, T0 = 0.0;
  double x0 = 0.0, u0 = 0.0, v0 = 0.0, y0 = 0.0;
  double sgn = 0.0, kx = 0.0, b = 0.0;  // Sign(slide) and the x'' coefficients

  bool OnWall() const { return mode == SimMode::kOnRightWall || mode == SimMode::kOnLeftWall; }
  Wall RestingWall() const { return mode == SimMode::kOnRightWall ? Wall::kRight : Wall::kLeft; }
  bool Sliding() const { return slide != Slide::kNone; }

  // The state at s from the force values w = f.Values(s) (one sincos serves them all).
  double X(double s, const ForceValues& w) const {
    if (OnWall()) return x0;
    return x0 + (u0 * s + kx * (w.Phi + 0.5 * b * s * s));
  }
  // x(s) - level with x0 - level taken first (exact next to a wall), so a body that stays close
  // to the wall (a chattering flight) keeps the relative accuracy of its distance from it.
  double Gap(double s, const ForceValues& w, double level) const {
    if (OnWall()) return x0 - level;
    return (x0 - level) + (u0 * s + kx * (w.Phi + 0.5 * b * s * s));
  }
  double U(double s, const ForceValues& w) const {
    if (OnWall()) return 0.0;
    return u0 + kx * (w.Pi + b * s);
  }
  double V(double s, const ForceValues& w) const {
    if (!Sliding()) return 0.0;
    if (OnWall()) return v0 - sgn * T0 * s;
    return v0 - (sgn * T0 * s + w.Pi) / (1.0 - alpha);
  }
  double Y(double s, const ForceValues& w) const {
    if (!Sliding()) return y0;
    if (OnWall()) return y0 + v0 * s - 0.5 * sgn * T0 * s * s;
    return y0 + v0 * s - (0.5 * sgn * T0 * s * s + w.Phi) / (1.0 - alpha);
  }
  // y(s) - y0: the displacement along the segment.
  double DY(double s, const ForceValues& w) const {
    if (!Sliding()) return 0.0;
    if (OnWall()) return v0 * s - 0.5 * sgn * T0 * s * s;
    return v0 * s - (0.5 * sgn * T0 * s * s + w.Phi) / (1.0 - alpha);
  }
  // x'' = kx (F + b) of a free mode.
  double Accel(const ForceValues& w) const { return kx * (w.F + b); }
  // v' = -(sgn T0 + F)/(1-alpha) of a sliding free mode.
  double VelocityRate(double F) const { return -(sgn * T0 + F) / (1.0 - alpha); }
  // integral_0^s F u of a free mode: with u = u0 + kx (Pi + b s), integral F Pi = Pi^2/2 and
  // integral s F = s Pi - Phi (integration by parts).
  double MotorWork(double s, const ForceValues& w) const {
    if (OnWall()) return 0.0;
    return u0 * w.Pi + kx * (0.5 * w.Pi * w.Pi + b * (s * w.Pi - w.Phi));
  }
};

// The capsule mode's friction direction and x'' coefficients.
void SetCoefficients(Segment& sg, Slide slide) {
  sg.slide = slide;
  sg.sgn = Sign(slide);
  sg.kx = slide == Slide::kNone ? 1.0 / sg.alpha : 1.0 / (sg.alpha * (1.0 - sg.alpha));
  sg.b = sg.sgn * sg.alpha * sg.T0;
}

// The first zero in (l, r] of f(s) = dir (x(s) - level) from below, dir = Sign(wall),
// level = Position(wall): where the inner body reaches `wall` moving towards it, on a piece
// between consecutive crossings of F = -b, where x'' = kx (F + b) keeps its sign, so f is
// convex or concave and has at most two zeros. Given the ends (lo, hi: angles, f, f', f''),
// the sign of f'' on the piece (`curvature`: dir times the sign of F + b on it,
// SegmentForce::PieceSign, when the piece starts with the body on the wall; otherwise
// f'(r) - f'(l), of the same sign as f' is monotone on the piece) and whether the piece starts
// with the body on the wall (from_wall: f(0) = 0, leaving it):
//   - f(l) < 0 <= f(r): exactly one crossing, found by the root finder;
//   - f(l) < 0, f(r) < 0, convex: no zero;
//   - f(l) < 0, f(r) < 0, concave: a zero only if the maximum (the unique zero of the monotone
//     f' = dir u) reaches 0; two tangent lines bound the maximum cheaply; where they meet
//     (st, the maximum itself for a parabola) f is evaluated once: f(st) >= 0 brackets the
//     first crossing in (l, st] at once, else the root of f' from st gives the maximum
//     exactly, and if f(max) >= 0 (including a grazing touch) the root on [l, max] gives the
//     first crossing;
//   - from the wall: concave cannot come back; convex comes back only after its minimum (root
//     of f'): where the tangents at the ends meet, f(st) < 0 already brackets the return in
//     (st, r], else the minimum is found from st and then as above; a piece with F + b = 0
//     within rounding (PieceSign 0) is neither: the body stays where it is.
// The crossing: detail::PhaseRoot (Halley's iteration with the closed-form derivatives, kept
// inside the bracket, bisection fallback, started from detail::ParabolaStart), to a few
// ulp in phase, with the force's values there; the extrema: detail::SafeNewtonFrom on f' from
// a point whose f' and f'' are known.
// Returns at.phi = +inf when there is no zero in (l, r].
using Hit = detail::PhaseZero;  // an event's local phase (+inf: none) and the force there
Hit NoHit() { return {{kInf, 1.0, 0.0}, {}}; }

Hit ReachOnPiece(const Segment& sg, Wall wall, const detail::BracketEnd& lo,
                 const detail::BracketEnd& hi, double curvature, bool from_wall) {
  const double level = Position(wall), dir = Sign(wall), l = lo.at.phi, r = hi.at.phi;
  const double fl = lo.f, dl = lo.df, fr = hi.f, dr = hi.df;
  // f = dir (x - level), f' = dir u, f'' = dir x'': all three from one sincos.
  const auto at = [&](double s) {
    const Angle a = detail::SegmentForce::At(s);
    const ForceValues w = sg.f.Values(a);
    return detail::BracketEnd{a, dir * sg.Gap(s, w, level), dir * sg.U(s, w), dir * sg.Accel(w)};
  };
  const auto jet = [&](const Angle& a, const ForceJet& j) {
    const ForceValues w{j.F, j.Pi, j.Phi};
    return detail::PhaseJet{dir * sg.Gap(a.phi, w, level), dir * sg.U(a.phi, w), dir * sg.Accel(w),
                            dir * sg.kx * j.dF};
  };
  const auto crossing = [&](const detail::BracketEnd& a, const detail::BracketEnd& b) {
    return detail::PhaseRoot(sg.f, jet, a.at, b.at, a.f, b.f, detail::ParabolaStart(a, b));
  };
  const auto dfddf = [&](double s) {
    const detail::BracketEnd p = at(s);
    return std::pair<double, double>(p.df, p.ddf);
  };
  // Where the tangents at l and r meet (inside (l, r) when dl and dr have opposite signs;
  // kept there against rounding).
  const auto tangents_meet = [&] {
    return std::clamp((fr - fl - dr * r + dl * l) / (dl - dr), l, r);
  };
  // Pressed into the wall (the caller settles this case first): the hit is at l.
  const auto pressed = [&] { return Hit{lo.at, sg.f.Values(lo.at)}; };
  if (from_wall) {
    if (curvature > 0.0 && fr >= 0.0) {
      // Convex, leaving the wall: it returns after its minimum.
      if (!(dl < 0.0 && dr > 0.0)) return pressed();
      const double st = tangents_meet();
      const detail::BracketEnd pt = at(st);
      if (pt.f < 0.0) return crossing(pt, hi);
      const double low = detail::SafeNewtonFrom(dfddf, l, r, dl, dr, st, pt.df, pt.ddf);
      const detail::BracketEnd pm = at(low);
      if (pm.f < 0.0) return crossing(pm, hi);
      return pressed();
    }
  } else if (fl < 0.0 && fr >= 0.0) {
    return crossing(lo, hi);
  } else if (fl < 0.0 && curvature < 0.0 && dl > 0.0 && dr < 0.0) {
    // Concave with its maximum inside [a, b] (f'(a) > 0 > f'(b)): f lies below its tangents,
    // so the height where the tangents at a and b meet bounds the maximum; below 0: no zero.
    // Otherwise f is evaluated at a point x (first where the tangents meet, then Newton steps
    // on f' towards the maximum): f(x) >= 0 brackets the first crossing in (l, x]; else the
    // sign of f'(x) shrinks [a, b] to the side of the maximum, and once the Newton step is
    // below the root tolerance x is the maximum, below 0: no zero (a grazing touch, f = 0
    // at the maximum, counts as an impact).
    double a = l, fa = fl, da = dl, b = r, fb = fr, db = dr;
    const auto meet = [&] { return std::clamp((fb - fa - db * b + da * a) / (da - db), a, b); };
    double x = meet();
    if (fa + da * (x - a) < 0.0) return NoHit();
    for (int cut = 0; cut < kMaxTangentCuts; ++cut) {
      const detail::BracketEnd p = at(x);
      if (p.f >= 0.0) return crossing(lo, p);
      if (p.df > 0.0) {
        a = x, fa = p.f, da = p.df;
      } else if (p.df < 0.0) {
        b = x, fb = p.f, db = p.df;
      } else {
        break;  // x is the maximum
      }
      const double step = p.df / p.ddf;
      if (std::abs(step) < detail::kRootAbsTol || b - a < detail::kRootAbsTol) break;
      const double newton = x - step;
      const double st = meet();
      if (fa + da * (st - a) < 0.0) break;  // the bound of the smaller bracket
      x = newton > a && newton < b ? newton : st;
    }
  }
  return NoHit();
}

// The first impact in (0, limit] on either wall: the pieces between the crossings of F = -b
// (`cuts`) in order, each searched for both walls with ReachOnPiece (the values at its ends
// serve both); the earliest hit wins (the left wall on a tie). kind is kStop and s = +inf
// when there is none. `end`, when given, is the force at the limit (the stop that ends a
// slide, from its root search).
struct Reach {
  Hit hit = NoHit();
  EventKind kind = EventKind::kStop;
};

Reach FirstImpact(const Segment& sg, const detail::CrossingList& cuts, double limit,
                  const Hit* end) {
  Angle al = detail::SegmentForce::At(0.0);
  ForceValues w = sg.f.Values(al);
  // Distances from the right and the left wall (<= 0 inside).
  double rl = sg.Gap(0.0, w, 1.0), ll = -sg.Gap(0.0, w, 0.0);
  double ul = sg.U(0.0, w), accl = sg.Accel(w);
  const bool right_from_wall = rl >= 0.0, left_from_wall = ll >= 0.0;
  int next_cut = 0;
  while (al.phi < limit) {
    const double l = al.phi;
    while (next_cut < cuts.n && cuts.phi[next_cut] <= l + kMinCut) ++next_cut;
    const double r = next_cut < cuts.n ? std::min(cuts.phi[next_cut], limit) : limit;
    const bool known = end != nullptr && end->at.phi == r;
    const Angle ar = known ? end->at : detail::StepAngle(sg.f, al, r);
    w = known ? end->values : sg.f.Values(ar);
    const double rr = sg.Gap(r, w, 1.0), lr = -sg.Gap(r, w, 0.0);
    const double ur = sg.U(r, w), accr = sg.Accel(w);
    // Sign of x'' on (l, r): from the force where a piece leaves a wall, else from the
    // monotone u.
    const double accel =
        l == 0.0 && (right_from_wall || left_from_wall) ? sg.f.PieceSign(-sg.b, l, r) : ur - ul;
    const Hit right = ReachOnPiece(sg, Wall::kRight, {al, rl, ul, accl}, {ar, rr, ur, accr}, accel,
                                   l == 0.0 && right_from_wall);
    const Hit left = ReachOnPiece(sg, Wall::kLeft, {al, ll, -ul, -accl}, {ar, lr, -ur, -accr},
                                  -accel, l == 0.0 && left_from_wall);
    if (left.at.phi <= right.at.phi && left.at.phi < kInf) return {left, EventKind::kImpactLeft};
    if (right.at.phi < kInf) return {right, EventKind::kImpactRight};
    al = ar;
    rl = rr;
    ll = lr;
    ul = ur;
    accl = accr;
  }
  return {};
}

// First s in (0, limit] where the sliding capsule stops: v' = -(sgn T0 + F)/(1-alpha) keeps its
// sign between the crossings of F = -sgn T0, so v is monotone on each piece and the first
// piece whose end has sgn v <= 0 brackets the unique stop (detail::PhaseRoot from
// detail::ParabolaStart, with the force there). at.phi = +inf when there is none.
Hit FirstStop(const Segment& sg, double limit) {
  const auto jet = [&](const Angle& a, const ForceJet& j) {
    const double k = -1.0 / (1.0 - sg.alpha);
    return detail::PhaseJet{sg.V(a.phi, {j.F, j.Pi, j.Phi}), sg.VelocityRate(j.F), k * j.dF,
                            k * j.ddF};
  };
  const auto end = [&](const Angle& a) {
    const detail::PhaseJet j = jet(a, sg.f.Jet(a));
    return detail::BracketEnd{a, j.f, j.df, j.ddf};
  };
  const detail::CrossingList cuts = sg.f.Crossings(-sg.sgn * sg.T0, 0.0, limit);
  detail::BracketEnd lo = end(detail::SegmentForce::At(0.0));
  // A probe just beyond the stop the parabola of v at the origin predicts: an extra cut that
  // brackets a short slide without the end of its piece.
  double probe = lo.at.phi + kProbeReach * (detail::ParabolaZero(lo) - lo.at.phi);
  int i = 0;
  while (lo.at.phi < limit) {
    while (i < cuts.n && cuts.phi[i] <= lo.at.phi + kMinCut) ++i;
    double r = i < cuts.n ? std::min(cuts.phi[i], limit) : limit;
    if (probe > lo.at.phi + kMinCut && probe < r) r = probe;
    probe = kInf;
    const detail::BracketEnd hi = end(detail::StepAngle(sg.f, lo.at, r));
    if (sg.sgn * hi.f <= 0.0) {
      return detail::PhaseRoot(sg.f, jet, lo.at, hi.at, lo.f, hi.f, detail::ParabolaStart(lo, hi));
    }
    lo = hi;
  }
  return NoHit();
}

// integral_0^S max(F u, 0) of a free mode: F u keeps its sign between the zeros of F and of u,
// and u is monotone between the crossings of F = -b (u' = kx (F + b)), so each such piece holds
// at most one zero of u. On the pieces between consecutive sign changes the exact integral
// (Segment::MotorWork) has the sign of F u, so only the positive ones are summed.
double PositiveMotorWork(const Segment& sg, double S) {
  if (sg.OnWall() || !(S > 0.0)) return 0.0;
  const auto u = [&](double s) { return sg.U(s, sg.f.Values(s)); };
  const auto udu = [&](double s) {
    const ForceValues w = sg.f.Values(s);
    return std::pair<double, double>(sg.U(s, w), sg.Accel(w));
  };
  // The sign changes: zeros of F (at most 2K) and of u (at most one per monotone piece).
  std::array<double, 2 * (2 * kMaxHarmonics + 2) + 2> cut{};
  int n = 0;
  const detail::CrossingList zf = sg.f.Crossings(0.0, 0.0, S);
  for (int i = 0; i < zf.n; ++i) cut[n++] = zf.phi[i];
  const detail::CrossingList mono = sg.f.Crossings(-sg.b, 0.0, S);
  double l = 0.0, ul = u(0.0);
  for (int i = 0; i <= mono.n; ++i) {
    const double r = i < mono.n ? mono.phi[i] : S;
    if (!(r > l)) continue;
    const double ur = u(r);
    if ((ul < 0.0 && ur > 0.0) || (ul > 0.0 && ur < 0.0))
      cut[n++] = detail::SafeNewtonFused(u, udu, l, r);
    l = r;
    ul = ur;
  }
  cut[n++] = S;
  std::sort(cut.begin(), cut.begin() + n);
  double positive = 0.0, w_lo = 0.0;
  for (int i = 0; i < n; ++i) {
    const double w_hi = sg.MotorWork(cut[i], sg.f.Values(cut[i]));
    positive += std::max(w_hi - w_lo, 0.0);
    w_lo = w_hi;
  }
  return positive;
}

// The first crossing of `level` after l + kMinCut, with `cuts` = the crossings in [0, tau)
// repeated with period tau (F is tau-periodic); l + tau if there is none.
double NextCut(const detail::CrossingList& cuts, double l) {
  for (int m = 0; m < 2; ++m) {
    for (int i = 0; i < cuts.n; ++i) {
      const double c = cuts.phi[i] + m * kTau;
      if (c > l + kMinCut) return c;
    }
  }
  return l + kTau;
}

// Sign of F - level right after s = 0 (SegmentForce::PieceSign): on the first piece after 0
// (first_only), or on the first piece within a period where F leaves the level by more than
// the rounding tolerance (0: none). Deciding on the piece, never from dF at a crossing, makes
// a tangential touch (dF = rounding noise of either sign) no crossing.
double SignAfterOrigin(const detail::SegmentForce& f, double level, bool first_only) {
  const detail::CrossingList cuts = f.Crossings(level, 0.0, kTau);
  double l = 0.0;
  while (l < kTau) {
    const double r = NextCut(cuts, l);
    const double sign = f.PieceSign(level, l, r);
    if (sign != 0.0 || first_only) return sign;
    l = r;
  }
  return 0.0;
}

// First s in [0, limit] where F crosses `level` upwards (or downwards): the start of the first
// piece between exact crossings (Forcing::Crossings) on which F - level > 0 (< 0) beyond
// rounding (SegmentForce::PieceSign). A tangential touch (no sign change across it) does not
// count; s = 0 when F leaves the level that way right from the start.
double FirstCrossing(const detail::SegmentForce& f, double level, bool upwards, double limit) {
  const double dir = upwards ? 1.0 : -1.0;
  const detail::CrossingList cuts = f.Crossings(level, 0.0, kTau);
  double l = 0.0;
  while (l <= limit) {
    const double r = NextCut(cuts, l);
    if (dir * f.PieceSign(level, l, r) > 0.0) return l;
    l = r;
  }
  return kInf;
}

// The earliest event of the current segment: its local phase s (+inf: none in the window),
// its kind, for a break-away the direction of the slide it starts, and the force's values
// at s when its root search left them (impacts and stops).
struct Event {
  double s = kInf;
  EventKind kind = EventKind::kStop;
  Slide slide = Slide::kNone;
  bool has_values = false;
  ForceValues w;
};

// Everything the event search of a segment depends on (the rest is fixed for the run): the
// mode, the slide, the origin's phase within the period (the force seen from it) and x, u, v
// there, compared bit for bit (so 0 and -0 differ).
struct SegmentKey {
  SimMode mode = SimMode::kRest;
  Slide slide = Slide::kNone;
  std::array<std::uint64_t, 4> bits{};

  bool operator==(const SegmentKey& o) const {
    return bits[0] == o.bits[0] && bits[1] == o.bits[1] && bits[2] == o.bits[2] &&
           bits[3] == o.bits[3] && mode == o.mode && slide == o.slide;
  }
};

// The run as a loop of three named steps: LocateEvent (the earliest event of the current mode
// within one period), Advance (move the segment's origin there: samples, energy, state) and
// ApplyEvent (the instantaneous transition, then Settle for the ones it triggers at the same
// phase).
class Simulation {
 public:
  Simulation(const Forcing& forcing, const Params& params, const SimOptions& opt,
             SimObserver* observer)
      : forcing_(forcing), params_(params), opt_(opt), observer_(observer) {
    force_scale_ = params.T0 + forcing.MaxAbs();
    in_transient_ = opt.transient > 0.0;
    end_turns_ = in_transient_ ? opt.transient : opt.periods;
  }

  SimResult Run();

 private:
  double Phase() const { return static_cast<double>(turns_) * kTau + r_; }
  // Phase left to the current boundary (the transient's end, then the run's end).
  double Remaining() const { return (end_turns_ - static_cast<double>(turns_)) * kTau - r_; }
  SimState StateAt(double s) const;
  SimState StateAt(double s, const ForceValues& w) const;  // w: the force's values at s

  // The three steps.
  Event LocateEvent() const;
  // LocateEvent, or its result for the same segment state earlier in the run (CycleMemo).
  Event NextEvent();
  SimState Advance(double s, const ForceValues* w = nullptr);  // w: the values at s if known
  void ApplyEvent(const Event& event, double u_before, double v_before);

  // Start a new segment at local phase s of the current one with the state `st` there.
  void Rebase(double s, const SimState& st);
  void AccumulateEnergy(double s, const ForceValues& w);
  void Emit(EventKind kind, double u_before, double v_before);
  // `fixed`, when given, is reported for every sample (at the sample's phase) instead of
  // the segment's state: the skipped tail of a chattering sequence.
  void EmitSamplesBefore(double s_end, bool final, const SimState* fixed = nullptr);
  // Instantaneous transitions at the origin: impacts with inward velocity, choice of the
  // capsule mode when v = 0, sticking to and leaving a wall. `hint` is the slide direction
  // of a break-away (kNone if none).
  void Settle(Slide hint);
  void Impact(Wall wall);
  // Adds the record of an impact on `wall` with u, v right before it (also returned in
  // `record`) to the sequence of chatter_ (a new sequence when it is empty or on the other
  // wall); returns the sequence's accumulation point estimated from its last impacts.
  detail::ChatterLimit RecordChatter(Wall wall, double u, double v, detail::ChatterRecord* record);
  // The phase from the origin to the accumulation point of `limit` if the sequence may end
  // there (docs/simulate.md "Chattering"), else a negative number.
  double ChatterTail(const detail::ChatterLimit& limit, const detail::ChatterRecord& now,
                     bool cut_off) const;
  // Moves the origin `tail` ahead to the accumulation point of `limit`: the body on `wall`
  // with u = 0, the capsule's velocity and position and the energy tallies extrapolated.
  // `now` is the record of the impact just applied, `kinetic` the kinetic energy before it.
  void JumpToAccumulation(Wall wall, const detail::ChatterLimit& limit, double tail,
                          const detail::ChatterRecord& now, double kinetic);
  void Release(double u_before, double v_before);
  // Sets the capsule mode at the origin from v (and F when v = 0) without other transitions.
  void UpdateMode(Slide hint);
  Slide RestOrSlide(Slide hint) const;
  bool FreeAccelIntoWall(Wall wall, Slide slide) const;
  // The transient's end: its figures move to res_.transient, the record starts.
  void EndTransient();
  // Span, displacement and mean velocity of the span that ends at the origin.
  void CloseTally(SimTally& tally) const;
  bool Fail(const char* what);
  // Ends the run with kNonFinite when the stored state holds inf or NaN; true if it did.
  bool StopIfNotFinite();

  const Forcing& forcing_;
  const Params& params_;
  const SimOptions& opt_;
  SimObserver* observer_;
  double force_scale_ = 0.0;
  double end_turns_ = 0.0;
  bool in_transient_ = false;
  double span_phase0_ = 0.0;  // phase and capsule position where the current span started
  double span_y0_ = 0.0;
  std::int64_t turns_ = 0;  // origin phase = turns_ * tau + r_, r_ in [0, tau)
  double r_ = 0.0;
  Segment sg_;
  SimResult res_;
  std::int64_t next_sample_ = 0;
  bool stop_ = false;  // SimObserver::Done: the run ends at local phase stop_at_
  double stop_at_ = 0.0;
  int chatter_count_ = 0;
  double last_impact_phase_ = -kInf;
  Wall last_impact_wall_ = Wall::kRight;
  // The current chattering sequence: its last impacts, and the run at its first impact (the
  // records count phase, position and energy from there).
  detail::ChatterSequence chatter_;
  struct ChatterStart {
    Wall wall = Wall::kRight;
    std::int64_t turns = 0;
    double r = 0.0, y = 0.0;
    Energy energy;
  } chatter_start_;
  std::array<double, 5> levels_{};  // the levels the events look for (Run)
  detail::CycleMemo<SegmentKey, Event> memo_;
};

SimState Simulation::StateAt(double s) const {
  SimState st;
  st.mode = sg_.mode;
  if (s == 0.0) {  // the stored state (exact; also right after an event, before settling)
    st.phi = Phase();
    st.x = sg_.x0;
    st.u = sg_.u0;
    st.v = sg_.v0;
    st.y = sg_.y0;
    return st;
  }
  return StateAt(s, sg_.f.Values(s));
}

SimState Simulation::StateAt(double s, const ForceValues& w) const {
  SimState st;
  st.mode = sg_.mode;
  st.phi = Phase() + s;
  st.x = sg_.X(s, w);
  st.u = sg_.U(s, w);
  st.v = sg_.V(s, w);
  st.y = sg_.Y(s, w);
  return st;
}

void Simulation::Rebase(double s, const SimState& st) {
  r_ += s;
  const std::int64_t turns_before = turns_;
  while (r_ >= kTau) {
    r_ -= kTau;
    ++turns_;
  }
  if (observer_ != nullptr && turns_ != turns_before) observer_->OnPeriods(turns_);
  sg_.f.Set(forcing_, r_);
  sg_.x0 = st.x;
  sg_.u0 = st.u;
  sg_.v0 = st.v;
  sg_.y0 = st.y;
}

// Energy over [0, s] of the segment (docs/model.md section 11), in closed form: motor work
// Segment::MotorWork (and its positive part), friction T0 |y(s) - y0| (v keeps its sign while
// the mode lasts: a slide ends at the stop); w: the force's values at s.
void Simulation::AccumulateEnergy(double s, const ForceValues& w) {
  Energy& en = res_.energy;
  en.motor_work += sg_.MotorWork(s, w);
  en.motor_work_positive += PositiveMotorWork(sg_, s);
  en.friction_loss += sg_.T0 * std::abs(sg_.DY(s, w));
}

// Moves the origin to local phase s; returns the state there (right before an event at s).
SimState Simulation::Advance(double s, const ForceValues* w) {
  EmitSamplesBefore(s, false);
  if (stop_) {  // the observer has seen enough: the run ends at its last sample
    s = stop_at_;
    w = nullptr;
  }
  const ForceValues values = w != nullptr ? *w : sg_.f.Values(s);
  if (opt_.energy) AccumulateEnergy(s, values);
  const SimState st = StateAt(s, values);
  Rebase(s, st);
  return st;
}

void Simulation::Emit(EventKind kind, double u_before, double v_before) {
  ++res_.events;
  switch (kind) {
    case EventKind::kImpactRight:
      ++res_.impacts_right;
      break;
    case EventKind::kImpactLeft:
      ++res_.impacts_left;
      break;
    case EventKind::kStop:
      ++res_.stops;
      break;
    case EventKind::kBreakaway:
      ++res_.breakaways;
      break;
    case EventKind::kStick:
      ++res_.sticks;
      break;
    case EventKind::kRelease:
      ++res_.releases;
      break;
  }
  if (observer_ != nullptr) {
    SimEvent ev;
    ev.kind = kind;
    ev.after = StateAt(0.0);
    ev.u_before = u_before;
    ev.v_before = v_before;
    observer_->OnEvent(ev);
  }
}

// Samples at phases k * sample_step in [origin, origin + s_end) of the current segment; with
// `final`, every remaining sample up to the end phase (rounding of k * step allowed).
void Simulation::EmitSamplesBefore(double s_end, bool final, const SimState* fixed) {
  if (observer_ == nullptr || !(opt_.sample_step > 0.0)) return;
  const double origin = Phase(), end = (opt_.transient + opt_.periods) * kTau,
               slack = 1e-12 * (1.0 + end);
  for (;;) {
    const double p = static_cast<double>(next_sample_) * opt_.sample_step;
    if (p > end + slack) return;
    const double s = p - origin;
    if (!final && s >= s_end) return;
    if (fixed != nullptr) {
      SimState st = *fixed;
      st.phi = p;
      observer_->OnSample(st);
    } else {
      observer_->OnSample(StateAt(std::max(s, 0.0)));
    }
    ++next_sample_;
    if (!final && observer_->Done()) {
      stop_ = true;
      stop_at_ = std::max(s, 0.0);
      return;
    }
  }
}

// The free relative acceleration x'' = kx (F + b) at the origin, for capsule mode `slide`,
// points into `wall`; for a body resting on the wall this is the sign of the contact force
// (docs/model.md section 3 with u' = 0). It is the sign of F + b on the first piece (between
// crossings of F with -b) after the origin where it is not zero within rounding: a contact
// force that only touches zero, or is zero for an instant, keeps the body on the wall (the
// same pieces decide a release in LocateEvent, so the two never disagree).
bool Simulation::FreeAccelIntoWall(Wall wall, Slide slide) const {
  const double dir = Sign(wall);
  const double level = -Sign(slide) * sg_.alpha * sg_.T0, tol = kLevelTol * force_scale_;
  const double g = sg_.f.F(0.0) - level;
  if (std::abs(g) > 1e3 * tol) return dir * g > 0.0;  // far from the level: no crossing near
  return dir * SignAfterOrigin(sg_.f, level, false) > 0.0;
}

// Capsule at v = 0 (docs/model.md section 3): rest while |F| <= T0; it slides forward once
// -F > T0, backward once F > T0. On the level within rounding, the sign of F -+ T0 on the
// piece right after the origin decides: a force that only touches +-T0 is no break-away.
Slide Simulation::RestOrSlide(Slide hint) const {
  if (hint != Slide::kNone) return hint;
  const double F = sg_.f.F(0.0), T0 = sg_.T0, tol = kLevelTol * force_scale_;
  if (F > T0 + tol) return Slide::kBackward;
  if (F < -T0 - tol) return Slide::kForward;
  if (F > T0 - tol && SignAfterOrigin(sg_.f, T0, true) > 0.0) return Slide::kBackward;
  if (F < -T0 + tol && SignAfterOrigin(sg_.f, -T0, true) < 0.0) return Slide::kForward;
  return Slide::kNone;
}

// Impact with `wall` (docs/model.md section 3): u+ = -e u, v+ = v + alpha (1+e) u. The impact
// is recorded in its chattering sequence; once the sequence may end (ChatterTail), the run
// jumps from right after this impact to the accumulation point, where Settle makes the body
// rest on the wall (or lets it leave). An impact slower than the cut-off whose sequence does
// not contract, or the end of a long run of close impacts that cannot be extrapolated, with
// the body pushed into the wall, is taken as plastic (u+ = 0, v+ = v + alpha u: the momentum
// of its remaining impacts); a contracting sequence below the cut-off whose ratio is not yet
// steady goes on.
// Energy: the kinetic energy lost, alpha (1-alpha) (1-e^2) u^2/2 (e = 0 when plastic: the
// losses of the remaining impacts, sum (1-e^2) e^(2k) = 1).
void Simulation::Impact(Wall wall) {
  const double u = sg_.u0, v = sg_.v0, phase = Phase();
  if (wall == last_impact_wall_ && phase - last_impact_phase_ < kChatterSpan) {
    ++chatter_count_;
  } else {
    chatter_count_ = 1;
  }
  last_impact_wall_ = wall;
  last_impact_phase_ = phase;
  detail::ChatterRecord now;
  const detail::ChatterLimit limit = RecordChatter(wall, u, v, &now);
  const bool slow =
      std::abs(u) < opt_.chatter_velocity && chatter_.Size() >= detail::ChatterSequence::kImpacts;
  const bool too_many = chatter_count_ > kMaxChatterImpacts;
  // A run that stops right after this impact (SimOptions::max_impacts_right) ends there.
  const bool stops_here =
      wall == Wall::kRight && opt_.max_impacts_right > 0 &&
      res_.impacts_right + res_.transient.impacts_right + 1 >= opt_.max_impacts_right;
  const double tail = stops_here ? -1.0 : ChatterTail(limit, now, slow || too_many);
  const bool contracting = limit.valid && limit.ratio <= 1.0 - kMinChatterContraction;
  sg_.x0 = Position(wall);
  bool plastic = false;
  if (tail < 0.0 && (too_many || (slow && !contracting))) {
    const double v_plastic = v + sg_.alpha * u;
    const Slide slide = SlideOf(v_plastic);
    sg_.v0 = v_plastic;
    plastic = FreeAccelIntoWall(wall, slide != Slide::kNone ? slide : RestOrSlide(Slide::kNone));
  }
  const double e = plastic ? 0.0 : params_.e;
  if (plastic) {
    sg_.u0 = 0.0;
    sg_.v0 = v + sg_.alpha * u;
    chatter_.Clear();
  } else {
    sg_.u0 = -params_.e * u;
    sg_.v0 = v + sg_.alpha * (1.0 + params_.e) * u;
  }
  if (sg_.u0 == 0.0) sg_.u0 = 0.0;  // no -0
  if (opt_.energy) {
    res_.energy.impact_loss += 0.5 * sg_.alpha * (1.0 - sg_.alpha) * (1.0 - e * e) * u * u;
  }
  UpdateMode(Slide::kNone);
  Emit(ImpactKind(wall), u, v);
  if (tail >= 0.0) {
    const double kinetic = 0.5 * ((1.0 - sg_.alpha) * v * v + sg_.alpha * (v + u) * (v + u));
    JumpToAccumulation(wall, limit, tail, now, kinetic);
  }
}

detail::ChatterLimit Simulation::RecordChatter(Wall wall, double u, double v,
                                               detail::ChatterRecord* record) {
  if (chatter_.Size() == 0 || wall != chatter_start_.wall) {
    chatter_.Clear();
    chatter_start_ = {wall, turns_, r_, sg_.y0, res_.energy};
  }
  detail::ChatterRecord rec;
  rec.phase = static_cast<double>(turns_ - chatter_start_.turns) * kTau + (r_ - chatter_start_.r);
  rec.speed = std::abs(u);
  rec.v = v;
  rec.y = sg_.y0 - chatter_start_.y;
  const Energy& e0 = chatter_start_.energy;
  rec.energy = {res_.energy.motor_work - e0.motor_work,
                res_.energy.motor_work_positive - e0.motor_work_positive,
                res_.energy.friction_loss - e0.friction_loss,
                res_.energy.impact_loss - e0.impact_loss};
  *record = rec;
  return chatter_.Add(rec);
}

// A sequence ends at its accumulation point when its speeds shrink steadily (both ratio
// estimates in (0, 1), within kChatterRatioSpread of each other) and either the estimated error
// of its accumulation phase is at most chatter_tolerance, or that error grew since the previous
// impact from at most kChatterRoundingFactor times the tolerance (rounding, not truncation,
// limits it: waiting would not help), or this impact is below the cut-off;
// and only if the tail it skips is short enough to be local (at most a period, within the
// run's span), the capsule's velocity keeps its sign over it, and F crosses none of the levels
// that change the motion (+-T0, 0, +-alpha T0) there: the sums assume one pattern of flights.
double Simulation::ChatterTail(const detail::ChatterLimit& limit, const detail::ChatterRecord& now,
                               bool cut_off) const {
  if (!limit.valid || !(limit.ratio_spread <= kChatterRatioSpread)) return -1.0;
  const bool accurate = limit.phase_error <= opt_.chatter_tolerance;
  const bool at_rounding =
      limit.phase_error > limit.previous_phase_error &&
      limit.previous_phase_error <= kChatterRoundingFactor * opt_.chatter_tolerance;
  if (!cut_off && !accurate && !at_rounding) return -1.0;
  const double tail = limit.at.phase - now.phase;
  if (!(tail >= 0.0 && tail <= std::min(kTau, Remaining()))) return -1.0;
  if (limit.at.v * now.v < 0.0) return -1.0;
  for (const double level : levels_) {
    if (sg_.f.Crossings(level, 0.0, tail).n > 0) return -1.0;
  }
  return tail;
}

void Simulation::JumpToAccumulation(Wall wall, const detail::ChatterLimit& limit, double tail,
                                    const detail::ChatterRecord& now, double kinetic) {
  SimState st;
  st.mode = sg_.mode;
  st.x = Position(wall);
  st.u = 0.0;
  st.v = limit.at.v;
  st.y = chatter_start_.y + limit.at.y;
  EmitSamplesBefore(tail, false, &st);
  if (stop_) {  // the observer stopped at a sample inside the tail: the run ends there
    Rebase(stop_at_, st);
    chatter_.Clear();
    return;
  }
  Rebase(tail, st);
  if (opt_.energy) {
    // Over the tail (from right before this impact): the motor's work and the impacts' loss
    // extrapolated, the kinetic energy at both ends exact for their states, and the friction
    // what the energy theorem leaves, so the budget holds for the state the run continues
    // from (it equals T0 |y* - y| to the extrapolation's error).
    const Energy& e0 = chatter_start_.energy;
    const Energy& at = limit.at.energy;
    const double motor = at.motor_work - now.energy.motor_work;
    const double impacts = at.impact_loss - now.energy.impact_loss;
    const double friction = motor - impacts - (0.5 * st.v * st.v - kinetic);
    res_.energy = {e0.motor_work + at.motor_work, e0.motor_work_positive + at.motor_work_positive,
                   e0.friction_loss + now.energy.friction_loss + friction,
                   e0.impact_loss + at.impact_loss};
  }
  chatter_.Clear();
  UpdateMode(Slide::kNone);
}

// The inner body leaves the wall it rested on (u stays 0).
void Simulation::Release(double u_before, double v_before) {
  chatter_.Clear();
  sg_.mode = SimMode::kRest;
  sg_.u0 = 0.0;
  UpdateMode(Slide::kNone);
  Emit(EventKind::kRelease, u_before, v_before);
}

void Simulation::UpdateMode(Slide hint) {
  const Slide slide = sg_.v0 > 0.0 || sg_.v0 < 0.0 ? SlideOf(sg_.v0)
                      : sg_.OnWall()               ? Slide::kNone
                                                   : RestOrSlide(hint);
  SetCoefficients(sg_, slide);
  if (sg_.OnWall()) return;
  sg_.mode = slide == Slide::kForward    ? SimMode::kSlideForward
             : slide == Slide::kBackward ? SimMode::kSlideBackward
                                         : SimMode::kRest;
}

void Simulation::Settle(Slide hint) {
  for (int iter = 0; iter < 8; ++iter) {
    if (!sg_.OnWall()) {
      if (sg_.x0 >= 1.0 && sg_.u0 > 0.0) {
        Impact(Wall::kRight);
        hint = Slide::kNone;
        continue;
      }
      if (sg_.x0 <= 0.0 && sg_.u0 < 0.0) {
        Impact(Wall::kLeft);
        hint = Slide::kNone;
        continue;
      }
      UpdateMode(hint);
      if (sg_.u0 == 0.0 && (sg_.x0 >= 1.0 || sg_.x0 <= 0.0)) {
        const Wall wall = sg_.x0 >= 1.0 ? Wall::kRight : Wall::kLeft;
        if (FreeAccelIntoWall(wall, sg_.slide)) {
          sg_.mode = wall == Wall::kRight ? SimMode::kOnRightWall : SimMode::kOnLeftWall;
          sg_.x0 = Position(wall);
          chatter_.Clear();
          Emit(EventKind::kStick, 0.0, sg_.v0);
        }
      }
      return;
    }
    const Slide slide = SlideOf(sg_.v0);
    SetCoefficients(sg_, slide);
    if (FreeAccelIntoWall(sg_.RestingWall(), slide)) return;  // the contact force keeps its sign
    Release(0.0, sg_.v0);
  }
}

Event Simulation::LocateEvent() const {
  constexpr double window = kTau;
  Event ev;
  if (sg_.OnWall()) {
    // Moving with the capsule: it stops (v' = -sgn T0), or the contact force changes sign.
    if (sg_.Sliding()) ev.s = sg_.v0 / (sg_.sgn * sg_.T0);
    const bool upwards = sg_.RestingWall() == Wall::kLeft;  // F + b turns away from the wall
    const double s = FirstCrossing(sg_.f, -sg_.b, upwards, std::min(window, ev.s));
    if (s <= ev.s) ev = {s, EventKind::kRelease, Slide::kNone, false, {}};
    return ev;
  }
  Hit stop = NoHit();
  if (sg_.Sliding()) {
    stop = FirstStop(sg_, window);
    ev = {stop.at.phi, EventKind::kStop, Slide::kNone, true, stop.values};
  } else {
    const double back = FirstCrossing(sg_.f, sg_.T0, true, window);
    const double fwd = FirstCrossing(sg_.f, -sg_.T0, false, std::min(window, back));
    ev = {std::min(back, fwd),
          EventKind::kBreakaway,
          fwd <= back ? Slide::kForward : Slide::kBackward,
          false,
          {}};
  }
  const double limit = std::min(window, ev.s);
  const detail::CrossingList cuts = sg_.f.Crossings(-sg_.b, 0.0, limit);
  const Reach impact = FirstImpact(sg_, cuts, limit, stop.at.phi == limit ? &stop : nullptr);
  if (impact.hit.at.phi <= ev.s) {
    ev = {impact.hit.at.phi, impact.kind, Slide::kNone, true, impact.hit.values};
  }
  return ev;
}

Event Simulation::NextEvent() {
  if (!opt_.reuse_cycles) return LocateEvent();
  SegmentKey key;
  key.mode = sg_.mode;
  key.slide = sg_.slide;
  const double values[] = {r_, sg_.x0, sg_.u0, sg_.v0};
  static_assert(sizeof(values) == sizeof(key.bits));
  std::memcpy(key.bits.data(), values, sizeof(values));
  if (const Event* known = memo_.Find(key, turns_)) {
    ++res_.reused_events;
    return *known;
  }
  const Event event = LocateEvent();
  memo_.Add(key, event);
  return event;
}

void Simulation::ApplyEvent(const Event& event, double u_before, double v_before) {
  Slide hint = Slide::kNone;
  switch (event.kind) {
    case EventKind::kStop:
      sg_.v0 = 0.0;
      UpdateMode(Slide::kNone);
      Emit(EventKind::kStop, u_before, v_before);
      break;
    case EventKind::kBreakaway:
      hint = event.slide;
      UpdateMode(hint);
      Emit(EventKind::kBreakaway, u_before, v_before);
      break;
    case EventKind::kImpactRight:
      Impact(Wall::kRight);
      break;
    case EventKind::kImpactLeft:
      Impact(Wall::kLeft);
      break;
    case EventKind::kRelease:
      Release(u_before, v_before);
      break;
    case EventKind::kStick:  // decided by Settle, never located
      break;
  }
  Settle(hint);
}

void Simulation::CloseTally(SimTally& tally) const {
  tally.span = Phase() - span_phase0_;
  tally.displacement = sg_.y0 - span_y0_;
  tally.v_mean = tally.span > 0.0 ? tally.displacement / tally.span : kNaN;
}

void Simulation::EndTransient() {
  static_cast<SimTally&>(res_.transient) = static_cast<const SimTally&>(res_);
  CloseTally(res_.transient);
  static_cast<SimTally&>(res_) = SimTally{};
  if (opt_.energy) res_.energy = Energy{0.0, 0.0, 0.0, 0.0};
  span_phase0_ = Phase();
  span_y0_ = sg_.y0;
  in_transient_ = false;
  end_turns_ = opt_.transient + opt_.periods;
  chatter_.Clear();  // its records count the energy from the old span's start
}

bool Simulation::Fail(const char* what) {
  res_.status = SimStatus::kEventLimit;
  res_.message = fmt::format("{} at phase {:.17g} after {} events", what, Phase(),
                             res_.events + res_.transient.events);
  return true;
}

bool Simulation::StopIfNotFinite() {
  if (std::isfinite(sg_.x0) && std::isfinite(sg_.u0) && std::isfinite(sg_.v0) &&
      std::isfinite(sg_.y0)) {
    return false;
  }
  res_.status = SimStatus::kNonFinite;
  res_.message = fmt::format(
      "the state is not finite (x = {}, u = {}, v = {}, y = {}) at phase {:.17g} after {} "
      "events: velocities or positions beyond double precision",
      sg_.x0, sg_.u0, sg_.v0, sg_.y0, Phase(), res_.events);
  return true;
}

SimResult Simulation::Run() {
  sg_.alpha = opt_.alpha;
  sg_.T0 = params_.T0;
  // The levels the events look for (docs/model.md section 3): F = +-T0 (break-away, stop),
  // F = -b = 0, -+alpha T0 (the sign of x'' at rest and while sliding).
  levels_ = {params_.T0, -params_.T0, 0.0, opt_.alpha * params_.T0, -(opt_.alpha * params_.T0)};
  sg_.f.Prepare(forcing_, levels_.data(), static_cast<int>(levels_.size()),
                kLevelTol * force_scale_);
  sg_.f.Set(forcing_, 0.0);
  sg_.x0 = opt_.x0;
  sg_.u0 = opt_.u0;
  sg_.v0 = opt_.v0;
  sg_.y0 = opt_.y0;
  span_y0_ = opt_.y0;
  if (opt_.energy) res_.energy = Energy{0.0, 0.0, 0.0, 0.0};
  // The work bound, saturated: the product of two valid options may exceed int64.
  const double events_bound =
      static_cast<double>(opt_.max_events_per_period) * std::ceil(opt_.transient + opt_.periods);
  const std::int64_t max_events = events_bound >= 9.2e18 ? std::numeric_limits<std::int64_t>::max()
                                                         : static_cast<std::int64_t>(events_bound);
  int stalled = 0;
  res_.status = SimStatus::kOk;
  Settle(Slide::kNone);
  for (;;) {
    if (stop_ || StopIfNotFinite()) break;
    const std::int64_t impacts_right = res_.impacts_right + res_.transient.impacts_right;
    if (opt_.max_impacts_right > 0 && impacts_right >= opt_.max_impacts_right) {
      res_.status = SimStatus::kImpactLimit;
      break;
    }
    if (res_.events + res_.transient.events >= max_events &&
        Fail("work bound max_events_per_period reached")) {
      break;
    }
    const double rem = Remaining();
    bool boundary = rem <= 0.0;
    if (!boundary) {
      // Events are searched over a whole period whatever is left of the run, so where an
      // event is found (to the last bit) never depends on where the run ends; those beyond
      // the end (and its slack) are left to the next run.
      const double window = std::min(kTau, rem + kEndSlack);
      const Event event = NextEvent();
      if (event.s <= window) {
        stalled = event.s > 0.0 ? 0 : stalled + 1;
        if (stalled > kMaxStalledEvents && Fail("no progress in phase")) break;
        const SimState before = Advance(event.s, event.has_values ? &event.w : nullptr);
        if (stop_) break;
        ApplyEvent(event, before.u, before.v);
        continue;
      }
      const double step = std::min(window, rem);  // no event in the window
      Advance(step);
      if (stop_) break;
      boundary = step >= rem;
    }
    if (!boundary) continue;
    if (!in_transient_) break;
    EndTransient();
  }
  if (res_.status != SimStatus::kNonFinite && !stop_ && !StopIfNotFinite()) {
    EmitSamplesBefore(0.0, true);
  }
  res_.final_state = StateAt(0.0);
  if (in_transient_) {  // stopped inside the transient: its figures, and an empty record
    EndTransient();
    static_cast<SimTally&>(res_) = SimTally{};
  } else {
    CloseTally(res_);
  }
  return res_;
}

}  // namespace

const char* EventKindName(EventKind kind) {
  static constexpr const char* kNames[] = {"impact_right", "impact_left", "stop",
                                           "breakaway",    "stick",       "release"};
  static_assert(std::size(kNames) == static_cast<std::size_t>(EventKind::kRelease) + 1);
  return detail::EnumName(kNames, kind);
}

const char* SimModeName(SimMode mode) {
  static constexpr const char* kNames[] = {"rest", "slide_forward", "slide_backward",
                                           "on_right_wall", "on_left_wall"};
  static_assert(std::size(kNames) == static_cast<std::size_t>(SimMode::kOnLeftWall) + 1);
  return detail::EnumName(kNames, mode);
}

const char* SimStatusName(SimStatus status) {
  static constexpr const char* kNames[] = {"not_run", "ok", "impact_limit", "event_limit",
                                           "non_finite"};
  static_assert(std::size(kNames) == static_cast<std::size_t>(SimStatus::kNonFinite) + 1);
  return detail::EnumName(kNames, status);
}

void SimOptions::Validate() const {
  Require(alpha > 0.0 && alpha < 1.0, "mass ratio alpha", alpha, "0 < alpha < 1");
  Require(x0 >= 0.0 && x0 <= 1.0, "initial position x0", x0, "0 <= x0 <= 1");
  Require(std::isfinite(u0), "initial relative velocity u0", u0, "a finite number");
  Require(std::isfinite(v0), "initial capsule velocity v0", v0, "a finite number");
  Require(std::isfinite(y0), "initial capsule position y0", y0, "a finite number");
  Require(transient >= 0.0 && transient <= 1e8, "transient", transient, "0 <= transient <= 1e8");
  Require(periods > 0.0 && periods <= 1e8, "periods", periods, "0 < periods <= 1e8");
  if (max_impacts_right < 0) {
    throw std::invalid_argument(fmt::format(
        "max_impacts_right = {} is invalid: expected >= 0 (0: no limit)", max_impacts_right));
  }
  Require(chatter_velocity > 0.0 && std::isfinite(chatter_velocity), "chatter_velocity",
          chatter_velocity, "a finite number > 0");
  Require(chatter_tolerance > 0.0 && std::isfinite(chatter_tolerance), "chatter_tolerance",
          chatter_tolerance, "a finite number > 0");
  if (max_events_per_period < 10) {
    throw std::invalid_argument(fmt::format("max_events_per_period = {} is invalid: expected >= 10",
                                            max_events_per_period));
  }
  Require(sample_step >= 0.0 && std::isfinite(sample_step), "sample_step", sample_step,
          "a finite number >= 0 (0: no samples)");
}

SimResult Simulate(const Forcing& forcing, const Params& params, const SimOptions& options,
                   SimObserver* observer) {
  params.Validate();
  options.Validate();
  Simulation sim(forcing, params, options, observer);
  return sim.Run();
}

}  // namespace capsubot
