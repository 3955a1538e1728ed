#pragma once
// Whether a path names a file this program can read as input, and if not,
// why, in words a user can act on; and the one way hsb opens such a file.
// Everything a user or a data file names goes through here before it is
// opened or hashed: a scene, a data file and the files it names (pieces,
// blocks, a series' steps, a detached header's data), a mask, a colour
// configuration, an image --skip-existing looks at. Opening a FIFO would
// wait for a writer for ever, a device (/dev/zero, /dev/urandom) never
// ends, and a reader that meets a file it may not read reports it as
// malformed.

#include <cstddef>
#include <cstdint>
#include <string>

namespace hsb {

// A regular file open for reading, or why it is not. A FIFO, socket or
// device is refused before anything opens it; one put in its place after
// that check is opened without waiting and refused then. Reads stop at
// the size the file had when opened: a file that grows meanwhile is read
// as it was, never without end.
class InputFile {
 public:
  explicit InputFile(const std::string& path);
  ~InputFile();
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;

  // "" when it is open; else unreadable_input's words.
  const std::string& why() const { return why_; }
  // The open descriptor (-1 when not open), for a reader to map or read.
  int descriptor() const { return fd_; }
  // Its size when opened.
  std::uint64_t size() const { return size_; }

  // Reads up to `bytes` bytes at `offset` into `into`, stopping at size():
  // how many it read (0 when it is not open).
  std::size_t read(std::uint64_t offset, void* into, std::size_t bytes) const;
  // The same, as text.
  std::string read(std::uint64_t offset, std::size_t bytes) const;

 private:
  int fd_ = -1;
  std::uint64_t size_ = 0;
  std::string why_;
};

// "" when `path` is a regular file that can be opened for reading; else
// "no such file", "a directory, not a file", "not a regular file (a FIFO,
// socket or device)" or "cannot be read: Permission denied".
std::string unreadable_input(const std::string& path);

// The first `bytes` bytes of the file at `path` (fewer for a shorter
// file; "" when it is no file unreadable_input accepts): what format
// probes and header checks look at.
std::string file_head(const std::string& path, std::size_t bytes);

// Its last `bytes` bytes, the same way: where a PDF ends.
std::string file_tail(const std::string& path, std::size_t bytes);

// The file `named` in the data file `from` (a piece, a block, a step, a
// detached header's data): relative to `from`'s folder unless absolute.
std::string file_named_in(const std::string& from, const std::string& named);

}  // namespace hsb
