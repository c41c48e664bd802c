#pragma once
// NLopt at the library boundary: every nlopt::result and every exception NLopt 2.7.1 throws
// (nlopt::roundoff_limited, nlopt::forced_stop, std::invalid_argument, std::bad_alloc,
// std::runtime_error) mapped to an OptimizeStatus; algorithm names checked against our lists;
// what our own objectives and constraints throw (an Interrupt) forwarded to the caller.

#include <deque>
#include <exception>
#include <nlopt.hpp>
#include <string>
#include <vector>

#include "capsubot/optimize/optimize_result.hpp"

namespace capsubot::detail {

/// The status of a finished nlopt::opt::optimize call that returned `result`.
OptimizeStatus StatusFromNlopt(nlopt::result result);

/// A status and message for an exception thrown by nlopt::opt::optimize (call inside a catch
/// block: rethrows and classifies the current exception).
OptimizeStatus StatusFromCurrentException(std::string& message);

/// The NLopt algorithm with this name ("LN_COBYLA"), after checking that the name is in
/// `allowed`; throws std::invalid_argument "<option> = "<name>" is invalid: expected one of
/// ..." otherwise (saying so if NLopt knows the name but it cannot take our constraints).
nlopt::algorithm AlgorithmFromName(const std::string& name, const std::vector<std::string>& allowed,
                                   const char* option);

/// True for the NLopt algorithms that need a gradient (LD_*, GD_*).
bool NeedsGradient(nlopt::algorithm algorithm);

/// The objective and constraints of one NLopt run, with what they throw kept for the caller:
/// NLopt's C++ interface turns an exception thrown inside optimize into its own failure and
/// loses it. A wrapped function that throws stops the run (nlopt::forced_stop, so NLopt calls
/// nothing more), and Rethrow() throws its exception again once optimize has returned or
/// thrown. Register with opt.set_max_objective(NloptCallbacks::Call, callbacks.Wrap(f, data))
/// (the same for constraints); the object must outlive the run.
class NloptCallbacks {
 public:
  /// The data to hand NLopt with Call for the function `f` and its data.
  void* Wrap(nlopt::func f, void* data);
  /// What NLopt calls: the wrapped function, or nlopt::forced_stop once one has thrown.
  static double Call(unsigned n, const double* x, double* gradient, void* wrapped);
  /// Throws the exception a wrapped function threw, if any.
  void Rethrow() const;

 private:
  struct Wrapped {
    nlopt::func f;
    void* data;
    NloptCallbacks* owner;
  };
  std::deque<Wrapped> wrapped_;  // a deque: the addresses handed to NLopt stay valid
  std::exception_ptr thrown_;
};

}  // namespace capsubot::detail
