// The CSV files a job writes (sweep, basins, bifurcation), read back as NumPy columns: the job
// writes them into a private temporary folder, the module returns their columns. The cells are
// the command line's text, so the numbers are the program's, bit for bit.

#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <stdlib.h>

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include "bindings.hpp"
#include "capsubot/model/version.hpp"
#include "capsubot/numerics/not_computed.hpp"

namespace capsubot::python {
namespace {

std::vector<std::string> SplitCells(const std::string& line) {
  std::vector<std::string> cells;
  std::size_t begin = 0;
  for (std::size_t comma = line.find(','); comma != std::string::npos;
       comma = line.find(',', begin)) {
    cells.push_back(line.substr(begin, comma - begin));
    begin = comma + 1;
  }
  cells.push_back(line.substr(begin));
  return cells;
}

// Whether `cell` is a whole number (an optional '-', then digits) that fits an int64.
bool ParseInteger(const std::string& cell, std::int64_t& value) {
  if (cell.empty() || cell.find_first_not_of("-0123456789") != std::string::npos) return false;
  errno = 0;
  char* end = nullptr;
  const long long v = std::strtoll(cell.c_str(), &end, 10);
  if (errno != 0 || end != cell.c_str() + cell.size()) return false;
  value = v;
  return true;
}

// Whether `cell` is a number (strtod: correctly rounded, as Python's float()); "" is NaN.
bool ParseNumber(const std::string& cell, double& value) {
  if (cell.empty()) {
    value = kNaN;
    return true;
  }
  char* end = nullptr;
  value = std::strtod(cell.c_str(), &end);
  return end == cell.c_str() + cell.size();
}

// One column as an array: int64 when every cell is a whole number, float64 when every cell is
// a number or empty (NaN), str otherwise.
py::object Column(const std::vector<std::vector<std::string>>& rows, std::size_t k) {
  const auto n = static_cast<py::ssize_t>(rows.size());
  py::array_t<std::int64_t> integers(n);
  bool all_integers = true;
  for (py::ssize_t i = 0; i < n && all_integers; ++i) {
    all_integers = ParseInteger(rows[static_cast<std::size_t>(i)][k], integers.mutable_at(i));
  }
  if (all_integers && n > 0) return std::move(integers);
  py::array_t<double> numbers(n);
  bool all_numbers = true;
  for (py::ssize_t i = 0; i < n && all_numbers; ++i) {
    all_numbers = ParseNumber(rows[static_cast<std::size_t>(i)][k], numbers.mutable_at(i));
  }
  if (all_numbers) return std::move(numbers);
  py::list texts;
  for (const auto& row : rows) texts.append(py::str(row[k]));
  return py::module_::import("numpy").attr("asarray")(texts, py::arg("dtype") = "str");
}

}  // namespace

OutputFolder::OutputFolder() {
  std::string pattern = (std::filesystem::temp_directory_path() / "capsubot-XXXXXX").string();
  if (mkdtemp(pattern.data()) == nullptr) {
    throw std::runtime_error(
        fmt::format("cannot create a temporary folder {}: {}", pattern, std::strerror(errno)));
  }
  path_ = pattern;
}

OutputFolder::~OutputFolder() {
  std::error_code ignored;  // a folder left behind in the temporary folder harms nothing
  std::filesystem::remove_all(path_, ignored);
}

std::string OutputFolder::File(const char* name) const { return (path_ / name).string(); }

py::dict CsvColumns(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(fmt::format("cannot read the job's file {}", path));
  std::string line;
  while (std::getline(in, line) && !line.empty() && line[0] == '#') {
  }
  const std::vector<std::string> header = SplitCells(line);
  std::vector<std::vector<std::string>> rows;
  while (std::getline(in, line)) {
    rows.push_back(SplitCells(line));
    if (rows.back().size() != header.size()) {
      throw std::runtime_error(fmt::format("{}: row {} has {} cells, the header {}", path,
                                           rows.size(), rows.back().size(), header.size()));
    }
  }
  py::dict columns;
  for (std::size_t k = 0; k < header.size(); ++k) columns[py::str(header[k])] = Column(rows, k);
  return columns;
}

py::dict JobProvenance(const char* command, const py::dict& options) {
  py::dict p;
  p["program"] = "capsubot";
  p["version"] = capsubot::Version();
  p["command"] = command;
  p["options"] = options;
  return p;
}

}  // namespace capsubot::python
