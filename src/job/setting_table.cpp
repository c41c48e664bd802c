#include "capsubot/job/setting_table.hpp"

#include <mutex>
#include <set>

namespace capsubot {

const char* KeptText(const std::string& text) {
  static std::mutex mutex;
  static std::set<std::string> texts;  // a set's elements never move
  const std::lock_guard<std::mutex> lock(mutex);
  return texts.insert(text).first->c_str();
}

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
