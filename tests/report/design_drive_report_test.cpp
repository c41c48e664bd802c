// The report of a drive design (docs/design.md, "Part (c)"): the JSON's keys and numbers and
// the text's force formula, on a result built here by hand (no search), so that each number
// printed is known: the speed in sqrt(mu g L) is computed here from the ladder's T0 and mean
// velocity, the backward force is the forward one negated.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "capsubot/report/design_json.hpp"
#include "capsubot/report/design_text.hpp"
#include "design/example_robot.hpp"

namespace capsubot {
namespace {

DriveDesignResult HandMadeDrive(bool pulse) {
  DriveDesignResult r;
  ReachResult step;
  step.drive = pulse ? DriveFamily::Pulse(2) : DriveFamily::Fourier(1);
  step.T0 = 0.1;
  step.alpha = 0.2;
  step.mean_velocity = 0.05;
  step.forcing = Forcing::Harmonic(0.05, 0.01, 0.0);
  r.ladder.push_back(step);
  if (pulse) {
    r.force.mean = 0.05;
    r.force.levels = {0.4, -0.3};
    r.force.switches = {0.0, 3.0};
    r.force.max_abs = 0.4;
    r.backward_force = r.force;
    r.backward_force.mean = -0.05;
    r.backward_force.levels = {-0.4, 0.3};
  } else {
    r.force.mean = 0.1;
    r.force.cos = {-0.2};
    r.force.sin = {0.3};
    r.force.max_abs = 0.46;
    r.backward_force = r.force;
    r.backward_force.mean = -0.1;
    r.backward_force.cos = {0.2};
    r.backward_force.sin = {-0.3};
  }
  r.forward.direction = Direction::kForward;
  r.forward.status = FromRestStatus::kOk;
  r.forward.m2_kg = 0.05;
  r.forward.frequency_hz = 12.0;
  r.forward.speed_mm_s = 40.0;
  r.backward = r.forward;
  r.backward.direction = Direction::kBackward;
  r.backward.speed_mm_s = -40.0;
  r.message = "hand-made";
  return r;
}

DesignJobResult JobWith(const DriveDesignResult& drive) {
  DesignJobResult job;
  job.input = testing::ExampleRobot();
  job.drive = drive;
  return job;
}

TEST(DesignDriveReport, JsonHoldsTheForceInNewtonsBothWaysAndTheLadder) {
  const nlohmann::json j = json::DesignJobJson(JobWith(HandMadeDrive(false)))["drive_design"];
  EXPECT_EQ(j["status"], "ok");
  EXPECT_EQ(j["message"], "hand-made");
  EXPECT_EQ(j["force_n"]["c"].get<double>(), 0.1);
  EXPECT_EQ(j["force_n"]["cos"][0].get<double>(), -0.2);
  EXPECT_EQ(j["force_n"]["sin"][0].get<double>(), 0.3);
  EXPECT_FALSE(j["force_n"].contains("levels"));
  EXPECT_EQ(j["backward_force_n"]["sin"][0].get<double>(), -0.3);
  EXPECT_EQ(j["forward"]["m2_kg"].get<double>(), 0.05);
  EXPECT_EQ(j["backward"]["speed_mm_s"].get<double>(), -40.0);
  ASSERT_EQ(j["ladder"].size(), 1U);
  EXPECT_DOUBLE_EQ(j["ladder"][0]["speed_sqrt_mu_g_L"].get<double>(), 0.05 / std::sqrt(0.1));
}

TEST(DesignDriveReport, APulseDriveHasLevelsAndSwitches) {
  const nlohmann::json j = json::DesignJobJson(JobWith(HandMadeDrive(true)))["drive_design"];
  EXPECT_EQ(j["force_n"]["levels"][1].get<double>(), -0.3);
  EXPECT_EQ(j["force_n"]["switches"][1].get<double>(), 3.0);
  EXPECT_FALSE(j["force_n"].contains("cos"));
  EXPECT_EQ(j["backward_force_n"]["levels"][0].get<double>(), -0.4);
}

TEST(DesignDriveReport, TextWritesTheForceWithItsSigns) {
  const std::string t = text::DesignJobText(JobWith(HandMadeDrive(false)));
  EXPECT_NE(t.find("F_N(s) = 0.1 - 0.2 cos 1s + 0.3 sin 1s N"), std::string::npos) << t;
  EXPECT_NE(t.find("F_N(s) = -0.1 + 0.2 cos 1s - 0.3 sin 1s N: the mirror image"),
            std::string::npos)
      << t;
  const std::string p = text::DesignJobText(JobWith(HandMadeDrive(true)));
  EXPECT_NE(p.find("F_N(s) = 0.4 N from s = 0, -0.3 N from s = 3"), std::string::npos) << p;
}

}  // namespace
}  // namespace capsubot
