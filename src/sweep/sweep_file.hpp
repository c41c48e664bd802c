#pragma once
// The file a sweep is written to: `<output>.partial`, locked while in use, with a checkpoint
// `<output>.checkpoint` recording how many grid points (and bytes) are complete, renamed to
// `<output>` when the sweep is done. An output that is "-" (stdout) or not a regular file
// (/dev/stdout, a pipe) is written in place, without partial file or checkpoint; a symlink
// is followed and its target replaced (as AtomicFile: capsubot::ResolveOutput).

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string>

#include "capsubot/io.hpp"

namespace capsubot::detail {

class SweepFile {
 public:
  /// Opens (and locks) the partial file. With `resume` and a checkpoint whose description is
  /// `description`, continues after its last complete point; otherwise starts a new file with
  /// `header`. Throws std::invalid_argument for a checkpoint of another sweep, IoError for a
  /// file that cannot be used (including one locked by another running sweep). `resume` with
  /// an output written in place is a std::invalid_argument.
  SweepFile(const std::string& output, const std::string& description, const std::string& header,
            bool resume, double checkpoint_seconds);
  ~SweepFile();  ///< closes the partial file, which stays for a later resume
  SweepFile(const SweepFile&) = delete;
  SweepFile& operator=(const SweepFile&) = delete;

  std::int64_t points_done() const { return points_; }  ///< complete grid points in the file

  /// Appends the rows of `points` complete grid points; checkpoints when the last
  /// checkpoint is older than checkpoint_seconds. Throws IoError.
  void Append(const char* data, std::size_t size, std::int64_t points);
  /// Checkpoint now: fsync the partial file, then write and fsync the checkpoint.
  void Checkpoint();
  /// fsync, rename the partial file to the output, remove the checkpoint. Throws IoError.
  void Commit();

  static std::string PartialPath(const std::string& output) { return output + ".partial"; }
  static std::string CheckpointPath(const std::string& output) { return output + ".checkpoint"; }

 private:
  [[noreturn]] void Fail(const std::string& what, const std::string& path) const;

  std::string output_;
  OutputTarget target_;  // the file renamed over at the end (symlinks followed)
  std::string partial_, checkpoint_, description_;
  int fd_ = -1;
  bool direct_ = false;      // written in place: no partial file, no checkpoint
  std::int64_t points_ = 0;  // complete points written
  std::int64_t bytes_ = 0;   // bytes written
  double checkpoint_seconds_ = 0.5;
  std::chrono::steady_clock::time_point last_checkpoint_;
};

}  // namespace capsubot::detail
