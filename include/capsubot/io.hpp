#pragma once
// Output files that other tools can read: atomic writes and round-trip number formatting.

#include <fstream>
#include <stdexcept>
#include <string>

namespace capsubot {

/// An output or input file that cannot be used (the message names the file and the reason).
class IoError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Writes to `path` atomically: the text goes to a temporary file beside it, which Commit()
/// renames to `path`; destroyed without Commit() (an exception, a kill), it leaves no file
/// under `path`. `what` names the file in messages ("--trajectory", ...). A path that is not
/// a regular file (/dev/stdout, a pipe) is written directly, and "-" means standard output.
class AtomicFile {
 public:
  AtomicFile(std::string path, std::string what);  ///< throws IoError if it cannot be created
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ofstream& stream() { return out_; }
  /// The file being written before Commit() (the path itself when written directly).
  const std::string& temp_path() const { return temp_; }
  void Commit();  ///< flush, check for write errors, rename; throws IoError

 private:
  std::string path_, what_, temp_;
  std::ofstream out_;
  bool committed_ = false;
  bool direct_ = false;  // not a regular file: no temporary, no rename
};

/// Most characters WriteNumber writes ("-2.2250738585072014e-308").
inline constexpr int kMaxNumberChars = 24;

/// Writes `value` at `out` (room for kMaxNumberChars) in its shortest round-trip form: the
/// fewest significant digits that read back to the same double (std::to_chars), "0.1" rather
/// than "0.10000000000000001"; inf as "inf"; nothing for NaN (a CSV empty cell). Returns
/// the end of what was written.
char* WriteNumber(char* out, double value);

/// WriteNumber's text as a string ("" for NaN).
std::string FormatNumber(double value);

}  // namespace capsubot
