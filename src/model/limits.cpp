#include "capsubot/model/limits.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <thread>

namespace capsubot {

int MaxUsefulThreads() {
  const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  return std::min(kMaxThreads, kThreadsPerCore * cores);
}

int CapThreads(int requested) { return std::min(requested, MaxUsefulThreads()); }

double TrajectoryRows(double periods, double samples_per_period) {
  return std::floor(periods * samples_per_period) + 1.0;
}

void RequireTrajectoryRows(double periods, double samples_per_period, const char* samples_name,
                           const char* periods_name) {
  const double rows = TrajectoryRows(periods, samples_per_period);
  if (rows > static_cast<double>(kMaxTrajectoryRows)) {
    throw std::invalid_argument(fmt::format(
        "{} = {} with {} = {} is invalid: expected at most {} rows of the trajectory "
        "(samples per period x periods + 1 = {:.0f})",
        samples_name, samples_per_period, periods_name, periods, kMaxTrajectoryRows, rows));
  }
}

}  // namespace capsubot
