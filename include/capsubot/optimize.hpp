#pragma once
// The optimisation problems of docs/model.md section 7 (P1 phase, P2 harmonic force, P3 Fourier
// force), each in its own header; this one includes them all.

#include "capsubot/optimize_forcing.hpp"
#include "capsubot/optimize_fourier.hpp"
#include "capsubot/optimize_phase.hpp"
#include "capsubot/optimize_reach.hpp"
#include "capsubot/optimize_request.hpp"
#include "capsubot/optimize_result.hpp"
