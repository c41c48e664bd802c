#pragma once
// A force as a user describes it (docs/model.md sections 2 and 15): the harmonic force
// A sin(phi + phi0) + c by its amplitude, a Fourier series by its coefficients, or a pulse
// force by its levels and switching phases, with the impact phase phi0 given or left to a
// command that solves for it. The command line and the
// Python module build their forces here, with the same rules and messages.

#include <optional>
#include <string>
#include <vector>

#include "capsubot/model/forcing.hpp"
#include "capsubot/model/setting_names.hpp"

namespace capsubot {

struct ForceSpec {
  std::optional<double> A;     ///< amplitude of the harmonic force (not with sin)
  std::optional<double> c;     ///< mean force (required, except for a pulse force: not with it)
  std::optional<double> phi0;  ///< impact phase [rad]; absent: 0 where the phase is solved for
  std::optional<std::vector<double>> cos, sin;  ///< Fourier coefficients a_k, b_k (cos needs sin)
  /// "sine" (A, c), "fourier" (sin, cos, c) or "pulse" (levels, switches); absent: the kind
  /// the parts given name.
  std::optional<std::string> waveform = std::nullopt;
  std::optional<std::vector<double>> levels = std::nullopt;  ///< the pulse force's levels L_1..L_N
  std::optional<std::vector<double>> switches =
      std::nullopt;  ///< its switching phases s_1..s_N [rad]

  /// The force. Throws std::invalid_argument naming what is missing or contradictory: A with
  /// sin, cos without sin, an empty series, no A and no sin, no c, (with `need_phase`) no phi0,
  /// an unknown waveform, parts of another waveform, a pulse force's bad levels or switches
  /// (Forcing::Pulse) or its c (the levels give the mean).
  /// Messages name the parameters (the fields A, c, phi0, sin, cos, waveform, levels, switches)
  /// in the front end's `names` (none: the fields themselves, the Python module's keywords).
  Forcing Build(bool need_phase = true, const FlagNames& names = {}) const;
};

/// Throws std::invalid_argument "a pulse force is invalid for <what>: ..." for a pulse force:
/// the analytic one-impact orbit (solve, orbits, P1-P3, sweeps of it) needs a smooth force.
void RefusePulse(const Forcing& forcing, const std::string& what);

/// A series of coefficients `name` (symbol a or b), when given, has 1 to kMaxHarmonics terms:
/// throws std::invalid_argument "sin = [] is invalid: ..." for an empty one.
void RequireSeriesTerms(const std::string& name, const char* symbol,
                        const std::optional<std::vector<double>>& terms);

}  // namespace capsubot
