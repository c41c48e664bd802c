// The trajectory of a one-impact orbit as CSV (orbit_csv): the grid of its options over one
// period, read back against what the orbit must be at its ends (docs/model.md section 4: just
// after the impact the inner body is at the right wall with u = -e u_impact and v = v_plus; just
// before the next one it is back there with u = u_impact); bad grids and a missing orbit are
// refused before anything is written.

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "capsubot/model/limits.hpp"
#include "capsubot/report/orbit_csv.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::InvalidArgumentMessage;

// The orbit's closed form evaluated at phi = 0 and tau, against the same closed form written
// with the shortest round-trip digits and read back: only the rounding of the evaluation.
constexpr double kClosedFormTol = 1e-12;

// A valid stable orbit (the second example of `capsubot solve --help`).
Orbit SmallOrbit() { return ComputeOrbit(Forcing::Harmonic(0.05, 0.02, -2.842), Params{0.1, 0.5}); }

std::vector<std::vector<double>> ReadRows(std::istream& in) {
  std::vector<std::vector<double>> rows;
  std::string line;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::istringstream cells(line);
    std::string cell;
    while (std::getline(cells, cell, ',')) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

TEST(OrbitCsvReport, RunsFromJustAfterTheImpactToJustBeforeTheNext) {
  const Orbit orbit = SmallOrbit();
  ASSERT_TRUE(orbit.ok());
  OrbitTrajectoryOptions grid;
  grid.samples = 5;
  std::ostringstream out;
  text::WriteOrbitTrajectoryCsv(out, orbit, grid);
  std::istringstream in(out.str());
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header, "phi,x,u,v");
  const std::vector<std::vector<double>> rows = ReadRows(in);
  ASSERT_EQ(rows.size(), 5u);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    ASSERT_EQ(rows[i].size(), 4u) << "row " << i;
    EXPECT_NEAR(rows[i][0], kTau * static_cast<double>(i) / 4.0, kClosedFormTol) << "row " << i;
  }
  const double e = 0.5;
  EXPECT_NEAR(rows.front()[1], 1.0, kClosedFormTol);
  EXPECT_NEAR(rows.front()[2], -e * orbit.u, kClosedFormTol);
  EXPECT_NEAR(rows.front()[3], orbit.v_plus, kClosedFormTol);
  EXPECT_NEAR(rows.back()[1], 1.0, kClosedFormTol);
  EXPECT_NEAR(rows.back()[2], orbit.u, kClosedFormTol);
}

TEST(OrbitCsvReport, RefusesABadGridAndAMissingOrbitBeforeWriting) {
  OrbitTrajectoryOptions grid;
  grid.samples = kMaxTrajectoryRows + 1;
  std::ostringstream out;
  EXPECT_EQ(InvalidArgumentMessage([&] { text::WriteOrbitTrajectoryCsv(out, SmallOrbit(), grid); }),
            "samples = " + std::to_string(kMaxTrajectoryRows + 1) +
                " is invalid: expected 2 <= samples <= " + std::to_string(kMaxTrajectoryRows));
  // c < 0 with a weak force: no positive mean force, no orbit.
  const Orbit none = ComputeOrbit(Forcing::Harmonic(0.05, -0.02, 0.0), Params{0.1, 0.5});
  ASSERT_FALSE(none.ok());
  EXPECT_EQ(
      InvalidArgumentMessage(
          [&] { text::WriteOrbitTrajectoryCsv(out, none, OrbitTrajectoryOptions{}); }),
      std::string("the orbit's trajectory is invalid: no orbit (") + StatusName(none.status) + ")");
  EXPECT_TRUE(out.str().empty());
}

}  // namespace
}  // namespace capsubot
