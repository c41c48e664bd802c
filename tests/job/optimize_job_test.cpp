// The optimize job is the calls it stands for, in one: its results equal those of the stages
// called directly, it tells its stages, lets an interrupt through, and refuses bad options
// before any work, naming the parameter.

#include "capsubot/job/optimize_job.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "capsubot/optimize/optimize.hpp"

namespace capsubot {
namespace {

// A small check from rest: 3 x 3 starts.
FromRestOptions SmallCheck() {
  FromRestOptions check;
  check.n_x = check.n_psi = 3;
  return check;
}

OptimizeJobOptions PhaseJob(double A, double c) {
  OptimizeJobOptions job;
  job.mode = PhaseProblem{A, c};
  job.check = SmallCheck();
  return job;
}

TEST(OptimizeJob, PhaseProblemIsP1CheckedFromRest) {
  const OptimizeJobOptions job = PhaseJob(0.3, 0.4);
  const auto result = std::get<ProblemJobResult>(RunOptimizeJob(job));
  const OptimizeResult direct =
      OptimizePhase(Forcing::Harmonic(0.3, 0.4, 0.0), job.params, PhaseOptionsFor(job.search));
  EXPECT_EQ(result.problem, "phase");
  EXPECT_EQ(result.result.status, direct.status);
  EXPECT_EQ(result.result.solution.orbit.forcing.phi0(), direct.solution.orbit.forcing.phi0());
  EXPECT_EQ(result.result.solution.orbit.I, direct.solution.orbit.I);
  const GaitFromRest from_rest = CheckGaitFromRest(direct.solution.orbit, job.params, job.check);
  EXPECT_EQ(result.from_rest.attractors.starts, 9);
  EXPECT_EQ(result.from_rest.reached, from_rest.reached);
  EXPECT_EQ(result.from_rest.attractors.mean_velocity, from_rest.attractors.mean_velocity);
  EXPECT_EQ(result.gait.rho_max, kRobustRhoMax);  // the robust default of the job
  EXPECT_EQ(result.gait.margins.clearance_stroke, kRobustMarginStroke);
  EXPECT_EQ(result.gait.margins.stick, kRobustStickMargin);
  EXPECT_EQ(RecommendedForcing(OptimizeJobResult(result)).phi0(),
            direct.solution.orbit.forcing.phi0());
}

// The main job with a small effort: 3 x 3 starts, a reach search of 2 x 2 starts and 12
// evaluations (about half a second).
TEST(OptimizeJob, MainJobContinuesBothMotionsAsTheStagesDo) {
  OptimizeJobOptions job;
  job.mode = MainJob{ReachEffort{2, 2, 8, 4}};
  job.check = SmallCheck();
  const auto r = std::get<MainJobResult>(RunOptimizeJob(job));
  ASSERT_TRUE(r.robust.found());
  EXPECT_EQ(r.gait.force_bound, job.params.T0);  // not given: T0
  const GaitRobustness gait = ComputeGaitRobustness(r.robust.solution.orbit);
  ASSERT_EQ(r.robustness.parameters.size(), 3U);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(r.robustness.parameters[i].down.parameter, gait.parameters[i].down.parameter);
    EXPECT_EQ(r.robustness.parameters[i].up.parameter, gait.parameters[i].up.parameter);
  }
  // The reach winner's most common motion is periodic here: it is continued from its state.
  ASSERT_FALSE(r.reach.attractors.attractors.empty());
  const Motion& motion = r.reach.attractors.attractors.front().motion;
  ASSERT_EQ(motion.status, MotionStatus::kPeriodic);
  const GaitRobustness reached =
      ComputeMotionRobustness({{r.reach.forcing, job.params, r.reach.alpha}, motion.section});
  ASSERT_EQ(r.reach_robustness.parameters.size(), 3U);
  for (std::size_t i = 0; i < 3; ++i) {
    const ParameterRobustness& p = r.reach_robustness.parameters[i];
    EXPECT_EQ(p.status, ContinuationStatus::kOk) << p.name << ": " << p.message;
    EXPECT_EQ(p.down.parameter, reached.parameters[i].down.parameter);
    EXPECT_EQ(p.up.parameter, reached.parameters[i].up.parameter);
    // The motion is followed some way each way before it is lost.
    EXPECT_LT(p.down.parameter, p.value) << p.name;
    EXPECT_TRUE(p.up.parameter > p.value || p.up.parameter == p.to) << p.name;
  }
}

TEST(OptimizeJob, MainJobClimbsFromTheSineToTheFastestDrives) {
  OptimizeJobOptions job;
  MainJob main{ReachEffort{2, 2, 8, 4}};
  main.drives.drive_evaluations = 20;
  main.drives.drive_polishes = 1;
  main.drives.drive_local_evaluations = 10;
  job.mode = main;
  job.check = SmallCheck();
  const auto r = std::get<MainJobResult>(RunOptimizeJob(job));
  ASSERT_EQ(r.drives.size(), 3U);  // K = 1 (the sine), 2, 3
  // The first step is the sine's reach result itself.
  EXPECT_EQ(r.drives[0].mean_velocity, r.reach.mean_velocity);
  EXPECT_EQ(r.drives[0].alpha, r.reach.alpha);
  for (std::size_t k = 1; k < r.drives.size(); ++k) {
    const ReachResult& d = r.drives[k];
    ASSERT_FALSE(std::isnan(d.mean_velocity)) << d.message;
    EXPECT_EQ(d.forcing.harmonics(), static_cast<int>(k + 1));
    EXPECT_LE(d.forcing.MaxAbs(), job.params.T0 * (1.0 + 1e-12));
    // Each step re-checks the winners below it: it is at least as fast when both hold.
    if (d.robust_to_settings && r.drives[k - 1].robust_to_settings) {
      EXPECT_GE(d.mean_velocity, r.drives[k - 1].mean_velocity);
    }
    // The reported speed is that of an independent run of the reported drive.
    EXPECT_EQ(FindAttractors({d.forcing, job.params, d.alpha}, job.check).mean_velocity,
              d.mean_velocity);
  }
}

// At T0 = 1e-6 the range of T0, [T0/2, 2 T0], is narrower than the continuation's
// finite-difference step of 1e-6: T0 is followed relative to its value, and every part of the
// robustness is computed or says why not; the bands have the levels asked for.
TEST(OptimizeJob, MainJobAtATinyT0ReportsEveryPartOfItsRobustness) {
  OptimizeJobOptions job;
  job.params.T0 = 1e-6;
  job.mode = MainJob{ReachEffort{2, 2, 8, 4}, {0.95, 0.9}};
  job.check = SmallCheck();
  const auto r = std::get<MainJobResult>(RunOptimizeJob(job));
  ASSERT_TRUE(r.robust.found());
  int parts = 0;
  for (const GaitRobustness* g : {&r.robustness, &r.reach_robustness}) {
    for (const ParameterRobustness& p : g->parameters) {
      ++parts;
      EXPECT_TRUE(p.status == ContinuationStatus::kOk || !p.message.empty()) << p.name;
      EXPECT_NE(p.band.status, SpeedBandStatus::kNotRun) << p.name;
      if (p.band.status == SpeedBandStatus::kOk) {
        EXPECT_EQ(p.band.down.size(), 2U) << p.name;
      }
    }
  }
  EXPECT_EQ(parts, 6);
  const ParameterRobustness& T0 = r.robustness.parameters.front();
  EXPECT_EQ(T0.name, "T0");
  EXPECT_EQ(T0.status, ContinuationStatus::kOk) << T0.message;
  EXPECT_DOUBLE_EQ(T0.from, 0.5e-6);
}

TEST(OptimizeJob, TellsItsStagesInOrderAndEndsWithEmpty) {
  OptimizeJobOptions job = PhaseJob(0.3, 0.4);
  std::vector<std::string> stages;
  job.on_stage = [&stages](const std::string& s) { stages.push_back(s); };
  RunOptimizeJob(job);
  ASSERT_EQ(stages.size(), 3U);
  EXPECT_EQ(stages[0], "optimize: --problem phase");
  EXPECT_EQ(stages[1], "optimize: the optimum checked from rest (simulated starts)");
  EXPECT_EQ(stages[2], "");
}

TEST(OptimizeJob, AnInterruptAbandonsTheJob) {
  struct Stop {};
  OptimizeJobOptions job = PhaseJob(0.3, 0.4);
  int asked = 0;
  job.search.interrupt = [&asked] {
    if (++asked == 3) throw Stop{};
  };
  EXPECT_THROW(RunOptimizeJob(job), Stop);
  EXPECT_EQ(asked, 3);
}

// The seeds a reach search computes itself (one per motor frequency with T0 free) ask for the
// job's gait, as its robust seed does: the request's margins and rho_max, whatever they are.
TEST(OptimizeJob, TheReachSearchsOwnSeedsAskForTheJobsGait) {
  OptimizeJobOptions job;
  job.check = SmallCheck();
  job.search.gait.margins = Margins{0.05, 0.1, 0.2};
  job.search.gait.rho_max = 0.8;
  job.search.gait.force_bound = 0.7;
  ReachEffort effort;
  effort.global_evaluations = 7;
  const ReachOptions r = job.ReachOptionsOf(effort, 0.4);
  EXPECT_EQ(r.seed_design.gait.margins.clearance, 0.05);
  EXPECT_EQ(r.seed_design.gait.margins.clearance_stroke, 0.1);
  EXPECT_EQ(r.seed_design.gait.margins.stick, 0.2);
  EXPECT_EQ(r.seed_design.gait.rho_max, 0.8);
  EXPECT_EQ(r.force_bound, 0.7);
  EXPECT_EQ(r.alpha, 0.4);
  EXPECT_EQ(r.global_evaluations, 7);
  EXPECT_EQ(r.check.n_x, 3);
  // The defaults: the robust gait of the library's own default seed.
  const ReachOptions robust = OptimizeJobOptions{}.ReachOptionsOf(ReachEffort{}, kNaN);
  EXPECT_EQ(robust.seed_design.gait.margins.clearance_stroke,
            RobustSeedDesign().gait.margins.clearance_stroke);
  EXPECT_EQ(robust.seed_design.gait.margins.stick, RobustSeedDesign().gait.margins.stick);
  EXPECT_EQ(robust.seed_design.gait.rho_max, RobustSeedDesign().gait.rho_max);
}

TEST(OptimizeJob, ModeNamesAreTheProblemNames) {
  EXPECT_STREQ(OptimizeModeName(MainJob{}), "");
  EXPECT_STREQ(OptimizeModeName(PhaseProblem{}), "phase");
  EXPECT_STREQ(OptimizeModeName(ForcingProblem{}), "forcing");
  EXPECT_STREQ(OptimizeModeName(FourierProblem{}), "fourier");
  EXPECT_STREQ(OptimizeModeName(ReachProblem{}), "reach");
}

// The message of Validate() for `job`, empty when it passes.
std::string Refusal(const OptimizeJobOptions& job) {
  try {
    job.Validate();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(OptimizeJob, BadOptionsAreRefusedNamingTheParameter) {
  EXPECT_EQ(Refusal(PhaseJob(0.3, 0.4)), "");
  EXPECT_NE(Refusal(PhaseJob(std::nan(""), 0.4)).find("A = nan"), std::string::npos);
  EXPECT_NE(Refusal(PhaseJob(-1.0, 0.4)).find("A = -1"), std::string::npos);
  EXPECT_NE(Refusal(PhaseJob(0.3, HUGE_VAL)).find("c = inf"), std::string::npos);

  OptimizeJobOptions job;  // the main job
  EXPECT_EQ(Refusal(job), "");
  job.search.gait.rho_max = 0.0;
  EXPECT_NE(Refusal(job).find("rho_max = 0"), std::string::npos);
  job = OptimizeJobOptions{};
  job.search.gait.force_bound = 2.0;  // above T0 = 1
  EXPECT_NE(Refusal(job).find("force_bound = 2"), std::string::npos);
  job = OptimizeJobOptions{};
  job.mode = ReachProblem{ReachEffort{}, 1.5, DriveFamily{}, NAN, NAN};
  EXPECT_NE(Refusal(job).find("alpha = 1.5"), std::string::npos);
  job.mode = MainJob{ReachEffort{0, 4}};
  EXPECT_NE(Refusal(job).find("n_x = 0"), std::string::npos);
  job = OptimizeJobOptions{};
  job.check.n_psi = 0;
  EXPECT_NE(Refusal(job).find("n_psi = 0"), std::string::npos);
  job = OptimizeJobOptions{};
  job.params.e = 1.5;
  EXPECT_NE(Refusal(job).find("e = 1.5"), std::string::npos);
  job = OptimizeJobOptions{};
  job.mode = MainJob{ReachEffort{}, {0.95, 1.0}};
  EXPECT_EQ(Refusal(job), "band_levels = 1 is invalid: expected fractions of the speed in (0, 1)");
}

TEST(OptimizeJob, RunValidatesFirst) {
  OptimizeJobOptions job = PhaseJob(0.3, 0.4);
  bool told = false;
  job.on_stage = [&told](const std::string&) { told = true; };
  job.check.n_x = 0;
  EXPECT_THROW(RunOptimizeJob(job), std::invalid_argument);
  EXPECT_FALSE(told);  // no stage began
}

}  // namespace
}  // namespace capsubot
