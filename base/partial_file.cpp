#include "base/partial_file.h"

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <mutex>
#include <set>
#include <stdexcept>
#include <utility>

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

// The scratch folder, for the signal handler: its path is complete before
// the process that made it is named, and only that process removes it (a
// forked child that inherits it does not).
char scratch_folder_path[kPathBytes];
std::atomic<pid_t> scratch_folder_owner{0};

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

// Whether the digits at `at` in `name`, ending there or at a '-' or '.',
// are the ID of a process that is gone. Never this one, nor one that is
// alive or not ours to signal (another user's, in a shared folder).
bool names_a_dead_process(const std::string& name, std::size_t at) {
  const std::size_t end = std::min(name.find_first_of("-.", at), name.size());
  const std::string pid_text = name.substr(at, end - at);
  if (pid_text.empty() || pid_text.size() > 9 || pid_text.find_first_not_of("0123456789") != std::string::npos)
    return false;
  const pid_t pid = pid_t(std::stol(pid_text));
  return pid != getpid() && kill(pid, 0) != 0 && errno == ESRCH;
}

// The mode a new file gets here: 0666 less the umask, which the kernel
// reports in /proc/self/status (umask() cannot be asked without setting
// it, for every thread at once).
mode_t new_file_mode() {
  static const mode_t mode = [] {
    std::ifstream status("/proc/self/status");
    for (std::string line; std::getline(status, line);)
      if (line.rfind("Umask:", 0) == 0) return mode_t(0666 & ~std::strtoul(line.c_str() + 6, nullptr, 8));
    return mode_t(0644);
  }();
  return mode;
}

// Removes the folder at `path` with the files in it (scratch folders hold
// no folders), by system calls alone, as a signal handler may: besides
// the registered files, a child killed mid-read leaves its own there.
// Entries removed while listed may shift the listing, hence a few passes.
void remove_folder_from_handler(const char* path) {
  const int fd = open(path, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0) return;
  alignas(dirent64) char buffer[4096];
  for (int pass = 0; pass < 4; ++pass) {
    bool removed = false;
    lseek(fd, 0, SEEK_SET);
    for (long n; (n = syscall(SYS_getdents64, fd, buffer, sizeof buffer)) > 0;)
      for (long at = 0; at < n;) {
        const auto* entry = reinterpret_cast<const dirent64*>(buffer + at);
        at += entry->d_reclen;
        const char* name = entry->d_name;
        if (name[0] == '.' && (name[1] == '\0' || (name[1] == '.' && name[2] == '\0'))) continue;
        removed = unlinkat(fd, name, 0) == 0 || removed;
      }
    if (!removed) break;
  }
  close(fd);
  rmdir(path);
}

}  // namespace

void remove_partial_files() {
  for (int i = 0; i < kSlots; ++i)
    if (registry_state[i].load() == 2) unlink(registry_paths[i]);
  if (scratch_folder_owner.load() == getpid()) remove_folder_from_handler(scratch_folder_path);
}

int remove_stale_partial_files(const std::filesystem::path& folder) {
  static const std::string own = kMarker + host_name() + "-";
  int removed = 0;
  std::error_code error;
  for (std::filesystem::directory_iterator it(folder, error), end; !error && it != end; it.increment(error)) {
    // ".NAME.partial-HOST-PID-XXXXXX.EXT" (".NAME.partial-HOST-PID.EXT"
    // before the X's) of this host.
    const std::string name = it->path().filename().string();
    const std::size_t at = name.rfind(own);
    if (name.empty() || name[0] != '.' || at == std::string::npos || !names_a_dead_process(name, at + own.size()))
      continue;
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

[[noreturn]] void fail_to_write(const std::filesystem::path& final_path, const char* what) {
  throw std::runtime_error(final_path.string() + ": cannot write the file (" + what + ": " + std::strerror(errno) + ")");
}

}  // namespace

PartialFile::PartialFile(const std::string& final_path) : final_(final_path) {
  const std::filesystem::path folder = final_.parent_path();
  clear_stale_once(folder);
  // mkostemps fills in the X's and makes the file only where no file or
  // link of that name is (O_CREAT | O_EXCL, which follows no link), mode
  // 0600.
  const std::string extension = final_.extension().string();
  std::string name = (folder / ("." + final_.stem().string() + kMarker + host_name() + "-" +
                                std::to_string(getpid()) + "-XXXXXX" + extension))
                         .string();
  const int fd = mkostemps(name.data(), int(extension.size()), O_CLOEXEC);
  if (fd < 0) fail_to_write(final_, "open");
  close(fd);
  temp_ = name;
  slot_ = register_path(name);
}

PartialFile::~PartialFile() {
  std::error_code ignored;
  if (!done_) std::filesystem::remove(temp_, ignored);
  unregister_path(slot_);
}

void PartialFile::write(const void* data, std::size_t size) const {
  // The file this object made: no other (O_NOFOLLOW), and not made anew.
  const int fd = ::open(temp_.c_str(), O_WRONLY | O_TRUNC | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0) fail_to_write(final_, "open");
  const char* bytes = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t n = ::write(fd, bytes, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      if (n == 0) errno = ENOSPC;
      ::close(fd);
      fail_to_write(final_, "write");
    }
    bytes += n;
    size -= std::size_t(n);
  }
  // A full disk may only show when the data reaches it.
  if (::fsync(fd) != 0 && errno != EINVAL) {
    ::close(fd);
    fail_to_write(final_, "fsync");
  }
  if (::close(fd) != 0) fail_to_write(final_, "close");
}

