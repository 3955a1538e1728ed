#pragma once
// Whether a path names a file this program can read as input (a scene or a
// data set), and if not, why, in words a user can act on. Checked before
// anything opens it: opening a FIFO would wait for a writer for ever, and a
// reader that meets a file it may not read reports it as malformed.

#include <cstddef>
#include <string>

namespace hsb {

// "" when `path` is a regular file that can be opened for reading; else
// "no such file", "a directory, not a file", "not a regular file (a FIFO,
// socket or device)" or "cannot be read: Permission denied".
std::string unreadable_input(const std::string& path);

// The first `bytes` bytes of the file at `path` (fewer for a shorter
// file; "" when it cannot be read): what format probes and header checks
// look at.
std::string file_head(const std::string& path, std::size_t bytes);

// The file `named` in the data file `from` (a piece, a block, a step, a
// detached header's data): relative to `from`'s folder unless absolute.
std::string file_named_in(const std::string& from, const std::string& named);

}  // namespace hsb
