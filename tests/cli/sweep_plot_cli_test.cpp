// `capsubot sweep --plot`: the CSV drawn by gnuplot into a PNG, a curve for one grid axis and a
// map for two; bad plots refused before the sweep runs (exit 2, the message names the flag, no
// file written). The PNG is checked by its signature and its size (the script's 1000 x 700
// pixels, read from the file's IHDR chunk).

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::RunCli;
using testing::TempPath;

const std::string kSweep = "sweep --A 0.05 --c 0.02 --stability";
const std::string kModel = " --T0 0.1 --e 0.5";

// The width and height of a PNG file (0, 0 if it is none).
std::pair<std::uint32_t, std::uint32_t> PngSize(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)),
                                         std::istreambuf_iterator<char>());
  const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (bytes.size() < 24 || !std::equal(signature, signature + 8, bytes.begin())) return {0, 0};
  const auto be32 = [&](std::size_t at) {
    return (std::uint32_t{bytes[at]} << 24) | (std::uint32_t{bytes[at + 1]} << 16) |
           (std::uint32_t{bytes[at + 2]} << 8) | std::uint32_t{bytes[at + 3]};
  };
  return {be32(16), be32(20)};
}

TEST(SweepPlot, DrawsACurveForOneAxisAndAMapForTwo) {
  const auto csv = TempPath("plot.csv"), png = TempPath("plot.png");
  const std::vector<std::string> grids = {
      "--grid phi0=-3:-2.4:13" + kModel, "--grid phi0=-3:-2.4:7 --grid e=0.3:1:5 --T0 0.1",
      "--grid T0=0.05:0.2:9:log --e 0.5 --phi0 -2.8 --plot-column I"};
  for (const std::string& grid : grids) {
    SCOPED_TRACE(grid);
    const auto r =
        RunCli(kSweep + " " + grid + " -o " + csv.string() + " --plot " + png.string() + " 2>&1");
    ASSERT_EQ(r.status, 0) << r.out;
    EXPECT_TRUE(std::filesystem::exists(csv));
    EXPECT_EQ(PngSize(png), (std::pair<std::uint32_t, std::uint32_t>{1000, 700}));
    std::filesystem::remove(png);
  }
}

TEST(SweepPlot, RefusesWhatCannotBeDrawnBeforeTheSweepRuns) {
  const auto csv = TempPath("refused.csv"), png = TempPath("refused.png");
  const std::string files = kModel + " -o " + csv.string() + " --plot " + png.string();
  const std::vector<std::pair<std::string, std::string>> cases = {
      {" --grid phi0=-3:-2.4:3" + files + " --plot-column status",
       "--plot-column = status is invalid: expected a numeric column of this sweep: phi0, "},
      {" --grid phi0=-3:-2.4:3" + files + " --plot-column speed",
       "--plot-column = speed is invalid"},
      {" --grid phi0=-3:-2.4:3 --grid e=0.5,1 --grid T0=0.1,0.2 -o " + csv.string() + " --plot " +
           png.string(),
       "--plot over a grid of 3 axes is invalid: expected one axis (a curve) or two (a map)"},
      {" --grid phi0=-3:-2.4:3" + kModel + " -o - --plot " + png.string(),
       "--plot with --output = - is invalid: expected a file (-o FILE), which the plot reads"},
      {" --grid phi0=-3:-2.4:3" + files + " --shard 0/2",
       "--plot with --shard = 0/2 is invalid: expected the whole grid (draw the merged file)"},
      {" --grid phi0=-3:-2.4:3" + kModel + " -o " + csv.string() + " --plot-column I",
       "--plot-column requires --plot"},
  };
  for (const auto& [args, message] : cases) {
    SCOPED_TRACE(args);
    const auto r = RunCli(kSweep + args + " 2>&1");
    EXPECT_EQ(r.status, 2) << r.out;
    EXPECT_NE(r.out.find(message), std::string::npos) << r.out;
    EXPECT_FALSE(std::filesystem::exists(csv));
    EXPECT_FALSE(std::filesystem::exists(png));
  }
}

}  // namespace
}  // namespace capsubot
