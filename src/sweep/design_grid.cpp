#include "capsubot/sweep/design_grid.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "capsubot/numerics/not_computed.hpp"
#include "sweep/grid_run.hpp"
#include "sweep/sweep_rows.hpp"

namespace capsubot {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Bumped whenever the bytes of a design grid change for the same options (invalidates
// checkpoints).
constexpr int kFormatVersion = 3;

// What a design grid may vary: the name (the design's setting), the domain and where the value
// goes. A new input is one row here and one enumerator.
struct DesignRule {
  DesignParameter parameter;
  const char* name;
  ParameterDomain domain;
  void (*set)(DesignInput& in, double value);
};

constexpr DesignRule kRules[] = {
    {DesignParameter::kM1,
     "m1",
     {0.0, true, kInf, false, "shell masses m1 > 0 [kg]"},
     [](DesignInput& in, double v) { in.m1 = v; }},
    {DesignParameter::kL,
     "L",
     {0.0, true, kInf, false, "gaps L > 0 [m]"},
     [](DesignInput& in, double v) { in.L = v; }},
    {DesignParameter::kMu,
     "mu",
     {0.0, true, kInf, false, "friction coefficients mu > 0"},
     [](DesignInput& in, double v) { in.mu = v; }},
    {DesignParameter::kGravity,
     "g",
     {0.0, true, kInf, false, "gravities g > 0 [m/s^2]"},
     [](DesignInput& in, double v) { in.g = v; }},
    {DesignParameter::kRestitution,
     "e",
     {0.0, false, 1.0, false, "restitutions 0 <= e <= 1"},
     [](DesignInput& in, double v) { in.e = v; }},
    {DesignParameter::kForceAmplitude,
     "force-amplitude",
     {0.0, false, kInf, false, "motor force amplitudes >= 0 [N]"},
     [](DesignInput& in, double v) { in.force.amplitude = v; }},
    {DesignParameter::kForceBias,
     "force-bias",
     {0.0, false, kInf, false, "mean motor forces >= 0 [N]"},
     [](DesignInput& in, double v) { in.force.bias = v; }},
    {DesignParameter::kFrequency,
     "frequency",
     {0.0, true, kInf, false, "frequencies f > 0 [Hz]"},
     [](DesignInput& in, double v) { in.frequency_min = in.frequency_max = v; }},
    {DesignParameter::kM2,
     "m2",
     {0.0, true, kInf, false, "inner masses m2 > 0 [kg]"},
     [](DesignInput&, double) {}},  // not an input field: the point's fixed m2 (PointInput)
    {DesignParameter::kMargin,
     "margin",
     {0.0, false, 0.5, true, "margins 0 <= margin < 0.5"},
     [](DesignInput& in, double v) { in.margin = v; }},
    {DesignParameter::kMarginStroke,
     "margin-stroke",
     {0.0, false, 0.5, true, "stroke margins 0 <= margin-stroke < 0.5"},
     [](DesignInput& in, double v) { in.margin_stroke = v; }},
    {DesignParameter::kStickMargin,
     "stick-margin",
     {0.0, false, 1.0, true, "stick margins 0 <= stick-margin < 1"},
     [](DesignInput& in, double v) { in.stick_margin = v; }},
    // Infinity: no stability requirement.
    {DesignParameter::kRhoMax,
     "rho-max",
     {0.0, true, kInf, false, "spectral radius bounds rho-max > 0 (inf: no bound)", true},
     [](DesignInput& in, double v) { in.rho_max = v; }},
};

const DesignRule& RuleOf(DesignParameter parameter) {
  for (const DesignRule& r : kRules) {
    if (r.parameter == parameter) return r;
  }
  return kRules[0];  // unreachable: every enumerator has a row
}

std::string Names() {
  std::vector<const char*> names;
  for (const DesignRule& r : kRules) names.push_back(r.name);
  return fmt::format("{}", fmt::join(names, ", "));
}

// Exact text of a double for the description (hexadecimal: no rounding at all).
std::string Hex(double value) { return fmt::format("{:a}", value); }

std::string HexList(const std::vector<double>& values) {
  std::vector<std::string> items;
  for (double v : values) items.push_back(Hex(v));
  return fmt::format("{}", fmt::join(items, ":"));
}

// One line that determines the bytes of the file, stored in its checkpoint.
std::string Description(const DesignGridOptions& o, const std::string& header) {
  std::string lines = header;
  std::replace(lines.begin(), lines.end(), '\n', '\x1f');  // the description is one line
  std::string d = fmt::format("design-grid format={} header={}", kFormatVersion, lines);
  for (const DesignGridAxis& axis : o.axes) {
    d += fmt::format(" grid={}:{}", axis.name(), static_cast<int>(axis.spacing));
    d += axis.spacing == GridSpacing::kList
             ? ":" + HexList(axis.values)
             : fmt::format(":{}:{}:{}", Hex(axis.lo), Hex(axis.hi), axis.n);
  }
  const DesignInput& in = o.input;
  d += fmt::format(
      " m1={} L={} mu={} g={} e={} amplitude={} bias={} cos={} sin={} f={}:{} m2={}:{} margin={} "
      "margin_stroke={} stick_margin={} rho_max={} scan_points={}",
      Hex(in.m1), Hex(in.L), Hex(in.mu), Hex(in.g), Hex(in.e), Hex(in.force.amplitude),
      Hex(in.force.bias), HexList(in.force.cos), HexList(in.force.sin), Hex(in.frequency_min),
      Hex(in.frequency_max), Hex(in.m2_min), Hex(in.m2_max), Hex(in.margin), Hex(in.margin_stroke),
      Hex(in.stick_margin), Hex(in.rho_max), in.scan_points);
  return d;
}

}  // namespace

const char* DesignParameterName(DesignParameter parameter) { return RuleOf(parameter).name; }

void DesignGridAxis::Validate() const { Check(ToString(), RuleOf(parameter).domain); }

std::string DesignGridAxis::column() const {
  if (parameter == DesignParameter::kM2) return "m2_kg";
  if (parameter == DesignParameter::kFrequency) return "frequency_hz";
  return name();
}

DesignGridAxis ParseDesignGridAxis(const std::string& spec) {
  const std::string name = GridSpecName(spec);
  for (const DesignRule& r : kRules) {
    if (name != r.name) continue;
    DesignGridAxis axis;
    axis.parameter = r.parameter;
    static_cast<GridValues&>(axis) = ParseGridValues(spec, r.domain);
    return axis;
  }
  throw std::invalid_argument(fmt::format(
      "grid {} is invalid: unknown parameter '{}': expected one of {}", spec, name, Names()));
}

std::int64_t DesignGridOptions::Points() const {
  std::int64_t n = 1;
  for (const DesignGridAxis& axis : axes) n *= axis.size();
  return axes.empty() ? 0 : n;
}

DesignInput DesignGridOptions::PointInput(std::int64_t point, double& m2) const {
  DesignInput in = input;
  m2 = kNaN;
  for (std::size_t i = 0; i < axes.size(); ++i) {
    const double value = RowMajorValue(axes, point, i);
    if (axes[i].parameter == DesignParameter::kM2) m2 = value;
    RuleOf(axes[i].parameter).set(in, value);
  }
  return in;
}

void DesignGridOptions::Validate() const {
  input.Validate();
  if (axes.empty()) {
    throw std::invalid_argument(
        "grid is missing: expected at least one axis (name=lo:hi:n, name=lo:hi:n:log or "
        "name=v1,v2,...)");
  }
  std::vector<std::int64_t> sizes;
  std::string specs;
  for (std::size_t i = 0; i < axes.size(); ++i) {
    axes[i].Validate();
    for (std::size_t j = 0; j < i; ++j) {
      if (axes[j].parameter == axes[i].parameter) {
        throw std::invalid_argument(
            fmt::format("grid {} is invalid: parameter {} already has a grid ({}): expected each "
                        "parameter at most once",
                        axes[i].ToString(), axes[i].name(), axes[j].ToString()));
      }
    }
    if (axes[i].parameter == DesignParameter::kForceAmplitude && input.force.fourier()) {
      throw std::invalid_argument(
          fmt::format("grid {} is invalid with a Fourier motor force: expected the harmonic force "
                      "F_N = A_N sin(omega t + phase) + c_N, whose amplitude the grid varies",
                      axes[i].ToString()));
    }
    sizes.push_back(axes[i].size());
    specs += (specs.empty() ? "" : " ") + axes[i].ToString();
  }
  CheckGridPoints(sizes, specs);
  // The rules of DesignInput bound each input apart: its smallest and largest value on the
  // grid are valid, so every point is.
  for (const DesignGridAxis& axis : axes) {
    for (const double value : {axis.Min(), axis.Max()}) {
      DesignInput in = input;
      RuleOf(axis.parameter).set(in, value);
      try {
        in.Validate();
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(fmt::format("grid {} is invalid: at {} = {}: {}",
                                                axis.ToString(), axis.name(), value, e.what()));
      }
    }
  }
  if (columns.empty() || !row) {
    throw std::invalid_argument("columns are missing: expected the result columns and their row");
  }
  for (const DesignGridAxis& axis : axes) {
    if (std::find(columns.begin(), columns.end(), axis.column()) != columns.end()) {
      throw std::invalid_argument(
          fmt::format("columns are invalid: {} is the column of grid {}: expected each column "
                      "once (the grid's value)",
                      axis.column(), axis.ToString()));
    }
  }
  ValidateFile(Points());
}

BlockComputeFactory DesignGridBlocks(const DesignGridOptions& o) {
  return [&o]() -> BlockCompute {
    return [&o](std::int64_t begin, std::int64_t end, std::string& out) {
      for (std::int64_t i = begin; i < end; ++i) {
        const std::int64_t point = o.shard + i * o.shards;
        double m2 = kNaN;
        const DesignInput in = o.PointInput(point, m2);
        {
          detail::RowBuffer cells(out);  // the grid's values straight into `out`
          for (std::size_t a = 0; a < o.axes.size(); ++a) {
            detail::AppendNumber(cells, RowMajorValue(o.axes, point, a));
            cells.push_back(',');
          }
        }
        out += o.row(DesignGait(in, m2));
        out += '\n';
      }
      return end - begin;
    };
  };
}

SweepSummary RunDesignGrid(const DesignGridOptions& o, const SweepProgressCallback& progress,
                           const BlockBackend& backend) {
  o.Validate();
  std::vector<std::string> columns;
  for (const DesignGridAxis& axis : o.axes) columns.push_back(axis.column());
  columns.insert(columns.end(), o.columns.begin(), o.columns.end());
  detail::GridRun run;
  run.output = o.output;
  run.header = detail::GridHeader(o.comments, o.shard, o.shards, o.Points(), columns);
  run.description = Description(o, run.header);
  run.resume = o.resume;
  run.checkpoint_seconds = o.checkpoint_seconds;
  run.points = detail::ShardCount(o.Points(), o.shard, o.shards);
  run.threads = WorkerThreads(o.threads);
  // A point is one design (a robot: ~1 ms; a search over m2 or f: ~0.1 s): one per block.
  run.block_points = [](std::int64_t points, int threads) {
    return BalancedBlock(points, threads, 1);
  };
  return detail::RunGridRows(run, DesignGridBlocks(o), progress, backend);
}

}  // namespace capsubot
