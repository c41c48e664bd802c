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

/// The small robot of docs/tutorial.md: shell 30 g, gap 10 mm, mu 0.3, e 0.7, motor
/// 0.05 sin(omega t + phase) + 0.05 N at 20 Hz. Its robust gait binds the stick margin, and
/// most of its starts from rest end with the inner body resting on the right wall.
inline DesignInput SmallRobot() {
  DesignInput in;
  in.m1 = 0.03;
  in.L = 0.01;
  in.mu = 0.3;
  in.e = 0.7;
  in.force.amplitude = 0.05;
  in.force.bias = 0.05;
  in.frequency_min = in.frequency_max = 20.0;
  return in;
}

}  // namespace capsubot::testing
