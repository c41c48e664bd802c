// The Python module `capsubot`: the library's computations with keyword arguments named as
// the command-line options, results as the dicts of the command line's --json (built by its
// JSON layer, src/report/; NumPy arrays for tables). pybind11 maps std::invalid_argument to
// ValueError and std::runtime_error to RuntimeError, with the library's message.

#include <string>

#include "bindings.hpp"
#include "capsubot/model/version.hpp"

PYBIND11_MODULE(capsubot, m) {
  m.doc() =
      std::string(
          "capsubot: the one-impact gaits of a vibro-impact capsule robot (the library behind the "
          "`capsubot` command line).\n\n"
          "solve, trajectory, solve_grid: the periodic orbit and its validity; simulate: the exact "
          "event-driven simulation; orbits: every orbit of a given robot; optimize: the fastest "
          "gait; attractors: the long-run motions from rest; periodic: a periodic motion of any "
          "kind by Newton shooting; continue_branch: its continuation in one parameter; design: a "
          "real robot in SI units; sweep, basins, bifurcation: the grid, basin map and bifurcation "
          "diagram commands, their CSV files as NumPy columns with their provenance. Keyword "
          "arguments are named as the command-line options; results are the dicts that `capsubot "
          "<command> --json` prints (None for null), without its provenance. Bad input raises "
          "ValueError with the library's message.\n\n") +
      capsubot::python::kUnits;
  m.attr("__version__") = capsubot::Version();
  capsubot::python::BindSolve(m);
  capsubot::python::BindSolveGrid(m);
  capsubot::python::BindSimulate(m);
  capsubot::python::BindOptimize(m);
  capsubot::python::BindOrbits(m);
  capsubot::python::BindAttractors(m);
  capsubot::python::BindPeriodic(m);
  capsubot::python::BindDesign(m);
  capsubot::python::BindContinuation(m);
  capsubot::python::BindSweep(m);
  capsubot::python::BindBasins(m);
  capsubot::python::BindBifurcation(m);
}
