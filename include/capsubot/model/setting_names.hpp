#pragma once
// How a front end names the settings the library's messages speak of. The library names a
// setting by its field ("hops", "reach_starts"); the command line writes a flag, the Python
// module a keyword argument. One table per job pairs each field with the front end's name; the
// rules of the jobs write their messages with it, and a message of a lower stage (which begins
// with a field's name: "record = 3 is invalid: ...") is rewritten with it.

#include <set>
#include <string>
#include <utility>
#include <vector>

namespace capsubot {

/// Pairs of a field and the front end's name of it, e.g. {"record", "--record"}.
using FlagNames = std::vector<std::pair<const char*, const char*>>;

/// A front end's names of a job's settings: its table and how it writes a setting with a value.
struct SettingNames {
  enum class Style {
    kFlags,     ///< a flag and its value: "--problem forcing", "no --problem"
    kKeywords,  ///< a keyword argument: "problem='forcing'", "problem=None"
  };
  FlagNames flags;
  Style style = Style::kFlags;

  /// The front end's name of `field` (the field itself when the table has no entry for it).
  std::string Name(const std::string& field) const;
  /// `field` as a rule names it: the flag's words ("10 <= global-evaluations <= ...") or the
  /// keyword.
  std::string InRule(const std::string& field) const;
  /// The text `value` of a setting as the front end writes it: forcing, or 'forcing'.
  std::string Value(const std::string& value) const;
  /// `field` given the text `value`: "--problem forcing" or "problem='forcing'".
  std::string Given(const std::string& field, const std::string& value) const;
  /// `field` not given: "no --problem" or "problem=None".
  std::string Absent(const std::string& field) const;
};

/// `names` without the entries of `fields`.
FlagNames Without(const FlagNames& names, const std::set<std::string>& fields);

/// `message` with its first word replaced by its flag when it is a field of `names` and is
/// followed by ' ' or ':' ("--record = 3 is invalid: ..."), and with every "field = " in the
/// rest of it (not an operand of an expression such as "to - from = 0.1") written as "flag = ".
std::string WithFlagNames(const std::string& message, const FlagNames& names);

}  // namespace capsubot
