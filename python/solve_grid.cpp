// solve_grid: the orbit, its validity and optionally its stability at every point of
// NumPy arrays of parameters (broadcast together), computed without the GIL on several
// threads: the library's speed from Python.

#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <exception>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <string>

#include "bindings.hpp"
#include "capsubot/model/limits.hpp"
#include "capsubot/orbit/stability.hpp"
#include "capsubot/orbit/validity.hpp"
#include "capsubot/parallel/blocks.hpp"

namespace capsubot::python {
namespace {

constexpr std::int64_t kBlockPoints = 2048;  // ~2 ms of Solve calls: the unit of work
constexpr std::int64_t kNoError = std::numeric_limits<std::int64_t>::max();

// The inputs, in this order; every one is an array broadcast to the grid's shape.
enum Input { kA, kMean, kPhi0, kT0, kRestitution, kMargin, kMarginStroke, kStickMargin, kInputs };
constexpr std::array<const char*, kInputs> kInputNames = {
    "A", "c", "phi0", "T0", "e", "margin", "margin_stroke", "stick_margin"};

using Array = py::array_t<double, py::array::forcecast>;

std::string ShapeText(const std::vector<py::ssize_t>& shape) {
  std::string s = "(";
  for (std::size_t d = 0; d < shape.size(); ++d) {
    s += fmt::format("{}{}", d > 0 ? ", " : "", shape[d]);
  }
  return s + (shape.size() == 1 ? ",)" : ")");
}

// The inputs broadcast to one shape: for each input, its data and its byte strides along the
// grid's dimensions (0 along a dimension it is broadcast over).
struct Layout {
  std::vector<py::ssize_t> shape;
  std::int64_t size = 1;
  std::array<const char*, kInputs> data{};
  std::array<std::vector<py::ssize_t>, kInputs> strides;

  explicit Layout(const std::array<Array, kInputs>& in) {
    std::size_t ndim = 0;
    for (const Array& a : in) ndim = std::max(ndim, static_cast<std::size_t>(a.ndim()));
    shape.assign(ndim, 1);
    std::vector<int> set_by(ndim, -1);  // which input set each dimension (for the message)
    for (int k = 0; k < kInputs; ++k) {
      const Array& a = in[k];
      const std::size_t lead = ndim - static_cast<std::size_t>(a.ndim());
      for (py::ssize_t d = 0; d < a.ndim(); ++d) {
        const py::ssize_t n = a.shape(d);
        py::ssize_t& out = shape[lead + static_cast<std::size_t>(d)];
        if (n == 1 || n == out) continue;
        if (out != 1) {
          const int other = set_by[lead + static_cast<std::size_t>(d)];
          const Array& b = in[other];
          throw std::invalid_argument(fmt::format(
              "{} of shape {} and {} of shape {} cannot be broadcast together (NumPy rules)",
              kInputNames[other], ShapeText({b.shape(), b.shape() + b.ndim()}), kInputNames[k],
              ShapeText({a.shape(), a.shape() + a.ndim()})));
        }
        out = n;
        set_by[lead + static_cast<std::size_t>(d)] = k;
      }
    }
    for (py::ssize_t n : shape) {
      if (n != 0 && size > std::numeric_limits<std::int64_t>::max() / n) {
        throw std::invalid_argument(
            fmt::format("the broadcast shape {} has too many points", ShapeText(shape)));
      }
      size *= n;
    }
    for (int k = 0; k < kInputs; ++k) {
      const Array& a = in[k];
      const std::size_t lead = ndim - static_cast<std::size_t>(a.ndim());
      data[k] = reinterpret_cast<const char*>(a.data());
      strides[k].assign(ndim, 0);
      for (py::ssize_t d = 0; d < a.ndim(); ++d) {
        if (a.shape(d) != 1) strides[k][lead + static_cast<std::size_t>(d)] = a.strides(d);
      }
    }
  }

