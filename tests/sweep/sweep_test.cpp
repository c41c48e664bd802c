// The sweep engine (capsubot/sweep.hpp): rows equal the single-point library calls, the file is
// byte-identical for any thread count and block size, an interrupted sweep leaves no output
// and resumes to the same bytes without recomputing finished points, bad options are named.

#include "capsubot/sweep.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/file.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "capsubot/io.hpp"
#include "capsubot/optimize_phase.hpp"
#include "capsubot/robot_orbits.hpp"
#include "capsubot/stability.hpp"
#include "capsubot/validity.hpp"
#include "sweep/sweep_rows.hpp"

namespace capsubot {
namespace {

// A fresh directory per test for the output files.
class TempDir {
 public:
  TempDir() {
    char pattern[] = "/tmp/capsubot_sweep_test_XXXXXX";
    path_ = ::mkdtemp(pattern);
  }
  ~TempDir() { std::system(("rm -rf '" + path_ + "'").c_str()); }
  std::string File(const std::string& name) const { return path_ + "/" + name; }

 private:
  std::string path_;
};

bool Exists(const std::string& path) { return ::access(path.c_str(), F_OK) == 0; }

std::string ReadFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> Split(const std::string& text, char sep) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(text);
  while (std::getline(in, part, sep)) parts.push_back(part);
  if (!text.empty() && text.back() == sep) parts.emplace_back();
  return parts;
}

// The CSV as rows of cells; rows[0] is the header.
std::vector<std::vector<std::string>> ReadCsv(const std::string& path) {
  std::vector<std::vector<std::string>> rows;
  for (const std::string& line : Split(ReadFile(path), '\n')) {
    if (!line.empty()) rows.push_back(Split(line, ','));
  }
  return rows;
}

std::string Violations(const Validity& v) {
  std::string s;
  for (const std::string& name : v.ViolationNames()) s += (s.empty() ? "" : ";") + name;
  return s;
}

// The cells phi1 ... violations of a solution, as the sweep must print them.
std::vector<std::string> SolutionCells(const Solution& s) {
  const Orbit& o = s.orbit;
  const Validity& v = s.validity;
  return {FormatNumber(o.phi1),   FormatNumber(o.alpha), FormatNumber(o.u),
          FormatNumber(o.v_plus), FormatNumber(o.I),     FormatNumber(o.v_mean),
          FormatNumber(v.x_min),  FormatNumber(v.x_max), v.valid() ? "1" : "0",
          Violations(v)};
}

SweepOptions PaperPhaseSweep(const std::string& output, int n) {
  SweepOptions o;
  o.grid.axes = {ParseGridAxis("phi0=-pi:pi:" + std::to_string(n))};
  o.forcing = Forcing::Harmonic(0.5, 0.5, 0.0);  // the paper's example c = A = T0/2
  o.output = output;
  return o;
}

TEST(SweepColumns, FollowTheDocumentedLayout) {
  SweepOptions o = PaperPhaseSweep("x.csv", 3);
  EXPECT_EQ(detail::SweepHeaderLine(o),
            "phi0,phi1,alpha,u,v_plus,I,v_mean,x_min,x_max,valid,violations\n");
  o.stability = true;
  EXPECT_EQ(detail::SweepHeaderLine(o),
            "phi0,phi1,alpha,u,v_plus,I,v_mean,x_min,x_max,valid,violations,spectral_radius,"
            "stable\n");
  o.grid.axes = {ParseGridAxis("A=0:1:2"), ParseGridAxis("c=0:1:2")};
  o.optimize_phi0 = true;
  EXPECT_EQ(detail::SweepHeaderLine(o),
            "A,c,phi0,phi1,alpha,u,v_plus,I,v_mean,x_min,x_max,valid,violations,"
            "spectral_radius,stable,status\n");
  o.optimize_phi0 = false;
  o.stability = false;
  o.grid.axes = {ParseGridAxis("alpha=0.1:0.9:2")};
  EXPECT_EQ(detail::SweepHeaderLine(o),
            "robot_alpha,orbits,orbit,phi0,phi1,alpha,u,v_plus,I,v_mean,x_min,x_max,valid,"
            "violations\n");
}

TEST(SweepNumbers, AreByteIdenticalToFormatNumber) {
  for (double x : {0.0, -0.0, 1.0, -2.944899971002, 1e-300, 6.02214076e23, 0.1, 1.0 / 3.0, 5e-324,
                   1.7976931348623157e308, -std::nan("")}) {
    detail::RowBuffer buffer;
    detail::AppendNumber(buffer, x);
    EXPECT_EQ(std::string(buffer.data(), buffer.size()), FormatNumber(x)) << x;
  }
  // Random doubles over the whole exponent range, subnormals and integers included.
  std::mt19937_64 rng(20211);
  for (int i = 0; i < 100000; ++i) {
    std::uint64_t bits = rng();
    double x = 0.0;
    std::memcpy(&x, &bits, sizeof x);
    if (i % 3 == 0) x = std::ldexp(static_cast<double>(bits >> 11), -52) * 1e3;  // ordinary
    if (i % 7 == 0) x = std::round(x);
    detail::RowBuffer buffer;
    detail::AppendNumber(buffer, x);
    ASSERT_EQ(std::string(buffer.data(), buffer.size()), FormatNumber(x)) << i;
  }
}

TEST(Sweep, PhaseRowsEqualSolveAtEveryPoint) {
  TempDir dir;
  const SweepOptions o = PaperPhaseSweep(dir.File("phase.csv"), 37);
  const SweepSummary summary = RunSweep(o);
  EXPECT_EQ(summary.points, 37);
  EXPECT_EQ(summary.rows, 37);
  const auto rows = ReadCsv(o.output);
  ASSERT_EQ(rows.size(), 38u);
  int valid = 0, invalid = 0;
  for (int i = 0; i < 37; ++i) {
    const double phi0 = o.grid.axes[0].Value(i);
    const Solution s = Solve(Forcing::Harmonic(0.5, 0.5, phi0), Params{});
    std::vector<std::string> expected = {FormatNumber(phi0)};
    for (const std::string& cell : SolutionCells(s)) expected.push_back(cell);
    EXPECT_EQ(rows[i + 1], expected) << "row " << i + 1;
    (s.validity.valid() ? valid : invalid)++;
  }
  EXPECT_GT(invalid, 0);  // the row layout is exercised with violations too
}

TEST(Sweep, TwoDimensionalGridRunsTheLastAxisFastest) {
  TempDir dir;
  SweepOptions o;
  o.grid.axes = {ParseGridAxis("A=0.1:0.4:4"), ParseGridAxis("c=0.05:0.3:3")};
  o.forcing = Forcing::Harmonic(1.0, 1.0, -2.0);
  o.params.T0 = 0.8;
  o.output = dir.File("ac.csv");
  RunSweep(o);
  const auto rows = ReadCsv(o.output);
  ASSERT_EQ(rows.size(), 13u);
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 3; ++j) {
      const double A = o.grid.axes[0].Value(i), c = o.grid.axes[1].Value(j);
      const Solution s = Solve(Forcing::Harmonic(A, c, -2.0), o.params);
      std::vector<std::string> expected = {FormatNumber(A), FormatNumber(c)};
      for (const std::string& cell : SolutionCells(s)) expected.push_back(cell);
      EXPECT_EQ(rows[1 + 3 * i + j], expected) << "A = " << A << ", c = " << c;
    }
  }
}

