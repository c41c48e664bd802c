// A sweep's CSV file drawn by gnuplot.

#include "capsubot/report/sweep_plot.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace capsubot::text {
namespace {

// The columns drawn when none is named, in order of preference: the speed of the motion from
// rest, of the orbit, the step per period.
const char* const kDefaultColumns[] = {"mean_velocity", "v_mean", "I"};

// `text` as a gnuplot single-quoted string (a quote is written twice).
std::string Quoted(const std::string& text) {
  std::string out = "'";
  for (const char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

// Whether the column holds numbers only (the others are words: statuses, violated conditions).
bool Numeric(const std::string& column) {
  return column != "status" && column != "violations" && column != "loss";
}

}  // namespace

std::string SweepPlotColumn(const SweepOptions& sweep, const std::string& column) {
  const std::vector<std::string> columns = SweepColumns(sweep);
  if (sweep.output == "-") {
    throw std::invalid_argument(
        "plot with output = - is invalid: expected a file (-o FILE), which the plot reads");
  }
  if (sweep.shards > 1) {
    throw std::invalid_argument(fmt::format(
        "plot with shard = {}/{} is invalid: expected the whole grid (draw the merged file)",
        sweep.shard, sweep.shards));
  }
  if (sweep.grid.axes.size() > 2) {
    throw std::invalid_argument(fmt::format(
        "plot over a grid of {} axes is invalid: expected one axis (a curve) or two (a map)",
        sweep.grid.axes.size()));
  }
  if (column.empty()) {
    for (const char* c : kDefaultColumns) {
      if (std::find(columns.begin(), columns.end(), c) != columns.end()) return c;
    }
  }
  std::vector<std::string> numeric;
  std::copy_if(columns.begin(), columns.end(), std::back_inserter(numeric), Numeric);
  if (std::find(numeric.begin(), numeric.end(), column) == numeric.end()) {
    throw std::invalid_argument(
        fmt::format("plot_column = {} is invalid: expected a numeric column of this sweep: {}",
                    column.empty() ? "(none)" : column, fmt::join(numeric, ", ")));
  }
  return column;
}

std::string SweepPlotScript(const SweepOptions& sweep, const std::string& column,
                            const std::string& png) {
  const auto& axes = sweep.grid.axes;
  std::string s = "set terminal pngcairo size 1000,700 font ',12'\n";
  s += fmt::format("set output {}\n", Quoted(png));
  s += "set datafile separator ','\nset datafile columnheaders\nset grid\nset key off\n";
  s += "set termoption noenhanced\n";
  const GridAxis& x = axes.back();
  s += fmt::format("set xlabel {}\n", Quoted(x.name()));
  if (x.spacing == GridSpacing::kLog) s += "set logscale x\n";
  const std::string file = Quoted(sweep.output);
  if (axes.size() == 1) {
    s += fmt::format("set ylabel {}\n", Quoted(column));
    s += fmt::format("set title {}\n",
                     Quoted(fmt::format("capsubot sweep: {} against {}", column, x.name())));
    return s + fmt::format("plot {} using {}:{} with linespoints pt 7 ps 0.6\n", file,
                           Quoted(x.name()), Quoted(column));
  }
  const GridAxis& y = axes.front();
  s += fmt::format("set ylabel {}\nset cblabel {}\n", Quoted(y.name()), Quoted(column));
  if (y.spacing == GridSpacing::kLog) s += "set logscale y\n";
  s += fmt::format("set title {}\n", Quoted(fmt::format("capsubot sweep: {} over {} and {}", column,
                                                        x.name(), y.name())));
  // Squares about one grid step wide: 60 points per side fill the plot at size 1.
  const double side = static_cast<double>(std::max(x.size(), y.size()));
  const double size = std::clamp(60.0 / side, 0.3, 3.0);
  return s + fmt::format("plot {} using {}:{}:{} with points pt 5 ps {:g} palette\n", file,
                         Quoted(x.name()), Quoted(y.name()), Quoted(column), size);
}

}  // namespace capsubot::text
