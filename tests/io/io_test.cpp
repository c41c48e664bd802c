// Output files: atomic writes leave either the whole file or nothing, follow symlinks and
// report failed writes; temporary files are registered for removal on signals.

#include "capsubot/io/io.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

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

TEST(AtomicFile, SymlinkIsFollowedAndItsTargetReplaced) {
  // link -> target (a regular file): the new text lands in the target, the link stays a link
  // and no temporary is left in the folder.
  const fs::path dir = TempPath("capsubot_io_symlink");
  fs::create_directories(dir);
  std::ofstream(dir / "target.csv") << "old\n";
  fs::create_symlink("target.csv", dir / "link.csv");
  fs::create_symlink("link.csv", dir / "chain.csv");  // two links deep
  int checked = 0;
  for (const char* name : {"link.csv", "chain.csv"}) {
    AtomicFile f((dir / name).string(), "--out");
    EXPECT_EQ(fs::path(f.temp_path()).parent_path(), fs::canonical(dir));
    f.stream() << name << "\n";
    f.Commit();
    EXPECT_TRUE(fs::is_symlink(dir / "link.csv"));
    EXPECT_TRUE(fs::is_symlink(dir / "chain.csv"));
    std::ifstream in(dir / "target.csv");
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, name);
    ++checked;
  }
  EXPECT_EQ(checked, 2);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 3);
  fs::remove_all(dir);
}

TEST(AtomicFile, DanglingSymlinkCreatesItsTarget) {
  const fs::path dir = TempPath("capsubot_io_dangling");
  fs::create_directories(dir);
  fs::create_symlink("new.csv", dir / "link.csv");
  AtomicFile f((dir / "link.csv").string(), "--out");
  f.stream() << "x\n";
  f.Commit();
  EXPECT_TRUE(fs::is_symlink(dir / "link.csv"));
  EXPECT_TRUE(fs::is_regular_file(dir / "new.csv"));
  fs::remove_all(dir);
}

TEST(AtomicFile, SymlinkLoopIsAnErrorNamingTheFile) {
  const fs::path dir = TempPath("capsubot_io_loop");
  fs::create_directories(dir);
  fs::create_symlink("b", dir / "a");
  fs::create_symlink("a", dir / "b");
  const std::string path = (dir / "a").string();
  try {
    AtomicFile f(path, "--out");
    ADD_FAILURE() << "no exception";
  } catch (const IoError& e) {
    EXPECT_EQ(std::string(e.what()),
              "--out " + path + " cannot be written: more than 40 symbolic links");
  }
  fs::remove_all(dir);
}

TEST(AtomicFile, WriteFailureIsAWriteError) {
  AtomicFile f("/dev/full", "--trajectory");  // a device: written in place, every write fails
  f.stream() << std::string(1 << 16, 'x');
  try {
    f.Commit();
    ADD_FAILURE() << "no exception";
  } catch (const WriteError& e) {
    EXPECT_STREQ(e.what(), "--trajectory /dev/full cannot be written: No space left on device");
  }
}

TEST(TempFileRegistry, SlotsAreReusedAndBounded) {
  std::vector<int> slots;
  for (int i = 0; i < kMaxTempFiles; ++i)
    slots.push_back(RegisterTempFile("/tmp/x" + std::to_string(i)));
  EXPECT_EQ(RegisterTempFile("/tmp/one-too-many"), -1);  // full: not registered, no crash
  EXPECT_EQ(RegisterTempFile(std::string(kMaxTempPathBytes, 'p')), -1);  // too long
  int distinct = 0;
  for (int i = 0; i < kMaxTempFiles; ++i) distinct += slots[i] == i ? 1 : 0;
  EXPECT_EQ(distinct, kMaxTempFiles);
  for (int slot : slots) UnregisterTempFile(slot);
  EXPECT_EQ(RegisterTempFile("/tmp/again"), 0);  // freed slots are used again
  UnregisterTempFile(0);
  UnregisterTempFile(-1);  // "not registered": nothing to do
}

