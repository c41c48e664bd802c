// Bifurcation diagrams (docs/model.md section 13). The coexistence below was seen in a sweep of
// alpha with `capsubot bifurcation` and is checked here against the classification of each
// motion (attractors_test, periodic_test validate those against independent simulations).

#include "capsubot/attract/bifurcation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "capsubot/orbit/stability.hpp"
#include "capsubot/orbit/validity.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

// The orbit's phi0 found again as a root of alpha(phi0) = alpha: its velocity and multipliers
// move by the root's tolerance times their slopes (order 1).
constexpr double kRootTol = 1e-10;
// A periodic motion found by Newton shooting of the simulated map: within 1e-12 of the fixed
// point, its mean velocity to rounding; its multipliers are central differences of step 1e-6
// (error of the order of the step squared times the map's curvature).
constexpr double kShootingTol = 1e-10;
constexpr double kShootingMultiplierTol = 1e-6;

const Forcing kOptimumForce =
    Forcing::Harmonic(0.34063197373861814, 0.06410131873607934, -3.1181183398453047);

const BifurcationPoint* Find(const BifurcationDiagram& d, SweepDirection dir, double param) {
  for (const BifurcationPoint& p : d.summary) {
    if (p.direction == dir && std::abs(p.param - param) < 1e-12) return &p;
  }
  return nullptr;
}

TEST(Bifurcation, UpAndDownSweepsDifferWhereTwoAttractorsCoexist) {
  // T0 = 0.5 with the stable optimum's force: for alpha in about (0.670, 0.681) a stable
  // 3-right/1-left period-1 motion (carried up from alpha = 0.66) coexists with a stable
  // period-2 motion of 4 right and 2 left impacts (carried down from alpha = 0.70, born from
  // the flip of the 2-right/1-left motion at alpha = 0.6822, periodic_test).
  Params params;
  params.T0 = 0.5;
  BifurcationOptions o;
  o.param = ModelParameter::kAlpha;
  o.from = 0.66;
  o.to = 0.70;
  o.steps = 21;
  o.start = RestStart(0.5, 1.0);
  o.analytic = false;
  const BifurcationDiagram d = ComputeBifurcation({kOptimumForce, params, 0.66}, o);
  ASSERT_EQ(d.summary.size(), 42U);
  const BifurcationPoint* up = Find(d, SweepDirection::kUp, 0.676);
  const BifurcationPoint* down = Find(d, SweepDirection::kDown, 0.676);
  ASSERT_NE(up, nullptr);
  ASSERT_NE(down, nullptr);
  EXPECT_EQ(up->motion.period, 1);
  EXPECT_EQ(up->motion.impacts_right, 3);
  EXPECT_EQ(up->motion.impacts_left, 1);
  EXPECT_LT(up->spectral_radius, 1.0);
  EXPECT_EQ(down->motion.period, 2);
  EXPECT_EQ(down->motion.impacts_right, 4);
  EXPECT_EQ(down->motion.impacts_left, 2);
  EXPECT_LT(down->spectral_radius, 1.0);
  EXPECT_GT(down->motion.mean_velocity, 2.0 * up->motion.mean_velocity);
  // At both ends the sweeps agree (one attractor there).
  for (double end : {0.66, 0.70}) {
    const BifurcationPoint* a = Find(d, SweepDirection::kUp, end);
    const BifurcationPoint* b = Find(d, SweepDirection::kDown, end);
    ASSERT_NE(a, nullptr);
    ASSERT_NE(b, nullptr);
    EXPECT_EQ(a->motion.period, b->motion.period);
    EXPECT_TRUE(testing::Near(a->motion.mean_velocity, b->motion.mean_velocity, 1e-9));
  }
  // Every recorded impact belongs to a value of the range and a record period; a periodic
  // motion found early contributes the impacts of one of its periods, so every value and
  // direction contributes at least one.
  std::size_t impacts = 0;
  for (const ImpactPoint& p : d.impacts) {
    EXPECT_GE(p.param, 0.66 - 1e-12);
    EXPECT_LE(p.param, 0.70 + 1e-12);
    EXPECT_GE(p.period_index, 0);
    EXPECT_LT(p.period_index, o.motion.record);
    ++impacts;
  }
  EXPECT_GE(impacts, 42U);
}

