#pragma once
// A force as a user describes it (docs/model.md section 2): the harmonic force
// A sin(phi + phi0) + c by its amplitude, or a Fourier series by its coefficients, with the
// impact phase phi0 given or left to a command that solves for it. The command line and the
// Python module build their forces here, with the same rules and messages.

#include <optional>
#include <string>
#include <vector>

#include "capsubot/model/forcing.hpp"

namespace capsubot {

struct ForceSpec {
  std::optional<double> A;     ///< amplitude of the harmonic force (not with sin)
  double c = 0.0;              ///< mean force
  std::optional<double> phi0;  ///< impact phase [rad]; absent: 0 where the phase is solved for
  std::optional<std::vector<double>> cos, sin;  ///< Fourier coefficients a_k, b_k (cos needs sin)

  /// The force. Throws std::invalid_argument naming what is missing or contradictory: A with
  /// sin, cos without sin, an empty series, no A and no sin, or (with `need_phase`) no phi0.
  /// Messages name the parameters with `prefix`: "" (A, sin: the Python module) or "--" (--A,
  /// --sin: the command line).
  Forcing Build(bool need_phase = true, const std::string& prefix = "") const;
};

/// A series of coefficients `name` (symbol a or b), when given, has 1 to kMaxHarmonics terms:
/// throws std::invalid_argument "sin = [] is invalid: ..." for an empty one.
void RequireSeriesTerms(const std::string& name, const char* symbol,
                        const std::optional<std::vector<double>>& terms);

}  // namespace capsubot
