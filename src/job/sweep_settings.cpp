#include "capsubot/job/sweep_settings.hpp"

#include <fmt/format.h>

#include <cmath>
#include <optional>
#include <stdexcept>
#include <type_traits>

#include "capsubot/io/io.hpp"

namespace capsubot {

const std::vector<SettingUse>& SweepSettingUses() {
  // The modes that optimise a gait read rho_max; those that search P2 or P3 (reach: its seed)
  // read the search's settings.
  static const std::vector<SettingUse> uses = {
      {"A", {"", "phi0"}},
      {"c", {"", "phi0"}},
      {"phi0", {""}},
      {"sin", {"", "phi0"}},
      {"cos", {"", "phi0"}},
      {"waveform", {"", "phi0"}},
      {"levels", {"", "phi0"}},
      {"switches", {"", "phi0"}},
      {"stability", {"", "phi0", "forcing", "fourier"}},
      {"rho_max", {"phi0", "forcing", "fourier", "reach"}},
      {"stable_only", {"phi0", "forcing", "fourier", "reach"}},
      {"scan_points", {"phi0"}},
      {"bound", {"forcing", "fourier", "reach"}},
      {"harmonics", {"fourier"}},
      {"starts", {"forcing", "fourier", "reach"}},
      {"hops", {"forcing", "reach"}},
      {"global_algorithm", {"forcing", "fourier", "reach"}},
      {"local_algorithm", {"forcing", "fourier", "reach"}},
      {"global_evaluations", {"forcing", "fourier", "reach"}},
      {"alpha", {"reach"}},
      {"from_rest_starts", {"reach"}},
      {"reach_starts", {"reach"}},
      {"reach_evaluations", {"reach"}},
      {"reach_local_evaluations", {"reach"}},
  };
  return uses;
}

const ModeSet& SweepModes() {
  static const ModeSet modes = {
      "optimize", {"phi0", "forcing", "fourier", "reach"}, "no {optimize}"};
  return modes;
}

namespace {

// Puts the settings given into a mode's options (a setting given replaces the mode's default)
// and notes, for a number not given, the mode's own default where it differs from the
// settings'. It notes every setting it reads, so that the table of the modes and what they read
// cannot drift apart unnoticed (Check).
class ModeFiller {
 public:
  ModeFiller(const SweepSettings& settings, const SettingNames& names)
      : settings_(settings), names_(names) {}

  const SweepSettings& settings() const { return settings_; }
  const SettingNames& names() const { return names_; }

  // Notes `field`; whether it was given.
  bool Reads(const char* field) {
    read_.insert(field);
    return settings_.Given(field);
  }
  // `target` = `value` when `field` was given (or `also`: another setting gave the value).
  template <class T, class V>
  void Take(const char* field, T& target, const V& value, bool also = false) {
    if (Reads(field) || also) {
      target = value;
    } else if constexpr (std::is_same_v<T, double>) {
      if (target != value && !(std::isnan(target) && std::isnan(value))) {
        defaults_.emplace_back(field, FormatNumber(target));
      }
    }
  }
  // Throws std::logic_error for a setting of the table that the mode `mode` uses but did not
  // read: given, it would be ignored.
  void Check(const std::string& mode) const {
    for (const SettingUse& use : SweepSettingUses()) {
      if (use.UsedBy(mode) && read_.count(use.setting) == 0) {
        throw std::logic_error("the sweep mode '" + mode + "' does not read " + use.setting);
      }
    }
  }
  const std::vector<std::pair<std::string, std::string>>& defaults() const { return defaults_; }

