#include "capsubot/io.hpp"

#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace capsubot {

AtomicFile::AtomicFile(std::string path, std::string what)
    : path_(std::move(path)), what_(std::move(what)) {
  struct stat st {};
  direct_ = path_ == "-" || (::stat(path_.c_str(), &st) == 0 && !S_ISREG(st.st_mode));
  temp_ = !direct_       ? fmt::format("{}.tmp.{}", path_, static_cast<long>(::getpid()))
          : path_ == "-" ? std::string("/dev/stdout")
                         : path_;
  out_.open(temp_, std::ios::out | std::ios::trunc);
  if (!out_) {
    throw IoError(fmt::format("{} {} cannot be written: {}", what_, path_, std::strerror(errno)));
  }
}

AtomicFile::~AtomicFile() {
  if (!committed_ && !direct_) {
    out_.close();
    std::remove(temp_.c_str());
  }
}

void AtomicFile::Commit() {
  out_.flush();
  const bool ok = static_cast<bool>(out_);
  out_.close();
  if (!ok || (!direct_ && std::rename(temp_.c_str(), path_.c_str()) != 0)) {
    const int err = errno;
    if (!direct_) std::remove(temp_.c_str());
    committed_ = true;
    throw IoError(fmt::format("{} {} cannot be written: {}", what_, path_, std::strerror(err)));
  }
  committed_ = true;
}

char* WriteNumber(char* out, double value) {
  if (std::isnan(value)) return out;
  return std::to_chars(out, out + kMaxNumberChars, value).ptr;
}

std::string FormatNumber(double value) {
  char text[kMaxNumberChars];
  return std::string(text, WriteNumber(text, value));
}

}  // namespace capsubot
