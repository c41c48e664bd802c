#include "capsubot/simulator.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "numerics/brent.hpp"

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
// kChatterSpan in phase of the previous one, end in the body resting on the wall.
constexpr int kMaxChatterImpacts = 10000;
constexpr double kChatterSpan = 1e-3;
// More consecutive events than this without any progress in phase: report, never hang.
constexpr int kMaxStalledEvents = 1000;

void Require(bool ok, const char* name, double value, const char* rule) {
  if (!ok) {
    throw std::invalid_argument(fmt::format("{} = {} is invalid: expected {}", name, value, rule));
  }
}

// The motion inside one mode in closed form (docs/model.md section 3), in the local phase s
// measured from the segment's origin; f is the force seen from there: f.F(s) = F(origin + s).
//   free modes:  x'' = kx (F + b),  kx = 1/alpha (rest) or 1/(alpha (1-alpha)) (slide),
//                b = sgn alpha T0 (sgn = +1 forward slide, -1 backward, 0 rest);
//                (1-alpha) v' = -(sgn T0 + F) while sliding.
//   on a wall:   x, u = 0 fixed; the capsule and the inner body move together: v' = -sgn T0.
struct Segment {
  Forcing f;
  SimMode mode = SimMode::kRest;
  double alpha = 0.0, T0 = 0.0;
  double x0 = 0.0, u0 = 0.0, v0 = 0.0, y0 = 0.0;
  double sgn = 0.0, kx = 0.0, b = 0.0;
  double tol = 0.0;  // |F - level| below this is "on the level" (kLevelTol * force scale)

  bool OnWall() const { return mode == SimMode::kOnRightWall || mode == SimMode::kOnLeftWall; }
  bool Sliding() const { return sgn != 0.0; }

  double X(double s) const {
    if (OnWall()) return x0;
    return x0 + u0 * s + kx * (f.Phi(s) + 0.5 * b * s * s);
  }
  double U(double s) const {
    if (OnWall()) return 0.0;
    return u0 + kx * (f.Pi(s) + b * s);
  }
  double V(double s) const {
    if (!Sliding()) return 0.0;
    if (OnWall()) return v0 - sgn * T0 * s;
    return v0 - (sgn * T0 * s + f.Pi(s)) / (1.0 - alpha);
  }
  double Y(double s) const {
    if (!Sliding()) return y0;
    if (OnWall()) return y0 + v0 * s - 0.5 * sgn * T0 * s * s;
    return y0 + v0 * s - (0.5 * sgn * T0 * s * s + f.Phi(s)) / (1.0 - alpha);
  }
};

// Friction direction and x'' coefficients of a capsule mode.
void SetCoefficients(Segment& sg, double sgn) {
  sg.sgn = sgn;
  sg.kx = sgn == 0.0 ? 1.0 / sg.alpha : 1.0 / (sg.alpha * (1.0 - sg.alpha));
  sg.b = sgn * sg.alpha * sg.T0;
}

