// Big buffers on transparent huge pages: what they hold is what an
// ordinary vector would, and where the kernel offers huge pages a buffer
// written for the first time is mapped 2 MB at a time.

#include <gtest/gtest.h>

#include <sys/resource.h>

#include <fstream>
#include <string>

#include "base/huge_pages.h"

namespace hsb {
namespace {

// The whole process's: the first writes are shared among the threads.
long minor_faults() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_minflt;
}

// The kernel's count of huge page faults it could not serve (no free 2 MB
// of memory): then the buffer got small pages, rightly.
long huge_page_fallbacks() {
  std::ifstream vmstat("/proc/vmstat");
  std::string name;
  long value = 0;
  while (vmstat >> name >> value)
    if (name == "thp_fault_fallback") return value;
  return 0;
}

// AddressSanitizer writes a byte of shadow for each eight of the buffer's,
// on pages of its own: a fault per 32 KB that no advice on the buffer
// removes. (This file is not instrumented, the code it tests is: the
// build says whether the process runs ASan's runtime.)
#if defined(HSB_ASAN_RUNTIME)
constexpr bool kShadowedMemory = true;
#else
constexpr bool kShadowedMemory = false;
#endif

bool huge_pages_offered() {
  std::ifstream setting("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string line;
  return std::getline(setting, line) && line.find("[never]") == std::string::npos;
}

TEST(HugePages, ReserveKeepsWhatTheVectorHeld) {
  std::vector<int> v = {3, 1, 4, 1, 5};
  reserve_on_huge_pages(v, 3'000'000);
  EXPECT_GE(v.capacity(), 3'000'000u);
  EXPECT_EQ(v, (std::vector<int>{3, 1, 4, 1, 5}));
  reserve_on_huge_pages(v, 10);  // room enough already: nothing changes
  EXPECT_EQ(v.size(), 5u);
}

TEST(HugePages, AssignHoldsTheValuesInTheRoomAsked) {
  std::vector<float> v(7, 2.0f);
  assign_on_huge_pages(v, 1000, 0.5f, 4000);
  EXPECT_EQ(v.size(), 1000u);
  EXPECT_GE(v.capacity(), 4000u);
  for (float x : v) ASSERT_EQ(x, 0.5f);
  advise_huge_pages(v.data() + 1, 3);  // less than a page, unaligned: a no-op
}

// The parallel first write clears exactly the range asked, from unaligned
// ends, large (pieces between huge-page boundaries, on every core) and
// small (one thread).
TEST(HugePages, FirstTouchZeroesExactlyTheRange) {
  for (const std::size_t bytes : {std::size_t(20) << 20, std::size_t(5000)}) {
    std::vector<unsigned char> buffer(bytes + 64, 0xab);
    first_touch_in_parallel(buffer.data() + 3, bytes);
    EXPECT_EQ(buffer[0], 0xab);
    EXPECT_EQ(buffer[2], 0xab);
    std::size_t zeros = 0;
    for (std::size_t i = 3; i < bytes + 3; ++i) zeros += buffer[i] == 0;
    EXPECT_EQ(zeros, bytes);
    for (std::size_t i = bytes + 3; i < buffer.size(); ++i) ASSERT_EQ(buffer[i], 0xab) << i;
  }
}

// 64 MB written once: 16,384 faults of 4 KB pages, or a few dozen of 2 MB.
TEST(HugePages, ABufferWrittenOnceTakesFewFaults) {
  if (!huge_pages_offered()) GTEST_SKIP() << "transparent huge pages are off on this machine";
  if (kShadowedMemory) GTEST_SKIP() << "AddressSanitizer's shadow memory faults a page per 32 KB written";
  constexpr std::size_t kValues = std::size_t(16) << 20;
  std::vector<float> v;
  const long fallbacks = huge_page_fallbacks(), before = minor_faults();
  assign_on_huge_pages(v, kValues, 1.0f);
  const long faults = minor_faults() - before;
  if (huge_page_fallbacks() != fallbacks) GTEST_SKIP() << "the kernel had no free huge pages";
  EXPECT_LT(faults, 4000);
  EXPECT_EQ(v[kValues - 1], 1.0f);
}

}  // namespace
}  // namespace hsb
