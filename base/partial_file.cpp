#include "base/partial_file.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <mutex>
#include <set>
#include <stdexcept>

namespace hsb {
namespace {

// Temporary files in flight: a slot's path is complete before the slot is
// marked ready, so a signal handler never reads half a name.
constexpr int kSlots = 64;
constexpr std::size_t kPathBytes = 4096;
char registry_paths[kSlots][kPathBytes];
std::atomic<int> registry_state[kSlots];  // 0 free, 1 being written, 2 ready

int register_path(const std::string& path) {
  if (path.size() >= kPathBytes) return -1;
  for (int i = 0; i < kSlots; ++i) {
    int free = 0;
    if (!registry_state[i].compare_exchange_strong(free, 1)) continue;
    std::memcpy(registry_paths[i], path.c_str(), path.size() + 1);
    registry_state[i].store(2);
    return i;
  }
  return -1;  // more files in flight than slots: that one is not covered
}

void unregister_path(int slot) {
  if (slot >= 0) registry_state[slot].store(0);
}

// This host's name, once, as one path component with no extension in it.
const std::string& host_name() {
  static const std::string host = [] {
    char name[256] = {};
    std::string h = gethostname(name, sizeof name - 1) == 0 && name[0] ? name : "host";
    for (char& c : h)
      if (c == '/' || c == '.') c = '_';
    return h;
  }();
  return host;
}

const std::string kMarker = ".partial-";

}  // namespace

void remove_partial_files() {
  for (int i = 0; i < kSlots; ++i)
    if (registry_state[i].load() == 2) unlink(registry_paths[i]);
}

int remove_stale_partial_files(const std::filesystem::path& folder) {
  static const std::string own = kMarker + host_name() + "-";
  int removed = 0;
  std::error_code error;
  for (std::filesystem::directory_iterator it(folder, error), end; !error && it != end; it.increment(error)) {
    // ".NAME.partial-HOST-PID.EXT" of this host: the digits after the host.
    const std::string name = it->path().filename().string();
    const std::size_t at = name.rfind(own);
    if (name.empty() || name[0] != '.' || at == std::string::npos) continue;
    const std::size_t digits = at + own.size(), dot = name.find('.', digits);
    if (dot == std::string::npos || dot == digits) continue;
    const std::string pid_text = name.substr(digits, dot - digits);
    if (pid_text.find_first_not_of("0123456789") != std::string::npos || pid_text.size() > 9) continue;
    const pid_t pid = pid_t(std::stol(pid_text));
    if (pid == getpid() || kill(pid, 0) == 0 || errno != ESRCH) continue;  // alive, or not ours to judge
    std::error_code ignored;
    removed += std::filesystem::remove(it->path(), ignored) ? 1 : 0;
  }
  return removed;
}

namespace {

// Each folder once per process: the first file written there clears what
// a killed run left.
void clear_stale_once(const std::filesystem::path& folder) {
  static std::mutex mutex;
  static std::set<std::string> cleared;
  const std::lock_guard<std::mutex> lock(mutex);
  if (cleared.insert(folder.string()).second) remove_stale_partial_files(folder.empty() ? "." : folder);
}

}  // namespace

PartialFile::PartialFile(const std::string& final_path)
    : final_(final_path),
      temp_(final_.parent_path() / ("." + final_.stem().string() + kMarker + host_name() + "-" +
                                    std::to_string(getpid()) + final_.extension().string())) {
  clear_stale_once(final_.parent_path());
  slot_ = register_path(temp_.string());
}

PartialFile::~PartialFile() {
  std::error_code ignored;
  if (!done_) std::filesystem::remove(temp_, ignored);
  unregister_path(slot_);
}

void PartialFile::write(const void* data, std::size_t size) const {
  const auto fail = [&](const char* what) {
    throw std::runtime_error(final_.string() + ": cannot write the file (" + what + ": " + std::strerror(errno) + ")");
  };
  const int fd = ::open(temp_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) fail("open");
  const char* bytes = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t n = ::write(fd, bytes, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      if (n == 0) errno = ENOSPC;
      ::close(fd);
      fail("write");
    }
    bytes += n;
    size -= std::size_t(n);
  }
  // A full disk may only show when the data reaches it.
  if (::fsync(fd) != 0 && errno != EINVAL) {
    ::close(fd);
    fail("fsync");
  }
  if (::close(fd) != 0) fail("close");
}

void PartialFile::commit() {
  std::error_code error;
  std::filesystem::rename(temp_, final_, error);
  if (error) throw std::runtime_error(final_.string() + ": cannot move the finished file into place: " + error.message());
  done_ = true;
}

std::string scratch_path(const std::string& what, const std::string& extension) {
  return (std::filesystem::temp_directory_path() / ("hsb-" + what + "-" + std::to_string(::getpid()) + extension))
      .string();
}

}  // namespace hsb