// First s in (0, limit] where the inner body reaches the wall `level` (1 or 0), moving towards
// it: the first zero of f(s) = dir (x(s) - level) from below, dir = +1 right wall, -1 left.
// x'' = kx (F + b) keeps its sign between consecutive crossings of F = -b (`cuts`), so on each
// piece f is convex or concave and has at most two zeros:
//   - f(l) < 0 <= f(r): exactly one crossing, found by the root finder;
//   - f(l) < 0, f(r) < 0, convex: no zero;
//   - f(l) < 0, f(r) < 0, concave: a zero only if the maximum (the unique zero of the monotone
//     f' = dir u) reaches 0; two tangent lines bound the maximum cheaply, else the root of f'
//     gives it exactly, and if f(max) >= 0 (including a grazing touch) the root on [l, max]
//     gives the first crossing;
//   - piece starting on the wall (f(0) = 0, leaving it): concave cannot come back; convex
//     comes back only after its minimum (root of f'), then as above; a piece with F + b = 0
//     within rounding (sg.tol) is neither: the body stays where it is.
// Root finder: detail::SafeNewton (Newton with the closed-form derivative, kept inside the
// bracket, bisection fallback), to ~1e-14 in phase: quadratic, and it holds no solver state.
// Returns +inf when there is no zero in (0, limit].
double FirstReach(const Segment& sg, double level, double dir, const PhaseList& cuts,
                  double limit) {
  const auto f = [&](double s) { return dir * (sg.X(s) - level); };
  const auto df = [&](double s) { return dir * sg.U(s); };
  const auto ddf = [&](double s) { return dir * sg.kx * (sg.f.F(s) + sg.b); };
  double l = 0.0, fl = f(0.0);
  const bool start_on_wall = fl >= 0.0;
  int next_cut = 0;
  while (l < limit) {
    while (next_cut < cuts.n && cuts.phi[next_cut] <= l + kMinCut) ++next_cut;
    const double r = next_cut < cuts.n ? std::min(cuts.phi[next_cut], limit) : limit;
    const double fr = f(r);
    const double curvature = dir * (sg.f.F(0.5 * (l + r)) + sg.b);  // sign of f'' on (l, r)
    if (l == 0.0 && start_on_wall) {
      if (curvature > sg.tol && fr >= 0.0) {
        // Convex, leaving the wall: it returns after its minimum.
        double lo = 0.0;
        if (df(0.0) < 0.0 && df(r) > 0.0) lo = detail::SafeNewton(df, ddf, 0.0, r);
        if (f(lo) < 0.0) return detail::SafeNewton(f, df, lo, r);
        return l;  // pressed into the wall (the caller settles this case first)
      }
    } else if (fl < 0.0 && fr >= 0.0) {
      return detail::SafeNewton(f, df, l, r);
    } else if (fl < 0.0 && curvature < 0.0) {
      const double dl = df(l), dr = df(r);
      if (dl > 0.0 && dr < 0.0) {
        // Concave with an interior maximum: bound it by the two tangents first.
        const double st = (fr - fl - dr * r + dl * l) / (dl - dr);
        const double bound = fl + dl * (st - l);
        if (bound >= 0.0) {
          const double smax = detail::SafeNewton(df, ddf, l, r);
          if (f(smax) >= 0.0) return detail::SafeNewton(f, df, l, smax);
        }
      }
    }
    l = r;
    fl = fr;
  }
  return kInf;
}

// First s in (0, limit] where the sliding capsule stops: v' = -(sgn T0 + F)/(1-alpha) keeps its
// sign between the crossings of F = -sgn T0, so v is monotone on each piece and the first
// piece whose end has sgn v <= 0 brackets the unique stop.
double FirstStop(const Segment& sg, double limit) {
  const auto v = [&](double s) { return sg.V(s); };
  const auto dv = [&](double s) { return -(sg.sgn * sg.T0 + sg.f.F(s)) / (1.0 - sg.alpha); };
  const PhaseList cuts = sg.f.Crossings(-sg.sgn * sg.T0, 0.0, limit);
  double l = 0.0;
  int i = 0;
  while (l < limit) {
    while (i < cuts.n && cuts.phi[i] <= l + kMinCut) ++i;
    const double r = i < cuts.n ? std::min(cuts.phi[i], limit) : limit;
    if (sg.sgn * v(r) <= 0.0) return detail::SafeNewton(v, dv, l, r);
    l = r;
  }
  return kInf;
}

// The first crossing of `level` after l + kMinCut, with `cuts` = the crossings in [0, tau)
// repeated with period tau (F is tau-periodic); l + tau if there is none.
double NextCut(const PhaseList& cuts, double l) {
  for (int m = 0; m < 2; ++m) {
    for (int i = 0; i < cuts.n; ++i) {
      const double c = cuts.phi[i] + m * kTau;
      if (c > l + kMinCut) return c;
    }
  }
  return l + kTau;
}

// Sign of F - level on the open piece (l, r) between consecutive crossings of the level:
// +1 or -1, or 0 when |F - level| <= tol in its middle (a touch, or a piece too short to
// matter: F stays on the level within rounding). Deciding on the piece, never from dF at a
// crossing, makes a tangential touch (dF = rounding noise of either sign) no crossing.
double PieceSign(const Forcing& f, double level, double tol, double l, double r) {
  const double g = f.F(0.5 * (l + r)) - level;
  return g > tol ? 1.0 : g < -tol ? -1.0 : 0.0;
}

