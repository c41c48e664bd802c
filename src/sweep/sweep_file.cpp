#include "sweep/sweep_file.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "capsubot/io/io.hpp"

namespace capsubot::detail {
namespace {

constexpr const char* kMagic = "capsubot sweep checkpoint 2";
// A checkpoint is its description plus a few short lines: anything much longer is not one.
constexpr std::size_t kCheckpointOverhead = 4096;
constexpr std::size_t kChunkBytes = std::size_t{1} << 20;  // reads of the partial file
// Rows written since the disk last started writing them: once this many, it starts, so
// that a checkpoint's fsync only waits for the last ones (the computing threads wait on
// the writing thread while it waits in fsync).
constexpr std::int64_t kWritebackBytes = std::int64_t{4} << 20;

std::uint32_t Crc32(std::uint32_t crc, const char* data, std::size_t size) {
  while (size > 0) {  // zlib takes at most 4 GB per call
    const auto n = static_cast<uInt>(std::min<std::size_t>(size, 1U << 30));
    crc = static_cast<std::uint32_t>(crc32(crc, reinterpret_cast<const Bytef*>(data), n));
    data += n;
    size -= n;
  }
  return crc;
}

// The checkpoint's text: the record, then the CRC-32 of the record.
std::string CheckpointText(std::int64_t points, std::int64_t bytes, std::uint32_t data_crc,
                           const std::string& description) {
  const std::string record = fmt::format("{}\npoints {}\nbytes {}\ndata_crc32 {:08x}\nsweep {}\n",
                                         kMagic, points, bytes, data_crc, description);
  return record + fmt::format("crc32 {:08x}\n", Crc32(0, record.data(), record.size()));
}

struct CheckpointRecord {
  bool exists = false;
  std::int64_t points = 0, bytes = 0;
  std::uint32_t data_crc = 0;
  std::string description;
};

[[noreturn]] void Corrupted(const std::string& path, const std::string& why) {
  throw IoError(fmt::format(
      "resume: checkpoint {} is not a valid capsubot sweep checkpoint ({}): delete it and "
      "its .partial file to start the sweep again",
      path, why));
}

// The whole file, at most `limit` bytes; only a regular file is read (never a device).
std::string ReadSmallFile(const std::string& path, std::size_t limit, bool& exists) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  exists = fd >= 0;
  if (fd < 0) {
    if (errno == ENOENT) return "";
    Corrupted(path, std::strerror(errno));
  }
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd);
    Corrupted(path, "not a regular file");
  }
  if (static_cast<std::size_t>(st.st_size) > limit) {
    ::close(fd);
    Corrupted(path, fmt::format("{} bytes, more than the {} of a checkpoint of this sweep",
                                static_cast<long long>(st.st_size), limit));
  }
  std::string text(static_cast<std::size_t>(st.st_size), '\0');
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::read(fd, &text[done], text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    done += static_cast<std::size_t>(n);
  }
  ::close(fd);
  text.resize(done);
  return text;
}

// Counts the rows and points of a file's rows given in chunks (PointRows): the first
// kMaxLineBytes of each row are held for PointRows::starts_point, never more.
class PointCounter {
 public:
  explicit PointCounter(const PointRows& rows) : rows_(rows) {}
  void Add(const char* data, std::size_t size) {
    for (std::size_t i = 0; i < size;) {
      const void* found = std::memchr(data + i, '\n', size - i);
      const std::size_t end = found != nullptr
                                  ? static_cast<std::size_t>(static_cast<const char*>(found) - data)
                                  : size;
      line_.append(data + i,
                   std::min(end - i, kMaxLineBytes - std::min(line_.size(), kMaxLineBytes)));
      if (found == nullptr) return;
      ++row_count_;
      if (!rows_.starts_point || rows_.starts_point(line_)) ++point_count_;
      line_.clear();
      i = end + 1;
    }
  }
  bool Complete() const { return line_.empty(); }  ///< the last row has its line break
  std::int64_t rows() const { return row_count_; }
  std::int64_t points() const { return point_count_; }

