#pragma once
// Shared test helpers: comparisons that print both sides, quadrature, running the CLI.

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "capsubot/model/params.hpp"
#include "capsubot/simulate/simulator.hpp"

namespace capsubot::testing {

/// The whole content of the file at `path`, byte for byte ("" when it cannot be read).
inline std::string ReadFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// |actual - expected| <= tol, printing both values and the difference on failure.
/// The message of the std::invalid_argument thrown by f ("" if none).
template <class Fn>
std::string InvalidArgumentMessage(const Fn& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

inline ::testing::AssertionResult Near(double actual, double expected, double tol) {
  const double diff = std::abs(actual - expected);
  if (diff <= tol) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "actual " << actual << " vs expected " << expected
                                       << ": difference " << diff << " > tolerance " << tol;
}

/// |actual - expected| <= tol * max(1, |expected|): an absolute tolerance where |expected| <= 1
/// (for quantities of order one that may pass through 0), a relative one above. For a small
/// quantity compared relatively (a velocity of 0.02) use RelNear.
inline ::testing::AssertionResult NearAbsBelowOne(double actual, double expected, double tol) {
  return Near(actual, expected, tol * std::max(1.0, std::abs(expected)));
}

/// Relative: |actual - expected| <= rel * |expected|.
inline ::testing::AssertionResult RelNear(double actual, double expected, double rel) {
  return Near(actual, expected, rel * std::abs(expected));
}

/// integral_a^b f by GSL's adaptive QAGS (independent of every closed form under test).
inline double Quadrature(const std::function<double(double)>& f, double a, double b) {
  gsl_set_error_handler_off();
  std::unique_ptr<gsl_integration_workspace, decltype(&gsl_integration_workspace_free)> ws(
      gsl_integration_workspace_alloc(1000), &gsl_integration_workspace_free);
  gsl_function fn;
  fn.function = [](double x, void* p) {
    return (*static_cast<const std::function<double(double)>*>(p))(x);
  };
  fn.params = const_cast<std::function<double(double)>*>(&f);
  double result = 0.0, error = 0.0;
  gsl_integration_qags(&fn, a, b, 1e-14, 1e-13, 1000, ws.get(), &result, &error);
  return result;
}

/// Simulator options: mass ratio alpha, start state (x0, u0, v0), `periods` periods.
inline SimOptions StartAt(double alpha, double x0, double u0, double v0, double periods) {
  SimOptions opt;
  opt.alpha = alpha;
  opt.x0 = x0;
  opt.u0 = u0;
  opt.v0 = v0;
  opt.periods = periods;
  return opt;
}

/// The mean velocity of a direct simulation from the state (x0, u0, v0) at the forcing phase
/// psi (the start of a long run, attract/), over `record` periods after `transient` periods:
/// what `capsubot simulate --transient T --periods R` gives. NaN when the run does not end ok.
inline double DirectVelocity(const Forcing& forcing, const Params& params, double alpha, double x0,
                             double u0, double v0, double psi, int transient, int record) {
  SimOptions o = StartAt(alpha, x0, u0, v0, record);
  o.transient = transient;
  o.max_events_per_period = 1000;
  const SimResult r = Simulate(forcing.WithPhase(forcing.phi0() + psi), params, o);
  return r.status == SimStatus::kOk ? r.displacement / (record * kTau) : std::nan("");
}

/// A force and model under a name (the name is what GoogleTest prints for the parameter).
struct NamedCase {
  const char* name;
  Forcing forcing;
  Params params;
  friend void PrintTo(const NamedCase& c, std::ostream* os) { *os << c.name; }
};

/// A path in the temporary directory unique to this process (test binaries of several build
/// trees may run at once), removed first if it exists.
inline std::filesystem::path TempPath(const std::string& name) {
  const auto p = std::filesystem::temp_directory_path() /
                 (std::to_string(static_cast<long>(::getpid())) + "_" + name);
  std::filesystem::remove(p);
  return p;
}

/// Output and exit status of a shell command.
struct CommandResult {
  int status = -1;
  std::string out;
};

/// Runs the shell command `command`, capturing stdout (and stderr with "2>&1").
inline CommandResult RunShell(const std::string& command) {
  CommandResult r;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return r;
  std::array<char, 4096> buffer{};
  std::size_t n = 0;
  while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) r.out.append(buffer.data(), n);
  const int raw = pclose(pipe);
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  return r;
}

/// A CSV file as capsubot writes it: its comment lines (each beginning with '#': the
/// provenance), its header line, its rows; without their line breaks.
struct CsvLines {
  std::vector<std::string> comments;
  std::string header;
  std::vector<std::string> rows;
};

/// Splits the text of a CSV file: the '#' lines before the header, the header, every later
/// line a row.
inline CsvLines SplitCsv(const std::string& text) {
  CsvLines csv;
  std::istringstream in(text);
  bool header = false;
  for (std::string line; std::getline(in, line);) {
    if (header) {
      csv.rows.push_back(line);
    } else if (line.rfind('#', 0) == 0) {
      csv.comments.push_back(line);
    } else {
      csv.header = line;
      header = true;
    }
  }
  return csv;
}

/// SplitCsv of the file at `path`.
inline CsvLines ReadCsv(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return SplitCsv(text.str());
}

/// Runs `capsubot <args>` (the built program), capturing stdout (and stderr with "2>&1").
inline CommandResult RunCli(const std::string& args) {
  return RunShell(std::string(CAPSUBOT_CLI) + " " + args);
}

}  // namespace capsubot::testing
