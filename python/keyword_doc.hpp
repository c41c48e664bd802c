#pragma once
// The docstring lines of a function's keyword arguments, written from the library's tables of
// the settings they set: each setting means in the module what it means on the command line
// (--help), in the module's names and with the documentation named as an installed user finds
// it.

#include <cmath>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "capsubot/io/io.hpp"
#include "capsubot/job/setting_table.hpp"
#include "capsubot/model/setting_names.hpp"

namespace capsubot::python {

/// The docstring lines of one argument: "    name    text", the name padded to 8 columns (or
/// followed by two spaces), `text` wrapped to 92 columns under column 12. A page of the
/// documentation is named as the installed user finds it ("docs/model.md section 12" ->
/// "capsubot documentation, model section 12"); a setting in braces left by HelpIn ("{problem}")
/// is its keyword.
std::string ArgumentLines(const std::string& name, const std::string& text);

/// The text of a default in a docstring: a number as the module prints it, a text quoted
/// ('LN_COBYLA'); empty for none (NaN, an empty text) and for a flag.
template <class Field>
std::string DefaultText(const Field& field) {
  if constexpr (std::is_floating_point_v<Field>) {
    return std::isnan(field) ? std::string() : FormatNumber(field);
  } else if constexpr (std::is_same_v<Field, std::string>) {
    return field.empty() ? std::string() : "'" + field + "'";
  } else if constexpr (std::is_same_v<Field, bool>) {
    return std::string();
  } else {
    return std::to_string(field);
  }
}

/// How a docstring line says a keyword's default: not at all (the signature shows it), or
/// "None: <default>" (the keyword's default is None, which leaves the library's).
enum class DefaultInDoc { kSignature, kNoneMeans };

/// The ArgumentLines of the rows `fields` of `table` (in that order), each named by `keywords`
/// (a field without an entry: itself), its help written in those names (HelpIn), then as
/// `defaults` says its default (the value in `options`, when the row shows one). Throws
/// std::logic_error for a field the table has no row of.
template <class Options>
std::string TableArgumentLines(const SettingTable<Options>& table, const Options& options,
                               const FlagNames& keywords, const std::vector<std::string>& fields,
                               DefaultInDoc defaults) {
  std::string lines;
  for (const std::string& field : fields) {
    const SettingRow<Options>& row = RowOf(table, field);
    std::string text = HelpIn(row.help, keywords);
    const std::string value =
        std::visit([&options](auto member) { return DefaultText(options.*member); }, row.member);
    if (defaults == DefaultInDoc::kNoneMeans && row.default_shown && !value.empty()) {
      text += "; None: " + value;
    }
    lines +=
        ArgumentLines(SettingNames{keywords, SettingNames::Style::kKeywords}.Name(field), text);
  }
  return lines;
}

/// The docstring lines of the force's parts A, c, sin, cos and, with `pulse` (a function that
/// simulates, which any periodic force drives), waveform, levels and switches (ForceSettings;
/// phi0, whose meaning depends on the function, is each function's own).
std::string ForceArgsDoc(bool pulse = true);

/// The docstring lines of the model arguments T0 and e (ParamsSettings).
std::string ModelArgsDoc();

/// The docstring lines of the margins of a robust gait (MarginsSettings), as the keywords
/// margin, margin_stroke and stick_margin.
std::string MarginArgsDoc();

/// The docstring line of the mass ratio alpha of the robot (MassRatioSettings).
std::string MassRatioArgDoc();

/// The docstring lines of the long-run settings transient, record, max_period,
/// state_tolerance, converged_tolerance, chatter_velocity and max_events_per_period
/// (MotionSettings).
std::string MotionArgsDoc();

/// The docstring lines of Newton shooting's max_period, step and chatter_velocity
/// (ShootingSettings).
std::string ShootingArgsDoc();

/// The rule of the number of worker threads: "more than 4 per core are lowered to that"
/// (kThreadsPerCore).
std::string ThreadsCapDoc();

/// The docstring line of the worker threads (`of`: " of the simulated starts") of a function
/// whose result does not depend on them.
std::string ThreadsArgDoc(const std::string& of = "");

/// The docstring lines of the check of a gait from rest: from_rest_starts, threads.
std::string FromRestArgsDoc();

/// The keyword of each margin of a robust gait (Margins' fields).
inline const FlagNames kMarginKeywords = {
    {"clearance", "margin"}, {"clearance_stroke", "margin_stroke"}, {"stick", "stick_margin"}};

}  // namespace capsubot::python
