// What the launcher of this process says about its job (ranks.hpp).

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <initializer_list>
#include <string>

#include "capsubot/cluster/ranks.hpp"

namespace capsubot {

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

void UseLauncherStdout() {
  if (LauncherValue({"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"}) < 1 || LaunchedRank() != 0) {
    return;
  }
  struct stat st {};
  if (::fstat(STDOUT_FILENO, &st) != 0 || S_ISREG(st.st_mode)) return;
  const std::string parent = "/proc/" + std::to_string(static_cast<long>(::getppid()));
  std::string name;
  std::getline(std::ifstream(parent + "/comm"), name);
  if (name != "mpirun" && name != "mpiexec" && name != "orterun" && name != "prterun") return;
  const int fd = ::open((parent + "/fd/1").c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
  if (fd < 0) return;  // mpirun's copy stays
  std::fflush(stdout);
  ::dup2(fd, STDOUT_FILENO);
  ::close(fd);
}

}  // namespace capsubot
