#include "capsubot/cli/strict_values.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <stdexcept>
#include <thread>

#include "capsubot/cluster/ranks.hpp"
#include "capsubot/io/io.hpp"
#include "capsubot/model/forcing.hpp"
#include "capsubot/model/limits.hpp"

namespace capsubot::cli {

namespace {

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

}  // namespace capsubot::cli
