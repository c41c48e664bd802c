#include "capsubot/sweep/sweep_merge.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "capsubot/io/io.hpp"
#include "sweep/shard_set.hpp"

namespace capsubot {
namespace {

// Most rows one point of a sweep has in robot mode: far above any robot's count of periodic
// orbits, far below what a damaged `orbits` cell could make the join wait for.
constexpr std::int64_t kMaxOrbitRows = std::int64_t{1} << 20;

// Robot mode (docs/model.md section 8): a point has one row per periodic orbit, each with the
// point's grid values, then `orbits` (their count) and `orbit` (1 .. orbits); a point without
// orbit has one row with orbits = 0 and an empty orbit cell. Without these columns a point has
// one row.
struct RobotColumns {
  int orbits = -1, orbit = -1;
  bool robot() const { return orbits >= 0 && orbit >= 0; }
};

// A row is shown in a message up to this many characters.
constexpr std::size_t kShownRowChars = 60;

std::string Shown(const std::string& row) {
  return row.size() > kShownRowChars ? row.substr(0, kShownRowChars) + "..." : row;
}

// Copies the rows of point `point` from shard `s` to `out`, checking in robot mode that the
// point has the rows its `orbits` cell counts, numbered 1 .. orbits, with the same grid
// values: a row lost, repeated or moved is refused, never merged. Returns the rows copied.
std::int64_t CopyPoint(detail::ShardFile& s, std::int64_t point, const RobotColumns& c,
                       std::ostream& out) {
  if (!s.has_next) detail::ThrowTruncated(s);
  if (!c.robot()) {
    out << s.next << '\n';
    s.Advance();
    return 1;
  }
  const std::string count(detail::RowCell(s.next, c.orbits));
  const std::size_t grid_end = detail::CellStart(s.next, c.orbits);
  const std::string grid = grid_end == std::string::npos ? s.next : s.next.substr(0, grid_end);
  std::int64_t orbits = 0;
  try {
    orbits = ParseInteger(count, "orbits", 0, kMaxOrbitRows);
  } catch (const std::invalid_argument&) {
    throw std::invalid_argument(fmt::format(
        "shard file {} point {} row '{}' is invalid: expected orbits = the point's count of "
        "orbits, an integer 0 <= orbits <= {}",
        s.path, point, Shown(s.next), kMaxOrbitRows));
  }
  const std::int64_t rows = std::max<std::int64_t>(orbits, 1);
  for (std::int64_t k = 1; k <= rows; ++k) {
    if (!s.has_next) {
      throw std::invalid_argument(fmt::format(
          "shard file {} is truncated: it ends in point {} after {} of its {} rows (orbits = {})",
          s.path, point, k - 1, rows, orbits));
    }
    const std::string expected = orbits == 0 ? std::string() : std::to_string(k);
    if (s.next.compare(0, grid.size(), grid) != 0 || detail::RowCell(s.next, c.orbits) != count ||
        detail::RowCell(s.next, c.orbit) != expected) {
      throw std::invalid_argument(fmt::format(
          "shard file {} point {} row {} '{}' is invalid: expected orbit = {} of its orbits = "
          "{} rows, with the point's grid values (a row lost, repeated or moved)",
          s.path, point, k, Shown(s.next), expected.empty() ? "(empty)" : expected, orbits));
    }
    out << s.next << '\n';
    s.Advance();
  }
  return rows;
}

}  // namespace

MergeSummary MergeSweepShards(const std::vector<std::string>& paths, const std::string& output) {
  std::vector<detail::ShardFile> shards = detail::OpenShardSet(paths, "points", output);
  const detail::ShardFile& first = shards.front();
  const std::int64_t n = first.n;
  const RobotColumns columns{detail::HeaderColumn(first.header, "orbits"),
                             detail::HeaderColumn(first.header, "orbit")};

  AtomicFile file(output, "output");
  std::ostream& out = file.stream();
  out << first.comments << first.header;
  MergeSummary summary;
  summary.shards = static_cast<int>(n);
  summary.points = first.units;
  for (std::int64_t p = 0; p < first.units; ++p) {
    detail::ShardFile& s = shards[static_cast<std::size_t>(p % n)];
    summary.rows += CopyPoint(s, p, columns, out);
    ++s.units_read;
  }
  detail::RequireShardsConsumed(shards);
  file.Commit();
  return summary;
}

}  // namespace capsubot