TEST(Sweep, ModelParameterAxesReachSolve) {
  TempDir dir;
  SweepOptions o;
  o.grid.axes = {ParseGridAxis("e=0.2:1:3"), ParseGridAxis("margin=0:0.1:2")};
  o.forcing = Forcing::Harmonic(0.3, 0.1, -2.5);
  o.params.T0 = 0.5;
  o.output = dir.File("em.csv");
  RunSweep(o);
  const auto rows = ReadCsv(o.output);
  ASSERT_EQ(rows.size(), 7u);
  for (int k = 0; k < 6; ++k) {
    Params p;
    p.T0 = 0.5;
    p.e = o.grid.Value(k, 0);
    p.margin = o.grid.Value(k, 1);
    const auto cells = SolutionCells(Solve(o.forcing, p));
    EXPECT_EQ(std::vector<std::string>(rows[k + 1].begin() + 2, rows[k + 1].end()), cells) << k;
  }
}

TEST(Sweep, FileIsByteIdenticalForAnyThreadCountAndBlockSize) {
  TempDir dir;
  SweepOptions o = PaperPhaseSweep(dir.File("ref.csv"), 1001);
  o.threads = 1;
  o.block_points = 2000;
  RunSweep(o);
  const std::string reference = ReadFile(o.output);
  ASSERT_GT(reference.size(), 1000u);
  for (int threads : {1, 2, 3, 8}) {
    for (int block : {1, 7, 64}) {
      o.output = dir.File("t" + std::to_string(threads) + "b" + std::to_string(block) + ".csv");
      o.threads = threads;
      o.block_points = block;
      const SweepSummary summary = RunSweep(o);
      EXPECT_EQ(summary.threads, threads);
      EXPECT_TRUE(ReadFile(o.output) == reference) << threads << " threads, blocks of " << block;
    }
  }
}

