#pragma once
// Abandoning a long computation from outside (a user's Ctrl-C): the optimisers, Newton
// shooting and every run of starts from rest ask an Interrupt, given in their options, as they
// go. The library itself never stops a run this way; a front end (the Python module) does.

#include <functional>

namespace capsubot {

/// Asked often by a long computation, always on the thread that called it (never on a worker
/// thread): at every evaluation of an optimiser's objective, every map evaluation of Newton
/// shooting and every period of its transient, after every block of simulated starts. It returns to
/// let the run go on, or throws to abandon it: the exception leaves the computation unchanged, once
/// its worker threads have stopped, and no result is returned. Empty: never asked. It may be asked
/// thousands of times a second: it must be cheap (a front end reads a flag, or a clock every so
/// often).
using Interrupt = std::function<void()>;

/// Asks `interrupt` (nothing when it is empty); what it throws goes through.
inline void Poll(const Interrupt& interrupt) {
  if (interrupt) interrupt();
}

}  // namespace capsubot
