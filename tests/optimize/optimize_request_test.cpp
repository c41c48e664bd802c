// The options of P1, P2 and P3 built from one search request
// (capsubot/optimize/optimize_request.hpp): every setting reaches the problems that use it, and an
// unset number of starts leaves each problem its own default.

#include "capsubot/optimize/optimize_request.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace capsubot {
namespace {

SearchRequest Request() {
  SearchRequest r;
  r.force_bound = 0.7;
  r.rho_max = 0.8;
  r.max_time = 12.0;
  r.global_algorithm = "GN_ISRES";
  r.local_algorithm = "LD_SLSQP";
  r.global_evaluations = 777;
  r.hops = 3;
  r.harmonics = 5;
  return r;
}

TEST(SearchRequest, ReachesP1) {
  const PhaseOptions p = PhaseOptionsFor(Request());
  EXPECT_EQ(p.rho_max, 0.8);
  EXPECT_EQ(p.max_time, 12.0);
  EXPECT_EQ(p.scan_points, PhaseOptions{}.scan_points);
}

TEST(SearchRequest, ReachesP2) {
  const ForcingDesignOptions d = ForcingOptionsFor(Request());
  EXPECT_EQ(d.force_bound, 0.7);
  EXPECT_EQ(d.rho_max, 0.8);
  EXPECT_EQ(d.max_time, 12.0);
  EXPECT_EQ(d.global_algorithm, "GN_ISRES");
  EXPECT_EQ(d.local_algorithm, "LD_SLSQP");
  EXPECT_EQ(d.global_evaluations, 777);
  EXPECT_EQ(d.hops, 3);
  EXPECT_EQ(d.starts, ForcingDesignOptions{}.starts);
  EXPECT_NO_THROW(d.Validate());
}

TEST(SearchRequest, ReachesP3AndItsHarmonicSeed) {
  const FourierOptions f = FourierOptionsFor(Request());
  EXPECT_EQ(f.harmonics, 5);
  EXPECT_EQ(f.search.global_algorithm, "GN_ISRES");
  EXPECT_EQ(f.search.global_evaluations, 777);
  EXPECT_EQ(f.search.starts, FourierOptions{}.search.starts);
  // The seed asks P3's gait (bound, stability, time, polish) with P2's default search effort.
  EXPECT_EQ(f.harmonic.force_bound, 0.7);
  EXPECT_EQ(f.harmonic.rho_max, 0.8);
  EXPECT_EQ(f.harmonic.max_time, 12.0);
  EXPECT_EQ(f.harmonic.local_algorithm, "LD_SLSQP");
  EXPECT_EQ(f.harmonic.global_algorithm, ForcingDesignOptions{}.global_algorithm);
  EXPECT_EQ(f.harmonic.hops, ForcingDesignOptions{}.hops);
  EXPECT_NO_THROW(f.Validate());
}

TEST(SearchRequest, GivenStartsReachP2AndP3) {
  SearchRequest r = Request();
  r.starts = 4;
  EXPECT_EQ(ForcingOptionsFor(r).starts, 4);
  EXPECT_EQ(FourierOptionsFor(r).search.starts, 4);
}

TEST(SearchRequest, WithRhoMaxChangesOnlyTheStabilityRequirement) {
  const SearchRequest exact = Request().WithRhoMax(SearchRequest{}.rho_max);
  EXPECT_TRUE(std::isinf(exact.rho_max));
  EXPECT_EQ(ForcingOptionsFor(exact).hops, 3);
  EXPECT_EQ(ForcingOptionsFor(exact).force_bound, 0.7);
}

TEST(SearchRequest, DefaultsAreEachProblemsDefaults) {
  const SearchRequest r;
  const ForcingDesignOptions d = ForcingOptionsFor(r), defaults;
  EXPECT_EQ(d.starts, defaults.starts);
  EXPECT_EQ(d.hops, defaults.hops);
  EXPECT_EQ(d.global_evaluations, defaults.global_evaluations);
  EXPECT_EQ(d.local_algorithm, defaults.local_algorithm);
  EXPECT_EQ(d.max_time, defaults.max_time);
  EXPECT_TRUE(std::isnan(d.force_bound));
  EXPECT_EQ(FourierOptionsFor(r).harmonics, FourierOptions{}.harmonics);
}

}  // namespace
}  // namespace capsubot