// Thrown by a progress callback to interrupt a sweep the way a crash would (mid-way).
struct Interrupt {};

TEST(Sweep, InterruptedSweepLeavesNoOutputAndResumesToTheSameBytes) {
  TempDir dir;
  SweepOptions o = PaperPhaseSweep(dir.File("full.csv"), 2000);
  o.threads = 2;
  o.block_points = 50;
  RunSweep(o);
  const std::string reference = ReadFile(o.output);

  o.output = dir.File("cut.csv");
  o.checkpoint_seconds = 0.0;  // checkpoint after every block
  std::int64_t reached = 0;
  EXPECT_THROW(RunSweep(o,
                        [&](const SweepProgress& p) {
                          reached = p.points_done;
                          if (p.points_done >= 700) throw Interrupt{};
                        }),
               Interrupt);
  EXPECT_EQ(reached, 700);
  EXPECT_FALSE(Exists(o.output)) << "a killed sweep must not leave a file under the final name";
  EXPECT_TRUE(Exists(o.output + ".partial"));
  EXPECT_TRUE(Exists(o.output + ".checkpoint"));

  o.resume = true;
  o.threads = 3;  // another thread count and block size: same bytes
  o.block_points = 33;
  std::int64_t resumed = -1, first_done = -1;
  const SweepSummary summary = RunSweep(o, [&](const SweepProgress& p) {
    if (first_done < 0) first_done = p.points_done;
    resumed = p.points_resumed;
  });
  EXPECT_EQ(summary.points_resumed, 700);  // the finished rows were not recomputed
  EXPECT_EQ(resumed, 700);
  EXPECT_EQ(first_done, 733);
  EXPECT_EQ(summary.rows, 2000 - 700);
  EXPECT_TRUE(ReadFile(o.output) == reference);
  EXPECT_FALSE(Exists(o.output + ".partial"));
  EXPECT_FALSE(Exists(o.output + ".checkpoint"));
}

TEST(Sweep, ResumeDropsRowsWrittenAfterTheLastCheckpoint) {
  TempDir dir;
  SweepOptions o = PaperPhaseSweep(dir.File("full.csv"), 300);
  RunSweep(o);
  const std::string reference = ReadFile(o.output);
  o.output = dir.File("cut.csv");
  o.block_points = 10;
  o.checkpoint_seconds = 1e9;  // only the initial checkpoint (header) exists
  EXPECT_THROW(RunSweep(o,
                        [](const SweepProgress& p) {
                          if (p.points_done >= 100) throw Interrupt{};
                        }),
               Interrupt);
  // Simulate a row torn by the kill after the checkpoint.
  std::ofstream(o.output + ".partial", std::ios::app) << "0.123,garbage";
  o.resume = true;
  const SweepSummary summary = RunSweep(o);
  EXPECT_EQ(summary.points_resumed, 0);
  EXPECT_TRUE(ReadFile(o.output) == reference);
}

