// The sweep job (capsubot/job/sweep_job.hpp): its file is the file of RunSweep with the
// options the job plans, the force is built from its parts as the job promises, each mode has
// its own defaults (the robust gait for the reach search), and bad options are named.

#include "capsubot/job/sweep_job.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::ReadFile;

using testing::InvalidArgumentMessage;

// The same force: mean, phase and every coefficient equal (both printed otherwise).
::testing::AssertionResult SameForce(const Forcing& actual, const Forcing& expected) {
  bool same = actual.harmonics() == expected.harmonics() && actual.mean() == expected.mean() &&
              actual.phi0() == expected.phi0();
  for (int k = 1; same && k <= actual.harmonics(); ++k) {
    same = actual.a(k) == expected.a(k) && actual.b(k) == expected.b(k);
  }
  const auto describe = [](const Forcing& f) {
    std::string d = fmt::format("c = {}, phi0 = {}", f.mean(), f.phi0());
    for (int k = 1; k <= f.harmonics(); ++k) {
      d += fmt::format(", a{} = {}, b{} = {}", k, f.a(k), k, f.b(k));
    }
    return d;
  };
  if (same) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "force " << describe(actual) << ", expected " << describe(expected);
}

Grid GridOf(std::initializer_list<const char*> specs) {
  Grid grid;
  for (const char* spec : specs) grid.axes.push_back(ParseGridAxis(spec));
  return grid;
}

// The orbit of A = 0.5, c = 0.5 at 5 phases (the first example of docs/sweep.md).
SweepJobOptions OrbitJob() {
  SweepJobOptions job;
  job.grid = GridOf({"phi0=-pi:pi:5"});
  SweepOrbitMode mode;
  mode.force.A = 0.5;
  mode.force.c = 0.5;
  mode.stability = true;
  job.mode = mode;
  job.file.comments = {"a comment"};
  job.file.threads = 2;
  return job;
}

TEST(SweepJob, WritesTheFileOfTheSweepItPlans) {
  SweepJobOptions job = OrbitJob();
  job.file.output = testing::TempPath("sweep_job.csv").string();
  SweepOptions sweep;  // the same sweep, written out by hand
  sweep.grid = job.grid;
  sweep.forcing = Forcing::Harmonic(0.5, 0.5, 0.0);
  sweep.stability = true;
  sweep.comments = job.file.comments;
  sweep.threads = 1;
  sweep.output = testing::TempPath("sweep_direct.csv").string();
  const SweepJobResult result = RunSweepJob(job);
  const SweepSummary direct = RunSweep(sweep);
  EXPECT_EQ(result.output, job.file.output);
  EXPECT_EQ(result.summary.points, 5);
  EXPECT_EQ(result.summary.rows, direct.rows);
  const std::string text = ReadFile(job.file.output);
  EXPECT_EQ(text.rfind("# a comment\nphi0,phi1,", 0), 0U) << text;
  EXPECT_EQ(text, ReadFile(sweep.output));
}

TEST(SweepJob, BuildsTheForceFromItsPartsAndTheGrid) {
  SweepJobOptions job = OrbitJob();
  job.file.output = "-";
  SweepOrbitMode& mode = std::get<SweepOrbitMode>(job.mode);
  EXPECT_TRUE(SameForce(PlanSweepJob(job).forcing, Forcing::Harmonic(0.5, 0.5, 0.0)));
  // A c grid: c need not be given (0 until the grid sets it).
  job.grid = GridOf({"c=0.1,0.2"});
  mode.force.c.reset();
  mode.phi0 = 1.0;
  EXPECT_TRUE(SameForce(PlanSweepJob(job).forcing, Forcing::Harmonic(0.5, 0.0, 1.0)));
  // An A grid: A need not be given.
  job.grid = GridOf({"A=0:1:3"});
  mode.force = SweepForce{};
  mode.force.c = 0.3;
  EXPECT_TRUE(SameForce(PlanSweepJob(job).forcing, Forcing::Harmonic(0.0, 0.3, 1.0)));
  // The Fourier force, its cosines 0 unless given; phi0 0 when the grid gives it.
  job.grid = GridOf({"phi0=0:1:3"});
  mode.phi0.reset();
  mode.force.sin = {0.3, 0.02};
  EXPECT_TRUE(
      SameForce(PlanSweepJob(job).forcing, Forcing::Fourier(0.3, {0.0, 0.0}, {0.3, 0.02}, 0.0)));
  mode.force.cos = {0.0, 0.01};
  EXPECT_TRUE(
      SameForce(PlanSweepJob(job).forcing, Forcing::Fourier(0.3, {0.0, 0.01}, {0.3, 0.02}, 0.0)));
}

