#include "capsubot/cli/progress.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>

namespace capsubot::cli {
namespace {

// How this process shows progress: the options of the one command a process runs set it.
enum class ProgressMode { kTerminal, kLines, kOff };
ProgressMode mode = ProgressMode::kTerminal;
std::string who = "capsubot";  // "capsubot sweep": the lines of --progress begin with it
const auto started = std::chrono::steady_clock::now();

bool StderrIsTerminal() { return ::isatty(STDERR_FILENO) != 0; }

double SecondsSinceStart() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
}

std::string Duration(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0.0) return "--:--";
  const long s = std::lround(seconds);
  return s >= 3600 ? fmt::format("{}:{:02}:{:02}", s / 3600, s / 60 % 60, s % 60)
                   : fmt::format("{:02}:{:02}", s / 60, s % 60);
}

std::string Rate(double rate) {
  if (rate >= 1e6) return fmt::format("{:.2f}M", rate / 1e6);
  if (rate >= 1e3) return fmt::format("{:.1f}k", rate / 1e3);
  return fmt::format("{:.3g}", rate);
}

}  // namespace

void AddProgressOptions(CLI::App& cmd) {
  const std::string name = "capsubot " + cmd.get_name();
  CLI::Option* lines = cmd.add_flag_callback(
      "--progress",
      [name] {
        mode = ProgressMode::kLines;
        who = name;
      },
      "show the progress as plain lines on stderr (no carriage returns), every 5 % or each "
      "stage, with the time elapsed and left, also when stderr is a file (a Slurm log); "
      "default: a bar redrawn in place when stderr is a terminal, nothing otherwise");
  cmd.add_flag_callback(
         "--no-progress", [] { mode = ProgressMode::kOff; }, "show no progress, also on a terminal")
      ->excludes(lines);
}

bool ProgressShown() {
  return mode == ProgressMode::kLines || (mode == ProgressMode::kTerminal && StderrIsTerminal());
}

void ProgressBar::Update(double done, double total, double seconds, double skipped) {
  if (!ProgressShown()) return;
  Reading r{};
  r.fraction = total > 0.0 ? std::min(done / total, 1.0) : 1.0;
  r.done = done;
  r.total = total;
  r.seconds = seconds;
  r.rate = seconds > 0.0 ? (done - skipped) / seconds : 0.0;
  r.left = r.rate > 0.0 ? (total - done) / r.rate : NAN;
  if (mode == ProgressMode::kLines) {
    Line(r);
  } else {
    Draw(r);
  }
}

void ProgressBar::Draw(const Reading& r) {
  const bool last = r.done >= r.total;
  if (!last && r.seconds - drawn_ < 0.1) return;
  drawn_ = r.seconds;
  constexpr int kWidth = 30;
  const int full = static_cast<int>(r.fraction * kWidth);
  fmt::print(stderr, "\r[{}{}] {:5.1f}%  {:.0f}/{:.0f} {}  {} {}/s  {} elapsed  {} left ",
             std::string(full, '#'), std::string(kWidth - full, '.'), 100.0 * r.fraction, r.done,
             r.total, unit_, Rate(r.rate), unit_, Duration(r.seconds), Duration(r.left));
  if (last) fmt::print(stderr, "\n");
  std::fflush(stderr);
}

void ProgressBar::Line(const Reading& r) {
  const bool last = r.done >= r.total;
  const int step = static_cast<int>(100.0 * r.fraction) / kProgressStep;
  if (ended_ || (!last && step <= step_ && r.seconds - drawn_ < kProgressLineSeconds)) return;
  ended_ = last;
  drawn_ = r.seconds;
  step_ = std::max(step, step_);
  fmt::print(stderr, "{}: {:3.0f}%  {:.0f}/{:.0f} {}  {} elapsed  {} left\n", who,
             std::floor(100.0 * r.fraction), r.done, r.total, unit_, Duration(r.seconds),
             Duration(r.left));
  std::fflush(stderr);
}

void ShowStage(const std::string& text, const std::string& count) {
  static std::string shown;     // --progress: the stage of the last line
  static double printed = 0.0;  // ... and when it was printed
  const std::string counted = count.empty() ? text : fmt::format("{} ({})", text, count);
  if (mode == ProgressMode::kLines) {
    const double now = SecondsSinceStart();
    if (text.empty() || (text == shown && now - printed < kProgressLineSeconds)) return;
    shown = text;
    printed = now;
    fmt::print(stderr, "capsubot {}  {} elapsed\n", counted, Duration(now));
  } else if (ProgressShown()) {
    fmt::print(stderr, "\r{}\033[K", counted);
  }
  std::fflush(stderr);
}

SweepProgressCallback GridProgress(ProgressBar& bar) {
  if (!ProgressShown()) return {};
  return [&bar](const SweepProgress& p) {
    bar.Update(static_cast<double>(p.points_done), static_cast<double>(p.points_total), p.seconds,
               static_cast<double>(p.points_resumed));
  };
}

}  // namespace capsubot::cli