TEST(Sweep, ResumeWithoutCheckpointStartsFromTheBeginning) {
  TempDir dir;
  SweepOptions o = PaperPhaseSweep(dir.File("a.csv"), 50);
  o.resume = true;
  const SweepSummary summary = RunSweep(o);
  EXPECT_EQ(summary.points_resumed, 0);
  EXPECT_EQ(ReadCsv(o.output).size(), 51u);
}

TEST(Sweep, ResumeRefusesTheCheckpointOfAnotherSweep) {
  TempDir dir;
  SweepOptions o = PaperPhaseSweep(dir.File("a.csv"), 500);
  o.block_points = 10;
  o.checkpoint_seconds = 0.0;
  EXPECT_THROW(RunSweep(o,
                        [](const SweepProgress& p) {
                          if (p.points_done >= 100) throw Interrupt{};
                        }),
               Interrupt);
  o.resume = true;
  o.params.T0 = 1.5;  // another sweep
  try {
    RunSweep(o);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("--resume: checkpoint " + o.output +
                                         ".checkpoint is invalid for this sweep"),
              std::string::npos)
        << e.what();
  }
  EXPECT_TRUE(Exists(o.output + ".checkpoint"));  // kept: the right options may still resume
}

TEST(Sweep, UnwritableOutputIsAnIoErrorNamingTheFile) {
  SweepOptions o = PaperPhaseSweep("/nonexistent_dir_capsubot/x.csv", 5);
  try {
    RunSweep(o);
    FAIL() << "expected IoError";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("--output /nonexistent_dir_capsubot/x.csv: cannot "
                                         "create /nonexistent_dir_capsubot/x.csv.partial"),
              std::string::npos)
        << e.what();
  }
}

TEST(Sweep, RefusesAnOutputAnotherSweepIsWriting) {
  TempDir dir;
  const SweepOptions o = PaperPhaseSweep(dir.File("busy.csv"), 5);
  // Hold the lock a running sweep would hold on the partial file.
  const int fd = ::open((o.output + ".partial").c_str(), O_RDWR | O_CREAT, 0644);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);
  try {
    RunSweep(o);
    ADD_FAILURE() << "expected IoError";
  } catch (const IoError& e) {
    EXPECT_EQ(
        std::string(e.what()),
        "--output " + o.output + ": another capsubot sweep is writing " + o.output + ".partial");
  }
  ::close(fd);
  EXPECT_FALSE(Exists(o.output));
  RunSweep(o);  // once the lock is gone the sweep runs
  EXPECT_TRUE(Exists(o.output));
}

