// Threads made ahead of need (spare_threads.h): they run their jobs, in
// parallel, report what a job threw, start work while another thread
// holds the dynamic loader's lock, and a forked child does not wait for
// threads it did not inherit.

#include <gtest/gtest.h>
#include <dlfcn.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>

#include "base/child_process.h"
#include "renderer/image/spare_threads.h"

namespace hsb {
namespace {

TEST(SpareThreads, RunAJobAndReportWhatItThrew) {
  make_spare_thread();
  int value = 0;
  run_on_spare_thread([&] { value = 42; }).get();
  EXPECT_EQ(value, 42);
  std::future<void> failed = run_on_spare_thread([] { throw std::runtime_error("no disk"); });
  EXPECT_THROW(failed.get(), std::runtime_error);
}

// Each job waits until the other has begun: run one after the other on
// one thread, neither would see the other (they give up after 10 s).
TEST(SpareThreads, RunJobsSideBySide) {
  make_spare_thread();
  std::mutex mutex;
  std::condition_variable changed;
  int begun = 0;
  const auto meet = [&] {
    std::unique_lock<std::mutex> lock(mutex);
    ++begun;
    changed.notify_all();
    return changed.wait_for(lock, std::chrono::seconds(10), [&] { return begun == 2; });
  };
  std::atomic<int> met{0};
  std::future<void> first = run_on_spare_thread([&] { met += meet(); });
  std::future<void> second = run_on_spare_thread([&] { met += meet(); });
  first.get();
  second.get();
  EXPECT_EQ(met.load(), 2);
}

// The reason they exist: a thread made now waits for a load to end, a
// spare one does not. The module's loading holds the loader's lock until
// the job lets it go (or 20 s pass); see loader_holding_module.cpp.
TEST(SpareThreads, StartWorkWhileTheLoaderHoldsItsLock) {
  make_spare_thread();
  int held[2], released[2];
  ASSERT_EQ(pipe(held), 0);
  ASSERT_EQ(pipe(released), 0);
  // The descriptors the module's resolver knows.
  ASSERT_EQ(dup2(held[1], 1001), 1001);
  ASSERT_EQ(dup2(released[0], 1000), 1000);
  void* module = nullptr;
  std::thread loader([&] { module = dlopen(HSB_LOADER_HOLDING_MODULE, RTLD_NOW | RTLD_LOCAL); });
  char byte = 0;
  ASSERT_EQ(read(held[0], &byte, 1), 1);  // the loader relocates the module
  std::future<void> job = run_on_spare_thread([&] { ASSERT_EQ(write(released[1], "r", 1), 1); });
  loader.join();
  job.get();
  ASSERT_NE(module, nullptr) << dlerror();
  const auto released_in_time = reinterpret_cast<int (*)()>(dlsym(module, "hsb_test_released"));
  ASSERT_NE(released_in_time, nullptr);
  EXPECT_EQ(released_in_time(), 1) << "the job did not start until the load had ended";
  dlclose(module);
  for (int fd : {held[0], held[1], released[0], released[1], 1000, 1001}) close(fd);
}

// A child of a fork has none of its parent's parked threads: its job
// gets a thread of its own. The fork waits for the parent's threads to
// sleep, as run_in_child's does: the parked thread may still be starting.
TEST(SpareThreads, RunAJobInAForkedChild) {
  make_spare_thread();
  wait_for_quiet_threads();
  EXPECT_EXIT(
      {
        std::future<void> job = run_on_spare_thread([] {});
        std::_Exit(job.wait_for(std::chrono::seconds(10)) == std::future_status::ready ? 0 : 1);
      },
      testing::ExitedWithCode(0), "");
}

}  // namespace
}  // namespace hsb
