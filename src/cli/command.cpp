#include "capsubot/cli/command.hpp"

#include <stdexcept>

#include "capsubot/io/io.hpp"

namespace capsubot::cli {

int RunNamingFlags(const FlagNames& names, const std::function<int()>& run) {
  try {
    return run();
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(WithFlagNames(e.what(), names));
  } catch (const WriteError& e) {
    throw WriteError(WithFlagNames(e.what(), names));
  } catch (const IoError& e) {
    throw IoError(WithFlagNames(e.what(), names));
  }
}

}  // namespace capsubot::cli
