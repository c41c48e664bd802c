#include "sweep/shard_set.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <system_error>

#include "capsubot/io/io.hpp"
#include "capsubot/sweep/grid.hpp"

namespace capsubot::detail {
namespace {

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
  LineReader reader(line);
  reader.Word("# shard ").Number(s.k).Word("/").Number(s.n).Word(" of ").Number(s.units).Word(" ");
  const std::size_t unit = line.find_last_of(' ') + 1;
  const bool letters =
      unit < line.size() &&
      std::all_of(line.begin() + unit, line.end(), [](char c) { return c >= 'a' && c <= 'z'; });
  if (!letters || !reader.Word(std::string_view(line).substr(unit)).Done()) return false;
  s.unit = line.substr(unit);
  return true;
}

// Refuses `output` when it is the file of one of the shards (also through a symlink or
// another hard link): writing it would destroy that shard. An output that does not exist yet
// cannot be one.
void RequireOutputNotAShard(const std::vector<std::string>& paths, const std::string& output) {
  std::error_code error;
  if (output == "-" || !std::filesystem::exists(output, error)) return;
  for (const std::string& path : paths) {
    if (SameFile(output, path)) {
      throw std::invalid_argument(fmt::format(
          "output {} is invalid: it is the shard file {}: expected a file other than the shards",
          output, path));
    }
  }
}

ShardFile OpenShard(const std::string& path, const std::string& unit) {
  ShardFile s;
  s.path = path;
  s.in = OpenShardStream(path);
  std::string line;
  bool marked = false;
  while (ReadShardFileLine(*s.in, line, path) && !line.empty() && line[0] == '#') {
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

int HeaderColumn(std::string_view header, std::string_view name) {
  int column = 0;
  std::size_t start = 0;
  for (;;) {
    const std::size_t end = std::min(header.find_first_of(",\n", start), header.size());
    if (header.substr(start, end - start) == name) return column;
    if (end >= header.size() || header[end] == '\n') return -1;
    start = end + 1;
    ++column;
  }
}

std::size_t CellStart(std::string_view row, int column) {
  std::size_t start = 0;
  for (int c = 0; c < column; ++c) {
    start = row.find(',', start);
    if (start == std::string_view::npos) return start;
    start += 1;
  }
  return start;
}

std::string_view RowCell(std::string_view row, int column) {
  const std::size_t start = CellStart(row, column);
  if (start == std::string_view::npos) return {};
  return row.substr(start, row.find(',', start) - start);
}

std::unique_ptr<std::ifstream> OpenShardStream(const std::string& path) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) {
    throw std::invalid_argument(
        fmt::format("shard file {} is invalid: it is a folder: expected a shard file", path));
  }
  auto in = std::make_unique<std::ifstream>(path, std::ios::binary);
  if (!*in) {
    throw IoError(fmt::format("shard file {} cannot be read: {}", path, std::strerror(errno)));
  }
  return in;
}

bool ReadShardFileLine(std::istream& in, std::string& line, const std::string& path) {
  if (!ReadLine(in, line, "shard file " + path)) return false;
  if (!line.empty() && line.back() == '\r') {
    throw std::invalid_argument(fmt::format(
        "shard file {} is invalid: its line endings are CR LF (a file converted to Windows "
        "line endings): expected the LF line endings capsubot writes (convert it back, e.g. "
        "with dos2unix)",
        path));
  }
  return true;
}

void ShardFile::Advance() {
  has_next = ReadShardFileLine(*in, next, path);
  if (has_next && in->eof()) {
    throw std::invalid_argument(
        fmt::format("shard file {} is truncated: its last line has no line break", path));
  }
}

LineReader& LineReader::Word(std::string_view text) {
  ok_ = ok_ && rest_.substr(0, text.size()) == text;
  if (ok_) rest_.remove_prefix(text.size());
  return *this;
}

LineReader& LineReader::Number(std::int64_t& value) {
  ok_ = ok_ && !rest_.empty() && std::isdigit(static_cast<unsigned char>(rest_.front())) != 0;
  if (!ok_) return *this;
  const auto [end, error] = std::from_chars(rest_.data(), rest_.data() + rest_.size(), value);
  ok_ = error == std::errc();
  rest_.remove_prefix(static_cast<std::size_t>(end - rest_.data()));
  return *this;
}

std::vector<ShardFile> OpenShardSet(const std::vector<std::string>& paths, const std::string& unit,
                                    const std::string& output) {
  if (paths.size() < 2) {
    throw std::invalid_argument(fmt::format(
        "shard files: {} given: expected the N >= 2 files of one sharded run", paths.size()));
  }
  RequireOutputNotAShard(paths, output);
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
  const std::int64_t n = shards.front().n;
  if (static_cast<std::int64_t>(shards.size()) != n) {
    // The first few missing shards (N may be large: the list is not).
    constexpr int kListed = 10;
    std::string missing;
    int listed = 0;
    for (std::int64_t k = 0, i = 0; k < n && listed <= kListed; ++k) {
      if (i < static_cast<std::int64_t>(shards.size()) &&
          shards[static_cast<std::size_t>(i)].k == k) {
        ++i;
      } else if (++listed <= kListed) {
        missing += (missing.empty() ? "" : ", ") + fmt::format("{}/{}", k, n);
      } else {
        missing += ", ...";
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
  const std::unique_ptr<std::ifstream> in = OpenShardStream(path);
  std::string line;
  ShardFile s;
  while (ReadShardFileLine(*in, line, path) && !line.empty() && line[0] == '#') {
    if (ReadShardLine(line, s)) return s.unit;
  }
  return "";
}

}  // namespace capsubot::detail