  // The multi-index of flat (C order) point p, as text: "(3, 4)".
  std::string IndexText(std::int64_t p) const {
    std::vector<py::ssize_t> index(shape.size());
    for (std::size_t d = shape.size(); d-- > 0;) {
      index[d] = static_cast<py::ssize_t>(p % shape[d]);
      p /= shape[d];
    }
    return ShapeText(index);
  }
};

// Walks the grid in C order from a flat index, keeping each input's byte offset (no
// division per point).
class Cursor {
 public:
  Cursor(const Layout& layout, std::int64_t start) : layout_(layout), index_(layout.shape.size()) {
    for (std::size_t d = layout.shape.size(); d-- > 0;) {
      index_[d] = static_cast<py::ssize_t>(start % layout.shape[d]);
      start /= layout.shape[d];
      for (int k = 0; k < kInputs; ++k) offset_[k] += index_[d] * layout.strides[k][d];
    }
  }
  double operator[](int k) const {
    double value;  // memcpy: a NumPy array need not be aligned
    std::memcpy(&value, layout_.data[k] + offset_[k], sizeof value);
    return value;
  }
  void Next() {
    for (std::size_t d = index_.size(); d-- > 0;) {
      if (++index_[d] < layout_.shape[d]) {
        for (int k = 0; k < kInputs; ++k) offset_[k] += layout_.strides[k][d];
        return;
      }
      for (int k = 0; k < kInputs; ++k) offset_[k] -= (index_[d] - 1) * layout_.strides[k][d];
      index_[d] = 0;
    }
  }

 private:
  const Layout& layout_;
  std::vector<py::ssize_t> index_;
  std::array<py::ssize_t, kInputs> offset_{};
};

// The output columns, contiguous in C order.
struct Outputs {
  double *phi1, *alpha, *u, *v_plus, *I, *v_mean, *x_min, *x_max, *spectral_radius;
  bool *valid, *stable;
  std::uint32_t* violations;
};

// Solves points [begin, end) and stores them; a point whose input the library rejects is
// recorded (the smallest such index wins) and ends the block.
class GridSolver {
 public:
  GridSolver(const Layout& layout, const Outputs& out, bool stability)
      : layout_(layout), out_(out), stability_(stability) {}

  // Returns the points solved: end - begin, or fewer when one was rejected.
  std::int64_t SolveBlock(std::int64_t begin, std::int64_t end) {
    std::vector<double> a{0.0}, b{0.0};  // the harmonic force as a series: b_1 = A
    Cursor in(layout_, begin);
    for (std::int64_t p = begin; p < end; ++p, in.Next()) {
      if (p > first_error_.load(std::memory_order_relaxed)) return p - begin;
      try {
        const double A = in[kA], c = in[kMean], phi0 = in[kPhi0];
        // Anything but an amplitude: Harmonic throws the library's message.
        if (!(std::isfinite(A) && A >= 0.0)) (void)Forcing::Harmonic(A, c, phi0);
        b[0] = A;
        const Forcing forcing = Forcing::Fourier(c, a, b, phi0);  // no allocation
        const Params params{in[kT0], in[kRestitution]};
        const Margins margins{in[kMargin], in[kMarginStroke], in[kStickMargin]};
        Store(p, capsubot::Solve(forcing, params, margins));
      } catch (...) {
        Fail(p, std::current_exception());
        return p - begin;
      }
    }
    return end - begin;
  }

  // Rethrows the error of the smallest failed index, naming it.
  void RethrowError() const {
    std::exception_ptr error;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      error = error_;
    }
    if (!error) return;
    const std::string where = "at index " + layout_.IndexText(first_error_.load());
    try {
      std::rethrow_exception(error);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(fmt::format("{}: {}", where, e.what()));
    } catch (const std::bad_alloc&) {
      throw;
    } catch (const std::exception& e) {
      throw std::runtime_error(fmt::format("{}: {}", where, e.what()));
    }
  }

