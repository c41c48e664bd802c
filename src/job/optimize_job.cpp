#include "capsubot/job/optimize_job.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "capsubot/model/limits.hpp"
#include "capsubot/numerics/not_computed.hpp"
#include "capsubot/optimize/optimize.hpp"

namespace capsubot {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

template <class... F>
struct Overloaded : F... {
  using F::operator()...;
};
template <class... F>
Overloaded(F...) -> Overloaded<F...>;

// The full check from rest, asking the job's interrupt.
FromRestOptions FromRestOptionsFor(const OptimizeJobOptions& options) {
  FromRestOptions check = options.check;
  check.attractor.interrupt = options.search.interrupt;
  return check;
}

// How far the main job's motions carry: their continuations (asking the job's interrupt) and
// the speed bands of their robots from rest over the job's check grid.
RobustnessOptions RobustnessOptionsFor(const OptimizeJobOptions& options, const MainJob& job) {
  RobustnessOptions r;
  r.continuation.interrupt = options.search.interrupt;
  r.speed_bands = true;
  r.band.levels = job.band_levels;
  r.band.from_rest = FromRestOptionsFor(options);
  return r;
}

// The reach winner's most common motion from rest when it is periodic (its section state is on
// it; the continuation's own Newton shooting refines it), else null.
const Motion* PeriodicMotionFromRest(const ReachResult& reach) {
  if (std::isnan(reach.mean_velocity) || reach.attractors.attractors.empty()) return nullptr;
  const Motion& m = reach.attractors.attractors.front().motion;
  return m.status == MotionStatus::kPeriodic ? &m : nullptr;
}

// The fastest drives under the reach search's bound: the Fourier ladder from its winner and the
// pulse drive of job.pulse_levels levels, with the main job's drive budgets.
void FastestDrives(const OptimizeJobOptions& options, const MainJob& job, MainJobResult& r) {
  ReachEffort drives = job.drives;
  drives.n_x = job.reach.n_x;
  drives.n_psi = job.reach.n_psi;
  drives.max_seconds = job.reach.max_seconds;
  const double bound = options.search.gait.force_bound;
  r.drives = ClimbDriveLadder(r.params, r.robust, r.reach,
                              drives.DriveOptions(DriveFamily::Fourier(job.drive_harmonics), bound,
                                                  kNaN, FromRestOptionsFor(options)))
                 .steps;
  r.pulse = OptimizeReach(r.params, r.robust,
                          drives.DriveOptions(DriveFamily::Pulse(job.pulse_levels), bound, kNaN,
                                              FromRestOptionsFor(options)));
}

MainJobResult RunMain(const OptimizeJobOptions& options, const MainJob& job) {
  const Params& p = options.params;
  MainJobResult r;
  r.params = p;
  r.gait = options.search.gait;
  r.gait.force_bound = options.search.gait.BoundFor(p);
  // 1. The paper's problem as the paper poses it (valid orbits, no margins): c = A = T0/2, best
  // phase. Its force sits on the friction bound, so any stick margin would exclude it.
  TellStage(options.on_stage, "optimize: 1/5 the paper's problem (P1)");
  r.paper = OptimizePhase(Forcing::Harmonic(p.T0 / 2.0, p.T0 / 2.0, 0.0), p,
                          PhaseOptionsFor(options.search.Exact(kInf)));
  // 2. The fastest robust gait, checked from rest inside 3; 3. the fastest motion from rest,
  // seeded with it; 4. how far it carries; 5. the exact optima, valid and stable.
  TellStage(options.on_stage, "optimize: 2/5 the fastest robust gait (P2)");
  r.robust = OptimizeForcing(p, ForcingOptionsFor(options.search));
  TellStage(options.on_stage,
            "optimize: 3/5 the fastest motion from rest (simulated starts; up to a minute)");
  r.reach = OptimizeReach(p, r.robust, options.ReachOptionsOf(job.reach, kNaN));
  TellStage(options.on_stage, "optimize: 3/5 the fastest Fourier and pulse drives from rest");
  FastestDrives(options, job, r);
  TellStage(options.on_stage,
            "optimize: 4/5 how far T0, e and alpha can move (continuation of both motions)");
  const RobustnessOptions robustness = RobustnessOptionsFor(options, job);
  if (r.robust.found()) {
    r.robustness = ComputeGaitRobustness(r.robust.solution.orbit, robustness);
  }
  if (const Motion* motion = PeriodicMotionFromRest(r.reach)) {
    r.reach_robustness =
        ComputeMotionRobustness({{r.reach.forcing, p, r.reach.alpha}, motion->section}, robustness);
  } else if (!std::isnan(r.reach.mean_velocity)) {
    r.reach_robustness = ComputeSpeedBands({r.reach.forcing, p, r.reach.alpha}, robustness,
                                           "its most common motion from rest is not periodic");
  }
  TellStage(options.on_stage, "optimize: 5/5 the exact optima without margins");
  r.fastest = OptimizeForcing(p, ForcingOptionsFor(options.search.Exact(kInf)));
  r.stable = OptimizeForcing(p, ForcingOptionsFor(options.search.Exact(1.0)));
  TellStage(options.on_stage, "");
  return r;
}

ReachJobResult RunReach(const OptimizeJobOptions& options, const ReachProblem& job) {
  const bool sine = job.drive.sine();
  TellStage(options.on_stage,
            fmt::format("optimize: 1/{} the robust gait that seeds the search (P2)", sine ? 2 : 3));
  const OptimizeResult robust = OptimizeForcing(options.params, ForcingOptionsFor(options.search));
  TellStage(options.on_stage, fmt::format("optimize: 2/{} the fastest motion from rest of the sine "
                                          "(simulated starts; up to a minute)",
                                          sine ? 2 : 3));
  ReachOptions sine_options = options.ReachOptionsOf(job.reach, job.alpha);
  sine_options.T0_min = job.T0_min;
  sine_options.T0_max = job.T0_max;
  ReachJobResult r{
      options.params, options.search.gait, OptimizeReach(options.params, robust, sine_options), {}};
  if (!sine) {
    TellStage(
        options.on_stage,
        fmt::format("optimize: 3/3 the fastest drive from rest, {} (simulated starts; minutes)",
                    job.drive.Describe()));
    ReachOptions drive_options = job.reach.DriveOptions(job.drive, options.search.gait.force_bound,
                                                        job.alpha, FromRestOptionsFor(options));
    drive_options.T0_min = job.T0_min;
    drive_options.T0_max = job.T0_max;
    if (job.drive.waveform == Waveform::kPulse) {
      r.ladder = {r.reach, OptimizeReach(options.params, robust, drive_options)};
    } else {
      r.ladder = ClimbDriveLadder(options.params, robust, r.reach, drive_options).steps;
    }
    r.reach = r.ladder.back();
  }
  TellStage(options.on_stage, "");
  return r;
}

ProblemJobResult RunProblem(const OptimizeJobOptions& options) {
  const std::string name = OptimizeModeName(options.mode);
  TellStage(options.on_stage, fmt::format("optimize: --problem {}", name));
  OptimizeResult result = std::visit(
      Overloaded{[&](const PhaseProblem& shape) {
                   return OptimizePhase(Forcing::Harmonic(shape.A, shape.c, 0.0), options.params,
                                        PhaseOptionsFor(options.search));
                 },
                 [&](const FourierProblem&) {
                   return OptimizeFourier(options.params, FourierOptionsFor(options.search));
                 },
                 [&](const auto&) {
                   return OptimizeForcing(options.params, ForcingOptionsFor(options.search));
                 }},
      options.mode);
  TellStage(options.on_stage, "optimize: the optimum checked from rest (simulated starts)");
  GaitFromRest from_rest =
      CheckGaitFromRest(result.solution.orbit, options.params, FromRestOptionsFor(options));
  TellStage(options.on_stage, "");
  return {name, options.params, options.search.gait, std::move(result), std::move(from_rest)};
}

}  // namespace

