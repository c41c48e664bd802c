// Conversions shared by the module's functions: the force arguments, and the JSON of the
// results (src/report/, as the command line prints it) as Python objects.

#include <fmt/format.h>
#include <pybind11/complex.h>
#include <pybind11/numpy.h>

#include <cmath>
#include <complex>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "bindings.hpp"
#include "capsubot/attract/start_grid.hpp"
#include "capsubot/model/limits.hpp"

namespace capsubot::python {
void ParseStarts(const char* name, const std::string& text, FromRestOptions& o) {
  const StartGrid grid = ParseStartGrid(name, text);
  o.n_x = grid.n_x;
  o.n_psi = grid.n_psi;
}

void TakeSearch(std::set<std::string>& given, const SearchKeywords& k, SearchRequest& search) {
  TakeGiven(given, "bound", k.bound, search.gait.force_bound);
  TakeGiven(given, "harmonics", k.harmonics, search.harmonics);
  TakeGiven(given, "starts", k.starts, search.starts);
  TakeGiven(given, "hops", k.hops, search.hops);
  TakeGiven(given, "global_algorithm", k.global_algorithm, search.global_algorithm);
  TakeGiven(given, "local_algorithm", k.local_algorithm, search.local_algorithm);
  TakeGiven(given, "global_evaluations", k.global_evaluations, search.global_evaluations);
}

FromRestOptions FromRestCheck(const std::string& starts, int threads) {
  FromRestOptions o;
  ParseStarts("from_rest_starts", starts, o);
  o.attractor.threads = CapThreads(threads);
  o.Validate();
  return o;
}

void SignalCheck::Check() {
  if (std::this_thread::get_id() != caller_) return;
  const auto now = std::chrono::steady_clock::now();
  if (now < next_) return;
  next_ = now + kInterval;
  py::gil_scoped_acquire gil;
  if (PyErr_CheckSignals() != 0) throw Interrupted();
}

namespace {

// Multipliers, written in JSON as {"re", "im"} objects (solve) or [re, im] pairs (periodic):
// one NumPy complex array in Python whatever the command.
py::object ComplexArray(const nlohmann::json& list) {
  py::array_t<std::complex<double>> out(static_cast<py::ssize_t>(list.size()));
  std::complex<double>* z = out.mutable_data();
  for (const auto& item : list) {
    const nlohmann::json& re = item.is_object() ? item.at("re") : item.at(0);
    const nlohmann::json& im = item.is_object() ? item.at("im") : item.at(1);
    *z++ = {re.is_number() ? re.get<double>() : std::nan(""),
            im.is_number() ? im.get<double>() : std::nan("")};
  }
  return std::move(out);
}

}  // namespace

py::object ToPython(const nlohmann::json& value) {
  switch (value.type()) {
    case nlohmann::json::value_t::object: {
      py::dict d;
      for (const auto& [key, item] : value.items()) {
        d[py::str(key)] =
            key == "multipliers" && item.is_array() ? ComplexArray(item) : ToPython(item);
      }
      return d;
    }
    case nlohmann::json::value_t::array: {
      py::list l;
      for (const auto& item : value) l.append(ToPython(item));
      return l;
    }
    case nlohmann::json::value_t::number_float: {
      const double x = value.get<double>();
      return std::isfinite(x) ? py::object(py::float_(x)) : py::object(py::none());
    }
    case nlohmann::json::value_t::number_integer:
      return py::int_(value.get<std::int64_t>());
    case nlohmann::json::value_t::number_unsigned:
      return py::int_(value.get<std::uint64_t>());
    case nlohmann::json::value_t::string:
      return py::str(value.get_ref<const std::string&>());
    case nlohmann::json::value_t::boolean:
      return py::bool_(value.get<bool>());
    default:  // null, and the binary and discarded values that the results never hold
      return py::none();
  }
}

}  // namespace capsubot::python
