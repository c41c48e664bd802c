#pragma once
// The example robot of docs/design.md and examples/robot.toml, shared by the design tests and
// benchmarks: m1 = 0.2 kg, L = 20 mm, mu = 0.3, e = 0.7, motor 0.5 sin(omega t + phase) + 0.1 N
// at 20 Hz, default robust-gait margins.

#include "capsubot/design/design.hpp"

namespace capsubot::testing {

inline DesignInput ExampleRobot() {
  DesignInput in;
  in.m1 = 0.2;
  in.L = 0.02;
  in.mu = 0.3;
  in.e = 0.7;
  in.force.amplitude = 0.5;
  in.force.bias = 0.1;
  in.frequency_min = in.frequency_max = 20.0;
  return in;
}

}  // namespace capsubot::testing
