#pragma once
// The optimisation problems of docs/model.md section 7 (P1 phase, P2 harmonic force, P3 Fourier
// force), each in its own header; this one includes them all.

#include "capsubot/optimize/optimize_forcing.hpp"
#include "capsubot/optimize/optimize_fourier.hpp"
#include "capsubot/optimize/optimize_phase.hpp"
#include "capsubot/optimize/optimize_request.hpp"
#include "capsubot/optimize/optimize_result.hpp"
