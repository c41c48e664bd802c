// The design job (docs/design.md): one design, parts (a) and (b), or a grid of designs, from
// one options struct.

#include "capsubot/job/design_job.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <tuple>

#include "capsubot/attract/start_grid.hpp"
#include "capsubot/design/gait_numbers.hpp"
#include "capsubot/io/io.hpp"
#include "capsubot/numerics/not_computed.hpp"
#include "capsubot/optimize/detail/optimize_common.hpp"

namespace capsubot {
namespace {

// The one rule of a grid of starts (ParseStartGrid's), for a grid given as its two sizes:
// "reach_starts = 0x4 is invalid: ..." names the part's field.
void RequireStarts(const char* name, const StartGrid& grid) {
  ParseStartGrid(name, fmt::format("{}x{}", grid.n_x, grid.n_psi));
}

// The columns of a grid's axes (DesignGridAxis::column: m2_kg, frequency_hz, ...).
using GridColumns = std::vector<std::string>;

// Whether the user-unit key `key` of a gait is a result column: all but those a grid's column
// holds (a gridded m2 is the column m2_kg, a gridded frequency frequency_hz).
bool ResultColumn(const char* key, const GridColumns& grid) {
  return std::find(grid.begin(), grid.end(), key) == grid.end();
}

// The result columns of a design grid, after the grid's: the gait's status, its numbers in
// the user's units (ResultColumn) and dimensionless, its orbits and binding limits.
std::vector<std::string> GaitColumns(const GridColumns& grid) {
  std::vector<std::string> columns = {"status"};
  for (const auto& [key, value] : UserUnits(Gait{})) {
    if (ResultColumn(key, grid)) columns.emplace_back(key);
  }
  for (const auto& [key, value] : Dimensionless(Gait{})) columns.emplace_back(key);
  columns.emplace_back("orbits");
  columns.emplace_back("binding");
  return columns;
}

// The cells of GaitColumns(grid).
std::string GaitCells(const Gait& g, const GridColumns& grid) {
  std::vector<std::string> cells = {GaitStatusName(g.status)};
  for (const auto& [key, value] : UserUnits(g)) {
    if (ResultColumn(key, grid)) cells.push_back(FormatNumber(value));
  }
  for (const auto& [key, value] : Dimensionless(g)) cells.push_back(FormatNumber(value));
  cells.push_back(std::to_string(g.orbits));
  cells.push_back(fmt::format("{}", fmt::join(g.binding, ";")));
  return fmt::format("{}", fmt::join(cells, ","));
}

// How far mu, e and m2 carry the gait: its continuations (asking the interrupt) and the speed
// bands of the robot from rest.
RobustnessOptions RobustnessOf(const DesignOneMode& one) {
  RobustnessOptions r;
  r.continuation.interrupt = one.interrupt;
  r.speed_bands = true;
  r.band.levels = one.band_levels;
  const DesignFromRestOptions part =
      one.from_rest ? one.from_rest->Options() : DesignFromRestPart().Options();
  r.band.from_rest = part.check;
  r.band.from_rest.attractor.interrupt = one.interrupt;
  return r;
}

DesignJobResult RunOne(const DesignJobOptions& options, const DesignOneMode& one) {
  DesignJobResult r;
  r.input = options.input;
  const int stages = one.from_rest ? 3 : 2;
  TellStage(options.on_stage,
            fmt::format("design: 1/{} the fastest robust one-impact gait", stages));
  r.design = Design(options.input, one.progress);
  if (r.design.one_impact.ok()) {
    TellStage(options.on_stage,
              fmt::format("design: 2/{} how far mu, e and m2 carry the gait", stages));
    const RobustnessOptions robustness = RobustnessOf(one);
    r.robustness = ComputeDesignRobustness(options.input, r.design.one_impact, robustness);
    const Orbit& o = r.design.one_impact.solution.orbit;
    // The robot of the speed bands (the motor's force, phi0 = 0): the same starts from rest.
    r.gait_from_rest = CheckGaitFromRest(o, r.design.one_impact.model.robot.forcing,
                                         Params{o.T0, o.e}, robustness.band.from_rest);
  }
  if (one.from_rest) {
    TellStage(options.on_stage, "design: 3/3 the fastest motion from rest");
    r.from_rest_options = one.from_rest->Options();
    DesignFromRestOptions run = r.from_rest_options;
    run.search.attractor.interrupt = one.from_rest->interrupt;
    run.check.attractor.interrupt = one.from_rest->interrupt;
    r.from_rest = DesignFromRest(options.input, run, one.from_rest->progress);
  }
  TellStage(options.on_stage, "");
  return r;
}

DesignJobResult RunDrive(const DesignJobOptions& options, const DesignDriveMode& mode) {
  DesignJobResult r;
  r.input = options.input;
  TellStage(options.on_stage,
            fmt::format("design: the fastest drive from rest, {} (simulated starts; minutes)",
                        mode.options.drive.Describe()));
  DriveDesignOptions run = mode.options;
  run.check.attractor.interrupt = mode.interrupt;
  r.drive = DesignDrive(options.input, run);
  TellStage(options.on_stage, "");
  return r;
}

DesignJobResult RunGrid(const DesignJobOptions& options, const DesignGridMode& mode) {
  const DesignGridOptions grid = DesignJobGrid(options.input, mode);
  DesignJobResult r;
  r.input = options.input;
  r.grid = DesignGridWritten{grid.output, RunDesignGrid(grid, mode.progress, mode.backend)};
  return r;
}

}  // namespace

const char* DesignChoiceName(DesignChoice choice) {
  switch (choice) {
    case DesignChoice::kGait:
      return "one_impact";
    case DesignChoice::kFromRestForward:
      return "from_rest_forward";
    case DesignChoice::kNone:
      break;
  }
  return "none";
}

double GaitSpeedFromRest(const DesignJobResult& r) {
  const Gait& g = r.design.one_impact;
  if (!g.ok() || !r.gait_from_rest.checked) return kNaN;
  return 1e3 * g.model.omega * r.input.L * r.gait_from_rest.attractors.mean_velocity;
}

DesignChoice ChooseDesign(const DesignJobResult& r) {
  const bool forward = r.from_rest && r.from_rest->forward.ok();
  const double gait = GaitSpeedFromRest(r);
  if (std::isnan(gait)) return forward ? DesignChoice::kFromRestForward : DesignChoice::kNone;
  return forward && r.from_rest->forward.speed_mm_s > gait ? DesignChoice::kFromRestForward
                                                           : DesignChoice::kGait;
}

DesignFromRestPart::DesignFromRestPart() {
  const DesignFromRestOptions d;
  from_rest_starts = {d.check.n_x, d.check.n_psi};
  reach_starts = {d.search.n_x, d.search.n_psi};
  reach_evaluations = d.global_evaluations;
  reach_local_evaluations = d.local_evaluations;
  reach_seconds = d.max_seconds;
  threads = d.search.attractor.threads;
}

void DesignFromRestPart::Validate() const {
  RequireStarts("from_rest_starts", from_rest_starts);
  RequireStarts("reach_starts", reach_starts);
  detail::RequireCount("reach_evaluations", reach_evaluations, 1, kMaxDesignFromRestEvaluations);
  detail::RequireCount("reach_local_evaluations", reach_local_evaluations, 0,
                       kMaxDesignFromRestEvaluations);
  detail::Require(
      std::isfinite(reach_seconds) && reach_seconds > 0.0,
      fmt::format("reach_seconds = {} is invalid: expected a finite time > 0 [s]", reach_seconds));
  Options().Validate();  // the rest (threads) has the same name here and there
}

DesignFromRestOptions DesignFromRestPart::Options() const {
  DesignFromRestOptions o;
  o.search.n_x = reach_starts.n_x;
  o.search.n_psi = reach_starts.n_psi;
  o.search.attractor.threads = threads;
  // The check's grid and threads; its record stays the long one of DesignFromRestOptions.
  o.check.n_x = from_rest_starts.n_x;
  o.check.n_psi = from_rest_starts.n_psi;
  o.check.attractor.threads = threads;
  o.global_evaluations = reach_evaluations;
  o.local_evaluations = reach_local_evaluations;
  o.max_seconds = reach_seconds;
  return o;
}

void DesignJobOptions::Validate() const {
  input.Validate();
  if (const auto* one = std::get_if<DesignOneMode>(&mode)) {
    if (one->from_rest) one->from_rest->Validate();
    RobustnessOf(*one).Validate();
    return;
  }
  if (const auto* drive = std::get_if<DesignDriveMode>(&mode)) {
    drive->options.Validate();
    return;
  }
  DesignJobGrid(input, std::get<DesignGridMode>(mode)).Validate();
}

DesignGridOptions DesignJobGrid(const DesignInput& input, const DesignGridMode& mode) {
  DesignGridOptions o;
  static_cast<GridFileOptions&>(o) = mode;
  o.input = input;
  o.axes = mode.axes;
  GridColumns grid;
  for (const DesignGridAxis& axis : o.axes) grid.push_back(axis.column());
  o.columns = GaitColumns(grid);
  o.row = [grid](const Gait& g) { return GaitCells(g, grid); };
  return o;
}

DesignJobResult RunDesignJob(const DesignJobOptions& options) {
  options.Validate();
  if (const auto* one = std::get_if<DesignOneMode>(&options.mode)) return RunOne(options, *one);
  if (const auto* drive = std::get_if<DesignDriveMode>(&options.mode)) {
    return RunDrive(options, *drive);
  }
  return RunGrid(options, std::get<DesignGridMode>(options.mode));
}

}  // namespace capsubot