 private:
  const SweepSettings& settings_;
  const SettingNames& names_;
  std::set<std::string> read_;
  std::vector<std::pair<std::string, std::string>> defaults_;
};

// The robot's T0 and e, and the margins of the mode's orbits.
void FillParams(ModeFiller& f, Params& p, Margins& m) {
  const SweepSettings& s = f.settings();
  f.Take("T0", p.T0, s.params.T0);
  f.Take("e", p.e, s.params.e);
  f.Take("margin", m.clearance, s.margins.clearance);
  f.Take("margin_stroke", m.clearance_stroke, s.margins.clearance_stroke);
  f.Take("stick_margin", m.stick, s.margins.stick);
}

void FillForce(ModeFiller& f, SweepForce& force) {
  const SweepSettings& s = f.settings();
  // A sweep solves the analytic orbit at every point: a pulse force is refused.
  const bool levels = f.Reads("levels"), switches = f.Reads("switches");
  if (levels || switches || (f.Reads("waveform") && s.waveform == "pulse")) {
    throw std::invalid_argument(
        "a pulse force is invalid for sweep: expected a sine or Fourier force (the analytic "
        "one-impact orbit needs one; simulate, attractors, periodic, continue, basins and "
        "bifurcation take a pulse force)");
  }
  f.Take("A", force.A, std::optional<double>(s.A));
  f.Take("c", force.c, std::optional<double>(s.c));
  f.Take("sin", force.sin, s.sin);
  f.Take("cos", force.cos, s.cos);
}

void FillRhoMax(ModeFiller& f, double& rho_max) {
  const bool stable_only = f.Reads("stable_only");
  f.Take("rho_max", rho_max, stable_only ? 1.0 : f.settings().search.gait.rho_max, stable_only);
}

// The bound, rho_max and search effort of P2, P3 and the reach search's seed.
void FillSearch(ModeFiller& f, SearchRequest& search) {
  const SearchRequest& given = f.settings().search;
  FillRhoMax(f, search.gait.rho_max);
  f.Take("bound", search.gait.force_bound, given.gait.force_bound);
  f.Take("starts", search.starts, given.starts);
  f.Take("global_algorithm", search.global_algorithm, given.global_algorithm);
  f.Take("local_algorithm", search.local_algorithm, given.local_algorithm);
  f.Take("global_evaluations", search.global_evaluations, given.global_evaluations);
}

void Fill(ModeFiller& f, SweepOrbitMode& m) {
  FillParams(f, m.params, m.margins);
  FillForce(f, m.force);
  f.Take("phi0", m.phi0, std::optional<double>(f.settings().phi0));
  f.Take("stability", m.stability, f.settings().stability);
}

void Fill(ModeFiller& f, SweepPhaseMode& m) {
  FillParams(f, m.params, m.phase.gait.margins);
  FillForce(f, m.force);
  f.Take("stability", m.stability, f.settings().stability);
  FillRhoMax(f, m.phase.gait.rho_max);
  f.Take("scan_points", m.phase.scan_points, f.settings().scan_points);
}

void Fill(ModeFiller& f, SweepForcingMode& m) {
  FillParams(f, m.params, m.search.gait.margins);
  f.Take("stability", m.stability, f.settings().stability);
  FillSearch(f, m.search);
  f.Take("hops", m.search.hops, f.settings().search.hops);
}

void Fill(ModeFiller& f, SweepFourierMode& m) {
  FillParams(f, m.params, m.search.gait.margins);
  f.Take("stability", m.stability, f.settings().stability);
  FillSearch(f, m.search);
  f.Take("harmonics", m.search.harmonics, f.settings().search.harmonics);
}

// `grid` = the grid of starts `field` when given (its syntax and limits: ParseStartGrid).
template <class Starts>
void FillStartGrid(ModeFiller& f, const char* field, const std::string& text, Starts& grid) {
  if (!f.Reads(field)) return;
  const StartGrid given = ParseStartGrid(f.names().Name(field), text);
  grid.n_x = given.n_x;
  grid.n_psi = given.n_psi;
}

void Fill(ModeFiller& f, SweepReachMode& m) {
  const SweepSettings& s = f.settings();
  FillParams(f, m.params, m.search.gait.margins);
  FillSearch(f, m.search);
  f.Take("hops", m.search.hops, s.search.hops);
  f.Take("alpha", m.reach.alpha, s.alpha);
  FillStartGrid(f, "from_rest_starts", s.from_rest_starts, m.reach.check);
  FillStartGrid(f, "reach_starts", s.reach_starts, m.reach.search);
  f.Take("reach_evaluations", m.reach.global_evaluations, s.reach_evaluations);
  f.Take("reach_local_evaluations", m.reach.local_evaluations, s.reach_local_evaluations);
}

// The mode of `settings` with the settings given; `filler` notes what it read.
SweepMode FilledMode(ModeFiller& filler) {
  SweepMode mode = SweepModeNamed(filler.settings().optimize);
  std::visit([&filler](auto& m) { Fill(filler, m); }, mode);
  filler.Check(filler.settings().optimize);
  return mode;
}

// The number given as the setting `field`, which a grid can give too.
double GivenNumber(const SweepSettings& s, const std::string& field) {
  const Params& p = s.params;
  const Margins& m = s.margins;
  const std::pair<const char*, double> numbers[] = {{"A", s.A},
                                                    {"c", s.c},
                                                    {"phi0", s.phi0},
                                                    {"T0", p.T0},
                                                    {"e", p.e},
                                                    {"margin", m.clearance},
                                                    {"margin_stroke", m.clearance_stroke},
                                                    {"stick_margin", m.stick},
                                                    {"alpha", s.alpha},
                                                    {"rho_max", s.search.gait.rho_max},
                                                    {"bound", s.search.gait.force_bound}};
  for (const auto& [name, value] : numbers) {
    if (field == name) return value;
  }
  throw std::logic_error("the sweep setting " + field + " is not a number of the grid");
}

// A value given both as a setting and by the grid.
void RejectGridConflicts(const SweepSettings& s, const SettingNames& names) {
  const std::string grid = names.Name("grid");
  for (const GridAxis& axis : s.grid.axes) {
    const std::string field = axis.name();
    if (s.Given(field)) {
      throw std::invalid_argument(fmt::format(
          "{} = {} is invalid with {} {}: expected the value from only one of them",
          names.Name(field), FormatNumber(GivenNumber(s, field)), grid, axis.ToString()));
    }
    if (axis.parameter == ModelParameter::kRhoMax && s.Given("stable_only")) {
      throw std::invalid_argument(fmt::format(
          "{} (rho_max = 1) is invalid with {} {}: expected the value from only one of them",
          names.Name("stable_only"), grid, axis.ToString()));
    }
  }
}

// The mode as the messages name it: "no --optimize", "--optimize forcing".
std::string ModeText(const std::string& mode, const SettingNames& names) {
  const std::string optimize = names.Name("optimize");
  return mode.empty() ? "no " + optimize : optimize + " " + mode;
}

// Refuses the first setting given that the mode does not read (it would be silently ignored),
// naming the modes that read it.
void RejectUnread(const SweepSettings& s, const SettingNames& names) {
  const std::string& mode = s.optimize;
  for (const SettingUse& use : SweepSettingUses()) {
    if (!s.Given(use.setting) || use.UsedBy(mode)) continue;
    std::string readers;
    for (const std::string& reader : use.modes) {
      readers += (readers.empty() ? "" : ", ") + ModeText(reader, names);
    }
    const std::string optimize = names.Name("optimize");
    throw std::invalid_argument(fmt::format(
        "{} is invalid {}: expected it only with {}", names.Name(use.setting),
        mode.empty() ? "without " + optimize : "with " + optimize + " " + mode, readers));
  }
}

}  // namespace

SweepJobOptions SweepJobFrom(const SweepSettings& settings, const SettingNames& names) {
  SweepJobOptions job;
  job.grid = settings.grid;
  (void)SweepModeNamed(settings.optimize);  // an unknown mode first
  RejectGridConflicts(settings, names);
  ModeFiller filler(settings, names);
  job.mode = FilledMode(filler);
  RejectUnread(settings, names);
  if (settings.Given("global_evaluations") && settings.search.global_algorithm == kMultistart) {
    throw std::invalid_argument(fmt::format(
        "{} is invalid with {} {}: expected an NLopt global algorithm with it (multistart has no "
        "evaluation budget)",
        names.Name("global_evaluations"), names.Name("global_algorithm"), kMultistart));
  }
  job.file = settings.file;
  job.Validate();
  return job;
}

std::vector<std::pair<std::string, std::string>> SweepModeDefaults(const SweepSettings& settings) {
  const SettingNames names;  // the settings are valid: no message is written
  ModeFiller filler(settings, names);
  (void)FilledMode(filler);
  return filler.defaults();
}

}  // namespace capsubot
