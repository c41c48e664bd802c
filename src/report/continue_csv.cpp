// The CSV table of `capsubot continue -o` (docs/continuation.md).

#include "capsubot/report/continue_csv.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <sstream>
#include <vector>

#include "capsubot/io/io.hpp"

namespace capsubot::text {
namespace {

// The columns every row has after its parameters, for rows whose motions have at most
// `columns` multipliers.
std::string MotionHeader(std::size_t columns) {
  std::string h = "x,u,v,psi,period,impacts_right,impacts_left,mean_velocity,spectral_radius";
  for (std::size_t k = 1; k <= columns; ++k) {
    h += ",mu" + std::to_string(k) + "_re,mu" + std::to_string(k) + "_im";
  }
  return h;
}

void MotionCells(std::ostream& out, const PeriodicMotion& m, std::size_t columns) {
  out << FormatNumber(m.state.x) << ',' << FormatNumber(m.state.u) << ',' << FormatNumber(m.state.v)
      << ',' << FormatNumber(m.state.psi) << ',' << m.period << ',' << m.impacts_right << ','
      << m.impacts_left << ',' << FormatNumber(m.mean_velocity) << ','
      << FormatNumber(m.spectral_radius);
  for (std::size_t k = 0; k < columns; ++k) {
    if (k < m.multipliers.size()) {
      out << ',' << FormatNumber(m.multipliers[k].real()) << ','
          << FormatNumber(m.multipliers[k].imag());
    } else {
      out << ",,";
    }
  }
  out << ',' << (m.stable ? 1 : 0);
}

template <class Point>
std::size_t MostMultipliers(const std::vector<Point>& points) {
  std::size_t columns = 0;
  for (const Point& p : points) columns = std::max(columns, p.motion.multipliers.size());
  return columns;
}

CsvTable BranchTable(const Branch& b, const std::string& name) {
  const std::size_t columns = MostMultipliers(b.points);
  std::ostringstream out;
  out << name << ',' << MotionHeader(columns) << ",stable,label\n";
  for (const BranchPoint& p : b.points) {
    out << FormatNumber(p.parameter) << ',';
    MotionCells(out, p.motion, columns);
    out << ',' << p.label << '\n';
  }
  return {out.str(), b.points.size()};
}

CsvTable CurveTable(const Curve& c, const std::string& name, const std::string& name2) {
  const std::size_t columns = MostMultipliers(c.points);
  std::ostringstream out;
  out << name << ',' << name2 << ',' << MotionHeader(columns) << ",stable,condition\n";
  for (const CurvePoint& p : c.points) {
    out << FormatNumber(p.parameter) << ',' << FormatNumber(p.parameter2) << ',';
    MotionCells(out, p.motion, columns);
    out << ',' << FormatNumber(p.condition) << '\n';
  }
  return {out.str(), c.points.size()};
}

}  // namespace

CsvTable ContinueJobCsv(const ContinueJobResult& r) {
  if (r.follow) {
    const Curve& c = r.follow->curve;
    return c.status == ContinuationStatus::kOk ? CurveTable(c, r.param, r.follow->param2)
                                               : CsvTable{};
  }
  return r.branch.status == ContinuationStatus::kOk ? BranchTable(r.branch, r.param) : CsvTable{};
}

std::string ContinueCsvWritten(const ContinueJobResult& result, const CsvTable& table,
                               const std::string& path) {
  return fmt::format("  written        {} {}points to {}\n", table.rows,
                     result.follow ? "curve " : "", path);
}

}  // namespace capsubot::text
