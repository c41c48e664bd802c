#pragma once
// Files and numbers as text: atomic writes that follow symlinks, removal of temporary files
// on SIGINT/SIGTERM, bounded reads of text files, round-trip number formatting and strict
// number parsing.

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <istream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace capsubot {

/// An output or input file that cannot be used (the message names the file and the reason).
class IoError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Writing to a file that could be opened failed (a full disk, /dev/full, a closed pipe):
/// the input was fine, the run could not be completed.
class WriteError : public IoError {
 public:
  using IoError::IoError;
};

/// Where an output path is written.
struct OutputTarget {
  /// The file that receives the text: `path` with symlinks of its last component followed
  /// (a symlink to a regular file is never replaced: its target is written); "/dev/stdout"
  /// for "-".
  std::string path;
  /// Written in place (standard output, a device, a pipe: no temporary file, no rename).
  bool in_place = false;
};

/// Resolves an output path: "-" is standard output; symlinks are followed (at most
/// kMaxSymlinks, relative targets against the link's folder); an existing file that is not
/// a regular file is written in place. Throws IoError naming `what` for a symlink loop.
OutputTarget ResolveOutput(const std::string& path, const std::string& what);

/// Symlinks followed by ResolveOutput before it reports a loop (Linux's own limit).
inline constexpr int kMaxSymlinks = 40;

/// Throws IoError (naming `what` and `path`) if `path` cannot be written, before a long run:
/// a regular file (new or existing) by creating its temporary file and removing it, untouched;
/// standard output, a device or a pipe by its permission only, without opening it (a pipe's
/// reader would see the end of the file).
void CheckWritable(const std::string& path, const std::string& what);

/// Whether paths `a` and `b` name one file: the same text, the same file once "." and ".."
/// and symlinks are resolved (also for a file that does not exist yet), or another hard link.
bool SameFile(const std::string& a, const std::string& b);

/// Throws std::invalid_argument when two of `outputs` (pairs of path and option; empty paths
/// are skipped) are the same file under other spellings ("./a.csv", "dir/../a.csv", an
/// absolute path, a symlink, a hard link): one would overwrite the other. Standard output,
/// devices and pipes (written in place) may be named twice.
void RequireDistinctOutputs(const std::vector<std::pair<std::string, std::string>>& outputs);

/// Writes to `path` atomically: the text goes to a temporary file `<target>.tmp.<pid>` beside
/// the target (ResolveOutput), which Commit() renames over the target; destroyed without
/// Commit() (an exception), it leaves no file behind, and SIGINT/SIGTERM remove it too once
/// InstallTempFileCleanup() ran. `what` names the file in messages ("--trajectory", ...).
/// Standard output ("-"), devices and pipes are written in place.
class AtomicFile {
 public:
  AtomicFile(std::string path, std::string what);  ///< throws IoError if it cannot be created
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ofstream& stream() { return out_; }
  /// The file being written before Commit() (the target itself when written in place).
  const std::string& temp_path() const { return temp_; }
  /// Flush, check for write errors (WriteError), rename over the target (IoError).
  void Commit();

 private:
  std::string path_, what_, target_, temp_;
  std::ofstream out_;
  bool committed_ = false;
  bool direct_ = false;  // written in place: no temporary, no rename
  int slot_ = -1;        // entry in the temporary-file registry (-1: none)
};

/// Temporary files removed when the process is ended by SIGINT or SIGTERM. At most
/// kMaxTempFiles at once, paths up to kMaxTempPathBytes - 1 bytes (longer ones are simply
/// not registered). Register returns the slot (-1 when not registered); Unregister(-1) does
/// nothing. Both are thread-safe and lock-free.
inline constexpr int kMaxTempFiles = 64;
inline constexpr int kMaxTempPathBytes = 4096;
int RegisterTempFile(const std::string& path);
void UnregisterTempFile(int slot);

/// Installs handlers for SIGINT and SIGTERM that remove the registered temporary files,
/// then re-raise the signal with its default action (the exit status is 128 + signal).
/// For programs (the library never installs it by itself); idempotent.
void InstallTempFileCleanup();

/// Longest line ReadLine accepts by default, and the largest file ReadTextFile reads by
/// default (1 MiB): far above any line or input file capsubot writes or reads (a CSV row is
/// a few hundred bytes, a --config file a few), far below what a device such as /dev/zero
/// would make the reader hold in memory.
inline constexpr std::size_t kMaxLineBytes = std::size_t{1} << 20;
inline constexpr std::size_t kMaxTextFileBytes = std::size_t{1} << 20;

/// Reads the next line of `in` into `line` without its '\n', as std::getline does (false
/// when nothing is left; eof set when the last line has no line break), but holds at most
/// `limit` bytes: a longer line throws std::invalid_argument "<what> is invalid: a line
/// longer than <limit> bytes".
bool ReadLine(std::istream& in, std::string& line, const std::string& what,
              std::size_t limit = kMaxLineBytes);

/// The whole file at `path`, read only if it is a regular file of at most `limit` bytes
/// (opened without blocking and checked first: a pipe without a writer, a device or a folder
/// is refused before any read; at most limit + 1 bytes are read). Throws IoError "<what>
/// <path> cannot be read: <reason>" and std::invalid_argument "<what> <path> is invalid:
/// expected a file of at most <limit> bytes" (with ", not a pipe or device" or ", not a
/// folder" for those).
std::string ReadTextFile(const std::string& path, const std::string& what,
                         std::size_t limit = kMaxTextFileBytes);

/// Most characters WriteNumber writes ("-2.2250738585072014e-308").
inline constexpr int kMaxNumberChars = 24;

/// Writes `value` at `out` (room for kMaxNumberChars) in its shortest round-trip form: the
/// fewest significant digits that read back to the same double (std::to_chars), "0.1" rather
/// than "0.10000000000000001"; inf as "inf"; nothing for NaN (a CSV empty cell). Returns
/// the end of what was written.
char* WriteNumber(char* out, double value);

/// WriteNumber's text as a string ("" for NaN).
std::string FormatNumber(double value);

/// Parses a decimal number: optional sign, digits with an optional point, optional exponent
/// ("-2.5", ".5", "1e-3", "+4E2"). Nothing else: no spaces, no hex, no "inf" or "nan", not
/// empty. The result is the nearest double; it must be finite, and a nonzero number must not
/// round to 0 (subnormal numbers are accepted). Throws std::invalid_argument
/// "<name> = <text> is invalid: expected ..." naming the rule.
double ParseNumber(std::string_view text, const std::string& name);

/// Parses a phase in radians: a number in the syntax of ParseNumber, or a multiple of pi
/// written [sign][N*]pi[/M] with N and M positive numbers in that syntax ("pi", "-pi/2",
/// "2*pi", "3*pi/4", "+pi/3"); no spaces. Its value is sign (N pi)/M in double precision (pi,
/// its halves and its doubles exactly the double nearest that multiple of pi). Throws
/// std::invalid_argument "<name> = <text> is invalid: expected ..." naming the rule.
double ParsePhase(std::string_view text, const std::string& name);

/// Parses an integer lo <= n <= hi: decimal digits with an optional sign, or a number in the
/// syntax of ParseNumber whose value is a whole number ("2e6"). Throws std::invalid_argument
/// "<name> = <text> is invalid: expected an integer lo <= n <= hi".
std::int64_t ParseInteger(std::string_view text, const std::string& name, std::int64_t lo,
                          std::int64_t hi);

/// `text` as shown in a message: quoted when empty or holding spaces or control characters.
std::string QuoteForMessage(std::string_view text);

/// The pieces of `text` between the `separator`s, empty ones included: "1,,2" -> {"1", "", "2"},
/// "" -> {""}.
std::vector<std::string> SplitText(const std::string& text, char separator);

}  // namespace capsubot
