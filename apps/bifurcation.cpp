// capsubot bifurcation: brute-force bifurcation diagram with the state carried along, up and
// down, plus the analytic one-impact orbits (docs/model.md section 13).

#include "capsubot/bifurcation.hpp"

#include <fmt/format.h>

#include <cmath>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include "attract_options.hpp"
#include "capsubot/bifurcation_shards.hpp"
#include "capsubot/grid.hpp"
#include "capsubot/io.hpp"
#include "commands.hpp"
#include "provenance.hpp"

namespace capsubot::app {
namespace {

struct BifurcationCommandOptions {
  RobotOptions robot;
  BifurcationOptions diagram;
  std::string param;
  std::string direction = "both";
  std::string start = "0.5,0";
  std::string over;   // "NAME=lo:hi:n" (the sweep's axis syntax), empty: one diagram
  std::string shard;  // "K/N", empty: the whole study
  std::string output, summary;
  bool no_analytic = false;
};

// The cell of the second parameter before a row ("" without it).
std::string OverCell(bool two, double over) { return two ? FormatNumber(over) + ',' : ""; }

std::string ImpactRow(const ImpactPoint& p, bool two) {
  return fmt::format("{}{},{},{},{},{},{}\n", OverCell(two, p.over), FormatNumber(p.param),
                     SweepDirectionName(p.direction), p.period_index, p.right ? "right" : "left",
                     FormatNumber(p.phase), FormatNumber(p.velocity));
}

std::string SummaryRow(const BifurcationPoint& p, bool two) {
  return fmt::format("{}{},{},{},{},{},{},{},{},{},{}\n", OverCell(two, p.over),
                     FormatNumber(p.param), SweepDirectionName(p.direction), p.motion.period,
                     p.motion.impacts_right, p.motion.impacts_left,
                     FormatNumber(p.motion.mean_velocity), FormatNumber(p.multiplier_re),
                     FormatNumber(p.multiplier_im), FormatNumber(p.spectral_radius),
                     MotionStatusName(p.motion.status));
}

// Writes `header` and the rows of `points` (part after part, as d.parts) to `file`; in a
// shard (`head` not empty: its comment lines) each part after its part line.
template <class Point, class Row>
void WriteRows(AtomicFile& file, const std::string& head, const std::string& header,
               const BifurcationDiagram& d, const std::vector<Point>& points, Row row) {
  auto& out = file.stream();
  out << head << header;
  std::size_t k = 0;
  for (const int part : d.parts) {
    std::string rows;
    std::int64_t count = 0;
    for (; k < points.size() && points[k].part == part; ++k, ++count) rows += row(points[k]);
    if (!head.empty()) out << BifurcationPartLine(part, d.total_parts, count);
    out << rows;
  }
}

int Run(BifurcationCommandOptions& opt, const CLI::App& cmd) {
  const Forcing forcing = opt.robot.forcing.Build();
  BifurcationOptions o = opt.diagram;
  o.param = ParseBifurcationParam(opt.param, &o.harmonic);
  o.motion = opt.robot.motion;
  o.start = ParseRestStart("--start", opt.start);
  o.analytic = !opt.no_analytic && !opt.summary.empty();
  if (opt.direction != "up" && opt.direction != "down" && opt.direction != "both") {
    throw std::invalid_argument(
        fmt::format("--direction = {} is invalid: expected up, down or both", opt.direction));
  }
  o.up = opt.direction != "down";
  o.down = opt.direction != "up";
  const bool two = !opt.over.empty();
  std::string over_name;
  if (two) {
    const GridAxis axis = ParseGridAxis(opt.over);
    over_name = axis.name();
    o.over = ParseBifurcationParam(over_name, &o.over_harmonic);
    for (std::int64_t i = 0; i < axis.size(); ++i) o.over_values.push_back(axis.Value(i));
  }
  if (!opt.shard.empty()) std::tie(o.shard, o.shards) = ParseShard(opt.shard);
  double alpha = opt.robot.alpha;
  if (o.param == BifurcationParam::kAlpha) alpha = o.from;  // the swept value decides
  if (two && o.over == BifurcationParam::kAlpha) alpha = o.over_values.front();
  if (std::isnan(alpha)) {
    throw std::invalid_argument("option --alpha is missing: give the mass ratio of the robot");
  }
  o.Validate();  // a bad --shard fails here, before any file is touched
  {
    AtomicFile probe(opt.output, "-o");  // fail on an unwritable path before the long run
  }
  const BifurcationDiagram d =
      ComputeBifurcation(forcing, opt.robot.params, alpha, o, TerminalProgress("parameter values"));
  // A shard's files: the run's name (without --shard and the paths), the shard line.
  const std::string head =
      opt.shard.empty()
          ? std::string()
          : "# " +
                CommandProvenance(cmd, {"--threads", "--output", "--summary", "--shard"})
                    .CommandLine() +
                '\n' +
                fmt::format("# shard {}/{} of {} continuations\n", o.shard, o.shards,
                            BifurcationContinuations(o));
  const std::string over_column = two ? over_name + ',' : "";
  AtomicFile impacts(opt.output, "-o");
  WriteRows(impacts, head, over_column + "param,direction,period_index,wall,phase,velocity\n", d,
            d.impacts, [two](const ImpactPoint& p) { return ImpactRow(p, two); });
  std::unique_ptr<AtomicFile> summary;
  if (!opt.summary.empty()) {
    summary = std::make_unique<AtomicFile>(opt.summary, "--summary");
    WriteRows(*summary, head,
              over_column +
                  "param,direction,period,impacts_right,impacts_left,mean_velocity,"
                  "largest_multiplier,largest_multiplier_im,spectral_radius,status\n",
              d, d.summary, [two](const BifurcationPoint& p) { return SummaryRow(p, two); });
  }
  impacts.Commit();
  if (summary) summary->Commit();
  fmt::print(
      "bifurcation diagram over {} = {:g} .. {:g} ({} values, {}){}{}: {} impacts written to "
      "{}{}\n",
      opt.param, o.from, o.to, o.steps, opt.direction,
      two ? fmt::format(" for {} values of {}", o.over_values.size(), over_name) : std::string(),
      opt.shard.empty() ? std::string()
                        : fmt::format(", shard {}/{} of {} continuations", o.shard, o.shards,
                                      BifurcationContinuations(o)),
      d.impacts.size(), opt.output,
      summary ? fmt::format(", {} summary rows to {}", d.summary.size(), opt.summary)
              : std::string());
  return 0;
}

}  // namespace

Command AddBifurcationCommand(CLI::App& app) {
  auto opt = std::make_shared<BifurcationCommandOptions>();
  CLI::App* cmd = app.add_subcommand(
      "bifurcation",
      "Bifurcation diagram by brute force (docs/model.md section 13): the parameter is stepped "
      "over its range with the state carried from each value to the next, up and then down, so "
      "coexisting attractors show as hysteresis. At each value: a transient, then the impacts of "
      "the record (-o) and a summary row (--summary) with the period, impacts, mean velocity and "
      "largest multiplier (Newton shooting), plus the valid analytic one-impact orbits "
      "(direction = analytic). --over: one diagram per value of a second parameter; --shard "
      "K/N: some of the continuations, joined by `capsubot merge` (docs/cluster.md).");
  AddRobotOptions(*cmd, opt->robot);
  cmd->get_option("--alpha")->required(false)->description(
      "mass ratio m2/(m1+m2) of the robot, 0 < alpha < 1 (not needed with --param alpha)");
  cmd->add_option("--param", opt->param,
                  "the parameter: A, c, alpha, T0, e, phi0, or a Fourier coefficient a1, b1, "
                  "a2, ... (a_k, b_k of the force given by --sin/--cos; a1 and b1 of the "
                  "harmonic force are 0 and A)")
      ->required();
  cmd->add_option("--from", opt->diagram.from, "first value of the parameter")->required();
  cmd->add_option("--to", opt->diagram.to, "last value of the parameter")->required();
  cmd->add_option("--steps", opt->diagram.steps, "values of the parameter, both ends included")
      ->capture_default_str();
  cmd->add_option("--direction", opt->direction, "up, down or both (up, then down)")
      ->capture_default_str();
  cmd->add_option("--start", opt->start,
                  "start of each sweep: from rest at x0 = X0, forcing phase PSI")
      ->type_name("X0,PSI")
      ->capture_default_str();
  cmd->add_option("-o,--output", opt->output,
                  "CSV of every recorded impact: param, direction, period_index, wall, phase, "
                  "velocity")
      ->required();
  cmd->add_option("--summary", opt->summary,
                  "CSV, one row per value and direction: param, direction, period, "
                  "impacts_right, impacts_left, mean_velocity, largest_multiplier (real part), "
                  "largest_multiplier_im, spectral_radius, status; plus the analytic orbits");
  cmd->add_flag("--no-analytic", opt->no_analytic,
                "leave the analytic one-impact orbits out of the summary");
  cmd->add_option("--over", opt->over,
                  "a two-parameter study: one diagram per value of this second parameter, "
                  "NAME=lo:hi:n, NAME=lo:hi:n:log or NAME=v1,v2,... (the syntax of `sweep "
                  "--grid`; NAME one of the --param choices); both CSVs get a first column NAME")
      ->type_name("NAME=LO:HI:N");
  cmd->add_option("--shard", opt->shard,
                  "compute only shard K of N (0 <= K < N <= the continuations, one per "
                  "direction and value of --over): the continuations q with q % N = K (q = "
                  "value index x directions + direction); the files get a comment line naming "
                  "the run, a line '# shard K/N of T continuations' and a line '# part P of Q: "
                  "R rows' before each part; `capsubot merge OUT SHARDS...` joins the N files "
                  "of -o (or of --summary) into the file of the whole study (docs/cluster.md)");
  AddThreadsOption(*cmd, opt->diagram.threads);
  return {cmd, [opt, cmd] { return Run(*opt, *cmd); }};
}

}  // namespace capsubot::app
