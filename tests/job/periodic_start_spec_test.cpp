// The start of Newton's method as a user gives it (capsubot/job/periodic_start_spec.hpp): from
// a state, from rest or from the period, with the transient given or the start's default.

#include "capsubot/job/periodic_start_spec.hpp"

#include <gtest/gtest.h>

#include <string>
#include <variant>

#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::InvalidArgumentMessage;

const StartStateSpec kState{0.5, 0.1, -0.2, 1.0};

TEST(PeriodicStartSpec, GivesEachKindOfStart) {
  const PeriodicStart state = PeriodicStartSpec{kState, std::nullopt, 7, std::nullopt}.Build("a");
  ASSERT_TRUE(std::holds_alternative<PeriodicFromState>(state));
  EXPECT_EQ(std::get<PeriodicFromState>(state).state.x, 0.5);
  EXPECT_EQ(std::get<PeriodicFromState>(state).transient, 7);

  const PeriodicStartSpec at_rest{{}, RestStart(0.25, 2.0), std::nullopt, std::nullopt};
  const PeriodicStart rest = at_rest.Build("a");
  ASSERT_TRUE(std::holds_alternative<PeriodicFromRest>(rest));
  EXPECT_EQ(std::get<PeriodicFromRest>(rest).x0, 0.25);
  EXPECT_EQ(std::get<PeriodicFromRest>(rest).psi, 2.0);
  EXPECT_EQ(std::get<PeriodicFromRest>(rest).transient, PeriodicFromRest{}.transient);

  const PeriodicStart known = PeriodicStartSpec{kState, std::nullopt, std::nullopt, 3}.Build("a");
  ASSERT_TRUE(std::holds_alternative<PeriodicOfPeriod>(known));
  EXPECT_EQ(std::get<PeriodicOfPeriod>(known).period, 3);
  EXPECT_EQ(std::get<PeriodicOfPeriod>(known).state.psi, 1.0);
}

TEST(PeriodicStartSpec, RefusesTwoStartsAndAPeriodWithATransientInTheFrontEndsNames) {
  const FlagNames flags = {{"x0", "--x0"},
                           {"u0", "--u0"},
                           {"v0", "--v0"},
                           {"psi", "--psi"},
                           {"from_rest", "--from-rest"},
                           {"transient", "--transient"},
                           {"period", "--period"}};
  const PeriodicStartSpec both{kState, RestStart(0.5, 0.0), std::nullopt, std::nullopt};
  EXPECT_EQ(InvalidArgumentMessage([&] { both.Build("ask", flags); }),
            "--from-rest gives the start: do not give --x0, --u0, --v0 or --psi with it");
  const PeriodicStartSpec period_and_transient{kState, std::nullopt, 5, 2};
  EXPECT_EQ(InvalidArgumentMessage([&] { period_and_transient.Build("ask", flags); }),
            "--period and --transient are exclusive: with the period given, Newton starts at the "
            "start itself");
  EXPECT_EQ(InvalidArgumentMessage([&] {
              period_and_transient.Build("ask");
            }).rfind("period and transient are exclusive", 0),
            0u);
}

}  // namespace
}  // namespace capsubot
