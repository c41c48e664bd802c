#pragma once
// The robot's own options: the force's parts (A, c, phi0, the Fourier and pulse lists, the
// waveform) and the parameters T0, e with the gait's margins, declared from the library's tables.

#include <CLI/CLI.hpp>
#include <vector>

#include "capsubot/job/force_settings.hpp"
#include "capsubot/model/forcing.hpp"
#include "capsubot/model/gait_requirements.hpp"
#include "capsubot/model/params.hpp"
#include "capsubot/model/setting_names.hpp"

namespace capsubot::cli {

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

}  // namespace capsubot::cli