 private:
  const PointRows& rows_;
  std::string line_;
  std::int64_t row_count_ = 0, point_count_ = 0;
};

// Reads and checks a checkpoint: any damage is reported (never silently restarted).
CheckpointRecord ReadCheckpoint(const std::string& path, std::size_t description_size) {
  CheckpointRecord r;
  const std::string text = ReadSmallFile(path, description_size + kCheckpointOverhead, r.exists);
  if (!r.exists) return r;
  // The last line, "crc32 xxxxxxxx\n", holds the CRC-32 of everything before it.
  constexpr std::size_t kCrcLine = 15;
  const std::size_t crc_line = text.size() < kCrcLine ? 0 : text.size() - kCrcLine;
  unsigned stored = 0;
  if (crc_line == 0 || text[crc_line - 1] != '\n' || text.compare(crc_line, 6, "crc32 ") != 0 ||
      std::sscanf(text.c_str() + crc_line, "crc32 %8x", &stored) != 1) {
    Corrupted(path, "no checksum line");
  }
  if (Crc32(0, text.data(), crc_line) != stored) Corrupted(path, "checksum mismatch");
  const std::string head = fmt::format("{}\n", kMagic);
  if (text.compare(0, head.size(), head) != 0) Corrupted(path, "unknown format");
  long long points = -1, bytes = -1;
  unsigned data_crc = 0;
  int used = 0;
  if (std::sscanf(text.c_str() + head.size(), "points %lld\nbytes %lld\ndata_crc32 %8x\nsweep %n",
                  &points, &bytes, &data_crc, &used) != 3 ||
      used == 0 || points < 0 || bytes <= 0) {
    Corrupted(path, "malformed record");
  }
  const std::size_t start = head.size() + static_cast<std::size_t>(used);
  r.points = points;
  r.bytes = bytes;
  r.data_crc = data_crc;
  r.description = text.substr(start, crc_line - 1 - start);
  return r;
}

// The checkpoint a resume continues from (exists false: none), refused when it is of
// another run or when its partial file is missing (a resume would start it empty).
CheckpointRecord ResumeRecord(const std::string& path, const std::string& description,
                              const std::string& run, const std::string& partial) {
  const CheckpointRecord record = ReadCheckpoint(path, description.size());
  struct stat st {};
  if (record.exists && ::stat(partial.c_str(), &st) != 0 && errno == ENOENT) {
    throw IoError(fmt::format(
        "resume: {} is missing, but its checkpoint {} says it holds {} points ({} bytes): "
        "expected the partial file of the interrupted {} beside its checkpoint (delete the "
        "checkpoint to start the {} again)",
        partial, path, record.points, record.bytes, run, run));
  }
  if (record.exists && record.description != description) {
    throw std::invalid_argument(
        fmt::format("resume: checkpoint {} is invalid for this {}: it was written by a {} with "
                    "other options or another capsubot version: expected the same options as the "
                    "interrupted run, or a run without resuming to start again",
                    path, run, run));
  }
  return record;
}

// The refusal of a resume of an output written in place (it has no checkpoint).
std::invalid_argument ResumeInPlace(const std::string& output) {
  return std::invalid_argument(
      fmt::format("resume with output {} is invalid: expected a regular file to resume (standard "
                  "output, pipes and devices are written in place, without checkpoint)",
                  output));
}

}  // namespace

void SweepFile::CheckResume(const std::string& output, const std::string& description,
                            const std::string& run) {
  const OutputTarget target = ResolveOutput(output, "output");
  if (target.in_place) throw ResumeInPlace(output);
  ResumeRecord(CheckpointPath(target.path), description, run, PartialPath(target.path));
}

void SweepFile::Fail(const std::string& what, const std::string& path) const {
  const std::string message =
      fmt::format("output {}: cannot {} {}: {}", output_, what, path, std::strerror(errno));
  // A file that was opened and then cannot take the rows (a full disk) is no bad input.
  if (what == "write" || what == "sync") throw WriteError(message);
  throw IoError(message);
}

