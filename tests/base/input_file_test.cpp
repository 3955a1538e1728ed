// Files a user or a data file names (input_file.h): a regular file is
// opened and read no further than its size; a FIFO, a device, a folder or
// a missing file is refused with its reason, at once, never waited on.

#include <gtest/gtest.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <future>
#include <string>

#include "base/input_file.h"
#include "tests/temp_dir.h"
#include "tests/without_waiting.h"

namespace hsb {
namespace {

std::filesystem::path scratch() { return test_temp_dir("input_file"); }

const std::string kNotRegular = "not a regular file (a FIFO, socket or device)";

TEST(InputFile, ReadsARegularFileNoFurtherThanItsSize) {
  const std::filesystem::path path = scratch() / "bytes.txt";
  std::ofstream(path, std::ios::binary) << "hyperstreamball";
  const InputFile file(path.string());
  ASSERT_EQ(file.why(), "");
  EXPECT_GE(file.descriptor(), 0);
  EXPECT_EQ(file.size(), 15u);
  EXPECT_EQ(file.read(0, 100), "hyperstreamball");
  EXPECT_EQ(file.read(5, 6), "stream");
  EXPECT_EQ(file.read(15, 4), "");
  EXPECT_EQ(file.read(40, 4), "");
  EXPECT_EQ(unreadable_input(path.string()), "");
  EXPECT_EQ(file_head(path.string(), 5), "hyper");
  EXPECT_EQ(file_tail(path.string(), 4), "ball");
  EXPECT_EQ(file_tail(path.string(), 100), "hyperstreamball");
}

TEST(InputFile, SaysWhyItIsNoFileToRead) {
  const std::filesystem::path dir = scratch();
  EXPECT_EQ(InputFile((dir / "absent.txt").string()).why(), "no such file");
  EXPECT_EQ(InputFile((dir / "absent" / "deeper.txt").string()).why(), "no such file");
  EXPECT_EQ(InputFile(dir.string()).why(), "a directory, not a file");
  // Devices never end: hashing /dev/zero or /dev/urandom would not.
  for (const char* device : {"/dev/zero", "/dev/urandom", "/dev/null"}) {
    const InputFile file(device);
    EXPECT_EQ(file.why(), kNotRegular) << device;
    EXPECT_EQ(file.descriptor(), -1) << device;
    EXPECT_EQ(file.read(0, 8), "") << device;
    EXPECT_EQ(unreadable_input(device), kNotRegular) << device;
    EXPECT_EQ(file_head(device, 8), "") << device;
    EXPECT_EQ(file_tail(device, 8), "") << device;
  }
}

TEST(InputFile, NeverWaitsOnAFifo) {
  const std::filesystem::path fifo = scratch() / "fifo.raw";
  std::filesystem::remove(fifo);
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(without_waiting(fifo, [&] { return InputFile(fifo.string()).why(); }), kNotRegular);
  EXPECT_EQ(without_waiting(fifo, [&] { return unreadable_input(fifo.string()); }), kNotRegular);
  EXPECT_EQ(without_waiting(fifo, [&] { return file_head(fifo.string(), 8); }), "");
  EXPECT_EQ(without_waiting(fifo, [&] { return file_tail(fifo.string(), 8); }), "");
}

TEST(InputFile, AFileNamedInAnotherIsBesideIt) {
  EXPECT_EQ(file_named_in("/data/a/header.nhdr", "values.raw"), "/data/a/values.raw");
  EXPECT_EQ(file_named_in("/data/a/header.nhdr", "../b/values.raw"), "/data/b/values.raw");
  EXPECT_EQ(file_named_in("/data/a/header.nhdr", "/dev/zero"), "/dev/zero");
}

}  // namespace
}  // namespace hsb
