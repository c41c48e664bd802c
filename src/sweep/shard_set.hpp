#pragma once
// The shard files of one run, opened and checked together (docs/cluster.md): each starts with
// comment lines, among them "# shard K/N of T <unit>" (unit "points": a sweep, "starts": a
// basin map), then a header line and its rows. The joiners of sweeps and of basin maps read
// them through this.

#include <cstdint>
#include <fstream>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace capsubot::detail {

/// One shard file: its lines before the rows, what its shard line says, and a one-line
/// lookahead over its rows.
struct ShardFile {
  std::string path;
  std::unique_ptr<std::ifstream> in;
  std::string comments;  ///< the comment lines other than the shard line
  std::string header;    ///< the header line, with its line break
  std::string unit;      ///< "points" or "starts"
  std::int64_t k = -1, n = 0;
  std::int64_t units = 0;  ///< T: the units of the whole run
  std::string next;        ///< the next row (valid when has_next)
  bool has_next = false;
  std::int64_t units_read = 0;  ///< kept by the joiner

  /// Reads the next row into `next`; throws std::invalid_argument for a last line without its
  /// line break (a truncated file) or a line longer than kMaxLineBytes.
  void Advance();
  /// Units [0, T) of shard K of N: unit u belongs to shard u % N.
  std::int64_t OwnUnits() const { return (units - k + n - 1) / n; }
};

/// The index of column `name` in the column names line `header` (its line break optional),
/// -1 when it has none.
int HeaderColumn(std::string_view header, std::string_view name);

/// Where cell `column` of CSV row `row` begins; npos when the row has fewer cells.
std::size_t CellStart(std::string_view row, int column);

/// Cell `column` of CSV row `row` ("" when the row has fewer cells).
std::string_view RowCell(std::string_view row, int column);

/// The file of a shard opened for reading; throws std::invalid_argument for a folder, IoError
/// for a file that cannot be opened (both naming the file).
std::unique_ptr<std::ifstream> OpenShardStream(const std::string& path);

/// ReadLine of a shard file's next line; a line that ends in '\r' (CR LF line endings: the
/// file was converted) throws std::invalid_argument naming the file and its line endings.
bool ReadShardFileLine(std::istream& in, std::string& line, const std::string& path);

/// Reads a line of fixed words and decimal numbers ("# shard 1/3 of 14 points"): Word
/// matches text, Number reads digits into an int64 (no sign, no wrap-around: a number beyond
/// int64 fails the line), Done says whether all of it matched.
class LineReader {
 public:
  explicit LineReader(std::string_view line) : rest_(line) {}
  LineReader& Word(std::string_view text);
  LineReader& Number(std::int64_t& value);
  bool Done() const { return ok_ && rest_.empty(); }

 private:
  std::string_view rest_;
  bool ok_ = true;
};

/// Opens the files, checks that each is a shard of `unit` ("points" or "starts"), that all
/// belong to the same run (same comment lines, header, N and T), that none is missing or
/// given twice, that `output` (the file the join writes) is none of them, and returns them
/// sorted by K (positioned on their first row). Throws std::invalid_argument naming the
/// file(s) and the rule, IoError for a file that cannot be read.
std::vector<ShardFile> OpenShardSet(const std::vector<std::string>& paths, const std::string& unit,
                                    const std::string& output);

/// Checks after joining that no shard holds rows beyond its units; throws
/// std::invalid_argument naming the file.
void RequireShardsConsumed(const std::vector<ShardFile>& shards);

/// Throws std::invalid_argument: shard `s` ends after s.units_read of its units.
[[noreturn]] void ThrowTruncated(const ShardFile& s);

/// The unit named by the shard line of the file at `path` ("points", "starts"), "" when it
/// has none. Throws IoError for a file that cannot be read.
std::string ShardUnit(const std::string& path);

}  // namespace capsubot::detail