void PartialFile::commit() {
  // Readable as any file the user makes, now that it is whole.
  const int fd = ::open(temp_.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0 || ::fchmod(fd, new_file_mode()) != 0) {
    const std::string why = std::strerror(errno);
    if (fd >= 0) ::close(fd);
    throw std::runtime_error(final_.string() + ": cannot give the finished file its mode: " + why);
  }
  ::close(fd);
  std::error_code error;
  std::filesystem::rename(temp_, final_, error);
  if (error) throw std::runtime_error(final_.string() + ": cannot move the finished file into place: " + error.message());
  done_ = true;
}

namespace {

// Removes the scratch folders in the temporary folder `temp` that a
// process of this host and user left when it died: "hsb-HOST-PID-XXXXXX",
// each a folder (not a link) of this user's, that nobody else could write in.
void remove_stale_scratch_folders(const std::filesystem::path& temp) {
  static const std::string own = "hsb-" + host_name() + "-";
  std::error_code error;
  for (std::filesystem::directory_iterator it(temp, error), end; !error && it != end; it.increment(error)) {
    const std::string name = it->path().filename().string();
    const std::size_t dash = name.rfind('-');
    struct stat st {};
    if (name.rfind(own, 0) != 0 || dash + 7 != name.size() || !names_a_dead_process(name, own.size()) ||
        lstat(it->path().c_str(), &st) != 0 || !S_ISDIR(st.st_mode) || st.st_uid != geteuid())
      continue;
    std::error_code ignored;
    std::filesystem::remove_all(it->path(), ignored);
  }
}

// The scratch folder and how many scratch files are in it.
std::mutex scratch_mutex;
std::string scratch_folder_name;
int scratch_files = 0;

// The scratch folder, made if there is none: mkdtemp makes it 0700 under
// a name nobody can foresee.
std::string use_scratch_folder() {
  const std::lock_guard<std::mutex> lock(scratch_mutex);
  if (scratch_files++ > 0) return scratch_folder_name;
  std::error_code error;
  const std::filesystem::path temp = std::filesystem::temp_directory_path(error);
  if (error) {
    --scratch_files;
    throw std::runtime_error("no temporary folder for scratch files: " + error.message());
  }
  static bool cleared = false;  // what a killed run left, once
  if (!std::exchange(cleared, true)) remove_stale_scratch_folders(temp);
  std::string name = (temp / ("hsb-" + host_name() + "-" + std::to_string(getpid()) + "-XXXXXX")).string();
  if (name.size() >= kPathBytes || !mkdtemp(name.data())) {
    --scratch_files;
    throw std::runtime_error("cannot make a scratch folder in " + temp.string() + ": " + std::strerror(errno));
  }
  scratch_folder_name = name;
  std::memcpy(scratch_folder_path, name.c_str(), name.size() + 1);
  scratch_folder_owner.store(getpid());
  return name;
}

// Removes the folder with its last scratch file (and whatever a child
// killed mid-write left in it).
void leave_scratch_folder() {
  const std::lock_guard<std::mutex> lock(scratch_mutex);
  if (--scratch_files > 0) return;
  const bool own = scratch_folder_owner.load() == getpid();
  scratch_folder_owner.store(0);
  std::error_code ignored;
  if (own) std::filesystem::remove_all(scratch_folder_name, ignored);
  scratch_folder_name.clear();
}

}  // namespace

ScratchFile::ScratchFile(const std::string& what, const std::string& extension) {
  const std::string folder = use_scratch_folder();
  try {
    file_ = std::make_unique<PartialFile>((std::filesystem::path(folder) / (what + extension)).string());
  } catch (...) {
    leave_scratch_folder();
    throw;
  }
}

ScratchFile::~ScratchFile() {
  file_.reset();
  leave_scratch_folder();
}

bool ScratchFile::written() const {
  struct stat st {};
  return lstat(file_->path().c_str(), &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0;
}

std::string scratch_folder() {
  const std::lock_guard<std::mutex> lock(scratch_mutex);
  return scratch_folder_name;
}

}  // namespace hsb