TEST(Bifurcation, AnalyticRowsAreTheValidOneImpactOrbits) {
  // The small stable orbit (solve --A 0.05 --c 0.02 --phi0 -2.842 --T0 0.1 --e 0.5): its alpha
  // and mean velocity from the closed form at that phi0 (Solve), its spectral radius from the
  // impact map (ComputeStability). The diagram finds it the other way round (the roots phi0 of
  // alpha(phi0) at the robot's alpha), and the up sweep finds it by simulation and Newton
  // shooting, whose multipliers are finite differences of the simulated map.
  Params params;
  params.T0 = 0.1;
  params.e = 0.5;
  const Forcing forcing = Forcing::Harmonic(0.05, 0.02, -2.842);
  const Solution s = Solve(forcing, params);
  ASSERT_TRUE(s.validity.valid());
  const double rho = ComputeStability(s.orbit).spectral_radius;
  ASSERT_LT(rho, 1.0);
  BifurcationOptions o;
  o.param = ModelParameter::kAlpha;
  o.from = s.orbit.alpha;
  o.to = 0.29;
  o.steps = 2;
  o.up = true;
  o.down = false;
  const BifurcationDiagram d = ComputeBifurcation({forcing, params, o.from}, o);
  int analytic = 0, matching = 0;
  for (const BifurcationPoint& p : d.summary) {
    if (p.direction != SweepDirection::kAnalytic) continue;
    ++analytic;
    if (p.param == o.from && testing::Near(p.motion.mean_velocity, s.orbit.v_mean, kRootTol)) {
      ++matching;
      EXPECT_TRUE(testing::Near(p.spectral_radius, rho, kRootTol));
    }
  }
  EXPECT_GE(analytic, 1);
  EXPECT_EQ(matching, 1);
  // The simulated motion at the same robot, from rest, is that orbit.
  const BifurcationPoint* up = Find(d, SweepDirection::kUp, o.from);
  ASSERT_NE(up, nullptr);
  EXPECT_EQ(up->motion.period, 1);
  EXPECT_EQ(up->motion.impacts_right, 1);
  EXPECT_EQ(up->motion.impacts_left, 0);
  EXPECT_TRUE(testing::Near(up->motion.mean_velocity, s.orbit.v_mean, kShootingTol));
  EXPECT_TRUE(testing::Near(up->spectral_radius, rho, kShootingMultiplierTol));
}

// Summary rows compared field by field (exact: the same computation, however it is split).
void ExpectSameRows(const std::vector<BifurcationPoint>& a, const std::vector<BifurcationPoint>& b,
                    const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].param, b[k].param) << what << " row " << k;
    EXPECT_EQ(a[k].direction, b[k].direction) << what << " row " << k;
    EXPECT_EQ(a[k].motion.period, b[k].motion.period) << what << " row " << k;
    EXPECT_EQ(a[k].motion.impacts_right, b[k].motion.impacts_right) << what << " row " << k;
    EXPECT_TRUE(a[k].motion.mean_velocity == b[k].motion.mean_velocity ||
                (std::isnan(a[k].motion.mean_velocity) && std::isnan(b[k].motion.mean_velocity)))
        << what << " row " << k;
  }
}

// The small stable orbit's robot (the robot of `capsubot bifurcation`'s examples), T0 stepped
// over 3 values, one diagram per value of the restitution in `over_e`.
struct StudyOverE {
  RobotModel robot{Forcing::Harmonic(0.05, 0.02, -2.842), Params{0.1, 0.5}, 0.2792869076315278};
  BifurcationOptions o;

  explicit StudyOverE(std::vector<double> over_e) {
    o.param = ModelParameter::kT0;
    o.from = 0.08;
    o.to = 0.12;
    o.steps = 3;
    o.motion.transient = 40;
    o.motion.record = 20;
    o.over = ModelParameter::kRestitution;
    o.over_values = std::move(over_e);
  }
};

