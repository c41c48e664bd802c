// The map of basins of attraction as a gnuplot script.

#include <fmt/format.h>

#include <algorithm>

#include "capsubot/report/basins_text.hpp"
#include "capsubot/report/text_format.hpp"

namespace capsubot::text {
namespace {

constexpr int kPlotColors = 10;  // attractors drawn in their own colour; the rest in grey
const char* const kColors[kPlotColors] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd",
                                          "#8c564b", "#e377c2", "#17becf", "#bcbd22", "#7f7f7f"};

// `text` with every "phi" typeset as gnuplot's Greek letter (enhanced text mode).
std::string TypesetPhi(std::string text) {
  const std::string phi = "{/Symbol f}";
  for (std::size_t at = text.find("phi"); at != std::string::npos;
       at = text.find("phi", at + phi.size())) {
    text.replace(at, 3, phi);
  }
  return text;
}

// The title: the force, then the robot (a line each: a Fourier force is long), in the typeset
// notation of the project's figures; "\n" is a line break in gnuplot's double-quoted string.
std::string Title(const BasinsJobResult& r) {
  const AttractorsJobOptions& o = r.map.options;
  const auto* plane = std::get_if<VelocityPlane>(&r.plane);
  return fmt::format("Basins of attraction: {}\\nT_0 = {:g}, e = {:g}, {{/Symbol a}} = {:.6g}{}",
                     TypesetPhi(ForceFormula(o.robot.forcing)), o.robot.params.T0, o.robot.params.e,
                     o.robot.alpha,
                     plane ? fmt::format(", start phase {{/Symbol y}} = {:g}", plane->psi) : "");
}

}  // namespace

std::string BasinsPlotScript(const BasinsJobResult& r, const std::string& png) {
  const Attractors& a = r.map.attractors;
  const auto* plane = std::get_if<VelocityPlane>(&r.plane);
  const int max_period = r.map.options.attractor.motion.max_period;
  std::string s = "set terminal pngcairo size 1000,800 font ',12'\n";
  s += fmt::format("set output '{}'\n", png);
  s += "set datafile separator ','\nset datafile columnheaders\n";
  s += fmt::format("set title \"{}\"\n", Title(r));
  s += "set xlabel 'start position x_0 of the inner body [L]'\n";
  s += plane ? "set ylabel 'start relative velocity u_0 [{/Symbol w}L]'\n"
             : "set ylabel 'start forcing phase {/Symbol y} [rad]'\n";
  s += "set xrange [0:1]\n";
  s += plane ? fmt::format("set yrange [{}:{}]\n", plane->u_min, plane->u_max)
             : "set yrange [0:2*pi]\n";
  const int colors = std::min<int>(kPlotColors, static_cast<int>(a.attractors.size()));
  s += fmt::format("set cbrange [0.5:{}.5]\nunset colorbox\n", kPlotColors + 1);
  s += "set palette maxcolors 11 defined (";
  for (int k = 0; k < kPlotColors; ++k) {
    s += fmt::format("{} '{}', ", k + 1, k < colors ? kColors[k] : "#cccccc");
  }
  s += "11 '#cccccc')\n";
  s += "set key outside below left Left reverse noenhanced\n";
  s += fmt::format(
      "plot '{}' using 1:2:(column('attractor') > {} ? {} : column('attractor')) "
      "with image notitle",
      std::get<WholeStartMap>(r.map.options.run).output, kPlotColors, kPlotColors + 1);
  for (int k = 0; k < colors; ++k) {
    s += fmt::format(", NaN with boxes fs solid fc rgb '{}' title \"{}: {}\"", kColors[k], k + 1,
                     BasinLegend(a.attractors[static_cast<std::size_t>(k)], max_period));
  }
  if (static_cast<int>(a.attractors.size()) > colors) {
    s += ", NaN with boxes fs solid fc rgb '#cccccc' title 'other attractors'";
  }
  return s + "\n";
}

}  // namespace capsubot::text
