#pragma once
// A job's settings as the front ends offer them: one row per field of an options struct, with
// what it means and the range a front end checks while reading it. The library writes each
// help once; it names the other settings by their fields in braces ("at most {max_period}"),
// and a front end writes them in its own names (HelpIn), as it does the library's messages.

#include <cstdint>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "capsubot/model/setting_names.hpp"

namespace capsubot {

/// `text` kept as long as the program, for a row's help or a FlagNames entry, which point to
/// their texts (safe to call from several threads).
const char* KeptText(const std::string& text);

/// One setting: the field of `Options` it sets and what it means.
template <class Options>
struct SettingRow {
  const char* field;  ///< the name the rules and messages use, "max_period"
  std::variant<double Options::*, int Options::*, std::int64_t Options::*, bool Options::*,
               std::string Options::*>
      member;
  const char* help;  ///< what it means and the rule of its value, fields in braces
  /// An integer's range, checked while reading it (lo < hi), or none (lo == hi).
  std::int64_t lo = 0, hi = 0;
  /// The kind of value a front end shows in its help ("FILE", "NXxNPSI"); nullptr: the type's.
  const char* type_name = nullptr;
  /// Whether the default is one value to show; a front end shows none either for a field whose
  /// default is "none" (NaN, an empty text).
  bool default_shown = true;
};

/// The settings of one options struct, in the order a front end lists them.
template <class Options>
using SettingTable = std::vector<SettingRow<Options>>;

/// The row of `field` in `table`; throws std::logic_error for a field the table has no row of
/// (a front end asking for a setting the library does not offer).
template <class Options>
const SettingRow<Options>& RowOf(const SettingTable<Options>& table, const std::string& field) {
  for (const SettingRow<Options>& row : table) {
    if (field == row.field) return row;
  }
  throw std::logic_error("no setting " + field + " in the table");
}

/// `help` with each "{field}" whose field has an entry in `names` written as its name there
/// ("{max_period}" -> "--max-period"); other braces ("{x, u, v}") are kept.
std::string HelpIn(const std::string& help, const FlagNames& names);

}  // namespace capsubot