TEST(Bifurcation, StudyOverASecondParameterIsTheDiagramAtEachValueAndItsShardsPartitionIt) {
  // The small stable orbit's robot, T0 stepped, at 3 restitutions: each diagram of the study
  // is the diagram computed alone with that e; 3 shards hold every part exactly once.
  StudyOverE study_e({0.4, 0.5, 0.6});
  const RobotModel& robot = study_e.robot;
  const BifurcationOptions& o = study_e.o;
  const BifurcationDiagram study = ComputeBifurcation(robot, o);
  ASSERT_EQ(study.total_parts, 9);  // 3 values x (up, down, analytic)
  EXPECT_EQ(BifurcationContinuations(o), 6);
  int values = 0;
  for (double e : o.over_values) {
    BifurcationOptions alone = o;
    alone.over_values.clear();
    RobotModel at_e = robot;
    at_e.params.e = e;
    const BifurcationDiagram d = ComputeBifurcation(at_e, alone);
    std::vector<BifurcationPoint> rows;
    for (const BifurcationPoint& r : study.summary) {
      if (r.over == e) rows.push_back(r);
    }
    ExpectSameRows(rows, d.summary, "e = " + std::to_string(e));
    ++values;
  }
  EXPECT_EQ(values, 3);

  std::vector<int> seen(9, 0);
  std::vector<BifurcationPoint> joined(0);
  for (int k = 0; k < 3; ++k) {
    BifurcationOptions shard = o;
    shard.shard = k;
    shard.shards = 3;
    const BifurcationDiagram d = ComputeBifurcation(robot, shard);
    for (int part : d.parts) ++seen[static_cast<std::size_t>(part)];
    joined.insert(joined.end(), d.summary.begin(), d.summary.end());
  }
  EXPECT_EQ(seen, std::vector<int>(9, 1));
  std::stable_sort(
      joined.begin(), joined.end(),
      [](const BifurcationPoint& a, const BifurcationPoint& b) { return a.part < b.part; });
  ExpectSameRows(joined, study.summary, "3 shards joined");
}

