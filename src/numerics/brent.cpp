#include "numerics/brent.hpp"

#include <vector>

namespace capsubot::detail {
namespace {

struct Free {
  void operator()(gsl_root_fsolver* s) const { gsl_root_fsolver_free(s); }
};

thread_local std::vector<std::unique_ptr<gsl_root_fsolver, Free>> t_solvers;  // by depth
thread_local std::size_t t_depth = 0;

}  // namespace

BrentLease::BrentLease() {
  static const bool handler_off = (gsl_set_error_handler_off(), true);
  (void)handler_off;
  if (t_solvers.size() <= t_depth) {
    t_solvers.emplace_back(gsl_root_fsolver_alloc(gsl_root_fsolver_brent));
  }
  solver_ = t_solvers[t_depth++].get();
}

BrentLease::~BrentLease() { --t_depth; }

}  // namespace capsubot::detail
