// The m2 search of Design against a dense brute-force scan over m2 written here: on a table of
// robots (drawn at random, plus a robot whose only window is 1.5 % of m2 wide, next to the fold
// where its orbits end), every window of robust gaits that the scan sees lies inside a window
// the design brackets, the design says no_gait only when the scan sees no gait, and its speed
// is at least the scan's best refined locally.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "capsubot/design/design.hpp"
#include "design/search.hpp"

namespace capsubot {
namespace {

// The design's speed against the scan's best refined: both converge to the same maximum (an
// interior one, or a cliff at a window's edge) to ~1e-9 in log(m2).
constexpr double kSpeedRelTol = 1e-6;
// m2 of the scan and of the design's brackets are computed by different exp() calls.
constexpr double kM2RelTol = 1e-12;
// Samples of the reference scan, log-spaced over [M2Min, M2Max] (spacing 3.5e-4 in log m2
// over the default range 0.01 m1 to 10 m1); the table's random robots use fewer, to keep the
// test's run time reasonable.
constexpr int kDenseScan = 20000;
// The design's best m2 against the scan's best refined, in log(m2): both resolve the same
// maximum (here a cliff at the window's edge) far below the scan's spacing.
constexpr double kBestLogM2Tol = 1e-6;
constexpr int kTableScan = 6000;

enum Requirements { kDefault, kMarginsOff, kNoStability };

struct Robot {
  double m1, L, mu, e, amplitude, bias, frequency;
  Requirements requirements;
};

DesignInput Input(const Robot& r) {
  DesignInput in;
  in.m1 = r.m1;
  in.L = r.L;
  in.mu = r.mu;
  in.e = r.e;
  in.force.amplitude = r.amplitude;
  in.force.bias = r.bias;
  in.frequency_min = in.frequency_max = r.frequency;
  if (r.requirements != kDefault) {
    in.margin = in.margin_stroke = in.stick_margin = 0.0;
    in.rho_max = r.requirements == kMarginsOff ? 1.0 : INFINITY;
  }
  return in;
}

// What a scan of log-spaced m2 (or f) sees: each window (a run of robots with a gait, by its
// first and last value) and the fastest robot, refined by local grids that shrink around it.
struct Reference {
  std::vector<std::pair<double, double>> windows;
  double best_value = NAN;  // the best m2 (or frequency), refined
  double best_speed = NAN;
};

// The speed of the robot's gait (-infinity without one).
double Speed(const DesignInput& in, double m2, double frequency) {
  const Gait g = EvaluateGait(in, m2, frequency);
  return g.ok() ? g.speed_mm_s : -INFINITY;
}

// A scan of speed_at(v) at n log-spaced v over [lo_value, hi_value].
template <class SpeedFn>
Reference Scan(const SpeedFn& speed_at, double lo_value, double hi_value, int n) {
  const double lo = std::log(lo_value), hi = std::log(hi_value);
  const auto value_at = [&](int i) { return std::exp(lo + (hi - lo) * i / (n - 1)); };
  Reference r;
  int best = -1;
  std::vector<double> speed(n);
  for (int i = 0; i < n; ++i) {
    speed[i] = speed_at(value_at(i));
    if (speed[i] == -INFINITY) continue;
    if (i == 0 || speed[i - 1] == -INFINITY) r.windows.push_back({value_at(i), 0.0});
    r.windows.back().second = value_at(i);
    if (best < 0 || speed[i] > speed[best]) best = i;
  }
  if (best < 0) return r;
  // Local grids of 11 points between the best point's neighbours, 16 times: the bracket
  // shrinks five-fold each time, from the scan's spacing to below 1e-12 of it.
  double a = std::log(value_at(std::max(best - 1, 0)));
  double c = std::log(value_at(std::min(best + 1, n - 1)));
  double x = std::log(value_at(best));
  r.best_speed = speed[best];
  for (int round = 0; round < 16; ++round) {
    const double step = (c - a) / 10.0;
    for (int k = 0; k <= 10; ++k) {
      const double y = a + step * k, v = speed_at(std::exp(y));
      if (v > r.best_speed) {
        r.best_speed = v;
        x = y;
      }
    }
    a = std::max(a, x - step);
    c = std::min(c, x + step);
  }
  r.best_value = std::exp(x);
  return r;
}

Reference ScanM2(const DesignInput& in, int n) {
  return Scan([&](double m2) { return Speed(in, m2, in.frequency_min); }, in.M2Min(), in.M2Max(),
              n);
}

// A robot of the former search's blind spot: its only window, m2 in [0.6497, 0.66] kg, lies
// between two of the 64 scan samples of [0.01, 10] kg and ends at a fold of alpha(phi0); the
// scan saw x_min < 0 on one side and no orbit on the other.
constexpr Robot kNarrowWindowRobot = {1.0, 0.02, 0.4, 0.5, 3.0, 0.8, 4.0, kMarginsOff};

// Robots drawn at random: m1 in [0.05, 5] kg, L in [5, 50] mm, motor amplitude 0.1 to 3 times
// mu m1 g and bias 0.05 to 0.6 times the amplitude, f in [2, 40] Hz (log-uniform), mu in
// [0.1, 0.8] and e in [0, 1] (uniform), the requirements in turn; rounded to 4 digits. Of
// them, the robots marked "missed" had a gait that the former search (a scan of 64 robots and
// golden-section refinement around the best) did not find, or found a slower one (checked by
// linking this table with the library before the bracketing).
constexpr Robot kTable[] = {
    {0.09262, 0.006845, 0.416, 0.021, 0.1246, 0.06871, 8.194, kMarginsOff},
    {3.208, 0.03542, 0.649, 0.925, 4.824, 0.6018, 3.919, kNoStability},
    {0.6554, 0.007848, 0.513, 0.346, 2.215, 0.5508, 18.21, kDefault},
    {1.109, 0.005463, 0.258, 0.676, 0.3814, 0.03928, 2.951, kNoStability},
    {1.783, 0.01816, 0.662, 0.807, 3.775, 0.7585, 9.74, kDefault},  // missed
    {0.4648, 0.04136, 0.704, 0.86, 0.6367, 0.2562, 5.034, kNoStability},
    {0.7971, 0.04099, 0.287, 0.607, 0.2535, 0.1177, 7.915, kMarginsOff},
    {0.8309, 0.01268, 0.113, 0.372, 0.2496, 0.08787, 36.46, kMarginsOff},
    {0.2165, 0.03357, 0.163, 0.603, 0.1362, 0.07212, 2.419, kMarginsOff},   // missed
    {4.051, 0.02264, 0.274, 0.593, 3.554, 1.535, 2.829, kMarginsOff},       // missed
    {0.08306, 0.02195, 0.354, 0.617, 0.1741, 0.07293, 4.031, kDefault},     // missed
    {0.1143, 0.01859, 0.195, 0.438, 0.2976, 0.04917, 2.647, kNoStability},  // missed
    {0.5087, 0.00542, 0.78, 0.065, 10.85, 0.6448, 15.9, kMarginsOff},       // missed
    {2.21, 0.02114, 0.33, 0.226, 6.02, 2.261, 26.49, kMarginsOff},          // missed
    {0.2014, 0.03375, 0.284, 0.675, 1.45, 0.2081, 2.87, kMarginsOff},       // missed
    {0.05971, 0.01072, 0.453, 0.786, 0.2699, 0.1503, 9.42, kNoStability},   // missed
    {1.87, 0.00736, 0.631, 0.284, 6.35, 1.576, 7.686, kNoStability},        // missed
    {0.2693, 0.01758, 0.485, 0.439, 0.2318, 0.09303, 3.275, kNoStability},  // missed (slower)
    {1.938, 0.006435, 0.555, 0.3, 9.597, 2.633, 10.24, kDefault},           // missed
    {0.1703, 0.01795, 0.365, 0.587, 0.2291, 0.0843, 3.122, kNoStability},   // missed (slower)
    {2.64, 0.01765, 0.15, 0.633, 3.098, 1.118, 2.819, kDefault},            // missed
    // A faster orbit becomes the gait just before the fold where it ends: two speed maxima
    // in one window (8.51 mm/s at 0.096 kg, 8.70 mm/s at 0.210 kg).
    {0.3217, 0.01467, 0.674, 0.738, 0.7917, 0.2926, 4.306, kNoStability},  // missed (slower)
};

// Checks the design of one robot against the scan `ref` of its m2; returns the windows the scan
// saw.
int ExpectDesignFindsEveryWindowOfTheScan(const Robot& robot, const Reference& ref, int row) {
  const DesignInput in = Input(robot);
  std::vector<detail::M2Window> windows;
  const Gait bracketed = detail::BestOverM2(in, in.frequency_min, &windows);
  const DesignResult r = Design(in);
  EXPECT_EQ(r.one_impact.status, bracketed.status) << "row " << row;
  if (bracketed.ok()) {
    EXPECT_EQ(r.one_impact.m2_kg, bracketed.m2_kg) << "row " << row;
  }
  for (const auto& [first, last] : ref.windows) {
    bool inside = false;
    for (const detail::M2Window& w : windows) {
      inside = inside ||
               (w.outer_lo <= first * (1.0 + kM2RelTol) && last <= w.outer_hi * (1.0 + kM2RelTol));
    }
    EXPECT_TRUE(inside) << "row " << row << ": the scan's window [" << first << ", " << last
                        << "] kg is in no window of the design (" << windows.size() << ")";
  }
  if (ref.windows.empty()) {
    // The design may find a window narrower than the scan's spacing; never a false one.
    if (r.status == DesignStatus::kOk) {
      EXPECT_TRUE(EvaluateGait(in, r.one_impact.m2_kg, in.frequency_min).ok()) << "row " << row;
    }
    return 0;
  }
  if (r.status != DesignStatus::kOk) {
    ADD_FAILURE() << "row " << row << ": " << r.message;
    return static_cast<int>(ref.windows.size());
  }
  EXPECT_TRUE(EvaluateGait(in, r.one_impact.m2_kg, in.frequency_min).ok()) << "row " << row;
  EXPECT_GE(r.one_impact.speed_mm_s, ref.best_speed * (1.0 - kSpeedRelTol))
      << "row " << row << ": design m2 = " << r.one_impact.m2_kg
      << " kg, scan m2 = " << ref.best_value << " kg";
  // It may be faster than the scan: in a window narrower than the scan's spacing (checked
  // here: no window of the scan holds its m2), or at the other of two local maxima of one
  // window, which the scan's local refinement does not reach (one of 250 other random robots
  // has its speed maxima at both edges of its window; none of the table).
  if (r.one_impact.speed_mm_s > ref.best_speed * (1.0 + kSpeedRelTol)) {
    for (const auto& [first, last] : ref.windows) {
      EXPECT_FALSE(first <= r.one_impact.m2_kg && r.one_impact.m2_kg <= last) << "row " << row;
    }
  }
  return static_cast<int>(ref.windows.size());
}

TEST(DesignWindows, FindsTheNarrowWindowNextToTheFoldWhereTheOrbitsEnd) {
  // The margins off, then the default margins (the window narrower still): each time one
  // window in the dense scan, and the design's gait is the scan's best refined, at the same m2.
  for (const Requirements requirements : {kMarginsOff, kDefault}) {
    Robot robot = kNarrowWindowRobot;
    robot.requirements = requirements;
    const Reference ref = ScanM2(Input(robot), kDenseScan);
    ASSERT_EQ(ExpectDesignFindsEveryWindowOfTheScan(robot, ref, -1), 1) << requirements;
    const DesignResult r = Design(Input(robot));
    ASSERT_EQ(r.status, DesignStatus::kOk) << r.message;
    EXPECT_TRUE(r.complete);
    EXPECT_NEAR(std::log(r.one_impact.m2_kg / ref.best_value), 0.0, kBestLogM2Tol) << requirements;
    EXPECT_NEAR(r.one_impact.speed_mm_s / ref.best_speed, 1.0, kSpeedRelTol) << requirements;
    // Without margins the fastest gait is where the orbit's x_min reaches the left wall (the
    // scan's best lies inside its window, not at an end of the range of m2).
    if (requirements == kMarginsOff) {
      EXPECT_EQ(r.one_impact.binding, std::vector<std::string>{"left_wall"});
    }
  }
}

TEST(DesignWindows, EveryWindowOfADenseScanIsFoundOnATableOfRandomRobots) {
  // Where the design is faster than the scan (row 17: in a window the scan does not see), the
  // check above asserts that no window of the scan holds its m2.
  int with_gait = 0, row = 0;
  for (const Robot& robot : kTable) {
    const Reference ref = ScanM2(Input(robot), kTableScan);
    with_gait += ExpectDesignFindsEveryWindowOfTheScan(robot, ref, row++) > 0;
  }
  // The rows were drawn as robots whose scan sees a gait (the former search missed or slowed
  // on most): a table whose scans see none would check only the no_gait path.
  EXPECT_GT(with_gait, 0);
}

// The frequency search: a robot of the table with its m2 fixed at 0.8788 kg and a clearance d
// from both walls just below the largest its gait allows. By the scaling of docs/model.md
// section 6, changing f multiplies 1 - x by k = (7.686 Hz / f)^2 and leaves the rest of the
// orbit as it is, so the walls with clearance d admit only k in [d/(1 - x_max), (1 - d)/(1 -
// x_min)] of the orbit at 7.686 Hz: a band of about 1e-4 in log f near 7.88 Hz, 200 times
// narrower than the spacing of the scan of [4, 16] Hz (the search before the bracketing found
// no gait).
TEST(DesignWindows, TheFrequencySearchFindsABandOfFrequenciesNarrowerThanItsScan) {
  DesignInput in = Input(kTable[16]);
  in.margin = 0.0492;
  in.frequency_min = 4.0;
  in.frequency_max = 16.0;
  constexpr double kM2 = 0.8788;
  const Gait g = DesignGait(in, kM2);
  ASSERT_TRUE(g.ok()) << GaitStatusName(g.status);
  // The scan: 4000 log-spaced frequencies (1.6e-5 apart in log f) over [7.5, 8.5] Hz, where
  // the band lies (outside it x reaches a wall's clearance).
  const Reference ref = Scan([&](double f) { return Speed(in, kM2, f); }, 7.5, 8.5, 4000);
  ASSERT_EQ(ref.windows.size(), 1u);
  EXPECT_LT(std::log(ref.windows[0].second / ref.windows[0].first), 2e-4);
  EXPECT_GE(g.frequency_hz, ref.windows[0].first * (1.0 - 1e-4));
  EXPECT_LE(g.frequency_hz, ref.windows[0].second * (1.0 + 1e-4));
  EXPECT_GE(g.speed_mm_s, ref.best_speed * (1.0 - kSpeedRelTol))
      << "design f = " << g.frequency_hz << " Hz, scan f = " << ref.best_value << " Hz";
}

// The same robot with the clearance d moved closer to the largest its gait allows, so that its
// band of frequencies is 1e-4, 1e-5 and 3e-6 wide in log f: the search brackets windows to
// 1e-6 (docs/design.md, "How the search works"), so it finds each. The band is computed here
// from the orbit at 7.686 Hz without clearance and the scaling of docs/model.md section 6
// (f -> k = (7.686 Hz / f)^2 multiplies 1 - x by k), and checked with EvaluateGait inside it
// and just outside.
TEST(DesignWindows, TheFrequencySearchFindsBandsDownToAFewTimesItsResolution) {
  constexpr double kM2 = 0.8788, kRefHz = 7.686;
  const DesignInput bare = Input(kTable[16]);  // no clearance, no stability requirement
  const Gait at_ref = EvaluateGait(bare, kM2, kRefHz);
  ASSERT_TRUE(at_ref.ok()) << GaitStatusName(at_ref.status);
  const double x_min = at_ref.solution.validity.x_min, x_max = at_ref.solution.validity.x_max;
  ASSERT_TRUE(x_min > 0.0 && x_max < 1.0) << x_min << " " << x_max;
  // The orbit's x_min and x_max are exact to rounding; the design refines f to 1e-9 in log f.
  constexpr double kBandRelTol = 1e-8;
  // The band's width in log f from d: rounding of the logarithms and square roots.
  constexpr double kWidthRounding = 1e-12;
  for (const double width : {1e-4, 1e-5, 3e-6}) {
    // Walls with clearance d admit k in [d/(1 - x_max), (1 - d)/(1 - x_min)]: the d for which
    // that interval is exp(2 width) wide.
    const double d = 1.0 / (1.0 + std::exp(2.0 * width) * (1.0 - x_min) / (1.0 - x_max));
    const double f_lo = kRefHz * std::sqrt((1.0 - x_min) / (1.0 - d));
    const double f_hi = kRefHz * std::sqrt((1.0 - x_max) / d);
    ASSERT_NEAR(std::log(f_hi / f_lo), width, kWidthRounding) << width;
    DesignInput in = bare;
    in.margin = d;
    in.frequency_min = 4.0;
    in.frequency_max = 16.0;
    EXPECT_TRUE(EvaluateGait(in, kM2, std::sqrt(f_lo * f_hi)).ok()) << width;
    EXPECT_FALSE(EvaluateGait(in, kM2, f_lo * (1.0 - width)).ok()) << width;
    EXPECT_FALSE(EvaluateGait(in, kM2, f_hi * (1.0 + width)).ok()) << width;
    const Gait g = DesignGait(in, kM2);
    ASSERT_TRUE(g.ok()) << "width " << width << ": " << GaitStatusName(g.status);
    EXPECT_GE(g.frequency_hz, f_lo * (1.0 - kBandRelTol)) << width;
    EXPECT_LE(g.frequency_hz, f_hi * (1.0 + kBandRelTol)) << width;
  }
}

}  // namespace
}  // namespace capsubot
