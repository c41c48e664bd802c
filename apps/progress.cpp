#include "progress.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>

namespace capsubot::app {
namespace {

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

bool StderrIsTerminal() { return ::isatty(STDERR_FILENO) != 0; }

void ProgressBar::Update(double done, double total, double seconds, double skipped) {
  const bool last = done >= total;
  if (!last && seconds - drawn_ < 0.1) return;
  drawn_ = seconds;
  const double fraction = total > 0.0 ? std::min(done / total, 1.0) : 1.0;
  const double rate = seconds > 0.0 ? (done - skipped) / seconds : 0.0;
  const double left = rate > 0.0 ? (total - done) / rate : NAN;
  constexpr int kWidth = 30;
  const int full = static_cast<int>(fraction * kWidth);
  fmt::print(stderr, "\r[{}{}] {:5.1f}%  {:.0f}/{:.0f} {}  {} {}/s  {} elapsed  {} left ",
             std::string(full, '#'), std::string(kWidth - full, '.'), 100.0 * fraction, done, total,
             unit_, Rate(rate), unit_, Duration(seconds), Duration(left));
  if (last) fmt::print(stderr, "\n");
  std::fflush(stderr);
}

void ShowStage(const std::string& text) {
  if (!StderrIsTerminal()) return;
  fmt::print(stderr, "\r{}\033[K", text);
  std::fflush(stderr);
}

SweepProgressCallback GridProgress(ProgressBar& bar) {
  if (!StderrIsTerminal()) return {};
  return [&bar](const SweepProgress& p) {
    bar.Update(static_cast<double>(p.points_done), static_cast<double>(p.points_total), p.seconds,
               static_cast<double>(p.points_resumed));
  };
}

}  // namespace capsubot::app