const char* OptimizeModeName(const OptimizeMode& mode) {
  static constexpr const char* kNames[] = {"", "phase", "forcing", "fourier", "reach"};
  return kNames[mode.index()];
}

ReachEffort MainJob::MainJobDriveEffort() {
  ReachEffort e;
  e.drive_evaluations = 150;
  e.drive_polishes = 2;
  e.drive_local_evaluations = 80;
  e.drive_refine_evaluations = 0;
  e.drive_screens = 0;
  return e;
}

ReachOptions OptimizeJobOptions::ReachOptionsOf(const ReachEffort& effort, double alpha) const {
  ReachOptions r = effort.Options(search.gait.force_bound, alpha, FromRestOptionsFor(*this));
  r.seed_design.gait.margins = search.gait.margins;
  r.seed_design.gait.rho_max = search.gait.rho_max;
  return r;
}

SearchRequest OptimizeJobOptions::RobustRequest() {
  SearchRequest r;
  r.gait.rho_max = kRobustRhoMax;
  r.gait.margins = RobustMargins();
  return r;
}

void OptimizeJobOptions::Validate() const {
  params.Validate();
  if (const auto* shape = std::get_if<PhaseProblem>(&mode)) {
    if (!(std::isfinite(shape->A) && shape->A >= 0.0)) {
      throw std::invalid_argument(fmt::format(
          "A = {} is invalid: expected a finite amplitude A >= 0 of F = A sin(phi + phi0) + c",
          shape->A));
    }
    if (!std::isfinite(shape->c)) {
      throw std::invalid_argument(
          fmt::format("c = {} is invalid: expected a finite mean force c", shape->c));
    }
    PhaseOptionsFor(search).Validate();
  } else {
    const ForcingDesignOptions design = ForcingOptionsFor(search);
    design.Validate();
    design.gait.BoundFor(params);
    if (std::holds_alternative<FourierProblem>(mode)) FourierOptionsFor(search).Validate();
  }
  check.Validate();
  if (const auto* job = std::get_if<MainJob>(&mode)) {
    job->reach.Validate();
    job->drives.Validate();
    DriveFamily::Pulse(job->pulse_levels).Validate();
    if (job->drive_harmonics < 2 || job->drive_harmonics > kMaxHarmonics) {
      throw std::invalid_argument(
          fmt::format("drive_harmonics = {} is invalid: expected 2 <= drive_harmonics <= {}",
                      job->drive_harmonics, kMaxHarmonics));
    }
    ReachOptionsOf(job->reach, kNaN).Validate();
    RobustnessOptionsFor(*this, *job).Validate();
  }
  if (const auto* job = std::get_if<ReachProblem>(&mode)) {
    job->reach.Validate();
    job->drive.Validate();
    ReachOptions reach = ReachOptionsOf(job->reach, job->alpha);
    reach.T0_min = job->T0_min;
    reach.T0_max = job->T0_max;
    reach.Validate();
  }
}

OptimizeJobResult RunOptimizeJob(const OptimizeJobOptions& options) {
  options.Validate();
  if (const auto* job = std::get_if<MainJob>(&options.mode)) return RunMain(options, *job);
  if (const auto* job = std::get_if<ReachProblem>(&options.mode)) return RunReach(options, *job);
  return RunProblem(options);
}

const Forcing& RecommendedForcing(const OptimizeJobResult& result) {
  return std::visit(
      Overloaded{
          [](const MainJobResult& r) -> const Forcing& { return r.robust.solution.orbit.forcing; },
          [](const ProblemJobResult& r) -> const Forcing& {
            return r.result.solution.orbit.forcing;
          },
          [](const ReachJobResult& r) -> const Forcing& { return r.reach.forcing; }},
      result);
}

}  // namespace capsubot
