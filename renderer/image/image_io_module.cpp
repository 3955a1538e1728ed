#include "renderer/image/image_io_module.h"

#include <dlfcn.h>
#include <pthread.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <future>
#include <mutex>
#include <stdexcept>
#include <thread>

namespace hsb {
namespace {

constexpr const char* kModuleName = "libhsb_image_io.so";

// The module beside the running binary (build/hsb), else where this build
// made it (for the test binaries in their own folders).
void* open_module(std::string& tried) {
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  std::vector<std::string> places;
  if (!error) places.push_back((self.parent_path() / kModuleName).string());
  places.push_back(HSB_IMAGE_IO_MODULE);
  for (const std::string& place : places) {
    if (!std::filesystem::exists(place)) continue;
    if (void* handle = dlopen(place.c_str(), RTLD_NOW | RTLD_LOCAL)) return handle;
    tried += std::string(" ") + dlerror();
  }
  for (const std::string& place : places) tried += " " + place;
  return nullptr;
}

// The loaded module, or the reason it is not.
struct Loaded {
  const ImageIo* functions = nullptr;
  std::string failure;
};

Loaded load() {
  std::string tried;
  void* handle = open_module(tried);
  if (!handle) return {nullptr, "cannot load hsb's image module " + std::string(kModuleName) + ":" + tried};
  using Entry = const ImageIo* (*)();
  const auto entry = reinterpret_cast<Entry>(dlsym(handle, "hsb_image_io_functions"));
  if (!entry) return {nullptr, std::string(kModuleName) + " has no hsb_image_io_functions"};
  return {entry(), ""};
}

// Makes the thread pool's threads now. A thread made while the loader
// runs waits for it to end (the loader holds the lock that a new thread's
// thread-local storage needs), so a render's first parallel loop stalled
// behind the load for a tenth of a second or more (on Teem's helix at
// 2000², 0.12 s of 0.34 s of preparing). One task per thread, each
// waiting until all have started, makes every worker begin; the wait
// gives up after 0.1 s on a machine too busy to start them.
void start_thread_pool() {
  const int threads = int(std::min<std::size_t>(
      std::size_t(tbb::this_task_arena::max_concurrency()),
      tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism)));
  std::atomic<int> begun{0};
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::milliseconds(100);
  tbb::parallel_for(
      0, threads,
      [&](int) {
        ++begun;
        while (begun.load() < threads && std::chrono::steady_clock::now() < give_up) std::this_thread::yield();
      },
      tbb::simple_partitioner());
}

std::once_flag started;
std::shared_future<Loaded> loading;

void start_loading() {
  std::call_once(started, [] {
    start_thread_pool();
    loading = std::async(std::launch::async, load).share();
    // fork() copies only its own thread: one taken while the loader holds
    // its lock on another would leave the child's loader locked for ever.
    pthread_atfork([] { loading.wait(); }, nullptr, nullptr);
  });
}

}  // namespace

void preload_image_io() { start_loading(); }

void finish_image_io_preload() {
  if (loading.valid()) loading.wait();
}

const ImageIo& image_io() {
  start_loading();
  const Loaded& loaded = loading.get();
  if (!loaded.functions) throw std::runtime_error(loaded.failure);
  return *loaded.functions;
}

}  // namespace hsb