// Sign of F - level right after s = 0: on the first piece after 0 (first_only), or on the
// first piece within a period where F leaves the level by more than tol (0: none).
double SignAfterOrigin(const Forcing& f, double level, double tol, bool first_only) {
  const PhaseList cuts = f.Crossings(level, 0.0, kTau);
  double l = 0.0;
  while (l < kTau) {
    const double r = NextCut(cuts, l);
    const double sign = PieceSign(f, level, tol, l, r);
    if (sign != 0.0 || first_only) return sign;
    l = r;
  }
  return 0.0;
}

// First s in [0, limit] where F crosses `level` in direction `dir` (+1 upwards, -1 downwards):
// the start of the first piece between exact crossings (Forcing::Crossings) on which
// dir (F - level) > tol. A tangential touch (no sign change across it) does not count; s = 0
// when F leaves the level that way right from the start.
double FirstCrossing(const Forcing& f, double level, double dir, double tol, double limit) {
  const PhaseList cuts = f.Crossings(level, 0.0, kTau);
  double l = 0.0;
  while (l <= limit) {
    const double r = NextCut(cuts, l);
    if (dir * PieceSign(f, level, tol, l, r) > 0.0) return l;
    l = r;
  }
  return kInf;
}

class Simulation {
 public:
  Simulation(const Forcing& forcing, const Params& params, const SimOptions& opt,
             SimObserver* observer)
      : forcing_(forcing), params_(params), opt_(opt), observer_(observer) {
    force_scale_ = params.T0 + forcing.MaxAbs();
    end_turns_ = opt.periods;
  }

  SimResult Run();

 private:
  double Phase() const { return static_cast<double>(turns_) * kTau + r_; }
  double Remaining() const { return (end_turns_ - static_cast<double>(turns_)) * kTau - r_; }
  // Start a new segment at local phase s of the current one with the given state.
  void Rebase(double s);
  SimState StateAt(double s) const;
  void Emit(EventKind kind, double u_before, double v_before);
  void EmitSamplesBefore(double s_end, bool final);
  // Instantaneous transitions at the origin: impacts with inward velocity, choice of the
  // capsule mode when v = 0, sticking to and leaving a wall. `hint` is the slide direction
  // of a break-away (0 if none).
  void Settle(double hint);
  void Impact(double dir);
  // Sets the capsule mode at the origin from v (and F when v = 0) without other transitions.
  void UpdateMode(double hint);
  double RestOrSlide(double hint) const;
  bool FreeAccelIntoWall(double dir, double sgn) const;
  bool Fail(const char* what);
  // Ends the run with kNonFinite when the stored state holds inf or NaN; true if it did.
  bool StopIfNotFinite();

  const Forcing& forcing_;
  const Params& params_;
  const SimOptions& opt_;
  SimObserver* observer_;
  double force_scale_ = 0.0;
  double end_turns_ = 0.0;
  std::int64_t turns_ = 0;  // origin phase = turns_ * tau + r_, r_ in [0, tau)
  double r_ = 0.0;
  Segment sg_;
  SimResult res_;
  std::int64_t next_sample_ = 0;
  int chatter_count_ = 0;
  double last_impact_phase_ = -kInf;
  double last_impact_dir_ = 0.0;
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
  st.phi = Phase() + s;
  st.x = sg_.X(s);
  st.u = sg_.U(s);
  st.v = sg_.V(s);
  st.y = sg_.Y(s);
  return st;
}