TEST(Bifurcation, StreamedFromALaterPartGivesTheLaterPartsOnlyInOrder) {
  // Shard 0 of 2 of a study over 2 values of e: parts 0 (e = 0.4 up), 2 (its analytic
  // orbits), 3 (e = 0.6 up), 5 (its analytic orbits). Streamed from its second part (a
  // resumed shard), the parts after it come in order with the rows ComputeBifurcation gives
  // them, and only the values of the one sweep left are simulated (the progress total).
  StudyOverE study_e({0.4, 0.6});
  const RobotModel& robot = study_e.robot;
  BifurcationOptions& o = study_e.o;
  o.shards = 2;
  o.threads = 3;
  const BifurcationDiagram whole = ComputeBifurcation(robot, o);
  ASSERT_EQ(whole.parts, (std::vector<int>{0, 2, 3, 5}));
  EXPECT_EQ(BifurcationParts(o), 6);
  std::vector<int> parts;
  std::vector<BifurcationPoint> rows;
  std::int64_t total = 0;
  StreamBifurcation(
      robot, o, 1,
      [&](const BifurcationDiagram& part) {
        ASSERT_EQ(part.parts.size(), 1u);
        EXPECT_EQ(part.total_parts, 6);
        parts.push_back(part.parts.front());
        rows.insert(rows.end(), part.summary.begin(), part.summary.end());
      },
      [&](std::int64_t, std::int64_t of) { total = of; });
  EXPECT_EQ(parts, (std::vector<int>{2, 3, 5}));
  EXPECT_EQ(total, 3);  // the 3 values of the e = 0.6 up sweep
  const auto later = std::find_if(whole.summary.begin(), whole.summary.end(),
                                  [](const BifurcationPoint& p) { return p.part >= 2; });
  ExpectSameRows(rows, std::vector<BifurcationPoint>(later, whole.summary.end()), "from part 1");
  const auto message = [&](int first) {
    try {
      StreamBifurcation(robot, o, first, [](const BifurcationDiagram&) {});
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message(5),
            "first part = 5 is invalid: expected 0 <= first <= 4 (the parts of the shard)");
  EXPECT_EQ(message(-1),
            "first part = -1 is invalid: expected 0 <= first <= 4 (the parts of the shard)");
  int calls = 0;
  StreamBifurcation(robot, o, 4, [&](const BifurcationDiagram&) { ++calls; });
  EXPECT_EQ(calls, 0);  // every part done: nothing computed
}

// A backend standing in for the worker ranks of an MPI job: every block computed by a
// computer of `make` (BifurcationBlocks, as a worker makes it: not the caller's computers,
// which tick its progress), the blocks in reverse order, then handed to the sink in order.
class ElsewhereBackend : public BlockBackend {
 public:
  explicit ElsewhereBackend(BlockComputeFactory make) : make_(std::move(make)) {}
  int Threads(int local) const override { return local; }
  void Run(const BlockPlan& plan, const BlockComputeFactory&,
           const BlockSink& sink) const override {
    const BlockCompute compute = make_();
    std::vector<std::pair<std::string, std::int64_t>> blocks(
        static_cast<std::size_t>(plan.Blocks()));
    for (std::int64_t k = plan.Blocks() - 1; k >= 0; --k) {
      auto& [bytes, count] = blocks[static_cast<std::size_t>(k)];
      count = compute(plan.Begin(k), plan.End(k), bytes);
    }
    for (std::int64_t k = 0; k < plan.Blocks(); ++k) {
      const auto& [bytes, count] = blocks[static_cast<std::size_t>(k)];
      sink(plan.Begin(k), plan.End(k), bytes, count);
    }
  }

 private:
  BlockComputeFactory make_;
};

TEST(Bifurcation, PartsComputedElsewhereGiveTheThreadedDiagram) {
  // The bytes of a part (BifurcationBlocks) carry all its rows: a study whose parts are
  // computed by another backend (out of order) is the threaded one, row for row, impacts and
  // summary, with their second parameter and part; the progress counts the values of each
  // sweep part when it arrives (the analytic parts simulate none).
  StudyOverE study_e({0.4, 0.6});
  const RobotModel& robot = study_e.robot;
  const BifurcationOptions& o = study_e.o;
  const BifurcationDiagram threaded = ComputeBifurcation(robot, o);
  ASSERT_EQ(threaded.parts, (std::vector<int>{0, 1, 2, 3, 4, 5}));
  const ElsewhereBackend elsewhere(BifurcationBlocks(robot, o));
  std::vector<std::int64_t> done;
  std::int64_t total = 0;
  const BifurcationDiagram d = ComputeBifurcation(
      robot, o,
      [&](std::int64_t n, std::int64_t of) {
        done.push_back(n);
        total = of;
      },
      elsewhere);
  EXPECT_EQ(d.parts, threaded.parts);
  EXPECT_EQ(d.total_parts, 6);
  ExpectSameRows(d.summary, threaded.summary, "parts computed elsewhere");
  for (std::size_t k = 0; k < d.summary.size() && k < threaded.summary.size(); ++k) {
    EXPECT_EQ(d.summary[k].over, threaded.summary[k].over) << "row " << k;
    EXPECT_EQ(d.summary[k].part, threaded.summary[k].part) << "row " << k;
  }
  ASSERT_EQ(d.impacts.size(), threaded.impacts.size());
  ASSERT_GT(d.impacts.size(), 10u);
  for (std::size_t k = 0; k < d.impacts.size(); ++k) {
    const ImpactPoint &a = d.impacts[k], &b = threaded.impacts[k];
    EXPECT_TRUE(a.param == b.param && a.direction == b.direction &&
                a.period_index == b.period_index && a.right == b.right && a.phase == b.phase &&
                a.velocity == b.velocity && a.over == b.over && a.part == b.part)
        << "impact " << k;
  }
  EXPECT_EQ(done, (std::vector<std::int64_t>{3, 6, 9, 12}));  // 4 sweeps of 3 values
  EXPECT_EQ(total, 12);
}

TEST(Bifurcation, OverTheSineCoefficientOfOneHarmonicEqualsTheDiagramOverA) {
  // The paper's family is the series with a_1 = 0, b_1 = A (forcing.hpp): stepping b1 of that
  // series steps A, so both diagrams must be the same numbers.
  const double c = kOptimumForce.mean(), phi0 = kOptimumForce.phi0();
  BifurcationOptions o;
  o.param = ModelParameter::kA;
  o.from = 0.30;
  o.to = 0.36;
  o.steps = 4;
  o.start = RestStart(0.5, 1.0);
  o.analytic = false;
  const double alpha = 0.6435592358295166;
  const BifurcationDiagram by_A = ComputeBifurcation({kOptimumForce, Params{}, alpha}, o);
  o.param = ModelParameter::kSin;
  o.harmonic = 1;
  const BifurcationDiagram by_b1 = ComputeBifurcation(
      {Forcing::Fourier(c, {0.0}, {kOptimumForce.amplitude()}, phi0), Params{}, alpha}, o);
  ASSERT_EQ(by_A.summary.size(), 8U);
  ASSERT_EQ(by_b1.summary.size(), by_A.summary.size());
  ASSERT_EQ(by_b1.impacts.size(), by_A.impacts.size());
  for (std::size_t i = 0; i < by_A.summary.size(); ++i) {
    const BifurcationPoint &p = by_A.summary[i], &q = by_b1.summary[i];
    EXPECT_EQ(q.param, p.param);
    EXPECT_EQ(q.direction, p.direction);
    EXPECT_EQ(q.motion.period, p.motion.period);
    EXPECT_EQ(q.motion.impacts_right, p.motion.impacts_right);
    EXPECT_EQ(q.motion.impacts_left, p.motion.impacts_left);
    EXPECT_EQ(q.motion.mean_velocity, p.motion.mean_velocity);
    EXPECT_EQ(q.spectral_radius, p.spectral_radius);
  }
}

TEST(Bifurcation, OverACosineCoefficientSimulatesTheForceWithThatCoefficient) {
  // A two-harmonic force, a_2 stepped: the first value of a sweep starts from `start`, so it
  // must be the long-run motion of the force built directly with that a_2 (an independent
  // construction of the series), at three values.
  const double c = kOptimumForce.mean(), phi0 = kOptimumForce.phi0(), A = kOptimumForce.amplitude();
  const double alpha = 0.6435592358295166;
  const Forcing base = Forcing::Fourier(c, {0.0, 0.0}, {A, 0.02}, phi0);
  BifurcationOptions o;
  o.param = ModelParameter::kCos;
  o.harmonic = 2;
  o.steps = 2;
  o.down = false;
  o.analytic = false;
  o.multipliers = false;
  o.start = RestStart(0.5, 1.0);
  std::vector<double> velocities;
  for (double a2 : {-0.03, 0.0, 0.03}) {
    o.from = o.to = a2;
    const BifurcationDiagram d = ComputeBifurcation({base, Params{}, alpha}, o);
    ASSERT_EQ(d.summary.size(), 2U);
    const Motion expected = LongRunMotion(
        {Forcing::Fourier(c, {0.0, a2}, {A, 0.02}, phi0), Params{}, alpha}, o.start, o.motion);
    const Motion& m = d.summary[0].motion;
    EXPECT_EQ(m.status, expected.status) << "a2 = " << a2;
    EXPECT_EQ(m.period, expected.period) << "a2 = " << a2;
    EXPECT_EQ(m.impacts_right, expected.impacts_right) << "a2 = " << a2;
    EXPECT_EQ(m.impacts_left, expected.impacts_left) << "a2 = " << a2;
    EXPECT_EQ(m.mean_velocity, expected.mean_velocity) << "a2 = " << a2;
    velocities.push_back(m.mean_velocity);
  }
  // The coefficient matters: the three motions differ.
  EXPECT_NE(velocities[0], velocities[1]);
  EXPECT_NE(velocities[1], velocities[2]);
}

TEST(BifurcationInput, BadParameterAndRangeAreNamed) {
  const auto message = [](const std::function<void()>& f) -> std::string {
    try {
      f();
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "no exception";
  };
  const std::string choices =
      " is invalid: expected one of A, c, alpha, T0, e, phi0, or a Fourier coefficient "
      "a1..a16, b1..b16";
  for (const char* bad : {"mu", "a0", "b17", "a01", "a", "c1"}) {
    EXPECT_EQ(message([&] { ParseRobotParameter(bad); }),
              std::string("parameter = ") + bad + choices);
  }
  int k = 0;
  EXPECT_EQ(ParseRobotParameter("b12", &k), ModelParameter::kSin);
  EXPECT_EQ(k, 12);
  EXPECT_EQ(ParseRobotParameter("phi0", &k), ModelParameter::kPhi0);
  EXPECT_EQ(k, 0);
  BifurcationOptions fourier;
  fourier.param = ModelParameter::kCos;
  fourier.harmonic = 2;
  fourier.from = 0.0;
  fourier.to = 0.1;
  EXPECT_EQ(message([&] {
              ComputeBifurcation({kOptimumForce, Params{}, 0.5}, fourier);
            }),
            "parameter = a2 is invalid for this force: expected a_k or b_k with 1 <= k <= K = 1, "
            "its harmonics");
  fourier.harmonic = 0;
  EXPECT_EQ(message([&] {
              ComputeBifurcation({kOptimumForce, Params{}, 0.5}, fourier);
            }),
            "harmonic = 0 is invalid: expected 1 <= k <= 16 for a_k and b_k, else 0");
  BifurcationOptions o;
  o.param = ModelParameter::kRestitution;
  o.from = 0.5;
  o.to = 1.5;
  EXPECT_EQ(message([&] {
              ComputeBifurcation({kOptimumForce, Params{}, 0.5}, o);
            }),
            "e = 1.5 makes the robot invalid: restitution e = 1.5 is invalid: expected 0 <= e "
            "<= 1");
  o.to = 1.0;
  o.steps = 1;
  EXPECT_EQ(message([&] {
              ComputeBifurcation({kOptimumForce, Params{}, 0.5}, o);
            }),
            "steps = 1 is invalid: expected 2 <= steps <= 10000000");
  // The second parameter of a study and the shards.
  o.steps = 3;
  o.over = o.param;
  o.over_values = {0.5};
  EXPECT_EQ(message([&] {
              ComputeBifurcation({kOptimumForce, Params{}, 0.5}, o);
            }),
            "second parameter = e is invalid: expected a parameter other than the diagram's");
  o.over = ModelParameter::kT0;
  o.over_values = {0.5, std::nan("")};
  EXPECT_EQ(message([&] {
              ComputeBifurcation({kOptimumForce, Params{}, 0.5}, o);
            }),
            "second parameter T0 = nan is invalid: expected finite values");
  o.over_values = {0.5, -1.0};
  EXPECT_NE(message([&] {
              ComputeBifurcation({kOptimumForce, Params{}, 0.5}, o);
            }).find(" at T0 = -1 makes the robot invalid: "),
            std::string::npos);
  o.over_values = {0.5, 1.0};
  o.shards = 5;
  EXPECT_EQ(message([&] {
              ComputeBifurcation({kOptimumForce, Params{}, 0.5}, o);
            }),
            "shard count N = 5 is invalid: the study has 4 continuations (2 values of the second "
            "parameter x 2 directions): expected 1 <= N <= 4");
  o.shards = 2;
  o.shard = 2;
  EXPECT_EQ(message([&] {
              ComputeBifurcation({kOptimumForce, Params{}, 0.5}, o);
            }),
            "shard K = 2 is invalid: expected 0 <= K < N = 2");
}

}  // namespace
}  // namespace capsubot
