#include "detail/brent.hpp"

namespace capsubot::detail {

gsl_root_fsolver* ThreadBrentSolver() {
  static const bool handler_off = (gsl_set_error_handler_off(), true);
  (void)handler_off;
  struct Free {
    void operator()(gsl_root_fsolver* s) const { gsl_root_fsolver_free(s); }
  };
  thread_local std::unique_ptr<gsl_root_fsolver, Free> solver(
      gsl_root_fsolver_alloc(gsl_root_fsolver_brent));
  return solver.get();
}

}  // namespace capsubot::detail
