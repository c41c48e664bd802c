// capsubot merge: joins the shard files of `capsubot sweep|basins|attractors|bifurcation --shard
// K/N` and `capsubot design --grid ... --shard K/N` into the file of the whole run (library:
// capsubot/sweep/sweep_merge.hpp, capsubot/sweep/basin_shards.hpp,
// capsubot/sweep/bifurcation_shards.hpp).

#include <fmt/format.h>
#include <unistd.h>

#include <memory>
#include <string>
#include <vector>

#include "capsubot/cli/help_format.hpp"
#include "capsubot/sweep/basin_shards.hpp"
#include "commands.hpp"

namespace capsubot::cli {
namespace {

struct MergeCliOptions {
  std::string output;
  std::vector<std::string> shards;
};

int Run(const MergeCliOptions& opt) {
  const MergeSummary summary = MergeShards(opt.shards, opt.output);
  if (::isatty(STDERR_FILENO) != 0) {
    fmt::print(stderr, "capsubot merge: {} shards, {} points or starts, {} rows written to {}\n",
               summary.shards, summary.points, summary.rows, opt.output);
  }
  return 0;
}

}  // namespace

Command AddMergeCommand(CLI::App& app) {
  auto opt = std::make_shared<MergeCliOptions>();
  CLI::App* cmd = app.add_subcommand(
      "merge",
      "Joins the N >= 2 shard files of one `capsubot sweep|basins|attractors|bifurcation "
      "--shard K/N` or `capsubot design --grid ... --shard K/N` run (any order) into OUT, "
      "byte-identical to the -o file of the run on one machine (a map of starts: the attractors "
      "are labelled over the whole map); refuses shards of different runs, a missing or "
      "duplicated shard, a truncated one, a line longer than 1 MiB and an OUT that is one of "
      "the shard files (docs/cluster.md).");
  cmd->add_option("OUT", opt->output,
                  "the CSV file to write (atomically; - : standard output), not a shard file")
      ->required()
      ->type_name("FILE");
  cmd->add_option("SHARD_FILES", opt->shards, "the N shard files")->required()->type_name("FILE");
  SetExamples(*cmd, {{"the 3 shard files of a sweep --shard K/3 (any order) into the "
                      "file of the whole sweep",
                      "merge p2.csv part0.csv part1.csv part2.csv"}});
  return {cmd, [opt] { return Run(*opt); }, {}};
}

}  // namespace capsubot::cli
