#pragma once
// The parts of a force as a front end reads them (ForceText) and what each means
// (ForceSettings): the harmonic force's A, c and phi0, a Fourier force's coefficients and a
// pulse's levels and switching phases as comma lists, and the force's kind. ForceSpec
// (model/force_spec.hpp) builds the force from the parts given.

#include <string>

#include "capsubot/job/setting_table.hpp"
#include "capsubot/numerics/not_computed.hpp"

namespace capsubot {

struct ForceText {
  double A = kNaN;       ///< amplitude of the harmonic force; NaN: not given
  double c = kNaN;       ///< mean force; NaN: not given
  double phi0 = kNaN;    ///< motor phase at phi = 0; NaN: not given
  std::string sin;       ///< "b1,b2,...": the Fourier force's sine coefficients
  std::string cos;       ///< "a1,a2,...": its cosine coefficients
  std::string waveform;  ///< "sine", "fourier" or "pulse"; "": the kind of the parts given
  std::string levels;    ///< "L1,L2,...": a pulse force's levels
  std::string switches;  ///< "s1,s2,...": its switching phases
};

/// A, c, phi0, sin, cos, waveform, levels, switches: their meaning and rules.
const SettingTable<ForceText>& ForceSettings();

}  // namespace capsubot
