// Bounded reads of text files: a line or a file longer than its limit is refused, so that a
// device (/dev/zero) or a damaged file cannot make a reader hold unbounded memory.

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "capsubot/io/io.hpp"

namespace capsubot {

namespace {

// The bytes a stream buffer already holds, scanned in place (as std::getline does inside the
// library): its get area's pointers are protected members of std::streambuf, reached through
// this derived type.
struct GetArea : std::streambuf {
  static const char* Begin(std::streambuf& b) { return (b.*&GetArea::gptr)(); }
  static const char* End(std::streambuf& b) { return (b.*&GetArea::egptr)(); }
  static void Skip(std::streambuf& b, std::size_t n) { (b.*&GetArea::gbump)(static_cast<int>(n)); }
};

}  // namespace

bool ReadLine(std::istream& in, std::string& line, const std::string& what, std::size_t limit) {
  line.clear();
  const std::istream::sentry ok(in, true);
  if (!ok) return false;
  std::streambuf& buffer = *in.rdbuf();
  for (;;) {
    if (std::streambuf::traits_type::eq_int_type(buffer.sgetc(),
                                                 std::streambuf::traits_type::eof())) {
      // As std::getline: the last line without its line break sets eof, nothing at all fails.
      in.setstate(line.empty() ? std::ios::eofbit | std::ios::failbit : std::ios::eofbit);
      return !line.empty();
    }
    const char* begin = GetArea::Begin(buffer);  // sgetc() filled the get area
    const auto held = static_cast<std::size_t>(GetArea::End(buffer) - begin);
    const void* found = std::memchr(begin, '\n', held);
    const std::size_t n = found != nullptr ? static_cast<const char*>(found) - begin : held;
    if (line.size() + n > limit) {
      throw std::invalid_argument(
          fmt::format("{} is invalid: a line longer than {} bytes", what, limit));
    }
    line.append(begin, n);
    GetArea::Skip(buffer, found != nullptr ? n + 1 : n);
    if (found != nullptr) return true;
  }
}

std::string ReadTextFile(const std::string& path, const std::string& what, std::size_t limit) {
  // Opened without blocking and checked before any read: a pipe without writer would block
  // the open, a device or a pipe may never end.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) {
    throw IoError(fmt::format("{} {} cannot be read: {}", what, path, std::strerror(errno)));
  }
  struct stat st {};
  const bool stated = ::fstat(fd, &st) == 0;
  const int err = errno;
  const auto refuse = [&](const std::string& why) {
    ::close(fd);
    throw std::invalid_argument(fmt::format(
        "{} {} is invalid: expected a file of at most {} bytes{}", what, path, limit, why));
  };
  if (!stated) {
    ::close(fd);
    throw IoError(fmt::format("{} {} cannot be read: {}", what, path, std::strerror(err)));
  }
  if (S_ISDIR(st.st_mode)) refuse(", not a folder");
  if (!S_ISREG(st.st_mode)) refuse(", not a pipe or device");
  if (static_cast<std::uint64_t>(st.st_size) > limit) refuse("");
  // At most limit + 1 bytes: a file that grew past the limit since fstat is refused too.
  std::string text(limit + 1, '\0');
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::read(fd, &text[done], text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const int read_err = errno;
      ::close(fd);
      throw IoError(fmt::format("{} {} cannot be read: {}", what, path, std::strerror(read_err)));
    }
    if (n == 0) break;
    done += static_cast<std::size_t>(n);
  }
  text.resize(done);
  if (text.size() > limit) refuse("");
  ::close(fd);
  return text;
}

}  // namespace capsubot
