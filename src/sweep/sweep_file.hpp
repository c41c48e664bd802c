#pragma once
// The file a sweep is written to: `<output>.partial`, locked while in use, with a checkpoint
// `<output>.checkpoint` recording how many grid points (and bytes) are complete, a CRC-32 of
// those bytes, the sweep's description and a CRC-32 of the checkpoint itself; renamed to
// `<output>` when the sweep is done. A checkpoint due during the run is written by a thread
// of its own while the next rows are written (its fsyncs take tens of milliseconds). An output that
// is "-" (stdout) or not a regular file
// (/dev/stdout, a pipe) is written in place, without partial file or checkpoint; a symlink
// is followed and its target replaced (as AtomicFile: capsubot::ResolveOutput).

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <future>
#include <string>
#include <string_view>

#include "capsubot/io/io.hpp"

namespace capsubot::detail {

/// What the rows of a file make: the points of the run, and which rows begin a point. A
/// resume counts the points in the rows its checkpoint vouches for: a checkpoint whose count
/// differs (a valid checksum, a wrong count) is damaged.
struct PointRows {
  std::int64_t points = 0;  ///< points of the run: a checkpoint of more is damaged
  /// Whether a row (without its line break) begins a point; empty: every row does.
  std::function<bool(std::string_view row)> starts_point;
};

class SweepFile {
 public:
  /// Opens (and locks) the partial file. With `resume` and a checkpoint whose description is
  /// `description`, continues after its last complete point (after checking both checksums);
  /// otherwise starts a new file with `header`. Throws std::invalid_argument for a checkpoint
  /// of another sweep or `resume` with an output written in place, IoError for a file that
  /// cannot be used (one locked by another running sweep, a corrupted checkpoint or partial
  /// file, a checkpoint that is not a small regular file or whose point count is not that of
  /// the rows it vouches for (`rows`), a checkpoint whose partial file is missing).
  /// `run` names what is written in the messages ("sweep", "shard").
  SweepFile(const std::string& output, const std::string& description, const std::string& header,
            const PointRows& rows, bool resume, double checkpoint_seconds,
            const std::string& run = "sweep");
  ~SweepFile();  ///< waits for a checkpoint being written; the partial file stays for a resume
  /// Throws what the constructor with `resume` would throw for an output written in place or
  /// for the checkpoint (damaged, or of another run), touching no file: a run that writes
  /// several files checks them all before it opens the first.
  static void CheckResume(const std::string& output, const std::string& description,
                          const std::string& run = "sweep");
  SweepFile(const SweepFile&) = delete;
  SweepFile& operator=(const SweepFile&) = delete;

  std::int64_t points_done() const { return points_; }  ///< complete grid points in the file
  /// Rows after the header taken over from the checkpoint (0 without a resume).
  std::int64_t rows_resumed() const { return rows_resumed_; }
  bool direct() const { return direct_; }  ///< written in place (no resume)

  /// Appends the rows of `points` complete grid points; starts a checkpoint of every row
  /// appended when the last one began checkpoint_seconds ago or more (after waiting for that
  /// one: at most one is being written). Throws IoError, also for a checkpoint that failed.
  void Append(const char* data, std::size_t size, std::int64_t points);
  /// Checkpoint now (after the one being written): fsync the partial file, then write and
  /// fsync the checkpoint.
  void Checkpoint();
  /// fsync, rename the partial file to the output, remove the checkpoint. Throws IoError
  /// (the partial file then stays with a checkpoint of every point: a resume completes it).
  void Commit();
  /// Removes the partial file and the checkpoint (a sweep that no resume could complete).
  void Discard();

  static std::string PartialPath(const std::string& output) { return output + ".partial"; }
  static std::string CheckpointPath(const std::string& output) { return output + ".checkpoint"; }

 private:
  [[noreturn]] void Fail(const std::string& what, const std::string& path) const;
  // Resumes from the checkpoint (checked against `rows`) or starts the file with `header`.
  void Open(const std::string& header, const PointRows& rows, bool resume);
  // The checkpoint of the first `points` points, `bytes` bytes with CRC-32 `crc`: fsync of
  // the partial file, then the checkpoint written, fsynced and renamed into place. Reads only
  // what stays constant once the file is open: safe beside Append.
  void WriteCheckpoint(std::int64_t points, std::int64_t bytes, std::uint32_t crc) const;
  // Starts a checkpoint of every row appended, written beside the next Append calls (after
  // the one being written).
  void StartCheckpoint();
  // Waits for the checkpoint being written, if any; rethrows its error.
  void FinishCheckpoint();

  std::string output_;
  std::string run_;      // "sweep", "shard": for the messages
  OutputTarget target_;  // the file renamed over at the end (symlinks followed)
  std::string partial_, checkpoint_, description_;
  std::string written_;  // the file written: partial_, or the output itself when direct
  int fd_ = -1;
  bool direct_ = false;      // written in place: no partial file, no checkpoint
  std::int64_t points_ = 0;  // complete points written
  std::int64_t rows_resumed_ = 0;
  std::int64_t bytes_ = 0;      // bytes written
  std::int64_t writeback_ = 0;  // bytes the disk was asked to write (sync_file_range)
  std::uint32_t crc_ = 0;       // CRC-32 of those bytes
  double checkpoint_seconds_ = 0.5;
  std::chrono::steady_clock::time_point last_checkpoint_;  // when the last one began
  std::future<void> pending_checkpoint_;  // the checkpoint being written beside Append
};

}  // namespace capsubot::detail
