#include "capsubot/job/force_settings.hpp"

namespace capsubot {

const SettingTable<ForceText>& ForceSettings() {
  using F = ForceText;
  static const SettingTable<ForceText> table = {
      {"A", &F::A,
       "amplitude A >= 0 of the force F = A sin(phi + phi0) + c, in units of (m1+m2) omega^2 L "
       "(required unless {sin}/{cos} are given)"},
      {"c", &F::c, "mean force c of F (same unit); a directed orbit needs c > 0"},
      {"phi0", &F::phi0,
       "motor phase phi0 [rad] at the impact: F(phi) = A sin(phi + phi0) + c with phi = 0 at "
       "the impact (required for the harmonic force; default 0 for a Fourier force); a number "
       "or a multiple of pi (pi, -pi/2, 2*pi)"},
      {"sin", &F::sin,
       "Fourier force instead of A: sine coefficients b_1,...,b_K of F = c + sum_k (a_k cos "
       "k(phi+phi0) + b_k sin k(phi+phi0))"},
      {"cos", &F::cos,
       "cosine coefficients a_1,...,a_K of the Fourier force (as many as {sin}; default all 0)"},
      {"waveform", &F::waveform,
       "the force's kind: sine ({A}, {c}, {phi0}), fourier ({sin}, {cos}, {c}) or pulse "
       "({levels}, {switches}); default: the kind of the parts given"},
      {"levels", &F::levels,
       "pulse force, which takes no {c}: levels L_1,...,L_N (1 <= N <= 16) of G(s) = L_j for s in "
       "[s_j, s_j+1), "
       "F(phi) = G(phi + phi0)"},
      {"switches", &F::switches,
       "pulse force: switching phases s_1 < ... < s_N in [0, 2 pi) [rad] of the motor phase, one "
       "per level"}};
  return table;
}

}  // namespace capsubot
