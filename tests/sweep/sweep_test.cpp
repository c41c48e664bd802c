// The sweep engine (capsubot/sweep/sweep.hpp): rows equal the single-point library calls, the file
// is byte-identical for any thread count and block size, an interrupted sweep leaves no output and
// resumes to the same bytes without recomputing finished points, bad options are named.

#include "capsubot/sweep/sweep.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/file.h>
#include <unistd.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "capsubot/io/io.hpp"
#include "capsubot/optimize/optimize_forcing.hpp"
#include "capsubot/optimize/optimize_fourier.hpp"
#include "capsubot/optimize/optimize_phase.hpp"
#include "capsubot/orbit/robot_orbits.hpp"
#include "capsubot/orbit/stability.hpp"
#include "capsubot/orbit/validity.hpp"
#include "capsubot/reach/optimize_reach.hpp"
#include "capsubot/sweep/sweep_merge.hpp"
#include "sweep/sweep_file.hpp"
#include "sweep/sweep_rows.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::ReadFile;

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

std::vector<std::string> Split(const std::string& text, char sep) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(text);
  while (std::getline(in, part, sep)) parts.push_back(part);
  if (!text.empty() && text.back() == sep) parts.emplace_back();
  return parts;
}

// The CSV as rows of cells, as a reader that skips '#' lines sees it; rows[0] is the header.
std::vector<std::vector<std::string>> ReadCsv(const std::string& path) {
  std::vector<std::vector<std::string>> rows;
  for (const std::string& line : Split(ReadFile(path), '\n')) {
    if (!line.empty() && line[0] != '#') rows.push_back(Split(line, ','));
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
  EXPECT_EQ(detail::SweepHeaderLines(o),
            "phi0,phi1,alpha,u,v_plus,I,v_mean,x_min,x_max,valid,violations\n");
  o.stability = true;
  EXPECT_EQ(detail::SweepHeaderLines(o),
            "phi0,phi1,alpha,u,v_plus,I,v_mean,x_min,x_max,valid,violations,spectral_radius,"
            "lambda_re,lambda_im,stable,loss\n");
  o.grid.axes = {ParseGridAxis("A=0:1:2"), ParseGridAxis("c=0:1:2")};
  o.optimize = SweepOptimize::kPhase;
  o.comments = {"made by a test", "second line"};
  EXPECT_EQ(detail::SweepHeaderLines(o),
            "# made by a test\n# second line\n"
            "A,c,phi0,phi1,alpha,u,v_plus,I,v_mean,x_min,x_max,valid,violations,"
            "spectral_radius,lambda_re,lambda_im,stable,loss,status\n");
  o.comments.clear();
  o.stability = false;
  o.grid.axes = {ParseGridAxis("T0=0.1,0.2"), ParseGridAxis("bound=0.05,0.1")};
  o.optimize = SweepOptimize::kForcing;
  EXPECT_EQ(detail::SweepHeaderLines(o),
            "T0,bound,A,c,phi0,phi1,alpha,u,v_plus,I,v_mean,x_min,x_max,valid,violations,"
            "status\n");
  o.optimize = SweepOptimize::kFourier;
  o.fourier.harmonics = 2;
  EXPECT_EQ(detail::SweepHeaderLines(o),
            "T0,bound,c,a1,a2,b1,b2,phi1,alpha,u,v_plus,I,v_mean,x_min,x_max,valid,violations,"
            "status\n");
  o.optimize = SweepOptimize::kNone;
  o.grid.axes = {ParseGridAxis("alpha=0.1:0.9:2")};
  EXPECT_EQ(detail::SweepHeaderLines(o),
            "robot_alpha,orbits,orbit,phi0,phi1,alpha,u,v_plus,I,v_mean,x_min,x_max,valid,"
            "violations\n");
}

// The rows go into the block's bytes: after what is there, through growths of the string
// (far past its first step of 4096 characters), and the string ends where the text does.
TEST(SweepRowBuffer, AppendsAfterTheBytesAndCutsThemToTheText) {
  std::string bytes = "kept,";
  std::string expected = bytes;
  constexpr int kRows = 2000;  // about 32,000 characters
  {
    detail::RowBuffer rows(bytes);
    for (int i = 0; i < kRows; ++i) {
      const double x = 0.1 * i;
      detail::AppendNumber(rows, x);
      rows.append(",cell,");
      rows.push_back('\n');
      expected += FormatNumber(x) + ",cell,\n";
    }
    EXPECT_EQ(rows.size(), expected.size());
    EXPECT_EQ(std::string(rows.data(), rows.size()), expected);
  }
  EXPECT_GT(expected.size(), 7u * 4096u);
  EXPECT_TRUE(bytes == expected) << "the string must end where the text ends";
}

TEST(SweepNumbers, AreShortestRoundTripAndEqualToFormatNumber) {
  const std::pair<double, const char*> exact[] = {
      {0.0, "0"},
      {-0.0, "-0"},
      {1.0, "1"},
      {0.1, "0.1"},
      {1.0 / 3.0, "0.3333333333333333"},
      {5e-324, "5e-324"},
      {1e22, "1e+22"},
      {1.7976931348623157e308, "1.7976931348623157e+308"},
      {-2.5e-5, "-2.5e-05"},
      {std::numeric_limits<double>::infinity(), "inf"},
      {std::nan(""), ""}};
  for (const auto& [x, text] : exact) {
    std::string bytes;
    detail::RowBuffer buffer(bytes);
    detail::AppendNumber(buffer, x);
    EXPECT_EQ(std::string(buffer.data(), buffer.size()), text);
    EXPECT_EQ(FormatNumber(x), text);
  }
  // Random doubles over the whole exponent range, subnormals and integers included: the text
  // reads back to the same double and is no longer than fmt's shortest form (an independent
  // implementation of shortest round-trip, Dragonbox).
  std::mt19937_64 rng(20211);
  int checked = 0;
  std::string bytes;
  detail::RowBuffer buffer(bytes);  // one buffer, reused as the sweep does
  for (int i = 0; i < 100000; ++i) {
    std::uint64_t bits = rng();
    double x = 0.0;
    std::memcpy(&x, &bits, sizeof x);
    if (i % 3 == 0) x = std::ldexp(static_cast<double>(bits >> 11), -52) * 1e3;  // ordinary
    if (i % 7 == 0) x = std::round(x);
    if (std::isnan(x)) continue;
    buffer.clear();
    detail::AppendNumber(buffer, x);
    const std::string text(buffer.data(), buffer.size());
    ASSERT_EQ(std::strtod(text.c_str(), nullptr), x) << text;
    const std::string shortest = fmt::format("{}", x);
    ASSERT_LE(text.size(), shortest.size()) << text << " vs " << shortest;
    ++checked;
  }
  EXPECT_GT(checked, 99000);
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
    Margins m;
    m.clearance = o.grid.Value(k, 1);
    const auto cells = SolutionCells(Solve(o.forcing, p, m));
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

// Interrupts a 500-point sweep after 100 points (checkpoint after every block).
SweepOptions InterruptedSweep(const TempDir& dir) {
  SweepOptions o = PaperPhaseSweep(dir.File("cut.csv"), 500);
  o.block_points = 10;
  o.checkpoint_seconds = 0.0;
  EXPECT_THROW(RunSweep(o,
                        [](const SweepProgress& p) {
                          if (p.points_done >= 100) throw Interrupt{};
                        }),
               Interrupt);
  o.resume = true;
  return o;
}

TEST(Sweep, ResumeRefusesTheCheckpointOfAnotherSweep) {
  TempDir dir;
  SweepOptions o = InterruptedSweep(dir);
  o.params.T0 = 1.5;  // another sweep
  try {
    RunSweep(o);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("resume: checkpoint " + o.output +
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
    EXPECT_NE(std::string(e.what()).find("output /nonexistent_dir_capsubot/x.csv: cannot "
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
    EXPECT_EQ(std::string(e.what()), "output " + o.output + ": another capsubot sweep is writing " +
                                         o.output + ".partial");
  }
  ::close(fd);
  EXPECT_FALSE(Exists(o.output));
  RunSweep(o);  // once the lock is gone the sweep runs
  EXPECT_TRUE(Exists(o.output));
}

TEST(SweepOptions, RejectsBadCombinationsWithAMessageNamingParametersNotFlags) {
  struct Bad {
    std::function<void(SweepOptions&)> change;
    std::string message;  // the whole message, or its beginning when it ends with "..."
  };
  const Bad cases[] = {
      {[](SweepOptions& o) { o.optimize = SweepOptimize::kPhase; },
       "grid phi0=-3.141592653589793:3.141592653589793:5 is invalid with optimize = phi0 "
       "(problem P1, the best impact phase phi0): expected a grid over A, c, T0, e, margin, "
       "ak, bk, rho_max, margin_stroke, stick_margin"},
      {[](SweepOptions& o) {
         o.grid.axes = {ParseGridAxis("A=0:1:3")};
         o.forcing = Forcing::Fourier(0.2, {0.1, 0.0}, {0.3, 0.1}, 0.0);
       },
       "grid A is invalid with a Fourier force..."},
      {[](SweepOptions& o) { o.threads = -1; },
       "threads = -1 is invalid: expected 1 <= threads <= 1024 (0: all cores)"},
      {[](SweepOptions& o) { o.output.clear(); }, "output is missing..."},
      {[](SweepOptions& o) {
         o.grid.axes = {ParseGridAxis("alpha=0.2:0.5:3")};
         o.optimize = SweepOptimize::kPhase;
       },
       "grid alpha=0.2:0.5:3 is invalid with optimize = phi0..."},
      {[](SweepOptions& o) {
         o.grid.axes = {ParseGridAxis("T0=0.05,0.2")};
         o.optimize = SweepOptimize::kForcing;
       },
       ""},  // accepted: the bound is T0 at each point
      {[](SweepOptions& o) {
         o.grid.axes = {ParseGridAxis("T0=0.05,0.2")};
         o.optimize = SweepOptimize::kForcing;
         o.design.gait.force_bound = 0.1;  // above the smallest T0
       },
       "force_bound = 0.1 is invalid..."},
      {[](SweepOptions& o) {
         o.grid.axes = {ParseGridAxis("T0=0.2,0.3"), ParseGridAxis("bound=0.1:0.25:4")};
         o.optimize = SweepOptimize::kFourier;
       },
       "force_bound = 0.25 is invalid..."},
      {[](SweepOptions& o) { o.grid.axes = {ParseGridAxis("bound=0.1,0.2")}; },
       "grid bound=0.1,0.2 is invalid with optimize = none..."},
      {[](SweepOptions& o) {
         o.grid.axes = {ParseGridAxis("rho_max=0.5,0.9")};
         o.optimize = SweepOptimize::kForcing;
       },
       ""},  // accepted: rho_max is the stability requirement (infinity: none)
      {[](SweepOptions& o) { o.comments = {"two\nlines"}; }, "comments are invalid..."},
      {[](SweepOptions& o) {
         o.grid.axes = {ParseGridAxis("T0=0.5,1")};
         o.optimize = SweepOptimize::kReach;
         o.reach.max_seconds = 20.0;  // a wall-clock limit would make rows machine-dependent
       },
       "reach.max_seconds = 20 is invalid with optimize = reach: expected infinity..."},
      {[](SweepOptions& o) {
         o.grid.axes = {ParseGridAxis("T0=0.5,1")};
         o.optimize = SweepOptimize::kReach;
         o.stability = true;
       },
       "stability = true is invalid with optimize = reach..."},
      {[](SweepOptions& o) { o.optimize = SweepOptimize::kReach; },
       "grid phi0=-3.141592653589793:3.141592653589793:5 is invalid with optimize = reach..."},
  };
  int checked = 0;
  for (const Bad& bad : cases) {
    SweepOptions o = PaperPhaseSweep("x.csv", 5);
    bad.change(o);
    const std::string message = testing::InvalidArgumentMessage([&] { o.Validate(); });
    const bool prefix =
        bad.message.size() > 3 && bad.message.compare(bad.message.size() - 3, 3, "...") == 0;
    if (prefix) {
      EXPECT_EQ(message.rfind(bad.message.substr(0, bad.message.size() - 3), 0), 0u) << message;
    } else {
      EXPECT_EQ(message, bad.message);
    }
    EXPECT_EQ(message.find("--"), std::string::npos)
        << "a library message names a flag: " << message;
    ++checked;
  }
  EXPECT_EQ(checked, 14);
  EXPECT_EQ(ParseSweepOptimize("forcing"), SweepOptimize::kForcing);
  EXPECT_EQ(testing::InvalidArgumentMessage([] { ParseSweepOptimize("phi1"); }),
            "optimize = phi1 is invalid: expected one of phi0, forcing, fourier, reach");
}

TEST(Sweep, StabilityColumnsEqualComputeStability) {
  TempDir dir;
  SweepOptions o = PaperPhaseSweep(dir.File("st.csv"), 61);
  o.stability = true;
  RunSweep(o);
  const auto rows = ReadCsv(o.output);
  ASSERT_EQ(rows.size(), 62u);
  int with_orbit = 0, stable = 0, unstable = 0;
  for (int i = 0; i < 61; ++i) {
    const Solution s = Solve(Forcing::Harmonic(0.5, 0.5, o.grid.axes[0].Value(i)), o.params);
    ASSERT_EQ(rows[i + 1].size(), 16u);
    const std::vector<std::string> cells(rows[i + 1].begin() + 11, rows[i + 1].end());
    if (!s.orbit.ok()) {
      EXPECT_EQ(cells, std::vector<std::string>(5, ""));
      continue;
    }
    ++with_orbit;
    const Stability st = ComputeStability(s.orbit);
    const std::vector<std::string> expected = {
        FormatNumber(st.spectral_radius), FormatNumber(st.multipliers[0].real()),
        FormatNumber(st.multipliers[0].imag()), st.stable ? "1" : "0",
        StabilityLossName(ClassifyLoss(st))};
    EXPECT_EQ(cells, expected) << "row " << i + 1;
    ++(st.stable ? stable : unstable);
  }
  EXPECT_GT(with_orbit, 0);
  EXPECT_GT(stable, 0);
  EXPECT_GT(unstable, 0);  // the paper's example has folds: the loss column is exercised
}

TEST(Sweep, OptimizedPhaseRowsEqualOptimizePhase) {
  TempDir dir;
  SweepOptions o;
  o.grid.axes = {ParseGridAxis("c=0.05:0.25:3")};
  o.forcing = Forcing::Harmonic(0.2, 0.0, 0.0);
  o.params.T0 = 0.5;
  o.optimize = SweepOptimize::kPhase;
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

// rho_max = inf in a grid list is no stability requirement: its rows are those of the sweep
// with the optimiser's default (OptimizeOptions::rho_max, infinite), written "inf" as the grid
// spec is; the file survives shards and merge byte for byte.
TEST(Sweep, RhoMaxInfinityInAListEqualsTheDefaultRunAndSurvivesMerge) {
  TempDir dir;
  SweepOptions o;
  o.grid.axes = {ParseGridAxis("c=0.05:0.25:3"), ParseGridAxis("rho_max=0.5,inf")};
  o.forcing = Forcing::Harmonic(0.2, 0.0, 0.0);
  o.params.T0 = 0.5;
  o.optimize = SweepOptimize::kPhase;
  o.phase.scan_points = 90;
  o.stability = true;
  o.output = dir.File("rho.csv");
  RunSweep(o);
  SweepOptions plain = o;
  plain.grid.axes = {o.grid.axes[0]};
  ASSERT_EQ(plain.phase.gait.rho_max, std::numeric_limits<double>::infinity());
  plain.output = dir.File("default.csv");
  RunSweep(plain);
  const auto rows = ReadCsv(o.output);
  const auto reference = ReadCsv(plain.output);
  ASSERT_EQ(rows.size(), 7u);
  ASSERT_EQ(reference.size(), 4u);
  int checked = 0, differ = 0;
  for (int i = 0; i < 3; ++i) {
    std::vector<std::string> row = rows[2 * i + 2];  // rho_max = inf
    EXPECT_EQ(row[1], "inf");
    row.erase(row.begin() + 1);
    EXPECT_EQ(row, reference[i + 1]) << "c = " << reference[i + 1][0];
    differ += rows[2 * i + 1][2] != row[1] ? 1 : 0;  // phi0 under rho_max = 0.5
    ++checked;
  }
  EXPECT_EQ(checked, 3);
  EXPECT_GE(differ, 1);  // the requirement rho_max = 0.5 binds somewhere: the test can fail
  std::vector<std::string> shards;
  for (int k = 0; k < 2; ++k) {
    SweepOptions shard = o;
    shard.shard = k;
    shard.shards = 2;
    shard.output = dir.File("rho" + std::to_string(k) + ".csv");
    RunSweep(shard);
    shards.push_back(shard.output);
  }
  MergeSweepShards(shards, dir.File("merged.csv"));
  EXPECT_EQ(ReadFile(dir.File("merged.csv")), ReadFile(o.output));
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
    const std::vector<Solution> orbits = FindRobotOrbits({o.forcing, o.params, alpha});
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

TEST(Sweep, ThreeGridSweepEqualsNestedLoopsOfSolve) {
  TempDir dir;
  SweepOptions o;
  // A linear, a list and a log axis: row-major, the first slowest.
  o.grid.axes = {ParseGridAxis("A=0.1:0.3:3"), ParseGridAxis("c=0.05,0.02,0.1"),
                 ParseGridAxis("e=0.25:1:3:log")};
  o.forcing = Forcing::Harmonic(1.0, 1.0, -2.6);
  o.params.T0 = 0.8;
  o.output = dir.File("three.csv");
  RunSweep(o);
  const auto rows = ReadCsv(o.output);
  ASSERT_EQ(rows.size(), 28u);
  const std::vector<double> cs = {0.05, 0.02, 0.1};
  const std::vector<double> es = {0.25, 0.5, 1.0};  // 0.25 * 2^k: exact on the log axis
  int r = 1, valid = 0;
  for (double A : {0.1, 0.2, 0.3}) {
    for (double c : cs) {
      for (double e : es) {
        Params p = o.params;
        p.e = e;
        const Solution s = Solve(Forcing::Harmonic(A, c, -2.6), p);
        std::vector<std::string> expected = {FormatNumber(A), FormatNumber(c), FormatNumber(e)};
        for (const std::string& cell : SolutionCells(s)) expected.push_back(cell);
        EXPECT_EQ(rows[r++], expected) << "A = " << A << ", c = " << c << ", e = " << e;
        valid += s.validity.valid();
      }
    }
  }
  EXPECT_EQ(r, 28);
  EXPECT_GT(valid, 0);
}

TEST(Sweep, FourierCoefficientGridsAddHarmonicsToTheForce) {
  TempDir dir;
  SweepOptions o;
  o.grid.axes = {ParseGridAxis("b2=0:0.04:3"), ParseGridAxis("a1=-0.02,0.02")};
  o.forcing = Forcing::Harmonic(0.2, 0.03, -2.8);
  o.output = dir.File("fourier.csv");
  RunSweep(o);
  const auto rows = ReadCsv(o.output);
  ASSERT_EQ(rows.size(), 7u);
  int checked = 0;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 2; ++j) {
      const double b2 = o.grid.axes[0].Value(i), a1 = o.grid.axes[1].Value(j);
      const Solution s = Solve(Forcing::Fourier(0.03, {a1, 0.0}, {0.2, b2}, -2.8), o.params);
      std::vector<std::string> expected = {FormatNumber(b2), FormatNumber(a1)};
      for (const std::string& cell : SolutionCells(s)) expected.push_back(cell);
      EXPECT_EQ(rows[1 + 2 * i + j], expected) << "b2 = " << b2 << ", a1 = " << a1;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 6);
}

// P2 at every point of a T0 grid: each row is what OptimizeForcing returns for that T0 (a
// reduced search budget keeps the test short; the sweep passes the same options).
TEST(Sweep, ForcingPerPointEqualsOptimizeForcing) {
  TempDir dir;
  SweepOptions o;
  o.grid.axes = {ParseGridAxis("T0=0.05,0.08,0.1,0.2,1")};
  o.optimize = SweepOptimize::kForcing;
  o.design.effort.starts = 2;
  o.design.hops = 2;
  o.stability = true;
  o.output = dir.File("p2.csv");
  RunSweep(o);
  const auto rows = ReadCsv(o.output);
  ASSERT_EQ(rows.size(), 6u);
  int found = 0;
  for (int i = 0; i < 5; ++i) {
    Params p = o.params;
    p.T0 = o.grid.axes[0].Value(i);
    const OptimizeResult r = OptimizeForcing(p, o.design);
    const Forcing& f = r.solution.orbit.forcing;
    std::vector<std::string> expected = {FormatNumber(p.T0), FormatNumber(f.amplitude()),
                                         FormatNumber(f.mean()), FormatNumber(f.phi0())};
    for (const std::string& cell : SolutionCells(r.solution)) expected.push_back(cell);
    const Stability st = ComputeStability(r.solution.orbit);
    for (const std::string& cell :
         {FormatNumber(st.spectral_radius), FormatNumber(st.multipliers[0].real()),
          FormatNumber(st.multipliers[0].imag()), std::string(st.stable ? "1" : "0"),
          std::string(StabilityLossName(ClassifyLoss(st)))}) {
      expected.push_back(cell);
    }
    expected.emplace_back(OptimizeStatusName(r.status));
    EXPECT_EQ(rows[i + 1], expected) << "T0 = " << p.T0;
    found += r.found();
  }
  EXPECT_EQ(found, 5);  // a valid gait at every T0
}

TEST(Sweep, FourierPerPointEqualsOptimizeFourier) {
  TempDir dir;
  SweepOptions o;
  o.grid.axes = {ParseGridAxis("e=0.5,1")};
  o.params.T0 = 0.1;
  o.optimize = SweepOptimize::kFourier;
  o.fourier.harmonics = 2;
  o.fourier.search.starts = 2;
  o.output = dir.File("p3.csv");
  RunSweep(o);
  const auto rows = ReadCsv(o.output);
  ASSERT_EQ(rows.size(), 3u);
  for (int i = 0; i < 2; ++i) {
    Params p = o.params;
    p.e = o.grid.axes[0].Value(i);
    const OptimizeResult r = OptimizeFourier(p, o.fourier);
    const Forcing f = r.solution.orbit.forcing.InImpactFrame();
    ASSERT_EQ(f.harmonics(), 2);
    std::vector<std::string> expected = {FormatNumber(p.e),    FormatNumber(f.mean()),
                                         FormatNumber(f.a(1)), FormatNumber(f.a(2)),
                                         FormatNumber(f.b(1)), FormatNumber(f.b(2))};
    for (const std::string& cell : SolutionCells(r.solution)) expected.push_back(cell);
    expected.emplace_back(OptimizeStatusName(r.status));
    EXPECT_EQ(rows[i + 1], expected) << "e = " << p.e;
  }
}

// The fastest motion from rest at every point of a T0 grid: each row is what OptimizeReach
// returns there, seeded by OptimizeForcing with the sweep's design options, as `capsubot
// optimize --problem reach` computes it (small budgets keep the test short; the sweep runs
// each point on one thread, the reference on all cores: the result must not depend on it).
TEST(Sweep, ReachPerPointEqualsOptimizeReachSeededByOptimizeForcing) {
  TempDir dir;
  SweepOptions o;
  o.grid.axes = {ParseGridAxis("T0=0.5,1")};
  o.optimize = SweepOptimize::kReach;
  o.design.gait.margins = RobustMargins();
  o.design.gait.rho_max = kRobustRhoMax;
  o.design.effort.starts = 2;
  o.design.hops = 1;
  o.reach.global_evaluations = 8;
  o.reach.local_evaluations = 4;
  o.reach.search.n_x = o.reach.search.n_psi = 2;
  o.reach.check.n_x = o.reach.check.n_psi = 2;
  o.threads = 2;
  o.output = dir.File("reach.csv");
  RunSweep(o);
  const auto rows = ReadCsv(o.output);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0], Split("T0,A,c,phi0,alpha,mean_velocity,seed_won,robust_to_settings,"
                           "max_relative_deviation,evaluations,seed_A,seed_c,seed_phi0,seed_alpha,"
                           "seed_I,seed_v_mean,seed_mean_velocity_from_rest,seed_reached,status",
                           ','));
  int found = 0;
  for (int i = 0; i < 2; ++i) {
    Params p = o.params;
    p.T0 = o.grid.axes[0].Value(i);
    ReachOptions ro = o.reach;
    ro.max_seconds = 1e6;  // never reached: the budgets stop the search
    ro.search.attractor.threads = ro.check.attractor.threads = 0;
    const ReachResult r = OptimizeReach(p, OptimizeForcing(p, o.design), ro);
    ASSERT_TRUE(r.seed.from_rest.checked) << "T0 = " << p.T0;
    const Orbit& so = r.seed.gait.solution.orbit;
    const std::vector<std::string> expected = {
        FormatNumber(p.T0),
        FormatNumber(r.forcing.amplitude()),
        FormatNumber(r.forcing.mean()),
        FormatNumber(r.forcing.phi0()),
        FormatNumber(r.alpha),
        FormatNumber(r.mean_velocity),
        r.seed_won ? "1" : "0",
        r.robust_to_settings ? "1" : "0",
        FormatNumber(r.spread.max_relative_deviation),
        std::to_string(r.evaluations),
        FormatNumber(so.forcing.amplitude()),
        FormatNumber(so.forcing.mean()),
        FormatNumber(so.forcing.phi0()),
        FormatNumber(so.alpha),
        FormatNumber(so.I),
        FormatNumber(so.v_mean),
        FormatNumber(r.seed.from_rest.attractors.mean_velocity),
        std::to_string(r.seed.from_rest.reached),
        OptimizeStatusName(r.status)};
    EXPECT_EQ(rows[i + 1], expected) << "T0 = " << p.T0;
    found += r.status == OptimizeStatus::kOk;
  }
  EXPECT_EQ(found, 2);  // a motion from rest at both T0
}

// A resume must not mix reach rows of other settings: every reach option that changes the rows
// is in the checkpoint's description; the thread count of the attractor search is not.
TEST(SweepCheckpoint, ReachDescriptionHoldsEveryReachOptionThatChangesTheRows) {
  SweepOptions o;
  o.grid.axes = {ParseGridAxis("T0=0.5,1")};
  o.optimize = SweepOptimize::kReach;
  o.output = "x.csv";
  const std::string base = detail::SweepDescription(o);
  const std::vector<std::function<void(SweepOptions&)>> changes = {
      [](SweepOptions& s) { s.reach.global_evaluations = 151; },
      [](SweepOptions& s) { s.reach.local_evaluations = 49; },
      [](SweepOptions& s) { s.reach.alpha = 0.5; },
      [](SweepOptions& s) { s.reach.search.n_x = 3; },
      [](SweepOptions& s) { s.reach.check.n_psi = 9; },
      [](SweepOptions& s) { s.reach.check.attractor.motion.transient = 201; },
      [](SweepOptions& s) { s.reach.max_spread = 0.02; },
      [](SweepOptions& s) { s.design.hops = 3; },
  };
  int checked = 0;
  for (const auto& change : changes) {
    SweepOptions changed = o;
    change(changed);
    EXPECT_NE(detail::SweepDescription(changed), base) << "change " << checked;
    ++checked;
  }
  EXPECT_EQ(checked, 8);
  SweepOptions threads = o;
  threads.reach.check.attractor.threads = 2;
  EXPECT_EQ(detail::SweepDescription(threads), base);
}

TEST(Sweep, CommentLinesComeFirstAndReadersThatSkipThemSeeTheTable) {
  TempDir dir;
  SweepOptions o = PaperPhaseSweep(dir.File("c.csv"), 9);
  o.comments = {"capsubot test sweep --grid phi0=-pi:pi:9", "second"};
  RunSweep(o);
  const std::string text = ReadFile(o.output);
  EXPECT_EQ(text.rfind("# capsubot test sweep --grid phi0=-pi:pi:9\n# second\nphi0,phi1,", 0), 0u);
  const auto rows = ReadCsv(o.output);  // skips '#' lines, as pandas' comment='#' does
  ASSERT_EQ(rows.size(), 10u);
  EXPECT_EQ(rows[0][0], "phi0");
  for (std::size_t r = 1; r < rows.size(); ++r) EXPECT_EQ(rows[r].size(), rows[0].size()) << r;
}

TEST(Sweep, FileIsByteIdenticalForAnyThreadCountWithCommentsStabilityAndAllSpacings) {
  TempDir dir;
  SweepOptions o;
  o.grid.axes = {ParseGridAxis("c=0.01:0.5:7:log"), ParseGridAxis("A=0.5,0.2"),
                 ParseGridAxis("phi0=-pi:pi:101")};
  o.comments = {"provenance"};
  o.stability = true;
  o.output = dir.File("ref.csv");
  o.threads = 1;
  o.block_points = 5000;
  RunSweep(o);
  const std::string reference = ReadFile(o.output);
  ASSERT_GT(reference.size(), 10000u);
  int runs = 0;
  for (int threads : {2, 3}) {
    for (int block : {1, 13, 0}) {
      o.output = dir.File("t" + std::to_string(threads) + "b" + std::to_string(block) + ".csv");
      o.threads = threads;
      o.block_points = block;
      RunSweep(o);
      EXPECT_TRUE(ReadFile(o.output) == reference) << threads << " threads, blocks of " << block;
      ++runs;
    }
  }
  EXPECT_EQ(runs, 6);
}

std::string IoErrorMessage(const SweepOptions& o) {
  try {
    RunSweep(o);
  } catch (const IoError& e) {
    return e.what();
  }
  return "";
}

TEST(SweepCheckpoint, AFlippedByteInTheCheckpointIsAnError) {
  TempDir dir;
  const SweepOptions o = InterruptedSweep(dir);
  const std::string checkpoint = detail::SweepFile::CheckpointPath(o.output);
  std::string text = ReadFile(checkpoint);
  int checked = 0;
  // A digit of the point count, of the byte count, of the description, of the checksum.
  for (const std::string key : {"points ", "bytes ", "T0=", "crc32 "}) {
    std::string bad = text;
    const std::size_t at = bad.rfind(key) + key.size();
    bad[at] = bad[at] == '1' ? '2' : '1';
    std::ofstream(checkpoint, std::ios::binary | std::ios::trunc) << bad;
    const std::string message = IoErrorMessage(o);
    EXPECT_EQ(message.rfind("resume: checkpoint " + checkpoint +
                                " is not a valid capsubot sweep checkpoint (checksum mismatch)",
                            0),
              0u)
        << key << ": " << message;
    ++checked;
  }
  EXPECT_EQ(checked, 4);
  std::ofstream(checkpoint, std::ios::binary | std::ios::trunc) << text;  // intact again
  RunSweep(o);
  EXPECT_EQ(ReadCsv(o.output).size(), 501u);
}

TEST(SweepCheckpoint, ChangedRowsInThePartialFileAreAnError) {
  TempDir dir;
  const SweepOptions o = InterruptedSweep(dir);
  const std::string partial = detail::SweepFile::PartialPath(o.output);
  std::string text = ReadFile(partial);
  const std::size_t at = text.find("\n-3.") + 2;  // a row's first digit
  text[at] = '4';
  std::ofstream(partial, std::ios::binary | std::ios::trunc) << text;
  EXPECT_EQ(IoErrorMessage(o), "resume: " + partial + " does not hold the rows its checkpoint " +
                                   detail::SweepFile::CheckpointPath(o.output) +
                                   " vouches for (checksum mismatch: the file was changed or "
                                   "damaged): delete both to start the sweep again");
}

TEST(SweepCheckpoint, ACheckpointThatIsNotASmallRegularFileIsNotRead) {
  TempDir dir;
  const SweepOptions o = InterruptedSweep(dir);
  const std::string checkpoint = detail::SweepFile::CheckpointPath(o.output);
  ASSERT_EQ(std::remove(checkpoint.c_str()), 0);
  ASSERT_EQ(::symlink("/dev/zero", checkpoint.c_str()), 0);  // endless: must not be read
  EXPECT_EQ(IoErrorMessage(o), "resume: checkpoint " + checkpoint +
                                   " is not a valid capsubot sweep checkpoint (not a regular "
                                   "file): delete it and its .partial file to start the sweep "
                                   "again");
  ASSERT_EQ(std::remove(checkpoint.c_str()), 0);
  std::ofstream(checkpoint) << std::string(1 << 20, 'x');  // far longer than a checkpoint
  EXPECT_NE(IoErrorMessage(o).find("1048576 bytes, more than the"), std::string::npos);
}

}  // namespace
}  // namespace capsubot
