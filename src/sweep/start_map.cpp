// The CSV of a map of starts and the resumable file of one of its shards.

#include "capsubot/sweep/start_map.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "capsubot/io/io.hpp"
#include "sweep/sweep_file.hpp"

namespace capsubot {
namespace {

constexpr std::size_t kFlushBytes = 1 << 16;  // rows gathered before a write

}  // namespace

const char* StartMapHeader(bool u0) {
  return u0 ? "x0,u0,attractor,period,impacts_right,impacts_left,mean_velocity,status\n"
            : "x0,psi,attractor,period,impacts_right,impacts_left,mean_velocity,status\n";
}

void AppendStartMapRow(std::string& out, const PhaseState& start, const Motion& m, bool u0,
                       const std::string& attractor) {
  out += FormatNumber(start.x);
  out += ',';
  out += FormatNumber(u0 ? start.u : start.psi);
  out += ',';
  out += attractor;
  out += fmt::format(",{},{},{},", m.period, m.impacts_right, m.impacts_left);
  out += FormatNumber(m.mean_velocity);
  out += ',';
  out += MotionStatusName(m.status);
  out += '\n';
}

void WriteStartMap(const std::string& output, const std::vector<PhaseState>& starts,
                   const Attractors& a, bool u0, const std::string& comments) {
  if (a.motions.size() != starts.size() || a.labels.size() != starts.size()) {
    throw std::invalid_argument(fmt::format(
        "attractors of {} motions and {} labels are invalid: expected one per start ({})",
        a.motions.size(), a.labels.size(), starts.size()));
  }
  AtomicFile file(output, "output");
  std::string rows = comments + StartMapHeader(u0);
  for (std::size_t k = 0; k < starts.size(); ++k) {
    AppendStartMapRow(rows, starts[k], a.motions[k], u0, std::to_string(a.labels[k] + 1));
    if (rows.size() > kFlushBytes) {
      file.stream() << rows;
      rows.clear();
    }
  }
  file.stream() << rows;
  file.Commit();
}

void StartShardOptions::Validate(std::size_t starts) const {
  if (shards < 1 || shard < 0 || shard >= shards) {
    throw std::invalid_argument(fmt::format(
        "shard = {}/{} is invalid: expected K/N with N >= 1 shards and 0 <= K < N", shard, shards));
  }
  if (static_cast<std::size_t>(shards) > starts) {
    throw std::invalid_argument(
        fmt::format("shard = {}/{} is invalid: the map has only {} starts: expected at most "
                    "as many shards as starts",
                    shard, shards, starts));
  }
  if (!(checkpoint_seconds >= 0.0) || !std::isfinite(checkpoint_seconds)) {
    throw std::invalid_argument(fmt::format(
        "checkpoint_seconds = {} is invalid: expected a finite time >= 0", checkpoint_seconds));
  }
}

std::vector<PhaseState> ShardStarts(const std::vector<PhaseState>& starts, int shard, int shards) {
  std::vector<PhaseState> mine;
  if (shards < 1 || shard < 0) return mine;
  mine.reserve(starts.size() / static_cast<std::size_t>(shards) + 1);
  for (std::size_t s = static_cast<std::size_t>(shard); s < starts.size();
       s += static_cast<std::size_t>(shards)) {
    mine.push_back(starts[s]);
  }
  return mine;
}

StartShardSummary WriteStartShard(const RobotModel& robot, const std::vector<PhaseState>& starts,
                                  const AttractorOptions& attractor,
                                  const StartShardOptions& options, const StartsProgress& progress,
                                  const BlockBackend& backend) {
  options.Validate(starts.size());
  const std::vector<PhaseState> mine = ShardStarts(starts, options.shard, options.shards);
  const std::string head =
      options.comments +
      fmt::format("# shard {}/{} of {} starts\n", options.shard, options.shards, starts.size()) +
      StartMapHeader(options.u0);
  std::string description = "map of starts " + head;  // one line: the checkpoint's record
  std::replace(description.begin(), description.end(), '\n', '\x1f');
  robot.params.Validate();  // before the file is touched
  attractor.Validate();
  for (const PhaseState& s : mine) ValidateStart(robot.alpha, s);
  detail::SweepFile file(options.output, description, head,
                         {static_cast<std::int64_t>(mine.size()), {}}, options.resume,
                         options.checkpoint_seconds, "shard");
  StartShardSummary summary;
  summary.starts = static_cast<std::int64_t>(mine.size());
  summary.resumed = file.points_done();
  std::string rows;
  StreamLongRunMotions(
      robot, mine, attractor, file.points_done(),
      [&](std::int64_t begin, std::int64_t end, const Motion* motions) {
        rows.clear();
        for (std::int64_t i = begin; i < end; ++i) {
          AppendStartMapRow(rows, mine[static_cast<std::size_t>(i)], motions[i - begin], options.u0,
                            "");
        }
        file.Append(rows.data(), rows.size(), end - begin);
        if (progress) progress(end, summary.starts);
      },
      backend);
  file.Commit();
  return summary;
}

}  // namespace capsubot
