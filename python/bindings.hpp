#pragma once
// The Python module's pieces: one Bind function per library concept (each in its own file,
// called by module.cpp), and the conversions they share (convert.cpp). The module is thin:
// it converts Python arguments to the library's inputs, calls the library, builds the result
// as the command line's --json does (the shared layer src/report/) and converts that JSON to
// Python objects (same keys, null -> None).

#include <pybind11/pybind11.h>

#include <chrono>
#include <exception>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "capsubot/attract/attractors.hpp"
#include "capsubot/model/force_spec.hpp"
#include "capsubot/model/forcing.hpp"
#include "capsubot/model/interrupt.hpp"
#include "capsubot/model/params.hpp"
#include "capsubot/optimize/optimize_request.hpp"
#include "keyword_doc.hpp"

namespace capsubot::python {

namespace py = pybind11;

// The functions of the module, one file per concept (solve.cpp, solve_grid.cpp, ...).
void BindSolve(py::module_& m);         // solve, trajectory
void BindSolveGrid(py::module_& m);     // solve_grid
void BindSimulate(py::module_& m);      // simulate
void BindOptimize(py::module_& m);      // optimize
void BindOrbits(py::module_& m);        // orbits
void BindAttractors(py::module_& m);    // attractors
void BindPeriodic(py::module_& m);      // periodic
void BindDesign(py::module_& m);        // design
void BindContinuation(py::module_& m);  // continue_branch
void BindSweep(py::module_& m);         // sweep
void BindBasins(py::module_& m);        // basins
void BindBifurcation(py::module_& m);   // bifurcation

/// The units every docstring refers to (docs/model.md section 2).
inline constexpr const char* kUnits =
    "Units (dimensionless; capsubot documentation, model section 2): phases in rad (period "
    "tau = 2 pi, phi = 0 at the impact on the right wall); positions in L (walls at x = 0 and "
    "x = 1); velocities in omega L; forces (A, c, cos, sin, T0) in (m1+m2) omega^2 L; alpha = "
    "m2/(m1+m2).";

/// An argument that None leaves to its default: `field` = `*value`, and `name` into `given` (the
/// settings given, which the library's rules read), when it is not None.
template <class T, class U>
void TakeGiven(std::set<std::string>& given, const char* name, const std::optional<T>& value,
               U& field) {
  if (!value) return;
  field = *value;
  given.insert(name);
}

/// The keywords of the search of P2, P3 and of the reach search's seed (optimize() and sweep());
/// None: not given.
struct SearchKeywords {
  std::optional<double> bound;
  std::optional<int> harmonics, starts, hops, global_evaluations;
  std::optional<std::string> global_algorithm, local_algorithm;
};

/// The keywords given into `search` (bound: search.gait.force_bound), each as TakeGiven.
void TakeSearch(std::set<std::string>& given, const SearchKeywords& keywords,
                SearchRequest& search);

/// A grid of starts "NXxNPSI" (e.g. "8x8") given as the argument `name` into options.n_x,
/// options.n_psi (the library's ParseStartGrid: its syntax and limits); throws
/// std::invalid_argument naming the argument.
void ParseStarts(const char* name, const std::string& text, FromRestOptions& options);

/// How the module checks a gait from rest, as the command line's --from-rest-starts and
/// --threads: the full grid `starts` (argument from_rest_starts), `threads` worker threads
/// (lowered to the command line's cap, CapThreads of limits.hpp).
FromRestOptions FromRestCheck(const std::string& starts, int threads);

/// The default grid of a basin map, as `capsubot basins --starts`.
inline constexpr const char* kDefaultBasinStarts = "64x64";

/// Thrown by SignalCheck when a Python signal handler raised (Ctrl-C: KeyboardInterrupt). The
/// Python error stays set; RunWithoutGil raises it once the library call has unwound.
struct Interrupted : std::exception {
  const char* what() const noexcept override { return "interrupted by a Python signal handler"; }
};

/// The Python signal check of a long library call that runs without the GIL, called as its
/// Interrupt (AsInterrupt) or from its progress callbacks or observers. On the thread that
/// called the module (Python runs signal handlers on the main thread only) and at most every
/// kInterval, it takes the GIL and runs the pending handlers; it throws Interrupted when one
/// raised. Elsewhere, and in between, it costs a clock read (operator(): a comparison, and a
/// clock read every kStride calls).
class SignalCheck {
 public:
  static constexpr std::chrono::milliseconds kInterval{50};
  static constexpr int kStride = 64;

  void operator()() {
    if (++calls_ % kStride == 0 || calls_ == 1) Check();
  }
  /// Checks now (still at most every kInterval): where a call is rare (once per start).
  void Check();
  /// Check() as the library's Interrupt (capsubot/model/interrupt.hpp), for the options of a long
  /// call; valid while this check lives (the call inside RunWithoutGil).
  Interrupt AsInterrupt() {
    return [this] { Check(); };
  }

 private:
  const std::thread::id caller_ = std::this_thread::get_id();
  std::chrono::steady_clock::time_point next_ = std::chrono::steady_clock::now();
  unsigned calls_ = 0;
};

/// Runs `work(check)` without the GIL, `check` a SignalCheck of this call; an Interrupted it
/// throws becomes the Python error again (KeyboardInterrupt), with the GIL taken back.
template <typename Work>
auto RunWithoutGil(Work&& work) {
  SignalCheck check;
  try {
    py::gil_scoped_release release;
    return std::forward<Work>(work)(check);
  } catch (const Interrupted&) {
    throw py::error_already_set();
  }
}

/// A JSON value as Python objects: objects -> dict, arrays -> list, numbers -> int or float
/// (NaN and infinities, which JSON writes as null, -> None), strings -> str, booleans -> bool,
/// null -> None.
py::object ToPython(const nlohmann::json& value);

/// A private temporary folder for the CSV files a job writes (sweep, basins, bifurcation),
/// removed with everything in it when the object goes.
class OutputFolder {
 public:
  OutputFolder();  ///< throws std::runtime_error when it cannot be created
  ~OutputFolder();
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;
  /// The path of file `name` in the folder.
  std::string File(const char* name) const;

 private:
  std::filesystem::path path_;
};

/// The CSV file a job wrote as {column name: NumPy array} in the header's order, after its
/// '#' comment lines: int64 for a column of whole numbers, float64 for numbers (an empty cell:
/// NaN), str otherwise. The numbers are the file's text read as Python's float() reads it.
py::dict CsvColumns(const std::string& path);

/// What made a result: {"program": "capsubot", "version", "command", "options"}, options the
/// call's arguments by their Python names (the command line's provenance, with its options
/// named as the module's arguments).
py::dict JobProvenance(const char* command, const py::dict& options);

/// Defines the module function `name` with keyword-only arguments: the force (A, c, phi0, cos,
/// sin, waveform, levels, switches: ForceArgsDoc()), the model (T0, e: ModelArgsDoc()), then
/// `rest` (alpha and the function's own), every function that takes a robot alike.
template <typename Func, typename... Rest>
void DefRobotFunction(py::module_& m, const char* name, Func&& f, const char* doc, Rest&&... rest) {
  m.def(name, std::forward<Func>(f), doc, py::kw_only(), py::arg("A") = py::none(),
        py::arg("c") = py::none(), py::arg("phi0") = py::none(), py::arg("cos") = py::none(),
        py::arg("sin") = py::none(), py::arg("waveform") = py::none(),
        py::arg("levels") = py::none(), py::arg("switches") = py::none(),
        py::arg("T0") = Params{}.T0, py::arg("e") = Params{}.e, std::forward<Rest>(rest)...);
}

}  // namespace capsubot::python
