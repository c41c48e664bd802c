// Text broken into lines of a width (capsubot/io/wrap_text.hpp), as the command line's helps and
// the Python module's docstrings wrap theirs.

#include "capsubot/io/wrap_text.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace capsubot {
namespace {

using Lines = std::vector<std::string>;

TEST(WrapText, BreaksAtSpacesWithinTheWidth) {
  EXPECT_EQ(WrapText("the fastest gait checked from rest", 12),
            (Lines{"the fastest", "gait checked", "from rest"}));
  EXPECT_EQ(WrapText("a  b   c", 80), (Lines{"a b c"}));  // one space between words
  EXPECT_EQ(WrapText("one\ntwo three", 80), (Lines{"one", "two three"}));  // its own breaks
  for (const std::string& line : WrapText(std::string(300, 'x') + " y", 50)) {
    EXPECT_LE(line.size(), 50u) << line;
  }
}

TEST(WrapText, AWordWiderThanTheWidthIsCutAfterACommaWhereItCan) {
  EXPECT_EQ(WrapWords({"columns:", "phi,x,u,v,y"}, 8), (Lines{"columns:", "phi,x,u,", "v,y"}));
  EXPECT_EQ(WrapWords({"abcdefghij"}, 4), (Lines{"abcd", "efgh", "ij"}));  // no comma: cut
}

}  // namespace
}  // namespace capsubot
