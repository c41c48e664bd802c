#include "sweep/shard_set.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "capsubot/grid.hpp"
#include "capsubot/io.hpp"

namespace capsubot::detail {
namespace {

constexpr int kMaxUnitChars = 15;  // "points", "starts", "continuations"

// How the messages name the runs of a unit.
struct RunKind {
  const char* unit;      // of the shard line
  const char* commands;  // the commands that write such shards
  const char* runs;      // "sweeps"
  const char* run;       // "sweep"
  const char* one_unit;  // "point"
};

constexpr RunKind kKinds[] = {
    {"points", "sweep", "sweeps", "sweep", "point"},
    {"starts", "basins|attractors", "basin maps", "basin map", "start"},
    {"continuations", "bifurcation", "bifurcation studies", "bifurcation study", "continuation"}};

const RunKind& KindOf(const std::string& unit) {
  for (const RunKind& k : kKinds) {
    if (unit == k.unit) return k;
  }
  return kKinds[0];
}

// Reads the shard line "# shard K/N of T <unit>" into `s`; false for any other line.
bool ReadShardLine(const std::string& line, ShardFile& s) {
  char unit[kMaxUnitChars + 1] = {};
  int used = 0;
  if (std::sscanf(line.c_str(), "# shard %d/%d of %lld %15[a-z]%n", &s.k, &s.n, &s.units, unit,
                  &used) != 4 ||
      static_cast<std::size_t>(used) != line.size()) {
    return false;
  }
  s.unit = unit;
  return true;
}

ShardFile OpenShard(const std::string& path, const std::string& unit) {
  ShardFile s;
  s.path = path;
  s.in = std::make_unique<std::ifstream>(path, std::ios::binary);
  if (!*s.in)
    throw IoError(fmt::format("shard file {} cannot be read: {}", path, std::strerror(errno)));
  std::string line;
  bool marked = false;
  while (std::getline(*s.in, line) && !line.empty() && line[0] == '#') {
    if (!marked && ReadShardLine(line, s)) {
      marked = true;
    } else {
      s.comments += line + '\n';
    }
  }
  if (!marked || s.unit != unit || s.n < 2 || s.k < 0 || s.k >= s.n || s.units < s.n ||
      s.units > kMaxGridPoints) {
    throw std::invalid_argument(fmt::format(
        "shard file {} is invalid: expected a file of `capsubot {} --shard K/N` (a line "
        "'# shard K/N of T {}' with 0 <= K < N, N >= 2, N <= T)",
        path, KindOf(unit).commands, unit));
  }
  if (s.in->eof()) {
    throw std::invalid_argument(fmt::format("shard file {} is truncated: no header line", path));
  }
  s.header = line + '\n';
  s.Advance();
  return s;
}

}  // namespace

void ShardFile::Advance() {
  has_next = static_cast<bool>(std::getline(*in, next));
  if (has_next && in->eof()) {
    throw std::invalid_argument(
        fmt::format("shard file {} is truncated: its last line has no line break", path));
  }
}

std::vector<ShardFile> OpenShardSet(const std::vector<std::string>& paths,
                                    const std::string& unit) {
  if (paths.size() < 2) {
    throw std::invalid_argument(fmt::format(
        "shard files: {} given: expected the N >= 2 files of one sharded run", paths.size()));
  }
  std::vector<ShardFile> shards;
  shards.reserve(paths.size());
  for (const std::string& path : paths) shards.push_back(OpenShard(path, unit));
  const ShardFile& first = shards.front();
  for (const ShardFile& s : shards) {
    if (s.comments != first.comments || s.header != first.header || s.n != first.n ||
        s.units != first.units) {
      throw std::invalid_argument(
          fmt::format("shard files {} and {} are of different {}: expected the same comment lines, "
                      "header, shard count N and {} count T",
                      first.path, s.path, KindOf(unit).runs, KindOf(unit).one_unit));
    }
  }
  std::sort(shards.begin(), shards.end(),
            [](const ShardFile& a, const ShardFile& b) { return a.k < b.k; });
  for (std::size_t i = 1; i < shards.size(); ++i) {
    if (shards[i].k == shards[i - 1].k) {
      throw std::invalid_argument(fmt::format("shard files {} and {} are both shard {}/{}",
                                              shards[i - 1].path, shards[i].path, shards[i].k,
                                              shards[i].n));
    }
  }
  const int n = shards.front().n;
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
  return shards;
}

void ThrowTruncated(const ShardFile& s) {
  throw std::invalid_argument(
      fmt::format("shard file {} is truncated: it ends after {} of its {} {}", s.path, s.units_read,
                  s.OwnUnits(), s.unit));
}

void RequireShardsConsumed(const std::vector<ShardFile>& shards) {
  for (const ShardFile& s : shards) {
    if (s.has_next) {
      throw std::invalid_argument(
          fmt::format("shard file {} holds more rows than its {} {}: expected a shard of this {}",
                      s.path, s.units_read, s.unit, KindOf(s.unit).run));
    }
  }
}

std::string ShardUnit(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw IoError(fmt::format("shard file {} cannot be read: {}", path, std::strerror(errno)));
  std::string line;
  ShardFile s;
  while (std::getline(in, line) && !line.empty() && line[0] == '#') {
    if (ReadShardLine(line, s)) return s.unit;
  }
  return "";
}

}  // namespace capsubot::detail