TEST(SweepJob, RefusesAForceWithAPartMissingOrGivenTwice) {
  const auto message = [](const std::function<void(SweepOrbitMode&, Grid&)>& change) {
    SweepJobOptions job = OrbitJob();
    job.file.output = "-";
    change(std::get<SweepOrbitMode>(job.mode), job.grid);
    return InvalidArgumentMessage([&] { job.Validate(); });
  };
  EXPECT_EQ(message([](SweepOrbitMode& m, Grid&) { m.force.c.reset(); }),
            "c is missing: give the mean force c (or a grid over c)");
  EXPECT_EQ(message([](SweepOrbitMode& m, Grid& g) {
              m.force.A.reset();
              g = GridOf({"T0=1,2"});
            }),
            "A is missing: give the amplitude A (or the Fourier coefficients sin, cos, or a grid "
            "over A)");
  EXPECT_EQ(message([](SweepOrbitMode&, Grid& g) { g = GridOf({"c=0.1,0.2"}); }),
            "phi0 is missing: give the impact phase phi0 [rad] (or a grid over phi0 or alpha, or "
            "optimize = phi0)");
  EXPECT_EQ(message([](SweepOrbitMode& m, Grid&) { m.force.sin = {0.1}; }),
            "A = 0.5 is invalid with sin: expected the amplitude A or the Fourier coefficients "
            "sin, cos, not both");
  EXPECT_EQ(message([](SweepOrbitMode& m, Grid&) {
              m.force.cos = {0.1};
            }).rfind("cos is invalid without sin", 0),
            0U);
  EXPECT_EQ(message([](SweepOrbitMode& m, Grid& g) {
              m.phi0 = 1.0;
              g = GridOf({"alpha=0.3"});
            }),
            "phi0 = 1 is invalid with grid alpha: expected no phi0 (the sweep finds phi0)");
}

TEST(SweepJob, ModesTakeTheirOwnDefaults) {
  SweepJobOptions job;
  job.grid = GridOf({"T0=0.5,1"});
  job.file.output = "-";
  job.mode = SweepModeNamed("reach");
  ASSERT_EQ(SweepModeOptimize(job.mode), SweepOptimize::kReach);
  const SweepOptions reach = PlanSweepJob(job);
  EXPECT_EQ(reach.optimize, SweepOptimize::kReach);
  EXPECT_EQ(reach.design.gait.rho_max, kRobustRhoMax);  // the robust seed of docs/model.md 12
  EXPECT_EQ(reach.design.gait.margins.clearance_stroke, kRobustMarginStroke);
  EXPECT_EQ(reach.design.gait.margins.stick, kRobustStickMargin);
  EXPECT_EQ(&SweepMargins(reach), &reach.design.gait.margins);  // the seed's are the sweep's
  EXPECT_TRUE(std::isinf(reach.reach.max_seconds));
  job.mode = SweepModeNamed("forcing");
  const SweepOptions forcing = PlanSweepJob(job);
  EXPECT_EQ(forcing.optimize, SweepOptimize::kForcing);
  EXPECT_TRUE(std::isinf(forcing.design.gait.rho_max));
  EXPECT_EQ(forcing.design.gait.margins.clearance_stroke, 0.0);
  // The search request is the one vocabulary: P2's options are ForcingOptionsFor's.
  SweepForcingMode mode;
  mode.search.starts = 3;
  mode.search.hops = 2;
  job.mode = mode;
  EXPECT_EQ(PlanSweepJob(job).design.effort.starts, ForcingOptionsFor(mode.search).effort.starts);
  EXPECT_EQ(PlanSweepJob(job).design.hops, 2);
  EXPECT_EQ(SweepModeOptimize(SweepModeNamed("")), SweepOptimize::kNone);
  EXPECT_EQ(SweepModeOptimize(SweepModeNamed("phi0")), SweepOptimize::kPhase);
  EXPECT_EQ(SweepModeOptimize(SweepModeNamed("fourier")), SweepOptimize::kFourier);
  EXPECT_EQ(InvalidArgumentMessage([] { SweepModeNamed("none"); }),
            "optimize = none is invalid: expected one of phi0, forcing, fourier, reach");
}

TEST(SweepJob, RefusesReachBudgetsOutOfRangeNamingThem) {
  SweepJobOptions job;
  job.grid = GridOf({"T0=0.5,1"});
  job.file.output = "-";
  SweepReachMode mode;
  mode.reach.global_evaluations = 0;
  job.mode = mode;
  EXPECT_EQ(InvalidArgumentMessage([&] { job.Validate(); }),
            "reach.global_evaluations = 0 is invalid: expected from 1 to 10000000 evaluations");
  mode.reach.global_evaluations = 8;
  mode.reach.local_evaluations = 10000001;
  job.mode = mode;
  EXPECT_EQ(InvalidArgumentMessage([&] { job.Validate(); }),
            "reach.local_evaluations = 10000001 is invalid: expected from 0 to 10000000 "
            "evaluations");
  mode.reach.local_evaluations = 4;
  mode.reach.force_bound = 0.2;  // the bound is the seed's
  job.mode = mode;
  EXPECT_EQ(InvalidArgumentMessage([&] {
              job.Validate();
            }).rfind("reach.force_bound = 0.2 is invalid: expected NaN", 0),
            0U);
}

TEST(SweepJob, ChecksTheSweepItPlans) {
  SweepJobOptions job = OrbitJob();
  EXPECT_EQ(InvalidArgumentMessage([&] { job.Validate(); }),
            "output is missing: expected the path of the CSV file to write");
  job.file.output = "-";
  job.grid = GridOf({"bound=0.1,0.2"});  // the orbit of a given force has no bound
  std::get<SweepOrbitMode>(job.mode).phi0 = 0.0;
  EXPECT_EQ(
      InvalidArgumentMessage([&] { job.Validate(); }).rfind("grid bound=0.1,0.2 is invalid", 0),
      0U);
}

}  // namespace
}  // namespace capsubot
