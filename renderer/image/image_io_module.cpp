#include "renderer/image/image_io_module.h"

#include <dlfcn.h>
#include <pthread.h>

#include <filesystem>
#include <future>
#include <mutex>
#include <stdexcept>

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

std::once_flag started;
std::shared_future<Loaded> loading;

void start_loading() {
  std::call_once(started, [] {
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
