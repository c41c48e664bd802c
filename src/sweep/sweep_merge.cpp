#include "capsubot/sweep_merge.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <memory>
#include <stdexcept>

#include "capsubot/grid.hpp"
#include "capsubot/io.hpp"

namespace capsubot {
namespace {

// One shard file: its lines before the rows, what its shard line says, and a one-line
// lookahead over its rows.
struct Shard {
  std::string path;
  std::unique_ptr<std::ifstream> in;
  std::string comments;  // the comment lines other than the shard line
  std::string header;
  int k = -1, n = 0;
  long long points = 0;
  std::string next;  // the next row (valid when has_next)
  bool has_next = false;
  std::int64_t points_read = 0;

  // Reads the next row into `next`; a last line without its line break is a truncated file.
  void Advance() {
    has_next = static_cast<bool>(std::getline(*in, next));
    if (has_next && in->eof()) {
      throw std::invalid_argument(
          fmt::format("shard file {} is truncated: its last line has no line break", path));
    }
  }
};

Shard OpenShard(const std::string& path) {
  Shard s;
  s.path = path;
  s.in = std::make_unique<std::ifstream>(path, std::ios::binary);
  if (!*s.in)
    throw IoError(fmt::format("shard file {} cannot be read: {}", path, std::strerror(errno)));
  std::string line;
  bool marked = false;
  while (std::getline(*s.in, line) && !line.empty() && line[0] == '#') {
    int used = 0;
    if (std::sscanf(line.c_str(), "# shard %d/%d of %lld points%n", &s.k, &s.n, &s.points, &used) ==
            3 &&
        static_cast<std::size_t>(used) == line.size()) {
      marked = true;
    } else {
      s.comments += line + '\n';
    }
  }
  if (!marked || s.n < 2 || s.k < 0 || s.k >= s.n || s.points < s.n || s.points > kMaxGridPoints) {
    throw std::invalid_argument(fmt::format(
        "shard file {} is invalid: expected a file of `capsubot sweep --shard K/N` (a line "
        "'# shard K/N of T points' with 0 <= K < N, N >= 2, N <= T)",
        path));
  }
  if (s.in->eof()) {
    throw std::invalid_argument(fmt::format("shard file {} is truncated: no header line", path));
  }
  s.header = line + '\n';
  s.Advance();
  return s;
}

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
  if (paths.size() < 2) {
    throw std::invalid_argument(fmt::format(
        "shard files: {} given: expected the N >= 2 files of one sharded sweep", paths.size()));
  }
  std::vector<Shard> shards;
  shards.reserve(paths.size());
  for (const std::string& path : paths) shards.push_back(OpenShard(path));
  const Shard& first = shards.front();
  for (const Shard& s : shards) {
    if (s.comments != first.comments || s.header != first.header || s.n != first.n ||
        s.points != first.points) {
      throw std::invalid_argument(fmt::format(
          "shard files {} and {} are of different sweeps: expected the same comment lines, "
          "header, shard count N and point count T",
          first.path, s.path));
    }
  }
  std::sort(shards.begin(), shards.end(), [](const Shard& a, const Shard& b) { return a.k < b.k; });
  for (std::size_t i = 1; i < shards.size(); ++i) {
    if (shards[i].k == shards[i - 1].k) {
      throw std::invalid_argument(fmt::format("shard files {} and {} are both shard {}/{}",
                                              shards[i - 1].path, shards[i].path, shards[i].k,
                                              shards[i].n));
    }
  }
  const int n = first.n;
  if (static_cast<int>(shards.size()) != n) {
    std::string missing;
    for (int k = 0, i = 0; k < n; ++k) {
      if (i < static_cast<int>(shards.size()) && shards[static_cast<std::size_t>(i)].k == k) {
        ++i;
      } else {
        missing += (missing.empty() ? "" : ", ") + fmt::format("{}/{}", k, n);
      }
    }
    throw std::invalid_argument(
        fmt::format("shard files: shard {} missing: expected all {} shards", missing, n));
  }
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
  summary.shards = n;
  summary.points = first.points;
  for (std::int64_t p = 0; p < first.points; ++p) {
    Shard& s = shards[static_cast<std::size_t>(p % n)];
    if (!s.has_next) {
      throw std::invalid_argument(
          fmt::format("shard file {} is truncated: it ends after {} of its {} points", s.path,
                      s.points_read, (first.points - s.k + n - 1) / n));
    }
    do {  // the rows of one point
      out << s.next << '\n';
      ++summary.rows;
      s.Advance();
    } while (s.has_next && !starts_point(s.next));
    ++s.points_read;
  }
  for (const Shard& s : shards) {
    if (s.has_next) {
      throw std::invalid_argument(fmt::format(
          "shard file {} holds more rows than its {} points: expected a shard of this sweep",
          s.path, s.points_read));
    }
  }
  file.Commit();
  return summary;
}

}  // namespace capsubot
