#pragma once
// How the Python module's design() names the runs of the design job: it has one design and
// one design with the fastest motion from rest (from_rest=True); the grid and the drive design
// are the command line's.

#include <string>

#include "capsubot/job/setting_names.hpp"

namespace capsubot::python {

/// The run `run` of the design job as design()'s messages name it.
inline std::string DesignRunKeywords(const std::string& run) {
  if (run.empty()) return "one design (from_rest=False)";
  if (run == "from-rest") return "from_rest=True";
  return run == "grid" ? "a design grid (capsubot design --grid)"
                       : "a drive design (capsubot design --drive)";
}

/// design()'s keywords are the settings' field names.
inline const SettingNames kDesignKeywords{{}, SettingNames::Style::kKeywords};

}  // namespace capsubot::python
