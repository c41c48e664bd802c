// What the launcher of this process says about its job (ranks.hpp).

#include "ranks.hpp"

#include <algorithm>
#include <cstdlib>
#include <initializer_list>

namespace capsubot::app {

namespace {

// The first of the launcher's variables `names` that is set, read as an integer; else -1.
int LauncherValue(std::initializer_list<const char*> names) {
  for (const char* name : names) {
    const char* value = std::getenv(name);
    if (value != nullptr) return std::atoi(value);
  }
  return -1;
}

}  // namespace

int LaunchedProcesses() {
  return std::max(1, LauncherValue({"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"}));
}

int LaunchedRank() {
  return std::max(0, LauncherValue({"OMPI_COMM_WORLD_RANK", "PMI_RANK", "PMIX_RANK"}));
}

}  // namespace capsubot::app