void Simulation::Rebase(double s) {
  const SimState st = StateAt(s);
  r_ += s;
  const std::int64_t turns_before = turns_;
  while (r_ >= kTau) {
    r_ -= kTau;
    ++turns_;
  }
  if (observer_ != nullptr && turns_ != turns_before) observer_->OnPeriods(turns_);
  sg_.f = forcing_.WithPhase(forcing_.phi0() + r_);
  sg_.x0 = st.x;
  sg_.u0 = st.u;
  sg_.v0 = st.v;
  sg_.y0 = st.y;
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
void Simulation::EmitSamplesBefore(double s_end, bool final) {
  if (observer_ == nullptr || !(opt_.sample_step > 0.0)) return;
  const double origin = Phase(), end = opt_.periods * kTau, slack = 1e-12 * (1.0 + end);
  for (;;) {
    const double p = static_cast<double>(next_sample_) * opt_.sample_step;
    if (p > end + slack) return;
    const double s = p - origin;
    if (!final && s >= s_end) return;
    observer_->OnSample(StateAt(std::max(s, 0.0)));
    ++next_sample_;
  }
}

// The free relative acceleration x'' = kx (F + b) at the origin, for capsule mode sgn, points
// into the wall dir (+1 right, -1 left); for a body resting on the wall this is the sign of
// the contact force (docs/model.md section 3 with u' = 0). It is the sign of F + b on the first
// piece (between crossings of F with -b) after the origin where it is not zero within
// rounding: a contact force that only touches zero, or is zero for an instant, keeps the body
// on the wall (the same pieces decide a release in Run, so the two never disagree).
bool Simulation::FreeAccelIntoWall(double dir, double sgn) const {
  const double level = -sgn * sg_.alpha * sg_.T0, tol = kLevelTol * force_scale_;
  const double g = sg_.f.F(0.0) - level;
  if (std::abs(g) > 1e3 * tol) return dir * g > 0.0;  // far from the level: no crossing near
  return dir * SignAfterOrigin(sg_.f, level, tol, false) > 0.0;
}

// Capsule at v = 0 (docs/model.md section 3): rest while |F| <= T0; it slides forward once
// -F > T0, backward once F > T0. Returns the friction sign of the mode (0 = rest). On the
// level within rounding, the sign of F -+ T0 on the piece right after the origin decides: a
// force that only touches +-T0 is no break-away.
double Simulation::RestOrSlide(double hint) const {
  if (hint != 0.0) return hint;
  const double F = sg_.f.F(0.0), T0 = sg_.T0, tol = kLevelTol * force_scale_;
  if (F > T0 + tol) return -1.0;
  if (F < -T0 - tol) return 1.0;
  if (F > T0 - tol && SignAfterOrigin(sg_.f, T0, tol, true) > 0.0) return -1.0;
  if (F < -T0 + tol && SignAfterOrigin(sg_.f, -T0, tol, true) < 0.0) return 1.0;
  return 0.0;
}

// Impact with wall dir (docs/model.md section 3): u+ = -e u, v+ = v + alpha (1+e) u. A slow impact
// (|u| < chatter_velocity, or the end of a long run of close impacts) with the body pushed
// into the wall is taken as plastic: it ends a chattering sequence with the momentum of its
// remaining impacts (u+ = 0, v+ = v + alpha u); Settle then makes the body rest on the wall.
void Simulation::Impact(double dir) {
  const double u = sg_.u0, v = sg_.v0, phase = Phase();
  if (dir == last_impact_dir_ && phase - last_impact_phase_ < kChatterSpan) {
    ++chatter_count_;
  } else {
    chatter_count_ = 1;
  }
  last_impact_dir_ = dir;
  last_impact_phase_ = phase;
  sg_.x0 = dir > 0.0 ? 1.0 : 0.0;
  bool plastic = false;
  if (std::abs(u) < opt_.chatter_velocity || chatter_count_ > kMaxChatterImpacts) {
    const double v_plastic = v + sg_.alpha * u;
    const double sgn = v_plastic > 0.0 ? 1.0 : v_plastic < 0.0 ? -1.0 : 0.0;
    sg_.v0 = v_plastic;
    plastic = FreeAccelIntoWall(dir, sgn != 0.0 ? sgn : RestOrSlide(0.0));
  }
  if (plastic) {
    sg_.u0 = 0.0;
    sg_.v0 = v + sg_.alpha * u;
  } else {
    sg_.u0 = -params_.e * u;
    sg_.v0 = v + sg_.alpha * (1.0 + params_.e) * u;
  }
  if (sg_.u0 == 0.0) sg_.u0 = 0.0;  // no -0
  UpdateMode(0.0);
  Emit(dir > 0.0 ? EventKind::kImpactRight : EventKind::kImpactLeft, u, v);
}

void Simulation::UpdateMode(double hint) {
  const double sgn = sg_.v0 > 0.0   ? 1.0
                     : sg_.v0 < 0.0 ? -1.0
                     : sg_.OnWall() ? 0.0
                                    : RestOrSlide(hint);
  SetCoefficients(sg_, sgn);
  if (sg_.OnWall()) return;
  sg_.mode = sgn > 0.0   ? SimMode::kSlideForward
             : sgn < 0.0 ? SimMode::kSlideBackward
                         : SimMode::kRest;
}

void Simulation::Settle(double hint) {
  for (int iter = 0; iter < 8; ++iter) {
    if (!sg_.OnWall()) {
      if (sg_.x0 >= 1.0 && sg_.u0 > 0.0) {
        Impact(1.0);
        hint = 0.0;
        continue;
      }
      if (sg_.x0 <= 0.0 && sg_.u0 < 0.0) {
        Impact(-1.0);
        hint = 0.0;
        continue;
      }
      UpdateMode(hint);
      const double sgn = sg_.sgn;
      if (sg_.u0 == 0.0 && (sg_.x0 >= 1.0 || sg_.x0 <= 0.0)) {
        const double dir = sg_.x0 >= 1.0 ? 1.0 : -1.0;
        if (FreeAccelIntoWall(dir, sgn)) {
          sg_.mode = dir > 0.0 ? SimMode::kOnRightWall : SimMode::kOnLeftWall;
          sg_.x0 = dir > 0.0 ? 1.0 : 0.0;
          Emit(EventKind::kStick, 0.0, sg_.v0);
        }
      }
      return;
    }
    const double dir = sg_.mode == SimMode::kOnRightWall ? 1.0 : -1.0;
    const double sgn = sg_.v0 > 0.0 ? 1.0 : sg_.v0 < 0.0 ? -1.0 : 0.0;
    SetCoefficients(sg_, sgn);
    if (FreeAccelIntoWall(dir, sgn)) return;  // the contact force keeps its sign
    sg_.mode = SimMode::kRest;                // free
    sg_.u0 = 0.0;
    UpdateMode(0.0);
    Emit(EventKind::kRelease, 0.0, sg_.v0);
  }
}

bool Simulation::Fail(const char* what) {
  res_.status = SimStatus::kEventLimit;
  res_.message = fmt::format("{} at phase {:.17g} after {} events", what, Phase(), res_.events);
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
  sg_.f = forcing_;
  sg_.x0 = opt_.x0;
  sg_.u0 = opt_.u0;
  sg_.v0 = opt_.v0;
  sg_.y0 = opt_.y0;
  // The work bound, saturated: the product of two valid options may exceed int64.
  const double events_bound =
      static_cast<double>(opt_.max_events_per_period) * std::ceil(opt_.periods);
  const std::int64_t max_events = events_bound >= 9.2e18 ? std::numeric_limits<std::int64_t>::max()
                                                         : static_cast<std::int64_t>(events_bound);
  const double tol = kLevelTol * force_scale_;
  sg_.tol = tol;
  int stalled = 0;
  res_.status = SimStatus::kOk;
  Settle(0.0);
  for (;;) {
    if (StopIfNotFinite()) break;
    if (opt_.max_impacts_right > 0 && res_.impacts_right >= opt_.max_impacts_right) {
      res_.status = SimStatus::kImpactLimit;
      break;
    }
    if (res_.events >= max_events && Fail("work bound max_events_per_period reached")) break;
    const double rem = Remaining();
    if (rem <= 0.0) break;
    const double W = std::min(kTau, rem + kEndSlack);
    double best = kInf, hint = 0.0;
    EventKind kind = EventKind::kStop;
    if (sg_.OnWall()) {
      const double dir = sg_.mode == SimMode::kOnRightWall ? 1.0 : -1.0;
      if (sg_.Sliding()) best = sg_.v0 / (sg_.sgn * sg_.T0);
      const double s = FirstCrossing(sg_.f, -sg_.b, -dir, tol, std::min(W, best));
      if (s <= best) {
        best = s;
        kind = EventKind::kRelease;
      }
    } else {
      if (sg_.Sliding()) {
        best = FirstStop(sg_, W);
      } else {
        const double back = FirstCrossing(sg_.f, sg_.T0, 1.0, tol, W);
        const double fwd = FirstCrossing(sg_.f, -sg_.T0, -1.0, tol, std::min(W, back));
        best = std::min(back, fwd);
        hint = fwd <= back ? 1.0 : -1.0;
        kind = EventKind::kBreakaway;
      }
      const double limit = std::min(W, best);
      const PhaseList cuts = sg_.f.Crossings(-sg_.b, 0.0, limit);
      const double right = FirstReach(sg_, 1.0, 1.0, cuts, limit);
      if (right <= best) {
        best = right;
        kind = EventKind::kImpactRight;
      }
      const double left = FirstReach(sg_, 0.0, -1.0, cuts, std::min(limit, best));
      if (left <= best) {
        best = left;
        kind = EventKind::kImpactLeft;
      }
    }
    if (!(best <= W)) {  // no event in the window
      const double step = std::min(W, rem);
      EmitSamplesBefore(step, false);
      Rebase(step);
      if (step >= rem) break;
      continue;
    }
    stalled = best > 0.0 ? 0 : stalled + 1;
    if (stalled > kMaxStalledEvents && Fail("no progress in phase")) break;
    EmitSamplesBefore(best, false);
    const double u_before = sg_.U(best), v_before = sg_.V(best);
    Rebase(best);
    switch (kind) {
      case EventKind::kStop:
        sg_.v0 = 0.0;
        UpdateMode(0.0);
        Emit(EventKind::kStop, u_before, v_before);
        Settle(0.0);
        break;
      case EventKind::kBreakaway:
        UpdateMode(hint);
        Emit(EventKind::kBreakaway, u_before, v_before);
        Settle(hint);
        break;
      case EventKind::kImpactRight:
      case EventKind::kImpactLeft:
        sg_.x0 = kind == EventKind::kImpactRight ? 1.0 : 0.0;
        Impact(kind == EventKind::kImpactRight ? 1.0 : -1.0);
        Settle(0.0);
        break;
      case EventKind::kRelease:
        sg_.mode = SimMode::kRest;
        sg_.u0 = 0.0;
        UpdateMode(0.0);
        Emit(EventKind::kRelease, u_before, v_before);
        Settle(0.0);
        break;
      case EventKind::kStick:
        break;
    }
  }
  if (res_.status != SimStatus::kNonFinite && !StopIfNotFinite()) EmitSamplesBefore(0.0, true);
  res_.final_state = StateAt(0.0);
  res_.displacement = res_.final_state.y - opt_.y0;
  res_.v_mean =
      res_.final_state.phi > 0.0 ? res_.displacement / res_.final_state.phi : SimResult::kNaN;
  return res_;
}

}  // namespace

