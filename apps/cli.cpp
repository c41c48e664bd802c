#include "cli.hpp"

#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <system_error>
#include <thread>

#include "capsubot/cluster/ranks.hpp"
#include "capsubot/io/io.hpp"
#include "capsubot/job/params_settings.hpp"
#include "capsubot/model/force_spec.hpp"
#include "setting_options.hpp"

namespace capsubot::app {

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

constexpr const char* kIntegerValidator = "integer";

// The transform of a numeric option: the strict parse, then the value in a form CLI11's own
// conversion reads back exactly (shortest round-trip, plain decimal integers).
// `allow_inf`: the text "inf" is also accepted (a bound that may be absent, e.g. --rho-max);
// `phase`: ParsePhase's syntax, multiples of pi included (--phi0, --psi).
CLI::Validator NumberText(const std::string& name, bool allow_inf, bool phase) {
  return CLI::Validator(
      [name, allow_inf, phase](std::string& text) {
        if (allow_inf && text == "inf") return std::string();
        try {
          const double value = phase ? ParsePhase(text, name) : ParseNumber(text, name);
          if (phase && std::abs(value) > kTau && std::abs(value) <= kMaxPhase)
            NotePhaseInRadians(name, text, value);
          text = FormatNumber(value);
          return std::string();
        } catch (const std::invalid_argument& e) {
          return std::string(e.what());
        }
      },
      "", "number");
}

CLI::Validator IntegerText(const std::string& name, std::int64_t lo, std::int64_t hi,
                           const std::string& description) {
  return CLI::Validator(
      [name, lo, hi](std::string& text) {
        try {
          text = std::to_string(ParseInteger(text, name, lo, hi));
          return std::string();
        } catch (const std::invalid_argument& e) {
          return std::string(e.what());
        }
      },
      description, kIntegerValidator);
}

bool HasValidator(CLI::Option* option, const char* name) {
  try {
    option->get_validator(name);
    return true;
  } catch (const CLI::OptionNotFound&) {
    return false;
  }
}

// A value of a text option (a path, --shard, --starts, ...) that is empty.
CLI::Validator NonEmptyText(const std::string& name) {
  return CLI::Validator(
      [name](std::string& text) {
        return text.empty() ? fmt::format("{} = '' is invalid: expected a value", name)
                            : std::string();
      },
      "", "non-empty");
}

}  // namespace

void NotePhaseInRadians(const std::string& name, const std::string& text, double value) {
  fmt::print(stderr, "capsubot: note: {} = {} is {:.4g} turns: phases are in radians\n", name, text,
             value / kTau);
}

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

int RunNamingFlags(const FlagNames& names, const std::function<int()>& run) {
  try {
    return run();
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(WithFlagNames(e.what(), names));
  } catch (const WriteError& e) {
    throw WriteError(WithFlagNames(e.what(), names));
  } catch (const IoError& e) {
    throw IoError(WithFlagNames(e.what(), names));
  }
}

std::pair<int, int> ParseShard(const std::string& text) {
  const std::size_t slash = text.find('/');
  // One count: digits only, no sign and no wrap-around.
  const auto count = [&text](std::size_t begin, std::size_t end, int& value) {
    const auto [stop, error] = std::from_chars(text.data() + begin, text.data() + end, value);
    return begin < end && std::isdigit(static_cast<unsigned char>(text[begin])) != 0 &&
           error == std::errc() && stop == text.data() + end;
  };
  int k = 0, n = 0;
  if (slash == std::string::npos || !count(0, slash, k) || !count(slash + 1, text.size(), n)) {
    throw std::invalid_argument(fmt::format(
        "--shard {} is invalid: expected K/N, e.g. 0/4 (shard K of N, 0 <= K < N)", text));
  }
  if (n < 1 || k >= n) {
    throw std::invalid_argument(fmt::format(
        "--shard = {} is invalid: expected K/N with N >= 1 shards and 0 <= K < N", text));
  }
  return {k, n};
}

bool SplitsRun(const std::string& text) {
  return !text.empty() && ParseShard(text) != std::pair<int, int>(0, 1);
}

void RequireShardForResume(const CLI::App& cmd, bool sharded, const char* what) {
  for (const char* flag : {"--resume", "--checkpoint-seconds"}) {
    if (cmd.count(flag) > 0 && !sharded) {
      throw std::invalid_argument(fmt::format(
          "{} is invalid without --shard K/N, N >= 2: expected it only for a shard of the {} (a "
          "whole {} is not checkpointed)",
          flag, what, what));
    }
  }
}

bool IsStandardOutput(const std::string& path) {
  if (path == "-") return true;
  struct stat file = {};
  struct stat out = {};
  return !path.empty() && ::stat(path.c_str(), &file) == 0 && ::fstat(STDOUT_FILENO, &out) == 0 &&
         file.st_dev == out.st_dev && file.st_ino == out.st_ino;
}

void RequireOutputApartFromJson(const std::string& output, const char* option, bool json) {
  if (!json || !IsStandardOutput(output)) return;
  throw std::invalid_argument(fmt::format(
      "{} {} with --json is invalid: both would be written to standard output, one after the "
      "other: expected {} FILE, another file than standard output, or no {}",
      option, output, option, option));
}

void UseStrictValues(CLI::App& app) {
  for (CLI::Option* option : app.get_options()) {
    const std::string type = option->get_type_name();
    if (type == "FLOAT" || type == kFloatOrInf || type == kPhase) {
      option->transform(NumberText(option->get_name(), type == kFloatOrInf, type == kPhase));
    } else if ((type == "INT" || type == "UINT") && !HasValidator(option, kIntegerValidator)) {
      option->transform(IntegerText(option->get_name(), type == "UINT" ? 0 : INT_MIN, INT_MAX, ""));
    } else if (option->get_items_expected_min() > 0) {
      option->check(NonEmptyText(option->get_name()));
    }
  }
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) {
    UseStrictValues(*sub);
  }
}

CLI::Option* Bounded(CLI::Option* option, std::int64_t lo, std::int64_t hi) {
  return option->transform(
      IntegerText(option->get_name(), lo, hi, fmt::format("in [{}, {}]", lo, hi)));
}

namespace {

// `requested` threads capped by capsubot::CapThreads, with a note (naming `who`) when lowered.
int CapThreads(int requested, const std::string& who) {
  const int cap = capsubot::CapThreads(requested);
  if (cap == requested) return requested;
  const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  if (LaunchedRank() != 0) return cap;  // under mpirun: said once, by rank 0
  fmt::print(stderr,
             "{}: note: --threads {} lowered to {} ({} per core on {} cores: more only adds "
             "overhead)\n",
             who, requested, cap, kThreadsPerCore, cores);
  return cap;
}

}  // namespace

CLI::Option* AddThreadsOption(CLI::App& cmd, int& threads, const std::string& help) {
  const std::string who = "capsubot " + cmd.get_name();
  return cmd.add_option("--threads", threads, help)
      ->capture_default_str()
      ->transform(CLI::Validator(
          [who](std::string& text) {
            try {
              const auto n = static_cast<int>(ParseInteger(text, "--threads", INT_MIN, INT_MAX));
              if (n < 0) {
                return fmt::format(
                    "--threads = {} is invalid: expected 1 <= threads (0: all cores)", text);
              }
              text = std::to_string(CapThreads(n, who));
              return std::string();
            } catch (const std::invalid_argument& e) {
              return std::string(e.what());
            }
          },
          "", kIntegerValidator));
}

}  // namespace capsubot::app
