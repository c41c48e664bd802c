#include "capsubot/optimize/detail/nlopt_status.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <new>
#include <stdexcept>

namespace capsubot::detail {

OptimizeStatus StatusFromNlopt(nlopt::result result) {
  switch (result) {
    case nlopt::SUCCESS:
    case nlopt::STOPVAL_REACHED:
    case nlopt::FTOL_REACHED:
    case nlopt::XTOL_REACHED:
      return OptimizeStatus::kOk;
    case nlopt::MAXEVAL_REACHED:
      return OptimizeStatus::kMaxEvaluations;
    case nlopt::MAXTIME_REACHED:
      return OptimizeStatus::kMaxTime;
    case nlopt::ROUNDOFF_LIMITED:
      return OptimizeStatus::kRoundoffLimited;
    case nlopt::FORCED_STOP:
      return OptimizeStatus::kForcedStop;
    case nlopt::INVALID_ARGS:
      return OptimizeStatus::kInvalidArguments;
    case nlopt::OUT_OF_MEMORY:
      return OptimizeStatus::kOutOfMemory;
    case nlopt::FAILURE:
      return OptimizeStatus::kFailure;
    default:
      return OptimizeStatus::kFailure;
  }
}

OptimizeStatus StatusFromCurrentException(std::string& message) {
  try {
    throw;
  } catch (const nlopt::roundoff_limited&) {
    message = "NLopt stopped: round-off limited the progress";
    return OptimizeStatus::kRoundoffLimited;
  } catch (const nlopt::forced_stop&) {
    message = "NLopt stopped: forced stop";
    return OptimizeStatus::kForcedStop;
  } catch (const std::invalid_argument& e) {
    message = fmt::format("NLopt rejected the problem: {}", e.what());
    return OptimizeStatus::kInvalidArguments;
  } catch (const std::bad_alloc&) {
    message = "NLopt ran out of memory";
    return OptimizeStatus::kOutOfMemory;
  } catch (const std::exception& e) {
    message = fmt::format("NLopt failed: {}", e.what());
    return OptimizeStatus::kFailure;
  }
}

nlopt::algorithm AlgorithmFromName(const std::string& name, const std::vector<std::string>& allowed,
                                   const char* option) {
  if (std::find(allowed.begin(), allowed.end(), name) == allowed.end()) {
    std::string list;
    for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
    const bool known = nlopt_algorithm_from_string(name.c_str()) >= 0;
    throw std::invalid_argument(fmt::format(
        "{} = \"{}\" is invalid: expected one of {}{}", option, name, list,
        known ? " (it is an NLopt algorithm, but not one that fits here: it cannot take "
                "nonlinear inequality constraints or is not of this stage)"
              : ""));
  }
  const int a = nlopt_algorithm_from_string(name.c_str());
  if (a < 0)
    throw std::invalid_argument(fmt::format("{} = \"{}\" is not an NLopt name", option, name));
  return static_cast<nlopt::algorithm>(a);
}

bool NeedsGradient(nlopt::algorithm algorithm) {
  const char* name = nlopt_algorithm_to_string(static_cast<nlopt_algorithm>(algorithm));
  return name != nullptr && name[1] == 'D';
}

void* NloptCallbacks::Wrap(nlopt::func f, void* data) {
  wrapped_.push_back({f, data, this});
  return &wrapped_.back();
}

double NloptCallbacks::Call(unsigned n, const double* x, double* gradient, void* wrapped) {
  const auto* w = static_cast<const Wrapped*>(wrapped);
  // After a throw NLopt may still call (e.g. the constraints of the same point): stop again.
  if (w->owner->thrown_) throw nlopt::forced_stop();
  try {
    return w->f(n, x, gradient, w->data);
  } catch (...) {
    w->owner->thrown_ = std::current_exception();
    throw nlopt::forced_stop();
  }
}

void NloptCallbacks::Rethrow() const {
  if (thrown_) std::rethrow_exception(thrown_);
}

}  // namespace capsubot::detail
