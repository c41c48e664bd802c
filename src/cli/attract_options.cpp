#include "capsubot/cli/attract_options.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <stdexcept>

#include "capsubot/cli/progress.hpp"
#include "capsubot/cli/setting_options.hpp"
#include "capsubot/job/motion_settings.hpp"
#include "capsubot/job/params_settings.hpp"

namespace capsubot::cli {

void AddRobotOptions(CLI::App& cmd, RobotOptions& o, bool with_motion) {
  AddForcingOptions(cmd, o.forcing);
  AddParamsOptions(cmd, o.model.params);
  AddSettings(cmd, o.model, MassRatioSettings(), {{"alpha", "--alpha"}});
  cmd.get_option("--alpha")->required();
  if (!with_motion) return;
  AddSettings(cmd, o.motion, MotionSettings(), MotionFlagNames());
}

AttractorsJobOptions MapJobOptions(const RobotOptions& robot, const std::string& starts,
                                   int threads) {
  AttractorsJobOptions o;
  o.robot = robot.Model();
  o.starts = ParseStartGrid("--starts", starts);
  o.attractor.motion = robot.motion;
  o.attractor.threads = threads;
  return o;
}

PhaseState ParseRestStart(const char* name, const std::string& text) {
  const std::size_t comma = text.find(',');
  const std::string a = text.substr(0, comma);
  const std::string b = comma == std::string::npos ? "" : text.substr(comma + 1);
  char* end1 = nullptr;
  char* end2 = nullptr;
  const double x0 = std::strtod(a.c_str(), &end1);
  const double psi = std::strtod(b.c_str(), &end2);
  if (a.empty() || b.empty() || end1 != a.c_str() + a.size() || end2 != b.c_str() + b.size()) {
    throw std::invalid_argument(
        fmt::format("{} = {} is invalid: expected X0,PSI (two numbers, e.g. 0.5,1)", name, text));
  }
  return RestStart(x0, psi);
}

const FlagNames& MotionFlagNames() {
  static const FlagNames names = [] {
    FlagNames n = WithDashedFlags({}, MotionSettings());
    n.emplace_back("threads", "--threads");
    return n;
  }();
  return names;
}

void StartStateOptions::Add(CLI::App& cmd) {
  options[0] = cmd.add_option("--x0", state.x, "start: position of the inner body");
  options[1] = cmd.add_option("--u0", state.u, "start: relative velocity");
  options[2] = cmd.add_option("--v0", state.v, "start: capsule velocity");
  options[3] =
      cmd.add_option("--psi", state.psi, "start: forcing phase (F = A sin(psi + phi0) + c there)")
          ->type_name(kPhase);
}

StartStateSpec StartStateOptions::Spec() const {
  const auto part = [this](int i, double value) {
    return options[i]->count() > 0 ? std::optional<double>(value) : std::nullopt;
  };
  return {part(0, state.x), part(1, state.u), part(2, state.v), part(3, state.psi)};
}

StartsProgress CountProgress(const char* what) {
  if (!ProgressShown()) return {};
  auto bar = std::make_shared<ProgressBar>(what);
  const auto start = std::chrono::steady_clock::now();
  return [bar, start](std::int64_t done, std::int64_t total) {
    const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
    bar->Update(static_cast<double>(done), static_cast<double>(total), seconds.count());
  };
}

}  // namespace capsubot::cli
