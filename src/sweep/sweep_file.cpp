#include "sweep/sweep_file.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "capsubot/io.hpp"

namespace capsubot::detail {
namespace {

constexpr const char* kMagic = "capsubot sweep checkpoint 1";

struct CheckpointRecord {
  bool exists = false;
  std::int64_t points = 0, bytes = 0;
  std::string description;
};

// Reads a checkpoint; a file that does not parse is reported (never silently restarted).
CheckpointRecord ReadCheckpoint(const std::string& path) {
  CheckpointRecord r;
  std::ifstream in(path);
  if (!in) return r;
  r.exists = true;
  std::string magic, points, bytes, sweep;
  std::getline(in, magic);
  in >> points >> r.points >> bytes >> r.bytes >> sweep;
  in.get();  // the space after "sweep"
  std::getline(in, r.description);
  if (magic != kMagic || points != "points" || bytes != "bytes" || sweep != "sweep" || !in ||
      r.points < 0 || r.bytes <= 0) {
    throw IoError(fmt::format(
        "--resume: checkpoint {} cannot be read (not a capsubot sweep checkpoint): delete it "
        "to start the sweep again",
        path));
  }
  return r;
}

}  // namespace

void SweepFile::Fail(const std::string& what, const std::string& path) const {
  const std::string message =
      fmt::format("--output {}: cannot {} {}: {}", output_, what, path, std::strerror(errno));
  // A file that was opened and then cannot take the rows (a full disk) is no bad input.
  if (what == "write" || what == "sync") throw WriteError(message);
  throw IoError(message);
}

SweepFile::SweepFile(const std::string& output, const std::string& description,
                     const std::string& header, bool resume, double checkpoint_seconds)
    : output_(output),
      target_(ResolveOutput(output, "--output")),
      partial_(PartialPath(target_.path)),
      checkpoint_(CheckpointPath(target_.path)),
      description_(description),
      checkpoint_seconds_(checkpoint_seconds) {
  direct_ = target_.in_place;
  if (direct_) {
    if (resume) {
      throw std::invalid_argument(fmt::format(
          "--resume with --output {} is invalid: expected a regular file to resume (standard "
          "output, pipes and devices are written in place, without checkpoint)",
          output_));
    }
    fd_ = output_ == "-" ? ::dup(STDOUT_FILENO) : ::open(output_.c_str(), O_WRONLY | O_CLOEXEC);
    if (fd_ < 0) Fail("open", output_);
    Append(header.data(), header.size(), 0);
    return;
  }
  fd_ = ::open(partial_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) Fail("create", partial_);
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int err = errno;
    ::close(fd_);
    fd_ = -1;
    if (err == EWOULDBLOCK) {
      throw IoError(
          fmt::format("--output {}: another capsubot sweep is writing {}", output_, partial_));
    }
    errno = err;
    Fail("lock", partial_);
  }
  CheckpointRecord record;
  if (resume) record = ReadCheckpoint(checkpoint_);
  if (record.exists) {
    if (record.description != description_) {
      throw std::invalid_argument(fmt::format(
          "--resume: checkpoint {} is invalid for this sweep: it was written by a sweep with "
          "other options or another capsubot version ({}): expected the same options as the "
          "interrupted run, or no --resume to start again",
          checkpoint_, record.description));
    }
    struct stat st {};
    if (::fstat(fd_, &st) != 0) Fail("read", partial_);
    if (st.st_size < record.bytes) {
      throw IoError(fmt::format(
          "--resume: {} holds {} bytes but its checkpoint {} says {}: delete both to start the "
          "sweep again",
          partial_, static_cast<long long>(st.st_size), checkpoint_, record.bytes));
    }
    // Rows after the checkpoint may be partial: drop them, they are computed again.
    if (::ftruncate(fd_, record.bytes) != 0) Fail("truncate", partial_);
    points_ = record.points;
    bytes_ = record.bytes;
  } else {
    if (::ftruncate(fd_, 0) != 0) Fail("truncate", partial_);
    points_ = 0;
    bytes_ = 0;
  }
  if (::lseek(fd_, bytes_, SEEK_SET) < 0) Fail("seek in", partial_);
  if (!record.exists) {
    Append(header.data(), header.size(), 0);
    Checkpoint();
  }
  last_checkpoint_ = std::chrono::steady_clock::now();
}

SweepFile::~SweepFile() {
  if (fd_ >= 0) ::close(fd_);
}

void SweepFile::Append(const char* data, std::size_t size, std::int64_t points) {
  std::size_t done = 0;
  while (done < size) {
    const ssize_t n = ::write(fd_, data + done, size - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      Fail("write", partial_);
    }
    done += static_cast<std::size_t>(n);
  }
  bytes_ += static_cast<std::int64_t>(size);
  points_ += points;
  if (direct_) return;
  const auto now = std::chrono::steady_clock::now();
  if (std::chrono::duration<double>(now - last_checkpoint_).count() >= checkpoint_seconds_) {
    Checkpoint();
  }
}

void SweepFile::Checkpoint() {
  if (direct_) return;
  // Data first: the checkpoint never claims bytes that are not on disk.
  if (::fsync(fd_) != 0) Fail("sync", partial_);
  const std::string text =
      fmt::format("{}\npoints {}\nbytes {}\nsweep {}\n", kMagic, points_, bytes_, description_);
  const std::string temp = checkpoint_ + ".tmp";
  const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) Fail("create", temp);
  const bool ok = ::write(fd, text.data(), text.size()) == static_cast<ssize_t>(text.size()) &&
                  ::fsync(fd) == 0;
  const int err = errno;
  ::close(fd);
  errno = err;
  if (!ok) Fail("write", temp);
  if (std::rename(temp.c_str(), checkpoint_.c_str()) != 0) Fail("rename", temp);
  last_checkpoint_ = std::chrono::steady_clock::now();
}

void SweepFile::Commit() {
  if (direct_) {
    ::close(fd_);
    fd_ = -1;
    return;
  }
  if (::fsync(fd_) != 0) Fail("sync", partial_);
  // Checkpoint first: killed in between, a partial file without checkpoint starts over.
  std::remove(checkpoint_.c_str());
  if (std::rename(partial_.c_str(), target_.path.c_str()) != 0) Fail("rename", partial_);
  ::close(fd_);
  fd_ = -1;
}

}  // namespace capsubot::detail
