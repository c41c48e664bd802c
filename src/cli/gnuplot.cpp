// A PNG drawn by gnuplot from a script, for the commands' --plot.

#include "capsubot/cli/gnuplot.hpp"

#include <fmt/format.h>

#include <cstdio>
#include <filesystem>

#include "capsubot/io/io.hpp"

namespace capsubot::cli {

void DrawPng(const std::function<std::string(const std::string& png)>& script,
             const std::string& path) {
  // The atomic file's temporary (or, for a device or pipe, the target itself) is where gnuplot
  // writes; its own stream stays empty, so Commit() only renames gnuplot's file into place.
  AtomicFile file(path, "--plot");
  FILE* gp = popen("gnuplot 2>&1", "w");
  if (gp == nullptr) throw IoError("--plot: cannot run gnuplot");
  std::fputs(script(file.temp_path()).c_str(), gp);
  const int status = pclose(gp);
  std::error_code ec;
  if (status != 0 || std::filesystem::file_size(file.temp_path(), ec) == 0 || ec) {
    throw IoError(
        fmt::format("--plot {}: gnuplot failed (is it installed? Debian package gnuplot-nox, see "
                    "scripts/install-deps.sh)",
                    path));
  }
  file.Commit();
}

}  // namespace capsubot::cli
