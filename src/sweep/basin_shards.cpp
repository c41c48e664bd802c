// Joining basin map shards: the rows read back into motions, regrouped over the whole map,
// written with their attractor labels.

#include "capsubot/sweep/basin_shards.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string_view>

#include "capsubot/io/io.hpp"
#include "capsubot/numerics/not_computed.hpp"
#include "capsubot/sweep/bifurcation_shards.hpp"
#include "capsubot/sweep/start_map.hpp"
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
  m.mean_velocity = cell[6].empty() ? kNaN : ParseNumber(cell[6], where + " mean_velocity");
  m.status = ParseStatus(cell[7], where + " status");
  return attractor;
}

// The u0 of the starts j of a map of n_y starts per x0: the value two of the first three x0
// share (an edited row among them is outvoted), else that of the first x0.
double ColumnU(const std::vector<PhaseState>& starts, std::size_t n_y, std::size_t j) {
  if (starts.size() / n_y >= 3 && starts[n_y + j].u == starts[2 * n_y + j].u) {
    return starts[n_y + j].u;
  }
  return starts[j].u;
}

// What start s of a map of n_y starts per x0 should be, "" when it is that: x0 = (i + 0.5)/n_x
// and, on the x0-psi plane, psi = 2 pi j/n_y (GridStart); on the x0-u0 plane u0 is the same at
// every x0 (ColumnU) and increases with j.
std::string GridMismatch(const std::vector<PhaseState>& starts, bool u0, std::size_t n_y,
                         std::size_t s) {
  const std::size_t n_x = starts.size() / n_y, i = s / n_y, j = s % n_y;
  if (i >= n_x) return fmt::format("{} starts, a multiple of {}", starts.size(), n_y);
  const PhaseState grid = GridStart(static_cast<int>(i), static_cast<int>(j), static_cast<int>(n_x),
                                    static_cast<int>(n_y));
  if (starts[s].x != grid.x) return "x0 = " + FormatNumber(grid.x);
  if (!u0 && starts[s].psi != grid.psi) return "psi = " + FormatNumber(grid.psi);
  if (u0 && starts[s].u != ColumnU(starts, n_y, j)) {
    return "u0 = " + FormatNumber(ColumnU(starts, n_y, j)) + " as at every x0";
  }
  if (u0 && j > 0 && !(ColumnU(starts, n_y, j) > ColumnU(starts, n_y, j - 1))) {
    return "u0 > " + FormatNumber(ColumnU(starts, n_y, j - 1)) + ", increasing with the start";
  }
  return "";
}

// Run lengths of equal x0 tried as the map's starts per x0: the most frequent few.
constexpr std::size_t kGridCandidates = 8;

// Refuses a map whose starts are not those of its grid (GridMismatch), x0 major. The starts
// per x0, n_y, is the run length of equal x0 that fits the most starts, among the most
// frequent ones (an edited row breaks a run or two). The cells are written in shortest
// round-trip form and read back exactly: a row whose start was edited, or copied from another
// start, is named (shard file and row).
void RequireGridStarts(const std::vector<PhaseState>& starts, bool u0,
                       const std::vector<detail::ShardFile>& shards) {
  const std::size_t total = starts.size();
  std::map<std::size_t, std::size_t> runs;  // run length -> runs of that length
  for (std::size_t s = 0, begin = 0; s < total; ++s) {
    if (s + 1 == total || starts[s + 1].x != starts[begin].x) {
      ++runs[s + 1 - begin];
      begin = s + 1;
    }
  }
  std::vector<std::pair<std::size_t, std::size_t>> by_count;  // (runs, length)
  for (const auto& [length, count] : runs) by_count.emplace_back(count, length);
  std::sort(by_count.rbegin(), by_count.rend());
  by_count.resize(std::min(by_count.size(), kGridCandidates));
  std::size_t n_y = by_count.front().second, fewest = total + 1;
  for (const auto& candidate : by_count) {
    std::size_t wrong = 0;
    for (std::size_t s = 0; s < total && wrong < fewest; ++s) {
      wrong += GridMismatch(starts, u0, candidate.second, s).empty() ? 0 : 1;
    }
    if (wrong < fewest) {
      fewest = wrong;
      n_y = candidate.second;
    }
  }
  for (std::size_t s = 0; s < total; ++s) {
    const std::string expected = GridMismatch(starts, u0, n_y, s);
    if (expected.empty()) continue;
    throw std::invalid_argument(fmt::format(
        "shard file {} start {} (x0 = {}, {} = {}) is invalid: expected start {} of the map's "
        "{} x {} grid, {}: a start edited or copied from another",
        shards[s % shards.size()].path, s / shards.size(), FormatNumber(starts[s].x),
        u0 ? "u0" : "psi", FormatNumber(u0 ? starts[s].u : starts[s].psi), s, total / n_y, n_y,
        expected));
  }
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
  RequireGridStarts(starts, u0, shards);
  const Attractors a = GroupMotions(starts, std::move(motions),
                                    Grouping{velocity_tolerance, Grouping{}.irregular_tolerance});

  AtomicFile file(output, "output");
  std::ostream& out = file.stream();
  out << first.comments << first.header;
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