template <class Fn>
std::string InvalidArgumentMessage(const Fn& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(SweepOptions, RejectsBadCombinationsWithAMessage) {
  SweepOptions o = PaperPhaseSweep("x.csv", 5);
  o.optimize_phi0 = true;
  EXPECT_NE(InvalidArgumentMessage([&] {
              o.Validate();
            }).find("--optimize phi0 with --grid phi0 is invalid"),
            std::string::npos);
  o = PaperPhaseSweep("x.csv", 5);
  o.grid.axes = {ParseGridAxis("A=0:1:3")};
  o.forcing = Forcing::Fourier(0.2, {0.1, 0.0}, {0.3, 0.1}, 0.0);
  EXPECT_NE(InvalidArgumentMessage([&] {
              o.Validate();
            }).find("--grid A is invalid with a Fourier force"),
            std::string::npos);
  o = PaperPhaseSweep("x.csv", 5);
  o.threads = -1;
  EXPECT_EQ(InvalidArgumentMessage([&] { o.Validate(); }),
            "--threads = -1 is invalid: expected 1 <= threads <= 1024 (0: all cores)");
  o = PaperPhaseSweep("", 5);
  EXPECT_NE(InvalidArgumentMessage([&] { o.Validate(); }).find("--output is missing"),
            std::string::npos);
  o = PaperPhaseSweep("x.csv", 5);
  o.grid.axes = {ParseGridAxis("alpha=0.2:0.5:3")};
  o.optimize_phi0 = true;
  EXPECT_NE(InvalidArgumentMessage([&] {
              o.Validate();
            }).find("--optimize phi0 with --grid alpha is invalid"),
            std::string::npos);
}

TEST(Sweep, StabilityColumnsEqualComputeStability) {
  TempDir dir;
  SweepOptions o = PaperPhaseSweep(dir.File("st.csv"), 61);
  o.stability = true;
  RunSweep(o);
  const auto rows = ReadCsv(o.output);
  ASSERT_EQ(rows.size(), 62u);
  int with_orbit = 0;
  for (int i = 0; i < 61; ++i) {
    const Solution s = Solve(Forcing::Harmonic(0.5, 0.5, o.grid.axes[0].Value(i)), o.params);
    ASSERT_EQ(rows[i + 1].size(), 13u);
    if (!s.orbit.ok()) {
      EXPECT_EQ(rows[i + 1][11], "");
      EXPECT_EQ(rows[i + 1][12], "");
      continue;
    }
    ++with_orbit;
    const Stability st = ComputeStability(s.orbit);
    EXPECT_EQ(rows[i + 1][11], FormatNumber(st.spectral_radius));
    EXPECT_EQ(rows[i + 1][12], st.stable ? "1" : "0");
  }
  EXPECT_GT(with_orbit, 0);
}

TEST(Sweep, OptimizedPhaseRowsEqualOptimizePhase) {
  TempDir dir;
  SweepOptions o;
  o.grid.axes = {ParseGridAxis("c=0.05:0.25:3")};
  o.forcing = Forcing::Harmonic(0.2, 0.0, 0.0);
  o.params.T0 = 0.5;
  o.optimize_phi0 = true;
  o.phase.scan_points = 90;
  o.output = dir.File("opt.csv");
  RunSweep(o);
  const auto rows = ReadCsv(o.output);
  ASSERT_EQ(rows.size(), 4u);
  for (int i = 0; i < 3; ++i) {
    const double c = o.grid.axes[0].Value(i);
    const OptimizeResult r = OptimizePhase(Forcing::Harmonic(0.2, c, 0.0), o.params, o.phase);
    std::vector<std::string> expected = {FormatNumber(c),
                                         FormatNumber(r.solution.orbit.forcing.phi0())};
    for (const std::string& cell : SolutionCells(r.solution)) expected.push_back(cell);
    expected.emplace_back(OptimizeStatusName(r.status));
    EXPECT_EQ(rows[i + 1], expected) << "c = " << c;
  }
}

TEST(Sweep, RobotModeWritesOneRowPerOrbitOfThatMassRatio) {
  TempDir dir;
  SweepOptions o;
  o.grid.axes = {ParseGridAxis("alpha=0.05:0.95:19")};
  o.forcing = Forcing::Harmonic(0.5, 0.5, 0.0);
  o.output = dir.File("robot.csv");
  RunSweep(o);
  const auto rows = ReadCsv(o.output);
  std::size_t r = 1;
  int points_without = 0, orbits_seen = 0;
  for (int i = 0; i < 19; ++i) {
    const double alpha = o.grid.axes[0].Value(i);
    const std::vector<Solution> orbits = FindRobotOrbits(o.forcing, o.params, alpha);
    if (orbits.empty()) {
      ASSERT_LT(r, rows.size());
      std::vector<std::string> expected(14, "");
      expected[0] = FormatNumber(alpha);
      expected[1] = "0";
      EXPECT_EQ(rows[r++], expected) << "alpha = " << alpha;
      ++points_without;
      continue;
    }
    for (std::size_t k = 0; k < orbits.size(); ++k) {
      ASSERT_LT(r, rows.size());
      std::vector<std::string> expected = {FormatNumber(alpha), std::to_string(orbits.size()),
                                           std::to_string(k + 1),
                                           FormatNumber(orbits[k].orbit.forcing.phi0())};
      for (const std::string& cell : SolutionCells(orbits[k])) expected.push_back(cell);
      EXPECT_EQ(rows[r++], expected) << "alpha = " << alpha << ", orbit " << k + 1;
      ++orbits_seen;
    }
  }
  EXPECT_EQ(r, rows.size());
  EXPECT_GT(orbits_seen, 0);
  EXPECT_GT(points_without, 0);  // both layouts are exercised (no orbit for alpha >= 0.4)
}

}  // namespace
}  // namespace capsubot