SweepFile::SweepFile(const std::string& output, const std::string& description,
                     const std::string& header, const PointRows& rows, bool resume,
                     double checkpoint_seconds, const std::string& run)
    : output_(output),
      run_(run),
      target_(ResolveOutput(output, "output")),
      partial_(PartialPath(target_.path)),
      checkpoint_(CheckpointPath(target_.path)),
      description_(description),
      checkpoint_seconds_(checkpoint_seconds) {
  direct_ = target_.in_place;
  if (direct_) {
    if (resume) throw ResumeInPlace(output_);
    written_ = output_ == "-" ? std::string("standard output") : output_;
    fd_ = output_ == "-" ? ::dup(STDOUT_FILENO) : ::open(output_.c_str(), O_WRONLY | O_CLOEXEC);
    if (fd_ < 0) Fail("open", written_);
    Append(header.data(), header.size(), 0);
    return;
  }
  written_ = partial_;
  // Checked before the open, which would create a missing partial file.
  if (resume) ResumeRecord(checkpoint_, description_, run_, partial_);
  fd_ = ::open(partial_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) Fail("create", partial_);
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int err = errno;
    ::close(fd_);
    fd_ = -1;
    if (err == EWOULDBLOCK) {
      throw IoError(
          fmt::format("output {}: another capsubot {} is writing {}", output_, run_, partial_));
    }
    errno = err;
    Fail("lock", partial_);
  }
  last_checkpoint_ = std::chrono::steady_clock::now();
  try {
    Open(header, rows, resume);
  } catch (...) {  // no destructor runs: release the file and its lock here
    if (pending_checkpoint_.valid()) pending_checkpoint_.wait();
    ::close(fd_);
    fd_ = -1;
    throw;
  }
}

void SweepFile::Open(const std::string& header, const PointRows& rows, bool resume) {
  const CheckpointRecord record =
      resume ? ResumeRecord(checkpoint_, description_, run_, partial_) : CheckpointRecord{};
  if (record.exists) {
    struct stat st {};
    if (::fstat(fd_, &st) != 0) Fail("read", partial_);
    if (st.st_size < record.bytes) {
      throw IoError(fmt::format(
          "resume: {} holds {} bytes but its checkpoint {} says {}: delete both to start the "
          "{} again",
          partial_, static_cast<long long>(st.st_size), checkpoint_, record.bytes, run_));
    }
    // The rows the checkpoint vouches for must be those written: check their CRC-32, and
    // count their points (rows after the header).
    std::vector<char> chunk(kChunkBytes);
    std::uint32_t crc = 0;
    PointCounter counter(rows);
    const auto header_bytes = static_cast<std::int64_t>(header.size());
    for (std::int64_t at = 0; at < record.bytes;) {
      const auto want = static_cast<std::size_t>(
          std::min<std::int64_t>(record.bytes - at, static_cast<std::int64_t>(kChunkBytes)));
      const ssize_t n = ::pread(fd_, chunk.data(), want, at);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) Fail("read", partial_);
      crc = Crc32(crc, chunk.data(), static_cast<std::size_t>(n));
      const std::int64_t skip = std::clamp<std::int64_t>(header_bytes - at, 0, n);
      counter.Add(chunk.data() + skip, static_cast<std::size_t>(n - skip));
      at += n;
    }
    if (crc != record.data_crc) {
      throw IoError(fmt::format(
          "resume: {} does not hold the rows its checkpoint {} vouches for (checksum "
          "mismatch: the file was changed or damaged): delete both to start the {} again",
          partial_, checkpoint_, run_));
    }
    if (record.bytes < header_bytes || !counter.Complete() || counter.points() != record.points ||
        record.points > rows.points) {
      Corrupted(checkpoint_,
                fmt::format("it says {} points, but the {} bytes it vouches for hold {} of the "
                            "{}'s {} points",
                            record.points, record.bytes, counter.points(), run_, rows.points));
    }
    rows_resumed_ = counter.rows();
    // Rows after the checkpoint may be partial: drop them, they are computed again.
    if (::ftruncate(fd_, record.bytes) != 0) Fail("truncate", partial_);
    points_ = record.points;
    bytes_ = writeback_ = record.bytes;
    crc_ = record.data_crc;
  } else if (::ftruncate(fd_, 0) != 0) {
    Fail("truncate", partial_);
  }
  if (::lseek(fd_, bytes_, SEEK_SET) < 0) Fail("seek in", partial_);
  if (!record.exists) {
    Append(header.data(), header.size(), 0);
    StartCheckpoint();
  }
}

