// Each problem's options from the user's search settings (capsubot/optimize/optimize_request.hpp).

#include "capsubot/optimize/optimize_request.hpp"

namespace capsubot {
namespace {

// The gait asked for: force bound, stability, time limit and local polish, with P2's default
// search. P3 asks it too, for the P2 optimum it starts from.
ForcingDesignOptions GaitOptionsFor(const SearchRequest& request) {
  ForcingDesignOptions d;
  d.gait = request.gait;
  d.local_algorithm = request.local_algorithm;
  d.max_time = request.max_time;
  d.interrupt = request.interrupt;
  return d;
}

}  // namespace

PhaseOptions PhaseOptionsFor(const SearchRequest& request) {
  PhaseOptions p;
  // P1 optimises the phase of a given force: no bound.
  p.gait.rho_max = request.gait.rho_max;
  p.gait.margins = request.gait.margins;
  p.max_time = request.max_time;
  p.interrupt = request.interrupt;
  return p;
}

ForcingDesignOptions ForcingOptionsFor(const SearchRequest& request) {
  ForcingDesignOptions d = GaitOptionsFor(request);
  d.effort.global_algorithm = request.global_algorithm;
  if (request.starts) d.effort.starts = *request.starts;
  d.effort.global_evaluations = request.global_evaluations;
  d.hops = request.hops;
  return d;
}

FourierOptions FourierOptionsFor(const SearchRequest& request) {
  FourierOptions f;
  f.harmonic = GaitOptionsFor(request);
  f.harmonics = request.harmonics;
  f.search.global_algorithm = request.global_algorithm;
  if (request.starts) f.search.starts = *request.starts;
  f.search.global_evaluations = request.global_evaluations;
  return f;
}

}  // namespace capsubot