 private:
  void Store(std::int64_t p, const Solution& s) const {
    const Orbit& o = s.orbit;
    const Validity& v = s.validity;
    out_.phi1[p] = o.phi1;
    out_.alpha[p] = o.alpha;
    out_.u[p] = o.u;
    out_.v_plus[p] = o.v_plus;
    out_.I[p] = o.I;
    out_.v_mean[p] = o.v_mean;
    out_.x_min[p] = v.x_min;
    out_.x_max[p] = v.x_max;
    out_.valid[p] = v.valid();
    out_.violations[p] = v.violations;
    if (stability_) {
      const Stability st = ComputeStability(o);
      out_.spectral_radius[p] = st.computed ? st.spectral_radius : kNaN;
      out_.stable[p] = st.computed && st.stable;
    }
  }

  void Fail(std::int64_t p, std::exception_ptr e) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (p < first_error_.load()) {
      first_error_.store(p);
      error_ = e;
    }
  }

  const Layout& layout_;
  const Outputs& out_;
  const bool stability_;
  std::atomic<std::int64_t> first_error_{kNoError};
  mutable std::mutex mutex_;
  std::exception_ptr error_;
};

// The threads asked for (None: all cores), lowered to the command line's cap (limits.hpp).
int ThreadCount(std::optional<int> threads) {
  if (!threads) return WorkerThreads(0);
  if (*threads < 1 || *threads > kMaxThreads) {
    throw std::invalid_argument(
        fmt::format("threads = {} is invalid: expected 1 <= threads <= {} (None: all cores)",
                    *threads, kMaxThreads));
  }
  return CapThreads(*threads);
}

// Input `name` as an array of doubles. Only what NumPy holds as integers or floating-point
// numbers is taken: None (which NumPy turns into NaN), booleans, strings, complex numbers and
// objects raise TypeError instead of being converted, and so does a masked array, whose mask
// the computation would ignore.
Array NumbersArgument(const char* name, const py::object& value) {
  const py::module_ np = py::module_::import("numpy");
  const auto refuse = [&](const char* why) {
    return py::type_error(fmt::format("{} must be a number or an array of numbers: {} (got {})",
                                      name, why, py::str(py::type::of(value)).cast<std::string>()));
  };
  if (value.is_none()) throw refuse("None is no number");
  if (py::isinstance(value, np.attr("ma").attr("MaskedArray"))) {
    throw refuse("a masked array's mask would be ignored (fill or compress it first)");
  }
  py::array numbers;
  try {
    numbers = np.attr("asarray")(value);
  } catch (const py::error_already_set&) {
    throw refuse("NumPy cannot read it as an array");
  }
  const char kind = numbers.dtype().kind();
  if (kind != 'i' && kind != 'u' && kind != 'f') {
    throw refuse(kind == 'b'                  ? "booleans are not numbers here"
                 : kind == 'c'                ? "complex numbers are not real numbers"
                 : kind == 'U' || kind == 'S' ? "strings are not converted"
                                              : "its elements are not all numbers");
  }
  return Array::ensure(numbers);
}

// Solves the grid in blocks on `threads` computing threads (blocks.hpp); the calling thread
// takes the blocks in order, checks for Ctrl-C and stops at the first block with a rejected
// point (every block before it was whole: its rejected point is the first in C order).
void RunBlocks(GridSolver& solver, std::int64_t size, int threads, SignalCheck& check) {
  BlockPlan plan;
  plan.end = size;
  plan.block = kBlockPoints;
  plan.threads = threads;
  const BlockComputeFactory make = [&solver]() -> BlockCompute {
    return [&solver](std::int64_t begin, std::int64_t end, std::string&) {
      return solver.SolveBlock(begin, end);
    };
  };
  LocalBlocks().Run(
      plan, make,
      [&](std::int64_t begin, std::int64_t end, const std::string&, std::int64_t solved) {
        if (solved < end - begin) solver.RethrowError();
        check.Check();
      });
}

