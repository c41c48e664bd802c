// What the launcher of this process says about its job (ranks.hpp).

#include "ranks.hpp"

#include <algorithm>
#include <cstdlib>

namespace capsubot::app {

int LaunchedProcesses() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"}) {
    const char* value = std::getenv(name);
    if (value != nullptr) return std::max(1, std::atoi(value));
  }
  return 1;
}

}  // namespace capsubot::app
