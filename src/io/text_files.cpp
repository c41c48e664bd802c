// Bounded reads of text files: a line or a file longer than its limit is refused, so that a
// device (/dev/zero) or a damaged file cannot make a reader hold unbounded memory.

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "capsubot/io.hpp"

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
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError(fmt::format("{} {} cannot be read: {}", what, path, std::strerror(errno)));
  std::string text(limit + 1, '\0');
  in.read(&text[0], static_cast<std::streamsize>(text.size()));
  if (in.bad()) throw IoError(fmt::format("{} {} cannot be read", what, path));
  text.resize(static_cast<std::size_t>(in.gcount()));
  if (text.size() > limit) {
    throw std::invalid_argument(
        fmt::format("{} {} is invalid: expected a file of at most {} bytes", what, path, limit));
  }
  return text;
}

}  // namespace capsubot
