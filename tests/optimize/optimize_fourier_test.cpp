// P3 (OptimizeFourier): the fastest K-harmonic force, docs/model.md section 7. References: the P2
// optimum (the K = 1 member of the family), Solve on the rebuilt force, the simulator.

#include "capsubot/optimize/optimize_fourier.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "capsubot/optimize/optimize_forcing.hpp"
#include "capsubot/orbit/validity.hpp"
#include "capsubot/simulate/simulator.hpp"
#include "optimize_test_utils.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

// The P3 family contains the P2 optimum, from which P3 starts.
constexpr double kSameValueTol = 1e-12;
// The simulator locates events to ~1e-12 in phase; the displacement over one period agrees
// with the closed form far below this.
constexpr double kSimulatorTol = 1e-8;

FourierOptions Quick(int K) {
  FourierOptions o;
  o.harmonics = K;
  o.search.starts = 4;  // a few polishes keep the test fast; the gain only grows with more
  return o;
}

TEST(OptimizeFourier, NeverLosesToTheHarmonicOptimumAndRecordsIt) {
  const Params params{1.0, 1.0};
  const OptimizeResult r = OptimizeFourier(params, Quick(3));
  ASSERT_TRUE(r.found()) << r.message;
  const OptimizeResult p2 = OptimizeForcing(params);
  EXPECT_EQ(r.baseline_I, p2.solution.orbit.I);
  EXPECT_GE(r.solution.orbit.I, r.baseline_I * (1.0 - kSameValueTol));
  EXPECT_EQ(r.solution.orbit.forcing.harmonics(), 3);
}

TEST(OptimizeFourier, KeepsTheHarmonicOptimumWhenTheForceBoundBinds) {
  // T0 = 0.3, bound 0.8 T0: the P2 optimum uses its whole bound, A + c = 0.24. Rebuilt as a
  // series (a_1 = A sin phi0, b_1 = A cos phi0), its max |F| exceeds 0.24 by one ulp; that is
  // the bound up to rounding, so P3 starts from a valid point and its gain is never negative.
  const Params params{0.3, 1.0};
  FourierOptions o;
  o.harmonics = 3;
  o.search.starts = 2;
  o.harmonic.gait.force_bound = 0.24;
  const OptimizeResult r = OptimizeFourier(params, o);
  ASSERT_EQ(r.status, OptimizeStatus::kOk) << r.message;
  EXPECT_GE(r.solution.orbit.I, r.baseline_I * (1.0 - kSameValueTol));
  EXPECT_TRUE(Solve(r.solution.orbit.forcing, params).validity.valid());
  EXPECT_TRUE(WithinForceBound(r.solution.validity.max_force, o.harmonic.gait.force_bound));
}

TEST(OptimizeFourier, OptimumSatisfiesEveryConstraintWhenRecheckedThroughSolve) {
  const Params params{0.3, 0.8};
  FourierOptions o = Quick(2);
  o.harmonic.gait.force_bound = 0.25;
  o.harmonic.gait.margins.clearance = 0.02;
  const OptimizeResult r = OptimizeFourier(params, o);
  ASSERT_TRUE(r.found()) << r.message;
  const Forcing& f = r.solution.orbit.forcing;
  EXPECT_EQ(f.phi0(), 0.0);  // coefficients seen from the impact
  std::vector<double> a, b;
  for (int k = 1; k <= f.harmonics(); ++k) {
    a.push_back(f.a(k));
    b.push_back(f.b(k));
  }
  const Solution s = Solve(Forcing::Fourier(f.mean(), a, b, 0.0), params, o.harmonic.gait.margins);
  EXPECT_TRUE(s.validity.valid()) << s.validity.violations;
  EXPECT_GT(f.mean(), 0.0);
  EXPECT_LE(s.validity.max_force, 0.25 * (1.0 + kSameValueTol));
  EXPECT_GE(s.validity.x_min, o.harmonic.gait.margins.clearance);
  EXPECT_EQ(s.orbit.I, r.solution.orbit.I);
}

TEST(OptimizeFourier, OptimumIsAPeriodicOrbitOfTheSimulator) {
  const Params params{1.0, 1.0};
  const OptimizeResult r = OptimizeFourier(params, Quick(3));
  ASSERT_TRUE(r.found()) << r.message;
  const Orbit& o = r.solution.orbit;
  const SimResult s = testing::SimulateOnePeriodFromImpact(o, params);
  ASSERT_EQ(s.status, SimStatus::kOk) << s.message;
  EXPECT_EQ(s.impacts_right, 1);
  EXPECT_TRUE(testing::NearAbsBelowOne(s.displacement, o.I, kSimulatorTol));
  EXPECT_TRUE(testing::Near(s.final_state.x, 1.0, kSimulatorTol));
}

TEST(OptimizeFourier, BadOptionsAreRejectedWithTheRule) {
  auto error = [](const FourierOptions& o) -> std::string {
    try {
      OptimizeFourier(Params{}, o);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "(no error)";
  };
  FourierOptions none;
  none.harmonics = 0;
  EXPECT_EQ(error(none), "harmonics K = 0 is invalid: expected 1 <= K <= 16");
  FourierOptions unknown;
  unknown.harmonic.local_algorithm = "cobyla";
  EXPECT_EQ(error(unknown),
            "local_algorithm = \"cobyla\" is invalid: expected one of LN_COBYLA, LD_SLSQP, "
            "LD_MMA, LD_CCSAQ");
  FourierOptions above;
  above.harmonic.gait.force_bound = 1.5;
  EXPECT_NE(
      error(above).find("force_bound = 1.5 is invalid: expected at most the friction bound T0 = 1"),
      std::string::npos);
}

}  // namespace
}  // namespace capsubot
