// The trajectory of a one-impact orbit as CSV rows.

#include "capsubot/report/orbit_csv.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "capsubot/io/io.hpp"

namespace capsubot::text {

void WriteOrbitTrajectoryCsv(std::ostream& out, const Orbit& orbit,
                             const OrbitTrajectoryOptions& options) {
  options.Validate();
  if (!orbit.ok()) {
    throw std::invalid_argument(
        fmt::format("the orbit's trajectory is invalid: no orbit ({})", StatusName(orbit.status)));
  }
  out << "phi,x,u,v\n";
  for (std::int64_t i = 0; i < options.samples; ++i) {
    const double phi = kTau * i / (options.samples - 1);
    out << FormatNumber(phi) << ',' << FormatNumber(orbit.x(phi)) << ','
        << FormatNumber(orbit.dx(phi)) << ',' << FormatNumber(orbit.v(phi)) << '\n';
  }
}

}  // namespace capsubot::text