py::dict SolveGrid(const py::object& A, const py::object& c, const py::object& phi0,
                   const py::object& T0, const py::object& e, const py::object& margin,
                   const py::object& margin_stroke, const py::object& stick_margin, bool stability,
                   std::optional<int> threads) {
  const int thread_count = ThreadCount(threads);
  const std::array<const py::object*, kInputs> objects = {
      &A, &c, &phi0, &T0, &e, &margin, &margin_stroke, &stick_margin};
  std::array<Array, kInputs> in;
  for (int k = 0; k < kInputs; ++k) in[k] = NumbersArgument(kInputNames[k], *objects[k]);
  const Layout layout(in);

  py::dict d;
  const auto column = [&](const char* name, auto zero) {
    py::array_t<decltype(zero)> a(layout.shape);
    d[name] = a;
    return a.mutable_data();
  };
  Outputs out{};
  out.phi1 = column("phi1", 0.0);
  out.alpha = column("alpha", 0.0);
  out.u = column("u", 0.0);
  out.v_plus = column("v_plus", 0.0);
  out.I = column("I", 0.0);
  out.v_mean = column("v_mean", 0.0);
  out.x_min = column("x_min", 0.0);
  out.x_max = column("x_max", 0.0);
  out.valid = column("valid", false);
  out.violations = column("violations", std::uint32_t{0});
  if (stability) {
    out.spectral_radius = column("spectral_radius", 0.0);
    out.stable = column("stable", false);
  }

  GridSolver solver(layout, out, stability);
  RunWithoutGil([&](SignalCheck& check) { RunBlocks(solver, layout.size, thread_count, check); });
  return d;
}

constexpr const char* kSolveGridDoc =
    "The one-impact orbit, its validity and optionally its stability at every point of a "
    "grid: the computation of solve (and of `capsubot sweep`) on NumPy arrays, at the "
    "library's speed (without the GIL, on several threads; Ctrl-C interrupts it).\n\n"
    "Arguments (keyword only; each a number or an array, all broadcast together by NumPy's "
    "rules, e.g. phi0 of shape (n,) with c of shape (m, 1) gives an (m, n) grid):\n"
    "    A       amplitude A >= 0 of F = A sin(phi + phi0) + c [force]\n"
    "    c       mean force [force]\n"
    "    phi0    motor phase at the impact [rad]\n";

constexpr const char* kSolveGridReturnsDoc =
    "\nReturns a dict of arrays of the broadcast shape (the columns of `capsubot sweep`): phi1 "
    "(rad), alpha, u (omega L), v_plus (omega L), I (L), v_mean (omega L), x_min, x_max (L), "
    "valid (bool), violations (uint32 bit mask: bit i set when condition CONDITIONS[i] is "
    "violated); with stability, spectral_radius and stable (bool). NaN where a quantity does "
    "not exist.\n\n"
    "Raises ValueError for inputs that cannot be broadcast or a point the library rejects "
    "(the message gives its index and the library's rule), TypeError for inputs that are not "
    "numbers: None, booleans, strings, complex numbers, objects, and masked arrays (their mask "
    "would be ignored).\n\n";

}  // namespace

void BindSolveGrid(py::module_& m) {
  py::tuple conditions(static_cast<std::size_t>(Condition::kCount));
  for (int i = 0; i < static_cast<int>(Condition::kCount); ++i) {
    conditions[static_cast<std::size_t>(i)] = ConditionName(static_cast<Condition>(i));
  }
  m.attr("CONDITIONS") = conditions;
  const std::string doc =
      std::string(kSolveGridDoc) + ModelArgsDoc() + MarginArgsDoc() +
      ArgumentLines("stability",
                    "also spectral_radius and stable (capsubot documentation, model section 8)") +
      ArgumentLines("threads", fmt::format("number of threads, 1..{} ({}); None: all cores",
                                           kMaxThreads, ThreadsCapDoc())) +
      kSolveGridReturnsDoc + kUnits;
  m.def("solve_grid", &SolveGrid, doc.c_str(), py::kw_only(), py::arg("A"), py::arg("c"),
        py::arg("phi0"), py::arg("T0") = Params{}.T0, py::arg("e") = Params{}.e,
        py::arg("margin") = Margins{}.clearance,
        py::arg("margin_stroke") = Margins{}.clearance_stroke,
        py::arg("stick_margin") = Margins{}.stick, py::arg("stability").noconvert() = false,
        py::arg("threads") = py::none());
}

}  // namespace capsubot::python
