// A start state as a user gives it (capsubot/attract/start_state_spec.hpp): all four parts or
// the other start, with the messages in the front end's names.

#include "capsubot/attract/start_state_spec.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace capsubot {
namespace {

std::string Refusal(const StartStateSpec& spec, bool other_given, const FlagNames& names) {
  try {
    spec.Build(other_given, "from_rest", "ask", names);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(StartStateSpec, GivesTheStateOrLeavesTheStartToTheOtherKind) {
  const StartStateSpec all{0.5, 0.1, -0.2, 1.0};
  const std::optional<PhaseState> state = all.Build(false, "from_rest", "ask");
  ASSERT_TRUE(state.has_value());
  EXPECT_EQ(state->x, 0.5);
  EXPECT_EQ(state->u, 0.1);
  EXPECT_EQ(state->v, -0.2);
  EXPECT_EQ(state->psi, 1.0);
  EXPECT_FALSE(StartStateSpec{}.Build(true, "from_rest", "ask").has_value());
}

TEST(StartStateSpec, NamesTheStartsInTheFrontEndsNames) {
  const FlagNames flags = {{"x0", "--x0"},
                           {"u0", "--u0"},
                           {"v0", "--v0"},
                           {"psi", "--psi"},
                           {"from_rest", "--from-rest"}};
  const StartStateSpec part{0.5, std::nullopt, std::nullopt, std::nullopt};
  EXPECT_EQ(Refusal(part, true, flags),
            "--from-rest gives the start: do not give --x0, --u0, --v0 or --psi with it");
  EXPECT_EQ(Refusal(part, true, {}),
            "from_rest gives the start: do not give x0, u0, v0 or psi with it");
  EXPECT_EQ(Refusal(part, false, flags),
            "the start is missing: give all of --x0, --u0, --v0, --psi (or ask)");
}

}  // namespace
}  // namespace capsubot
