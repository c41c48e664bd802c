// Output files: atomic writes leave either the whole file or nothing; numbers round-trip.

#include "capsubot/io.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "test_utils.hpp"

namespace capsubot {
namespace {

namespace fs = std::filesystem;
using testing::TempPath;

TEST(AtomicFile, CommitPublishesTheWholeFile) {
  const fs::path p = TempPath("capsubot_io_commit.csv");
  {
    AtomicFile f(p.string(), "--out");
    f.stream() << "a,b\n1,2\n";
    EXPECT_FALSE(fs::exists(p));  // nothing under the final name before Commit
    f.Commit();
  }
  std::ifstream in(p);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text, "a,b\n1,2\n");
  fs::remove(p);
}

TEST(AtomicFile, AbandonedFileLeavesNothingBehind) {
  const fs::path p = TempPath("capsubot_io_abandon.csv");
  std::string temp;
  try {
    AtomicFile f(p.string(), "--out");
    temp = f.temp_path();
    f.stream() << "half a row";
    throw std::runtime_error("interrupted");
  } catch (const std::runtime_error&) {
  }
  EXPECT_FALSE(fs::exists(p));
  EXPECT_FALSE(fs::exists(temp));
}

TEST(AtomicFile, UnwritableDirectoryNamesTheFileAndReason) {
  try {
    AtomicFile f("/nonexistent-dir/x.csv", "--trajectory");
    FAIL() << "no exception";
  } catch (const IoError& e) {
    EXPECT_STREQ(e.what(),
                 "--trajectory /nonexistent-dir/x.csv cannot be written: No such file or "
                 "directory");
  }
}

TEST(AtomicFile, SpecialFilesAreWrittenInPlace) {
  // /dev/null is not a regular file: no temporary beside it, no rename over it.
  AtomicFile f("/dev/null", "--events");
  EXPECT_EQ(f.temp_path(), "/dev/null");
  f.stream() << "x\n";
  f.Commit();
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
  AtomicFile out("-", "--events");  // standard output
  EXPECT_EQ(out.temp_path(), "/dev/stdout");
}

TEST(FormatNumber, RoundTripsEveryDouble) {
  for (double x : {0.1, 1.0 / 3.0, -2.944899971002, 6.283185307179586, 1e-300, 123456789.0}) {
    EXPECT_EQ(std::strtod(FormatNumber(x).c_str(), nullptr), x) << FormatNumber(x);
  }
  EXPECT_EQ(FormatNumber(0.5), "0.5");
}

TEST(FormatNumber, NaNIsAnEmptyCell) { EXPECT_EQ(FormatNumber(std::nan("")), ""); }

}  // namespace
}  // namespace capsubot