const char* EventKindName(EventKind kind) {
  switch (kind) {
    case EventKind::kImpactRight:
      return "impact_right";
    case EventKind::kImpactLeft:
      return "impact_left";
    case EventKind::kStop:
      return "stop";
    case EventKind::kBreakaway:
      return "breakaway";
    case EventKind::kStick:
      return "stick";
    case EventKind::kRelease:
      return "release";
  }
  return "unknown";
}

const char* SimModeName(SimMode mode) {
  switch (mode) {
    case SimMode::kRest:
      return "rest";
    case SimMode::kSlideForward:
      return "slide_forward";
    case SimMode::kSlideBackward:
      return "slide_backward";
    case SimMode::kOnRightWall:
      return "on_right_wall";
    case SimMode::kOnLeftWall:
      return "on_left_wall";
  }
  return "unknown";
}

const char* SimStatusName(SimStatus status) {
  switch (status) {
    case SimStatus::kNotRun:
      return "not_run";
    case SimStatus::kOk:
      return "ok";
    case SimStatus::kImpactLimit:
      return "impact_limit";
    case SimStatus::kEventLimit:
      return "event_limit";
    case SimStatus::kNonFinite:
      return "non_finite";
  }
  return "unknown";
}

void SimOptions::Validate() const {
  Require(alpha > 0.0 && alpha < 1.0, "mass ratio alpha", alpha, "0 < alpha < 1");
  Require(x0 >= 0.0 && x0 <= 1.0, "initial position x0", x0, "0 <= x0 <= 1");
  Require(std::isfinite(u0), "initial relative velocity u0", u0, "a finite number");
  Require(std::isfinite(v0), "initial capsule velocity v0", v0, "a finite number");
  Require(std::isfinite(y0), "initial capsule position y0", y0, "a finite number");
  Require(periods > 0.0 && periods <= 1e8, "periods", periods, "0 < periods <= 1e8");
  if (max_impacts_right < 0) {
    throw std::invalid_argument(fmt::format(
        "max_impacts_right = {} is invalid: expected >= 0 (0: no limit)", max_impacts_right));
  }
  Require(chatter_velocity > 0.0 && std::isfinite(chatter_velocity), "chatter_velocity",
          chatter_velocity, "a finite number > 0");
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
