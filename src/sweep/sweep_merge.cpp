#include "capsubot/sweep_merge.hpp"

#include <algorithm>

#include "capsubot/io.hpp"
#include "sweep/shard_set.hpp"

namespace capsubot {
namespace {

// Robot mode (docs/model.md section 8): a point may have several rows; a point's first row
// has orbit = 1, or an empty orbit cell when the point has no orbit. Else one row a point.
int OrbitColumn(const std::string& header) {
  int column = 0;
  std::size_t start = 0;
  for (;;) {
    const std::size_t end = std::min(header.find_first_of(",\n", start), header.size());
    if (header.compare(start, end - start, "orbit") == 0) return column;
    if (end >= header.size() || header[end] == '\n') return -1;
    start = end + 1;
    ++column;
  }
}

std::string Cell(const std::string& row, int column) {
  std::size_t start = 0;
  for (int c = 0; c < column; ++c) {
    start = row.find(',', start);
    if (start == std::string::npos) return "";
    start += 1;
  }
  return row.substr(start, row.find(',', start) - start);
}

}  // namespace

MergeSummary MergeSweepShards(const std::vector<std::string>& paths, const std::string& output) {
  std::vector<detail::ShardFile> shards = detail::OpenShardSet(paths, "points", output);
  const detail::ShardFile& first = shards.front();
  const std::int64_t n = first.n;
  const int orbit = OrbitColumn(first.header);
  const auto starts_point = [orbit](const std::string& row) {
    if (orbit < 0) return true;
    const std::string cell = Cell(row, orbit);
    return cell.empty() || cell == "1";
  };

  AtomicFile file(output, "output");
  std::ostream& out = file.stream();
  out << first.comments << first.header;
  MergeSummary summary;
  summary.shards = static_cast<int>(n);
  summary.points = first.units;
  for (std::int64_t p = 0; p < first.units; ++p) {
    detail::ShardFile& s = shards[static_cast<std::size_t>(p % n)];
    if (!s.has_next) detail::ThrowTruncated(s);
    do {  // the rows of one point
      out << s.next << '\n';
      ++summary.rows;
      s.Advance();
    } while (s.has_next && !starts_point(s.next));
    ++s.units_read;
  }
  detail::RequireShardsConsumed(shards);
  file.Commit();
  return summary;
}

}  // namespace capsubot
