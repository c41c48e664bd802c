// Joining basin map shards: the rows read back into motions, regrouped over the whole map,
// written with their attractor labels.

#include "capsubot/basin_shards.hpp"

#include <fmt/format.h>

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string_view>

#include "capsubot/bifurcation_shards.hpp"
#include "capsubot/io.hpp"
#include "capsubot/start_map.hpp"
#include "sweep/shard_set.hpp"

namespace capsubot {
namespace {

// x0, psi or u0, attractor, period, impacts_right, impacts_left, mean_velocity, status.
constexpr std::size_t kColumns = 8;

MotionStatus ParseStatus(std::string_view name, const std::string& what) {
  for (MotionStatus s : {MotionStatus::kPeriodic, MotionStatus::kNoPeriod,
                         MotionStatus::kEventLimit, MotionStatus::kNotRun}) {
    if (name == MotionStatusName(s)) return s;
  }
  throw std::invalid_argument(
      fmt::format("{} = {} is invalid: expected periodic, no_period, event_limit or not_run", what,
                  QuoteForMessage(name)));
}

// One row of shard `s` (its units_read-th start): the start, its motion, and the offset of
// its empty attractor cell.
std::size_t ParseRow(const detail::ShardFile& s, bool u0, PhaseState& start, Motion& m) {
  std::array<std::string_view, kColumns> cell;
  std::string_view rest(s.next);
  std::size_t count = 0, attractor = 0;
  for (; count < kColumns; ++count) {
    const std::size_t comma = rest.find(',');
    cell[count] = rest.substr(0, comma);
    if (count == 2) attractor = static_cast<std::size_t>(cell[2].data() - s.next.data());
    if (comma == std::string_view::npos) break;
    rest.remove_prefix(comma + 1);
  }
  const std::string where = fmt::format("shard file {} start {}", s.path, s.units_read);
  if (count != kColumns - 1 || !cell[2].empty()) {
    throw std::invalid_argument(fmt::format(
        "{} is invalid: expected a row of {} cells with an empty attractor cell", where, kColumns));
  }
  start = RestStart(ParseNumber(cell[0], where + " x0"), 0.0);
  (u0 ? start.u : start.psi) = ParseNumber(cell[1], where + (u0 ? " u0" : " psi"));
  m.period = static_cast<int>(ParseInteger(cell[3], where + " period", 0, 1 << 20));
  m.impacts_right = ParseInteger(cell[4], where + " impacts_right", 0, INT64_MAX / 2);
  m.impacts_left = ParseInteger(cell[5], where + " impacts_left", 0, INT64_MAX / 2);
  m.mean_velocity = cell[6].empty() ? Motion::kNaN : ParseNumber(cell[6], where + " mean_velocity");
  m.status = ParseStatus(cell[7], where + " status");
  return attractor;
}

}  // namespace

MergeSummary MergeBasinShards(const std::vector<std::string>& paths, const std::string& output,
                              double velocity_tolerance) {
  std::vector<detail::ShardFile> shards = detail::OpenShardSet(paths, "starts", output);
  const detail::ShardFile& first = shards.front();
  const bool u0 = first.header == StartMapHeader(true);
  if (!u0 && first.header != StartMapHeader(false)) {
    const std::string_view header = StartMapHeader(false);
    throw std::invalid_argument(
        fmt::format("shard file {} is invalid: expected the header of a basin map, {}", first.path,
                    header.substr(0, header.size() - 1)));
  }
  const auto n = static_cast<std::size_t>(first.units);
  std::vector<PhaseState> starts(n);
  std::vector<Motion> motions(n);
  std::vector<std::string> rows(n);
  std::vector<std::size_t> cells(n);
  for (std::size_t p = 0; p < n; ++p) {
    detail::ShardFile& s = shards[p % shards.size()];
    if (!s.has_next) detail::ThrowTruncated(s);
    cells[p] = ParseRow(s, u0, starts[p], motions[p]);
    rows[p].swap(s.next);
    s.Advance();
    ++s.units_read;
  }
  detail::RequireShardsConsumed(shards);
  const Attractors a = GroupMotions(starts, std::move(motions),
                                    Grouping{velocity_tolerance, Grouping{}.irregular_tolerance});

  AtomicFile file(output, "output");
  std::ostream& out = file.stream();
  out << first.header;
  for (std::size_t p = 0; p < n; ++p) {
    out.write(rows[p].data(), static_cast<std::streamsize>(cells[p]));
    out << a.labels[p] + 1;
    out.write(rows[p].data() + cells[p], static_cast<std::streamsize>(rows[p].size() - cells[p]));
    out << '\n';
  }
  file.Commit();
  MergeSummary summary;
  summary.shards = static_cast<int>(shards.size());
  summary.points = summary.rows = first.units;
  return summary;
}

MergeSummary MergeShards(const std::vector<std::string>& paths, const std::string& output) {
  const std::string unit = paths.empty() ? "" : detail::ShardUnit(paths.front());
  if (unit == "starts") return MergeBasinShards(paths, output);
  if (unit == "continuations") return MergeBifurcationShards(paths, output);
  return MergeSweepShards(paths, output);
}

}  // namespace capsubot
