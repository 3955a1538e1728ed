#pragma once
// A file that appears complete or not at all: written under a temporary
// name beside its final path (".NAME.partial-HOST-PID.EXT", hidden), then
// renamed into place, which replaces a file of that name only at the very
// end.
//
// Every temporary name is registered while it exists, so that a signal
// handler can remove them all before the program exits
// (remove_partial_files, async-signal-safe): an interrupted run leaves
// neither a temporary file nor a half-written one under a final name. A
// process killed outright (SIGKILL, a node lost) cannot clean up; its
// temporaries carry its host and process ID, so the next run that writes
// into the folder removes them, and never those of a process still
// running, here or on another node that shares the folder.

#include <filesystem>
#include <string>

namespace hsb {

class PartialFile {
 public:
  explicit PartialFile(const std::string& final_path);
  ~PartialFile();
  PartialFile(const PartialFile&) = delete;
  PartialFile& operator=(const PartialFile&) = delete;

  // Where to write.
  std::string path() const { return temp_.string(); }

  // Writes `size` bytes to path(), checking every step down to the disk
  // (a full disk, a file size limit): throws std::runtime_error naming the
  // final path when any fails. For writers that report no errors of their
  // own, which write into memory and hand the bytes here.
  void write(const void* data, std::size_t size) const;

  // Moves the finished file into place; throws std::runtime_error (and
  // removes it) when that fails.
  void commit();

 private:
  std::filesystem::path final_, temp_;
  int slot_ = -1;  // in the registry
  bool done_ = false;
};

// A path for this process's scratch file in the temporary folder
// ("hsb-WHAT-PID.EXT"), to write through a PartialFile that is never
// committed: the file is gone when that ends, or on a signal.
std::string scratch_path(const std::string& what, const std::string& extension);

// Removes every registered temporary file. Safe to call from a signal
// handler: it only reads fixed buffers and calls unlink().
void remove_partial_files();

// Removes the temporaries in `folder` that a process of this host left
// when it died; returns how many. PartialFile calls it once per folder.
int remove_stale_partial_files(const std::filesystem::path& folder);

}  // namespace hsb
