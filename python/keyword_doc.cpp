#include "keyword_doc.hpp"

#include <fmt/format.h>

#include <cstddef>
#include <regex>
#include <sstream>
#include <vector>

#include "capsubot/io/wrap_text.hpp"
#include "capsubot/job/force_settings.hpp"
#include "capsubot/job/motion_settings.hpp"
#include "capsubot/job/params_settings.hpp"
#include "capsubot/job/shooting_settings.hpp"
#include "capsubot/model/limits.hpp"

namespace capsubot::python {
namespace {

constexpr std::size_t kNameColumn = 4;   // "    name"
constexpr std::size_t kTextColumn = 12;  // the text, and its wrapped lines
constexpr std::size_t kWidth = 92;

// `text` for a reader of the installed module: its pages of the documentation by name, its
// settings by keyword.
std::string ForInstalledReader(const std::string& text) {
  static const std::regex page(R"(docs/([a-z_]+)\.md)");
  static const std::regex field(R"(\{([A-Za-z_][A-Za-z0-9_]*)\})");
  return std::regex_replace(std::regex_replace(text, page, "capsubot documentation, $1"), field,
                            "$1");
}

}  // namespace

std::string ArgumentLines(const std::string& name, const std::string& text) {
  std::string head = std::string(kNameColumn, ' ') + name;
  head += head.size() < kTextColumn ? std::string(kTextColumn - head.size(), ' ') : "  ";
  std::istringstream in(ForInstalledReader(text));
  std::vector<std::string> words;
  for (std::string word; in >> word;) words.push_back(word);
  // The first line goes on beside the name, as far as the width allows; the others under it.
  std::size_t beside = 0, used = head.size();
  while (beside < words.size() && (beside == 0 || used + words[beside].size() <= kWidth)) {
    used += words[beside].size() + 1;
    ++beside;
  }
  std::string lines = head;
  for (std::size_t i = 0; i < beside; ++i) lines += (i == 0 ? "" : " ") + words[i];
  lines += '\n';
  if (beside == words.size()) return lines;
  for (const std::string& line :
       WrapWords({words.begin() + static_cast<std::ptrdiff_t>(beside), words.end()},
                 kWidth - kTextColumn)) {
    lines += std::string(kTextColumn, ' ') + line + '\n';
  }
  return lines;
}

std::string ThreadsCapDoc() {
  return fmt::format("more than {} per core are lowered to that", kThreadsPerCore);
}

std::string ThreadsArgDoc(const std::string& of) {
  return ArgumentLines("threads", "worker threads" + of + " (0: all cores; " + ThreadsCapDoc() +
                                      "); the result does not depend on it");
}

std::string FromRestArgsDoc() {
  return ArgumentLines("from_rest_starts",
                       "grid 'NXxNPSI' of starts from rest on which a gait is checked (capsubot "
                       "documentation, model section 12; key from_rest)") +
         ThreadsArgDoc(" of the simulated starts");
}

std::string ForceArgsDoc(bool pulse) {
  std::vector<std::string> parts = {"A", "c", "sin", "cos"};
  if (pulse) parts.insert(parts.end(), {"waveform", "levels", "switches"});
  return TableArgumentLines(ForceSettings(), ForceText{}, {}, parts, DefaultInDoc::kSignature);
}

std::string ModelArgsDoc() {
  return TableArgumentLines(ParamsSettings(), Params{}, {}, {"T0", "e"}, DefaultInDoc::kSignature);
}

std::string MarginArgsDoc() {
  return TableArgumentLines(MarginsSettings(), Margins{}, kMarginKeywords,
                            {"clearance", "clearance_stroke", "stick"}, DefaultInDoc::kSignature);
}

std::string MassRatioArgDoc() {
  return TableArgumentLines(MassRatioSettings(), RobotModel{}, {}, {"alpha"},
                            DefaultInDoc::kSignature);
}

std::string MotionArgsDoc() {
  return TableArgumentLines(MotionSettings(), MotionOptions{}, {},
                            {"transient", "record", "max_period", "state_tolerance",
                             "converged_tolerance", "chatter_velocity", "max_events_per_period"},
                            DefaultInDoc::kSignature);
}

std::string ShootingArgsDoc() {
  return TableArgumentLines(ShootingSettings(), ShootingOptions{}, {},
                            {"max_period", "step", "chatter_velocity"}, DefaultInDoc::kSignature);
}

}  // namespace capsubot::python
