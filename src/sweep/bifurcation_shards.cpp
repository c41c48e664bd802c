// Joining the shards of a bifurcation study: their parts put back in order.

#include "capsubot/sweep/bifurcation_shards.hpp"

#include <fmt/format.h>

#include <cstdint>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "capsubot/io/io.hpp"
#include "sweep/shard_set.hpp"

namespace capsubot {
namespace {

// The part line a shard file is positioned on: part `part` of `parts` with `rows` rows; part
// -1 when the file is done.
struct PartLine {
  std::int64_t part = -1;
  std::int64_t parts = 0;
  std::int64_t rows = 0;
};

// Most parts of a study: BifurcationOptions counts them in an int.
constexpr std::int64_t kMaxParts = INT32_MAX;

// Reads "# part P of Q: R rows" into `p`; false for any other line.
bool ParsePartLine(const std::string& line, PartLine& p) {
  return detail::LineReader(line)
      .Word("# part ")
      .Number(p.part)
      .Word(" of ")
      .Number(p.parts)
      .Word(": ")
      .Number(p.rows)
      .Word(" rows")
      .Done();
}

// Reads the part line of `s` (or its end) and moves past it.
PartLine ReadPart(detail::ShardFile& s) {
  PartLine p;
  if (!s.has_next) return p;
  if (!ParsePartLine(s.next, p) || p.part >= p.parts || p.parts > kMaxParts) {
    throw std::invalid_argument(
        fmt::format("shard file {} line '{}' is invalid: expected '# part P of Q: R rows' with 0 "
                    "<= P < Q <= {}, R >= 0",
                    s.path, s.next, kMaxParts));
  }
  s.Advance();
  return p;
}

// Where a part none of the files is positioned on is: the file that holds it further on (its
// parts out of order), found by reading the part lines of each file again; none when no file
// holds it. Only on this error path: each file is read once more, line by line.
[[noreturn]] void ThrowPartNotNext(const std::vector<detail::ShardFile>& shards,
                                   const std::vector<PartLine>& at, std::int64_t part,
                                   std::int64_t parts) {
  for (std::size_t k = 0; k < shards.size(); ++k) {
    const std::unique_ptr<std::ifstream> in = detail::OpenShardStream(shards[k].path);
    std::string line;
    std::int64_t previous = -1;
    while (detail::ReadShardFileLine(*in, line, shards[k].path)) {
      PartLine p;
      if (!ParsePartLine(line, p)) continue;
      if (p.part == part && previous > part) {
        throw std::invalid_argument(fmt::format(
            "shard file {} holds part {} of {} after part {}: expected its parts in increasing "
            "order (parts moved within the file)",
            shards[k].path, part, parts, previous));
      }
      previous = p.part;
    }
  }
  std::string positions;
  for (std::size_t k = 0; k < shards.size(); ++k) {
    positions +=
        fmt::format("{}{} at {}", positions.empty() ? "" : ", ", shards[k].path,
                    at[k].part < 0 ? std::string("its end") : fmt::format("part {}", at[k].part));
  }
  throw std::invalid_argument(fmt::format(
      "shard files: part {} of {} is in none of them ({}): expected every part in one file (a "
      "file truncated, or of another study)",
      part, parts, positions));
}

}  // namespace

std::string BifurcationPartLine(int part, int parts, std::int64_t rows) {
  return fmt::format("# part {} of {}: {} rows\n", part, parts, rows);
}

MergeSummary MergeBifurcationShards(const std::vector<std::string>& paths,
                                    const std::string& output) {
  std::vector<detail::ShardFile> shards = detail::OpenShardSet(paths, "continuations", output);
  std::vector<PartLine> at(shards.size());
  for (std::size_t k = 0; k < shards.size(); ++k) at[k] = ReadPart(shards[k]);
  const std::int64_t parts = at.front().parts;
  AtomicFile file(output, "output");
  std::ostream& out = file.stream();
  out << shards.front().comments << shards.front().header;
  MergeSummary summary;
  summary.shards = static_cast<int>(shards.size());
  summary.points = shards.front().units;
  for (std::int64_t part = 0; part < parts; ++part) {
    std::size_t k = 0;
    while (k < shards.size() && at[k].part != part) ++k;
    if (k == shards.size()) ThrowPartNotNext(shards, at, part, parts);
    detail::ShardFile& s = shards[k];
    if (at[k].parts != parts) {
      throw std::invalid_argument(fmt::format(
          "shard files {} and {} are of different bifurcation studies: expected the same part "
          "count Q ({} and {})",
          shards.front().path, s.path, parts, at[k].parts));
    }
    for (std::int64_t row = 0; row < at[k].rows; ++row) {
      if (!s.has_next || s.next.rfind("# part ", 0) == 0) {
        throw std::invalid_argument(
            fmt::format("shard file {} is truncated: part {} ends after {} of its {} rows", s.path,
                        part, row, at[k].rows));
      }
      out << s.next << '\n';
      s.Advance();
      ++summary.rows;
    }
    at[k] = ReadPart(s);
  }
  for (std::size_t k = 0; k < shards.size(); ++k) {
    if (at[k].part >= 0) {
      throw std::invalid_argument(fmt::format(
          "shard file {} holds part {} of {} out of order or twice: expected each part once, in "
          "increasing order",
          shards[k].path, at[k].part, at[k].parts));
    }
  }
  file.Commit();
  return summary;
}

}  // namespace capsubot
