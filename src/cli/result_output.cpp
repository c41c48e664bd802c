#include "capsubot/cli/result_output.hpp"

#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <stdexcept>

#include "capsubot/io/io.hpp"

namespace capsubot::cli {

namespace {

bool ToStandardOutput(const std::string& path) { return path.empty() || path == "-"; }

}  // namespace

CLI::Option* AddResultOutputOption(CLI::App& cmd, std::string& path, const std::string& what) {
  return cmd
      .add_option("-o,--output", path,
                  fmt::format("write {} (with --json its JSON object) to FILE instead of "
                              "standard output, atomically; - for standard output",
                              what))
      ->type_name("FILE");
}

void CheckResultOutput(const std::string& path) {
  if (!ToStandardOutput(path)) CheckWritable(path, "-o");
}

void WriteResult(const std::string& path, const std::string& text) {
  if (ToStandardOutput(path)) {
    fmt::print("{}", text);
    return;
  }
  AtomicFile file(path, "-o");
  file.stream() << text;
  file.Commit();
}

std::string JsonOutput(nlohmann::json j, const Provenance& provenance) {
  j["provenance"] = provenance.Json();
  return j.dump() + "\n";
}

void ResultOutput::Add(CLI::App& cmd, const std::string& json_help, const std::string& what) {
  cmd.add_flag("--json", json, json_help);
  AddResultOutputOption(cmd, path, what);
}

bool IsStandardOutput(const std::string& path) {
  if (path == "-") return true;
  struct stat file = {};
  struct stat out = {};
  return !path.empty() && ::stat(path.c_str(), &file) == 0 && ::fstat(STDOUT_FILENO, &out) == 0 &&
         file.st_dev == out.st_dev && file.st_ino == out.st_ino;
}

void RequireOutputApartFromJson(const std::string& output, const char* option, bool json) {
  if (!json || !IsStandardOutput(output)) return;
  throw std::invalid_argument(fmt::format(
      "{} {} with --json is invalid: both would be written to standard output, one after the "
      "other: expected {} FILE, another file than standard output, or no {}",
      option, output, option, option));
}

}  // namespace capsubot::cli
