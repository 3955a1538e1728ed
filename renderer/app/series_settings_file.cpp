#include "renderer/app/series_settings_file.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <sstream>
#include <system_error>
#include <thread>

#include "base/input_file.h"
#include "base/partial_file.h"
#include "base/sha1.h"
#include "renderer/library/picture_output.h"
#include "renderer/scene/scene_spec.h"

namespace hsb {
namespace {

// Larger than any settings file hsb writes (a dozen short lines).
constexpr std::uint64_t kMostBytes = 64 * 1024;
// How often a waiting task looks whether the lock is free, and reports.
constexpr auto kWaitPeriod = std::chrono::milliseconds(200);

std::string series_sha1(const std::vector<SeriesMember>& members) {
  std::string hashes = std::string("Hyperstreamball ") + HSB_VERSION + "\n";
  for (const SeriesMember& m : members) hashes += scene_sha1(load_scene_or_data_file(m.scene, m.overrides)) + "\n";
  return sha1_hex(hashes);
}

std::string first_line(const std::string& sha1) { return "# series " + sha1; }

// The settings in the file at `path`, or nothing when it is missing or
// not one hsb wrote for these steps.
std::optional<std::vector<std::string>> settings_from(const std::string& path, const std::string& sha1) {
  const InputFile file(path);
  struct stat about {};
  if (!file.why().empty() || fstat(file.descriptor(), &about) != 0 || about.st_uid != geteuid() ||
      file.size() > kMostBytes)
    return std::nullopt;
  std::istringstream text(file.read(0, std::size_t(file.size())));
  std::string line;
  if (!std::getline(text, line) || line != first_line(sha1)) return std::nullopt;
  std::vector<std::string> settings;
  const std::vector<std::string>& keys = series_pinned_keys();
  while (std::getline(text, line)) {
    if (line.empty() || line[0] == '#') continue;
    const std::size_t eq = line.find('=');
    if (eq == std::string::npos || std::find(keys.begin(), keys.end(), line.substr(0, eq)) == keys.end())
      return std::nullopt;
    settings.push_back(line);
  }
  return settings;
}

// Written whole or not at all (a task killed while writing leaves no
// file that another would read as finished).
void store(const std::string& path, const std::string& sha1, const std::vector<SeriesMember>& members,
           const std::vector<std::string>& settings) {
  std::string text = first_line(sha1) + "\n# The settings hsb pins on every image of the time series " +
                     std::filesystem::path(members.front().scene).filename().string() + " (" +
                     std::to_string(members.size()) + " steps), read once for every task that renders it.\n" +
                     "# Delete it freely: the next render reads the steps again.\n";
  for (const std::string& s : settings) text += s + "\n";
  try {
    PartialFile file(path);
    file.write(text.data(), text.size());
    file.commit();
  } catch (const std::exception&) {
    // A folder that takes no file: each task reads the steps itself.
  }
}

// An exclusive flock on `path`, held until destroyed; none where the
// file system refuses (the caller then works alone).
class FolderLock {
 public:
  FolderLock(const std::string& path, const std::function<void(SeriesWork, double)>& progress) : path_(path) {
    fd_ = open(path.c_str(), O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0600);
    if (fd_ < 0) return;
    while (flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      if (errno != EWOULDBLOCK && errno != EINTR) {
        close(fd_);
        fd_ = -1;
        return;
      }
      if (progress) progress(SeriesWork::waiting, 0.0);
      std::this_thread::sleep_for(kWaitPeriod);
    }
  }
  ~FolderLock() {
    if (fd_ < 0) return;
    // Removed while still held: a task waiting on it finds the settings
    // file when it gets the lock; one that comes later makes a new lock.
    unlink(path_.c_str());
    close(fd_);
  }
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

 private:
  std::string path_;
  int fd_ = -1;
};

}  // namespace

std::vector<std::string> series_settings_in(const std::string& folder, const std::vector<SeriesMember>& members,
                                            const std::function<void(SeriesWork, double)>& progress) {
  if (members.empty()) return {};
  const std::string sha1 = series_sha1(members);
  const std::filesystem::path base = std::filesystem::path(folder) / (".hsb-series-" + sha1);
  const std::string path = base.string() + ".toml";
  if (std::optional<std::vector<std::string>> found = settings_from(path, sha1)) return *found;
  std::error_code ignored;
  std::filesystem::create_directories(folder, ignored);
  const FolderLock lock(base.string() + ".lock", progress);
  // Another task may have finished them while this one waited.
  if (std::optional<std::vector<std::string>> found = settings_from(path, sha1)) return *found;
  std::vector<std::string> settings = shared_series_settings(members, [&](double fraction) {
    if (progress) progress(SeriesWork::reading, fraction);
  });
  store(path, sha1, members, settings);
  return settings;
}

}  // namespace hsb
