#pragma once
// Pieces shared by the subcommands: the command record, the force and model options.

#include <CLI/CLI.hpp>
#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "capsubot/job/force_settings.hpp"
#include "capsubot/model/forcing.hpp"
#include "capsubot/model/gait_requirements.hpp"
#include "capsubot/model/limits.hpp"
#include "capsubot/model/params.hpp"
#include "capsubot/model/setting_names.hpp"
#include "capsubot/numerics/not_computed.hpp"

namespace capsubot::app {

/// A subcommand: its parser and what to run once the command line is parsed. `run` returns
/// the exit status; it throws std::invalid_argument or IoError for bad input (exit status 2).
struct Command {
  CLI::App* parser = nullptr;
  std::function<int()> run;
  /// Whether the command as parsed distributes its work over the ranks of an MPI job
  /// (ranks.hpp); empty: it never does, and main refuses it under mpirun with P > 1.
  std::function<bool()> distributed;
};

/// The force: the paper's A sin(phi + phi0) + c, or a Fourier series c + sum (a_k cos + b_k sin).
struct ForcingOptions {
  ForceText parts;  ///< the parts as given, the comma lists as text (parsed by Build)
  CLI::Option* A_option = nullptr;
  CLI::Option* c_option = nullptr;
  CLI::Option* phi0_option = nullptr;
  CLI::Option* fourier_option = nullptr;

  /// The coefficients b_1..b_K of --sin (empty when not given); throws std::invalid_argument
  /// naming the option for an element that is not a number.
  std::vector<double> Sines() const;
  /// The coefficients a_1..a_K of --cos (empty when not given), as Sines().
  std::vector<double> Cosines() const;
  /// The force the options describe; throws std::invalid_argument naming what is missing.
  /// With `need_phase` false, phi0 may be absent (it is then 0: a command that solves for it).
  Forcing Build(bool need_phase = true) const;
};

/// The flags of the force's parts (ForceText's fields).
const FlagNames& ForceFlags();

/// Adds --A, --c, --phi0 (with `with_phase`), --sin, --cos, --waveform, --levels, --switches
/// to `cmd`, from the library's table (ForceSettings).
void AddForcingOptions(CLI::App& cmd, ForcingOptions& options, bool with_phase = true);

/// Adds --T0, --e and (given `margins`) the margins --margin, --margin-stroke, --stick-margin to
/// `cmd` (their defaults: the values in `params` and `margins`).
void AddParamsOptions(CLI::App& cmd, Params& params, Margins* margins = nullptr);

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

/// Whether output path `path` is standard output: "-", or a path to the file, pipe or terminal
/// standard output writes to (/dev/stdout, or the file it is redirected to).
bool IsStandardOutput(const std::string& path);

/// Refuses (std::invalid_argument) `output` of `option` ("-o") on standard output
/// (IsStandardOutput) together with --json (`json`), which prints its object there too: the
/// two would be mixed in one stream ("-o - with --json is invalid: ...").
void RequireOutputApartFromJson(const std::string& output, const char* option, bool json);

/// Runs `run`; a std::invalid_argument, WriteError or IoError it throws is thrown again (the
/// same type) WithFlagNames(names): the library's field names as the flags that set them.
int RunNamingFlags(const FlagNames& names, const std::function<int()>& run);

/// --shard "K/N" -> (K, N): decimal digits, K and N at most INT_MAX, 0 <= K < N; throws
/// std::invalid_argument naming the option, its value and the rule.
std::pair<int, int> ParseShard(const std::string& text);

/// Whether --shard `text` splits the run into N >= 2 shards: false when not given ("") and
/// for 0/1, the one shard of the whole run, which writes the files of the run without
/// --shard. Throws ParseShard's errors.
bool SplitsRun(const std::string& text);

/// Refuses --resume or a given --checkpoint-seconds of `cmd` when not `sharded` (N >= 2)
/// (std::invalid_argument): only a shard is checkpointed, not the whole `what` ("map").
void RequireShardForResume(const CLI::App& cmd, bool sharded, const char* what);

}  // namespace capsubot::app
