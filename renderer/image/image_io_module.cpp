#include "renderer/image/image_io_module.h"

#include <dlfcn.h>
#include <sys/single_threaded.h>
#include <unistd.h>
#include <pthread.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <new>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <future>
#include <mutex>
#include <stdexcept>
#include <system_error>
#include <thread>

#include "base/process_memory.h"
#include "base/thread_room.h"
#include "renderer/image/spare_threads.h"

namespace hsb {
namespace {

constexpr const char* kModuleName = "libhsb_image_io.so";

// Whether the module may be loaded with RTLD_DEEPBIND, its libraries
// looking up their symbols among themselves before the process's global
// scope. Without it every one of the 168,000 symbol lookups of OIIO's 261
// libraries first walks the 116 libraries hsb links (VTK, HDF5, Pango and
// theirs): on Teem's helix at 2000² the load took 0.32 s and the render
// waited 0.15 s for it, against 0.20 s and none with it.
//
// Deep binding changes which definition a symbol binds to only where two
// exist. The process must not hold a second copy of what those libraries
// share with it: an interposed allocator (a preloaded malloc, a
// sanitizer's) would meet blocks from libc's; the executable's copies of
// libstdc++'s streams (copy relocations) are the only ones constructed,
// and of libc's __libc_single_threaded the only one cleared when threads
// start (a library reading libc's own would count references without
// atomics). hsb is compiled without copy relocations
// (-mno-direct-extern-access, CMakeLists.txt); here each of those symbols,
// as hsb itself is bound to it, must be the definition of the library
// that defines it (where a deep-bound library binds), or the module loads
// the ordinary way.
bool deep_binding_is_safe() {
  void* libc = dlopen("libc.so.6", RTLD_NOW | RTLD_NOLOAD);
  void* libstdcxx = dlopen("libstdc++.so.6", RTLD_NOW | RTLD_NOLOAD);
  if (!libc || !libstdcxx) {
    for (void* opened : {libc, libstdcxx})
      if (opened) dlclose(opened);
    return false;
  }
  using New = void* (*)(std::size_t);
  using Delete = void (*)(void*);
  const auto at = [](auto function) { return reinterpret_cast<const void*>(function); };
  struct Shared {
    void* owner;
    const char* name;
    const void* bound;
  };
  const Shared shared[] = {
      {libc, "malloc", at(&malloc)},
      {libc, "calloc", at(&calloc)},
      {libc, "realloc", at(&realloc)},
      {libc, "free", at(&free)},
      {libc, "aligned_alloc", at(&aligned_alloc)},
      {libc, "posix_memalign", at(&posix_memalign)},
      {libc, "stdin", &stdin},
      {libc, "stdout", &stdout},
      {libc, "stderr", &stderr},
      {libc, "environ", &environ},
      {libc, "__libc_single_threaded", &__libc_single_threaded},
      {libstdcxx, "_Znwm", at(static_cast<New>(&::operator new))},
      {libstdcxx, "_Znam", at(static_cast<New>(&::operator new[]))},
      {libstdcxx, "_ZdlPv", at(static_cast<Delete>(&::operator delete))},
      {libstdcxx, "_ZdaPv", at(static_cast<Delete>(&::operator delete[]))},
      {libstdcxx, "_ZSt3cin", &std::cin},
      {libstdcxx, "_ZSt4cout", &std::cout},
      {libstdcxx, "_ZSt4cerr", &std::cerr},
      {libstdcxx, "_ZSt4clog", &std::clog}};
  bool same = true;
  for (const Shared& s : shared) same = same && dlsym(s.owner, s.name) == s.bound;
  dlclose(libc);
  dlclose(libstdcxx);
  return same;
}

// The module beside the running binary (build/hsb), else where this build
// made it (for the test binaries in their own folders).
void* open_module(std::string& tried) {
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  std::vector<std::string> places;
  if (!error) places.push_back((self.parent_path() / kModuleName).string());
  places.push_back(HSB_IMAGE_IO_MODULE);
  // Lazily: a function of those libraries is bound at its first call, and
  // most are never called. Binding all of them at the load (RTLD_NOW)
  // took a 40² picture's output 0.39 s, against 0.23 s lazily, most of
  // the time of every small picture in a batch.
  const int flags = RTLD_LAZY | RTLD_LOCAL | (image_io_binds_deep() ? RTLD_DEEPBIND : 0);
  for (const std::string& place : places) {
    if (!std::filesystem::exists(place)) continue;
    if (void* handle = dlopen(place.c_str(), flags)) return handle;
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
bool loads_when_needed = false;  // no thread for the load: image_io() runs it
double file_resident_at_start = 0.0;  // when the load began

void start_loading() {
  std::call_once(started, [] {
    // Without room for the threads below and the libraries', nothing is
    // started: image_io() says why (preload_image_io must not throw).
    try {
      fit_threads_to_room();
    } catch (const ResourceError&) {
      return;
    }
    start_thread_pool();
    make_spare_thread();  // for the picture's writer, which starts while the module loads
    file_resident_at_start = file_resident_bytes();
    try {
      loading = std::async(std::launch::async, load).share();
    } catch (const std::system_error&) {
      // The system refused the thread after all (another process of the
      // user's took the room): the module loads where it is first needed.
      loading = std::async(std::launch::deferred, load).share();
      loads_when_needed = true;
      return;
    }
    // fork() copies only its own thread: one taken while the loader holds
    // its lock on another would leave the child's loader locked for ever.
    pthread_atfork([] { loading.wait(); }, nullptr, nullptr);
  });
}

}  // namespace

void preload_image_io() { start_loading(); }

bool image_io_binds_deep() {
  static const bool deep = deep_binding_is_safe();
  return deep;
}

double image_io_pending_bytes() {
  // A whole load, measured in hsb (Debian 12, OIIO 2.4): its libraries'
  // files come to 72 MB resident more, their relocations and constructors
  // (OIIO's string table among them) to 43 MB of anonymous memory.
  constexpr double kFiles = 72e6, kAnonymous = 43e6;
  if (!loading.valid() || loading.wait_for(std::chrono::seconds(0)) == std::future_status::ready) return 0.0;
  // The files resident since the load began are mostly its libraries'
  // (hsb's own code paged in meanwhile is a few megabytes). Their share of
  // a whole load's stands for the share of the whole that is in: the
  // relocations go with the files, library by library, and only the
  // constructors come at the end. Counting all of the anonymous part until
  // the load returned put fig09's estimate with 27,500 to 157,000 sources
  // 5–45 MB over its peak, which sometimes passed the memory test's 25 %;
  // the share puts it within 15 % either way.
  const double files_in = std::clamp(file_resident_bytes() - file_resident_at_start, 0.0, kFiles);
  return (1.0 - files_in / kFiles) * (kFiles + kAnonymous);
}

void finish_image_io_preload() {
  if (loading.valid() && !loads_when_needed) loading.wait();
}

const ImageIo& image_io() {
  start_loading();
  fit_threads_to_room();  // when start_loading found no room, why
  const Loaded& loaded = loading.get();
  if (!loaded.functions) throw std::runtime_error(loaded.failure);
  return *loaded.functions;
}

}  // namespace hsb