SweepFile::~SweepFile() {
  // Its error is not reported: the run stopped with another one, or never read it (Commit).
  if (pending_checkpoint_.valid()) pending_checkpoint_.wait();
  if (fd_ >= 0) ::close(fd_);
}

void SweepFile::Append(const char* data, std::size_t size, std::int64_t points) {
  std::size_t done = 0;
  while (done < size) {
    const ssize_t n = ::write(fd_, data + done, size - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      Fail("write", written_);
    }
    done += static_cast<std::size_t>(n);
  }
  bytes_ += static_cast<std::int64_t>(size);
  points_ += points;
  if (direct_) return;
  crc_ = Crc32(crc_, data, size);
  if (bytes_ - writeback_ >= kWritebackBytes) {
    // Only starts the writing, without waiting: a failure shows in the next fsync.
    ::sync_file_range(fd_, writeback_, bytes_ - writeback_, SYNC_FILE_RANGE_WRITE);
    writeback_ = bytes_;
  }
  const auto now = std::chrono::steady_clock::now();
  if (std::chrono::duration<double>(now - last_checkpoint_).count() >= checkpoint_seconds_) {
    StartCheckpoint();
  }
}

void SweepFile::StartCheckpoint() {
  FinishCheckpoint();
  pending_checkpoint_ =
      std::async(std::launch::async, [this, points = points_, bytes = bytes_, crc = crc_] {
        WriteCheckpoint(points, bytes, crc);
      });
  last_checkpoint_ = std::chrono::steady_clock::now();
}

void SweepFile::FinishCheckpoint() {
  if (pending_checkpoint_.valid()) pending_checkpoint_.get();
}

void SweepFile::Checkpoint() {
  if (direct_) return;
  FinishCheckpoint();
  WriteCheckpoint(points_, bytes_, crc_);
  last_checkpoint_ = std::chrono::steady_clock::now();
}

void SweepFile::WriteCheckpoint(std::int64_t points, std::int64_t bytes, std::uint32_t crc) const {
  // Data first: the checkpoint never claims bytes that are not on disk (the fsync also
  // covers rows appended since `bytes`: harmless).
  if (::fsync(fd_) != 0) Fail("sync", partial_);
  const std::string text = CheckpointText(points, bytes, crc, description_);
  const std::string temp = checkpoint_ + ".tmp";
  const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) Fail("create", temp);
  const bool ok = ::write(fd, text.data(), text.size()) == static_cast<ssize_t>(text.size()) &&
                  ::fsync(fd) == 0;
  const int err = errno;
  ::close(fd);
  errno = err;
  if (!ok) {
    std::remove(temp.c_str());
    errno = err;
    Fail("write", temp);
  }
  if (std::rename(temp.c_str(), checkpoint_.c_str()) != 0) Fail("rename", temp);
}

void SweepFile::Commit() {
  if (direct_) {
    ::close(fd_);
    fd_ = -1;
    return;
  }
  FinishCheckpoint();
  if (::fsync(fd_) != 0) Fail("sync", partial_);
  // Checkpoint first: killed in between, a partial file without checkpoint starts over.
  std::remove(checkpoint_.c_str());
  if (std::rename(partial_.c_str(), target_.path.c_str()) != 0) {
    const int err = errno;
    Checkpoint();  // every point is done: a resume only renames
    errno = err;
    Fail("rename to the output", partial_);
  }
  ::close(fd_);
  fd_ = -1;
}

void SweepFile::Discard() {
  if (direct_) return;
  if (pending_checkpoint_.valid())
    pending_checkpoint_.wait();  // not to have it put back; its error is moot
  std::remove(checkpoint_.c_str());
  std::remove(partial_.c_str());
}

}  // namespace capsubot::detail
