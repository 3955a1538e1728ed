#pragma once
// A file that appears complete or not at all: written under a temporary
// name beside its final path (".NAME.partial-HOST-PID-XXXXXX.EXT",
// hidden), then renamed into place, which replaces a file of that name
// only at the very end.
//
// The temporary is made by this program, under a name nobody can foresee
// (the X's are random), only where no file or link of that name is
// (O_EXCL: a link planted there is never written through), and readable
// by its user alone until it is committed.
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
#include <memory>
#include <string>

namespace hsb {

class PartialFile {
 public:
  // Makes the temporary file, empty. Throws std::runtime_error naming the
  // final path when it cannot (no such folder, no permission).
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

  // Gives the finished file the mode any new file gets (0666 less the
  // umask) and moves it into place; throws std::runtime_error (and
  // removes it) when that fails.
  void commit();

 private:
  std::filesystem::path final_, temp_;
  int slot_ = -1;  // in the registry
  bool done_ = false;
};

// A scratch file of this process's, never committed: the temporary of
// "WHAT.EXT" in a folder of the process's own in the temporary folder
// ($TMPDIR/hsb-HOST-PID-XXXXXX, mode 0700, made with the first scratch
// file and removed with the last, or by remove_partial_files). Nobody
// else can read the folder, write in it or plant a link there, so what
// is read back from it is what this process (or its child) wrote.
class ScratchFile {
 public:
  ScratchFile(const std::string& what, const std::string& extension);
  ~ScratchFile();
  ScratchFile(const ScratchFile&) = delete;
  ScratchFile& operator=(const ScratchFile&) = delete;

  // Where to write (and read back).
  std::string path() const { return file_->path(); }
  // Whether anything has been written to it: it is made empty, so an
  // empty one holds no answer (a child that never wrote).
  bool written() const;

 private:
  std::unique_ptr<PartialFile> file_;
};

// The folder scratch files are made in while any exists, else "".
std::string scratch_folder();

// Removes every registered temporary file, and this process's scratch
// folder with what is in it. Safe to call from a signal handler: it only
// reads fixed buffers and makes system calls (unlink, getdents, rmdir).
void remove_partial_files();

// Removes the temporaries in `folder` that a process of this host left
// when it died; returns how many. PartialFile calls it once per folder
// (the first scratch file likewise removes a dead process's scratch
// folder).
int remove_stale_partial_files(const std::filesystem::path& folder);

}  // namespace hsb
