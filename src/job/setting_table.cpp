#include "capsubot/job/setting_table.hpp"

namespace capsubot {

std::string HelpIn(const std::string& help, const FlagNames& names) {
  std::string out = help;
  for (const auto& [field, name] : names) {
    const std::string braced = "{" + std::string(field) + "}";
    for (std::size_t at = out.find(braced); at != std::string::npos;
         at = out.find(braced, at + 1)) {
      out.replace(at, braced.size(), name);
    }
  }
  return out;
}

}  // namespace capsubot
