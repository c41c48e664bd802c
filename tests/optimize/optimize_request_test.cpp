// The options of P1, P2 and P3 built from one search request
// (capsubot/optimize/optimize_request.hpp): every setting reaches the problems that use it, and an
// unset number of starts leaves each problem its own default.

#include "capsubot/optimize/optimize_request.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "test_utils.hpp"

namespace capsubot {
namespace {

SearchRequest Request() {
  SearchRequest r;
  r.gait.force_bound = 0.7;
  r.gait.rho_max = 0.8;
  r.max_time = 12.0;
  r.global_algorithm = "GN_ISRES";
  r.local_algorithm = "LD_SLSQP";
  r.global_evaluations = 777;
  r.hops = 3;
  r.harmonics = 5;
  return r;
}

TEST(GaitRequirements, TheBoundIsT0UnlessGivenAndNeverAboveT0) {
  Params params;
  params.T0 = 0.5;
  GaitRequirements gait;
  EXPECT_EQ(gait.BoundFor(params), 0.5);  // NaN: T0
  gait.force_bound = 0.25;
  EXPECT_EQ(gait.BoundFor(params), 0.25);
  gait.force_bound = 0.75;
  EXPECT_EQ(testing::InvalidArgumentMessage([&] { gait.BoundFor(params); }),
            "force_bound = 0.75 is invalid: expected at most the friction bound T0 = 0.5 (a "
            "force above it moves the capsule without impacts, docs/model.md section 6)");
}

TEST(GaitRequirements, ValidateNamesTheBadFieldItsValueAndTheRule) {
  GaitRequirements gait;
  EXPECT_NO_THROW(gait.Validate());
  gait.force_bound = -1.0;
  EXPECT_EQ(testing::InvalidArgumentMessage([&] { gait.Validate(); }),
            "force_bound = -1 is invalid: expected a finite bound > 0 (not given: T0)");
  gait.force_bound = 1.0;
  gait.rho_max = 0.0;
  EXPECT_EQ(testing::InvalidArgumentMessage([&] { gait.Validate(); }),
            "rho_max = 0 is invalid: expected rho_max > 0 (infinity: no stability requirement)");
  gait.rho_max = GaitRequirements::kInf;  // no stability requirement
  EXPECT_NO_THROW(gait.Validate());
}

TEST(SearchRequest, ReachesP1) {
  const PhaseOptions p = PhaseOptionsFor(Request());
  EXPECT_EQ(p.gait.rho_max, 0.8);
  EXPECT_TRUE(std::isnan(p.gait.force_bound));  // P1 optimises the phase of a given force
  EXPECT_EQ(p.max_time, 12.0);
  EXPECT_EQ(p.scan_points, PhaseOptions{}.scan_points);
}

TEST(SearchRequest, ReachesP2) {
  const ForcingDesignOptions d = ForcingOptionsFor(Request());
  EXPECT_EQ(d.gait.force_bound, 0.7);
  EXPECT_EQ(d.gait.rho_max, 0.8);
  EXPECT_EQ(d.max_time, 12.0);
  EXPECT_EQ(d.effort.global_algorithm, "GN_ISRES");
  EXPECT_EQ(d.local_algorithm, "LD_SLSQP");
  EXPECT_EQ(d.effort.global_evaluations, 777);
  EXPECT_EQ(d.hops, 3);
  EXPECT_EQ(d.effort.starts, ForcingDesignOptions{}.effort.starts);
  EXPECT_NO_THROW(d.Validate());
}

TEST(SearchRequest, ReachesP3AndItsHarmonicSeed) {
  const FourierOptions f = FourierOptionsFor(Request());
  EXPECT_EQ(f.harmonics, 5);
  EXPECT_EQ(f.search.global_algorithm, "GN_ISRES");
  EXPECT_EQ(f.search.global_evaluations, 777);
  EXPECT_EQ(f.search.starts, FourierOptions{}.search.starts);
  // The seed asks P3's gait (bound, stability, time, polish) with P2's default search effort.
  EXPECT_EQ(f.harmonic.gait.force_bound, 0.7);
  EXPECT_EQ(f.harmonic.gait.rho_max, 0.8);
  EXPECT_EQ(f.harmonic.max_time, 12.0);
  EXPECT_EQ(f.harmonic.local_algorithm, "LD_SLSQP");
  EXPECT_EQ(f.harmonic.effort.global_algorithm, ForcingDesignOptions{}.effort.global_algorithm);
  EXPECT_EQ(f.harmonic.hops, ForcingDesignOptions{}.hops);
  EXPECT_NO_THROW(f.Validate());
}

TEST(SearchRequest, GivenStartsReachP2AndP3) {
  SearchRequest r = Request();
  r.starts = 4;
  EXPECT_EQ(ForcingOptionsFor(r).effort.starts, 4);
  EXPECT_EQ(FourierOptionsFor(r).search.starts, 4);
}

TEST(SearchRequest, ExactDropsTheMarginsAndSetsOnlyTheStabilityRequirement) {
  SearchRequest robust = Request();
  robust.gait.margins = RobustMargins();
  const SearchRequest exact = robust.Exact(SearchRequest{}.gait.rho_max);
  EXPECT_TRUE(std::isinf(exact.gait.rho_max));
  EXPECT_FALSE(exact.gait.margins.Any());
  EXPECT_TRUE(robust.gait.margins.Any());
  EXPECT_EQ(ForcingOptionsFor(exact).hops, 3);
  EXPECT_EQ(ForcingOptionsFor(exact).gait.force_bound, 0.7);
}

TEST(SearchRequest, DefaultsAreEachProblemsDefaults) {
  const SearchRequest r;
  const ForcingDesignOptions d = ForcingOptionsFor(r), defaults;
  EXPECT_EQ(d.effort.starts, defaults.effort.starts);
  EXPECT_EQ(d.hops, defaults.hops);
  EXPECT_EQ(d.effort.global_evaluations, defaults.effort.global_evaluations);
  EXPECT_EQ(d.local_algorithm, defaults.local_algorithm);
  EXPECT_EQ(d.max_time, defaults.max_time);
  EXPECT_TRUE(std::isnan(d.gait.force_bound));
  EXPECT_EQ(FourierOptionsFor(r).harmonics, FourierOptions{}.harmonics);
}

}  // namespace
}  // namespace capsubot