TEST(FormatNumber, RoundTripsEveryDouble) {
  for (double x : {0.1, 1.0 / 3.0, -2.944899971002, 6.283185307179586, 1e-300, 123456789.0}) {
    EXPECT_EQ(std::strtod(FormatNumber(x).c_str(), nullptr), x) << FormatNumber(x);
  }
  EXPECT_EQ(FormatNumber(0.5), "0.5");
}

TEST(FormatNumber, NaNIsAnEmptyCell) { EXPECT_EQ(FormatNumber(std::nan("")), ""); }

TEST(ReadLine, ReadsLinesAsGetlineDoesUpToItsLimit) {
  std::istringstream in("ab\n\ncdef\nlast");
  std::string line;
  std::vector<std::string> lines;
  while (ReadLine(in, line, "test", 4)) lines.push_back(line);
  EXPECT_EQ(lines, (std::vector<std::string>{"ab", "", "cdef", "last"}));
  EXPECT_TRUE(in.eof());  // the last line had no line break
  std::istringstream longer("abcde\n");
  try {
    ReadLine(longer, line, "shard file x.csv", 4);
    ADD_FAILURE() << "a line of 5 bytes was read with a limit of 4";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "shard file x.csv is invalid: a line longer than 4 bytes");
  }
}

TEST(ReadLine, ReadsAFileWhoseLinesCrossItsBufferAsGetlineDoes) {
  // Lines of 1 to 40,000 bytes from a file: many cross the file buffer's refills (a few KiB),
  // and the last one has no line break; std::getline reading the same file is the reference.
  const fs::path path = fs::temp_directory_path() / "capsubot_read_line.txt";
  {
    std::ofstream out(path, std::ios::binary);
    for (int i = 0; i < 200; ++i) {
      out << std::string(static_cast<std::size_t>(1 + (i * 7919) % 40000),
                         static_cast<char>('a' + i % 26));
      if (i < 199) out << '\n';
    }
  }
  std::ifstream ours(path, std::ios::binary), reference(path, std::ios::binary);
  std::string line, expected;
  int lines = 0;
  while (ReadLine(ours, line, "test", 40000)) {
    ASSERT_TRUE(std::getline(reference, expected));
    EXPECT_EQ(line, expected) << "line " << lines;
    ++lines;
  }
  EXPECT_FALSE(std::getline(reference, expected));
  EXPECT_EQ(lines, 200);
  fs::remove(path);
}

TEST(ReadTextFile, ReadsAFileUpToItsLimitAndRefusesMore) {
  const fs::path path = fs::temp_directory_path() / "capsubot_read_text_file.txt";
  std::ofstream(path) << "12345";
  EXPECT_EQ(ReadTextFile(path.string(), "--config", 5), "12345");
  try {
    ReadTextFile(path.string(), "--config", 4);
    ADD_FAILURE() << "a file of 5 bytes was read with a limit of 4";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()),
              "--config " + path.string() + " is invalid: expected a file of at most 4 bytes");
  }
  fs::remove(path);
  // A device without end is refused after limit + 1 bytes, not read forever.
  EXPECT_THROW(ReadTextFile("/dev/zero", "--config"), std::invalid_argument);
  EXPECT_THROW(ReadTextFile(path.string(), "--config"), IoError);
}

// Only a regular file is read: a pipe without a writer (whose open would wait for one for
// ever), a device and a folder are refused at once, naming the file and the rule.
TEST(ReadTextFile, RefusesPipesDevicesAndFoldersWithoutWaiting) {
  const fs::path folder = fs::temp_directory_path() / "capsubot_read_text_folder";
  fs::remove_all(folder);
  fs::create_directories(folder);
  const fs::path fifo = folder / "ff";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const std::vector<std::pair<std::string, std::string>> cases = {
      {fifo.string(), ", not a pipe or device"},
      {"/dev/zero", ", not a pipe or device"},
      {folder.string(), ", not a folder"}};
  int checked = 0;
  for (const auto& [path, why] : cases) {
    try {
      ReadTextFile(path, "--config");
      ADD_FAILURE() << path << " was read";
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()),
                "--config " + path + " is invalid: expected a file of at most 1048576 bytes" + why);
    }
    ++checked;
  }
  EXPECT_EQ(checked, 3);
  fs::remove_all(folder);
}

}  // namespace
}  // namespace capsubot
