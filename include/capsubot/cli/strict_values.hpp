#pragma once
// The one syntax of the values of options: numbers as capsubot::ParseNumber reads them, integers
// in their range, phases with multiples of pi, no empty value; and --threads, capped.

#include <CLI/CLI.hpp>
#include <cstdint>
#include <string>

namespace capsubot::cli {

/// Gives every numeric option of `app` and of its subcommands the one number syntax of
/// capsubot::ParseNumber (floating-point options) or ParseInteger (integer options: the
/// range of Bounded, else that of int). Call once, after every option is added. An option
/// is numeric by its CLI11 type name (FLOAT, INT, UINT): keep those names on numeric options.
/// Options of type kFloatOrInf also accept "inf" (e.g. --rho-max inf: no bound). Every other
/// option that takes a value refuses an empty one (`-o ""`, `--shard ""`): never read as absent.
void UseStrictValues(CLI::App& app);

/// CLI11 type name of a floating-point option that also accepts "inf".
inline constexpr const char* kFloatOrInf = "FLOAT|inf";
/// A phase beyond one turn is valid (up to kMaxPhase, where the refusal says the same), but
/// often a value meant in degrees: prints the one-line note "capsubot: note: <name> = <text> is
/// <value / 2 pi> turns: phases are in radians" on stderr.
void NotePhaseInRadians(const std::string& name, const std::string& text, double value);

/// Type name of a phase option (UseStrictValues reads it with ParsePhase: 0.5, pi, -pi/2).
inline constexpr const char* kPhase = "PHASE";

/// A size option: its integer value must lie in [lo, hi], checked while parsing (before any
/// work), the range named in the message and shown in --help.
CLI::Option* Bounded(CLI::Option* option, std::int64_t lo, std::int64_t hi);

/// Adds --threads (worker threads, 0: all cores) to `cmd`, with `help`. The one rule of every
/// command: a negative value is refused while parsing; a value above kThreadsPerCore x the
/// cores (at most kMaxThreads: the library's capsubot::CapThreads, limits.hpp) is lowered to
/// it with a note on stderr naming the command (said once under mpirun).
CLI::Option* AddThreadsOption(CLI::App& cmd, int& threads,
                              const std::string& help =
                                  "worker threads (0: all cores); the output does not depend "
                                  "on it");

}  // namespace capsubot::cli
