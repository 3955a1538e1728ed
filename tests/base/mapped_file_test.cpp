// A file mapped read-only (mapped_file.h): its bytes as written, nothing
// for what cannot be mapped (no file, a directory, an empty file, a FIFO,
// a device), and a mapping that moves with its owner.

#include <gtest/gtest.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <future>
#include <string>

#include "base/mapped_file.h"
#include "tests/temp_dir.h"
#include "tests/without_waiting.h"

namespace hsb {
namespace {

std::filesystem::path scratch() { return test_temp_dir("mapped_file"); }

TEST(MappedFile, HoldsTheFilesBytes) {
  const std::filesystem::path path = scratch() / "bytes.bin";
  std::string written(3'000'000, '\0');
  for (std::size_t i = 0; i < written.size(); ++i) written[i] = char(i * 7919 % 251);
  std::ofstream(path, std::ios::binary) << written;
  const MappedFile mapped(path.string());
  ASSERT_EQ(mapped.size(), written.size());
  EXPECT_EQ(std::string(reinterpret_cast<const char*>(mapped.data()), mapped.size()), written);
}

TEST(MappedFile, IsEmptyWhereThereIsNothingToMap) {
  const std::filesystem::path dir = scratch();
  std::ofstream(dir / "empty.bin").close();
  for (const std::filesystem::path& path : {dir / "absent.bin", dir, dir / "empty.bin"}) {
    const MappedFile mapped(path.string());
    EXPECT_EQ(mapped.size(), 0u) << path;
    EXPECT_EQ(mapped.data(), nullptr) << path;
  }
}

// A FIFO (a NRRD's detached data file may name one) is never opened to
// wait for a writer: nothing to map, at once. Should the mapping wait,
// a writer comes after a few seconds to release it, and the test fails.
TEST(MappedFile, IsEmptyAtOnceForAFifoOrADevice) {
  const std::filesystem::path fifo = scratch() / "fifo.raw";
  std::filesystem::remove(fifo);
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(without_waiting(fifo, [&] { return MappedFile(fifo.string()).size(); }), 0u);
  EXPECT_EQ(MappedFile("/dev/zero").size(), 0u);
}

TEST(MappedFile, MovesWithItsOwner) {
  const std::filesystem::path path = scratch() / "moved.bin";
  std::ofstream(path, std::ios::binary) << "hyperstreamball";
  MappedFile first(path.string());
  const unsigned char* bytes = first.data();
  MappedFile second(std::move(first));
  EXPECT_EQ(first.size(), 0u);
  EXPECT_EQ(second.data(), bytes);
  MappedFile third;
  third = std::move(second);
  ASSERT_EQ(third.size(), 15u);
  EXPECT_EQ(std::string(reinterpret_cast<const char*>(third.data()), 15), "hyperstreamball");
}

}  // namespace
}  // namespace hsb
