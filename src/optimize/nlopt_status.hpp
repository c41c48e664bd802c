#pragma once
// NLopt at the library boundary: every nlopt::result and every exception NLopt 2.7.1 throws
// (nlopt::roundoff_limited, nlopt::forced_stop, std::invalid_argument, std::bad_alloc,
// std::runtime_error) mapped to an OptimizeStatus; algorithm names checked against our lists.

#include <nlopt.hpp>
#include <string>
#include <vector>

#include "capsubot/optimize_result.hpp"

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

}  // namespace capsubot::detail
