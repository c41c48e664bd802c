#pragma once
// How the Python module's design() names the runs of the design job: it has one design, one
// design with the fastest motion from rest (from_rest=True) and the drive design (drive=); the
// grid is the command line's.

#include <string>

#include "capsubot/model/setting_names.hpp"

namespace capsubot::python {

/// The run `run` of the design job as design()'s messages name it.
inline std::string DesignRunKeywords(const std::string& run) {
  if (run.empty()) return "one design (from_rest=False)";
  if (run == "from-rest") return "from_rest=True";
  return run == "grid" ? "a design grid (capsubot design --grid)" : "drive";
}

/// design()'s keywords are the settings' field names.
inline const SettingNames kDesignKeywords{{}, SettingNames::Style::kKeywords};

}  // namespace capsubot::python
