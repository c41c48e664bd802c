#include "capsubot/cli/force_options.hpp"

#include <fmt/format.h>

#include <stdexcept>
#include <string>
#include <utility>

#include "capsubot/cli/setting_options.hpp"
#include "capsubot/cli/strict_values.hpp"
#include "capsubot/io/io.hpp"
#include "capsubot/job/params_settings.hpp"
#include "capsubot/model/force_spec.hpp"

namespace capsubot::cli {
namespace {

// "0.1,0,0.05" -> {0.1, 0, 0.05}; every element is a number of ParseNumber ("1,,2" is a typo),
// or with `phases` of ParsePhase ("0,pi/2,pi").
std::vector<double> ParseCoefficients(const char* option, const std::string& text,
                                      bool phases = false) {
  std::vector<double> values;
  for (const std::string& element : SplitText(text, ',')) {
    try {
      values.push_back(phases ? ParsePhase(element, option) : ParseNumber(element, option));
    } catch (const std::invalid_argument&) {
      throw std::invalid_argument(fmt::format(
          "{} = {} is invalid: expected comma-separated {} (element {} is '{}')", option,
          QuoteForMessage(text), phases ? "phases (numbers or multiples of pi)" : "numbers",
          values.size() + 1, element));
    }
  }
  return values;
}

}  // namespace

const FlagNames& ForceFlags() {
  static const FlagNames flags = WithDashedFlags({}, ForceSettings());
  return flags;
}

void AddForcingOptions(CLI::App& cmd, ForcingOptions& o, bool with_phase) {
  std::vector<std::string> fields;  // the table's parts, in its order
  for (const SettingRow<ForceText>& row : ForceSettings()) {
    if (with_phase || std::string(row.field) != "phi0") fields.emplace_back(row.field);
  }
  AddSettings(cmd, o.parts, ForceSettings(), ForceFlags(), fields);
  o.A_option = cmd.get_option("--A");
  o.c_option = cmd.get_option("--c");
  if (with_phase) o.phi0_option = cmd.get_option("--phi0")->type_name(kPhase);
  o.fourier_option = cmd.get_option("--sin")->excludes(o.A_option);
  cmd.get_option("--cos")->needs(o.fourier_option);
  cmd.get_option("--waveform")->check(CLI::IsMember({"sine", "fourier", "pulse"}));
  for (const auto& [flag, list] :
       {std::pair("--sin", "b1,b2,..."), std::pair("--cos", "a1,a2,..."),
        std::pair("--levels", "L1,L2,..."), std::pair("--switches", "s1,s2,...")}) {
    cmd.get_option(flag)->type_name(list);  // the comma lists, as typed
  }
  CLI::Option* switches = cmd.get_option("--switches");  // phases, in ParsePhase's syntax
  switches->description(switches->get_description() + " (multiples of pi as pi/2, 3*pi/2)");
}

std::vector<double> ForcingOptions::Sines() const {
  return parts.sin.empty() ? std::vector<double>() : ParseCoefficients("--sin", parts.sin);
}

std::vector<double> ForcingOptions::Cosines() const {
  return parts.cos.empty() ? std::vector<double>() : ParseCoefficients("--cos", parts.cos);
}

Forcing ForcingOptions::Build(bool need_phase) const {
  ForceSpec spec;
  if (A_option->count() > 0) spec.A = parts.A;
  if (c_option->count() > 0) spec.c = parts.c;
  if (!parts.waveform.empty()) spec.waveform = parts.waveform;
  if (!parts.levels.empty()) spec.levels = ParseCoefficients("--levels", parts.levels);
  if (!parts.switches.empty()) {
    spec.switches = ParseCoefficients("--switches", parts.switches, true);
  }
  if (phi0_option != nullptr && phi0_option->count() > 0) spec.phi0 = parts.phi0;
  if (fourier_option->count() > 0) {
    spec.sin = Sines();
    if (!parts.cos.empty()) spec.cos = Cosines();
  }
  return spec.Build(need_phase, ForceFlags());
}

void AddParamsOptions(CLI::App& cmd, Params& p, Margins* margins) {
  static const FlagNames kFlags = DashedFlags("T0 e", {{"clearance", "--margin"},
                                                       {"clearance_stroke", "--margin-stroke"},
                                                       {"stick", "--stick-margin"}});
  AddSettings(cmd, p, ParamsSettings(), kFlags);
  if (margins != nullptr) AddSettings(cmd, *margins, MarginsSettings(), kFlags);
}

}  // namespace capsubot::cli
