// Atomic output files: the text goes to a temporary file beside the target, renamed over it.

#include "capsubot/io/io.hpp"

#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <vector>

namespace capsubot {
namespace {

std::string Folder(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  return slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
}

}  // namespace

OutputTarget ResolveOutput(const std::string& path, const std::string& what) {
  if (path == "-") return {"/dev/stdout", true};
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0) {  // exists, symlinks followed
    if (!S_ISREG(st.st_mode)) return {path, true};
    // A regular file, possibly behind symlinks (/dev/stdout redirected to a file): write
    // beside the file itself, so the rename replaces it and never a link.
    const std::unique_ptr<char, decltype(&std::free)> real(::realpath(path.c_str(), nullptr),
                                                           &std::free);
    if (real) return {real.get(), false};
    throw IoError(fmt::format("{} {} cannot be written: {}", what, path, std::strerror(errno)));
  }
  // Not there yet, or a dangling symlink: follow the links of the last component, the new
  // file is created where the last one points.
  std::string p = path;
  for (int links = 0;; ++links) {
    if (::lstat(p.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return {p, false};
    if (links == kMaxSymlinks) {
      throw IoError(fmt::format("{} {} cannot be written: more than {} symbolic links", what, path,
                                kMaxSymlinks));
    }
    std::vector<char> buffer(PATH_MAX);
    const ssize_t n = ::readlink(p.c_str(), buffer.data(), buffer.size() - 1);
    if (n < 0) {
      throw IoError(fmt::format("{} {} cannot be written: {}", what, path, std::strerror(errno)));
    }
    const std::string target(buffer.data(), static_cast<std::size_t>(n));
    p = !target.empty() && target[0] == '/' ? target : Folder(p) + target;
  }
}

void CheckWritable(const std::string& path, const std::string& what) {
  const OutputTarget target = ResolveOutput(path, what);
  if (!target.in_place) {
    AtomicFile probe(path, what);  // removed unused by its destructor
    return;
  }
  if (::access(target.path.c_str(), W_OK) != 0) {
    throw IoError(fmt::format("{} {} cannot be written: {}", what, path, std::strerror(errno)));
  }
}

namespace {

// The file a path names, for comparing two spellings: symlinks resolved where the path exists,
// "." and ".." removed lexically where it does not yet.
std::filesystem::path Spelled(const std::string& path) {
  std::error_code error;
  const std::filesystem::path absolute = std::filesystem::absolute(path, error).lexically_normal();
  std::filesystem::path p = std::filesystem::weakly_canonical(absolute, error);
  return error ? absolute : p;
}

// Standard output, a device or a pipe: written in place, so naming it twice replaces nothing.
bool InPlace(const std::string& path) {
  struct stat st {};
  return path == "-" || (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode));
}

}  // namespace

bool SameFile(const std::string& a, const std::string& b) {
  std::error_code error;
  return a == b || Spelled(a) == Spelled(b) || std::filesystem::equivalent(a, b, error);
}

void RequireDistinctOutputs(const std::vector<std::pair<std::string, std::string>>& outputs) {
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    for (std::size_t j = i + 1; j < outputs.size(); ++j) {
      const auto& [a, a_option] = outputs[i];
      const auto& [b, b_option] = outputs[j];
      if (a.empty() || b.empty() || InPlace(a) || InPlace(b)) continue;
      if (SameFile(a, b)) {
        throw std::invalid_argument(
            fmt::format("{} = {} is invalid: it is the file of {} = {}: expected another file",
                        b_option, QuoteForMessage(b), a_option, QuoteForMessage(a)));
      }
    }
  }
}

AtomicFile::AtomicFile(std::string path, std::string what)
    : path_(std::move(path)), what_(std::move(what)) {
  const OutputTarget target = ResolveOutput(path_, what_);
  target_ = target.path;
  direct_ = target.in_place;
  temp_ = direct_ ? target_ : fmt::format("{}.tmp.{}", target_, static_cast<long>(::getpid()));
  // Registered before it exists: a signal right after the open still removes it.
  if (!direct_) slot_ = RegisterTempFile(temp_);
  out_.open(temp_, std::ios::out | std::ios::trunc);
  if (!out_) {
    const int err = errno;
    UnregisterTempFile(slot_);
    slot_ = -1;
    throw IoError(fmt::format("{} {} cannot be written: {}", what_, path_, std::strerror(err)));
  }
}

AtomicFile::~AtomicFile() {
  if (!committed_ && !direct_) {
    out_.close();
    std::remove(temp_.c_str());
  }
  UnregisterTempFile(slot_);
}

void AtomicFile::Commit() {
  committed_ = true;
  // errno keeps the reason of a write that failed earlier (the stream only keeps badbit).
  out_.flush();
  const bool written = static_cast<bool>(out_);
  int err = errno;
  out_.close();
  if (written && !out_) err = errno;  // close flushes what is left
  const bool ok = written && static_cast<bool>(out_);
  if (ok && (direct_ || std::rename(temp_.c_str(), target_.c_str()) == 0)) return;
  if (ok) err = errno;
  if (!direct_) std::remove(temp_.c_str());
  throw WriteError(fmt::format("{} {} cannot be written: {}", what_, path_,
                               std::strerror(err != 0 ? err : EIO)));
}

}  // namespace capsubot
