#include "base/input_file.h"

#include <filesystem>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace hsb {
namespace {

const char* const kNotRegular = "not a regular file (a FIFO, socket or device)";

}  // namespace

InputFile::InputFile(const std::string& path) {
  struct stat st {};
  if (stat(path.c_str(), &st) != 0) {
    why_ = errno == ENOENT || errno == ENOTDIR ? "no such file" : std::string("cannot be read: ") + std::strerror(errno);
    return;
  }
  if (S_ISDIR(st.st_mode)) {
    why_ = "a directory, not a file";
    return;
  }
  if (!S_ISREG(st.st_mode)) {
    why_ = kNotRegular;
    return;
  }
  // Opened, not only stat'ed: permissions, ACLs and read-only mounts all
  // decide, and only open() asks them all. Without waiting, and without
  // becoming a terminal's process, should something other than a regular
  // file have taken the name since: fstat then says what was opened.
  fd_ = open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
  if (fd_ < 0) {
    why_ = std::string("cannot be read: ") + std::strerror(errno);
    return;
  }
  if (fstat(fd_, &st) != 0 || !S_ISREG(st.st_mode)) {
    why_ = S_ISDIR(st.st_mode) ? "a directory, not a file" : kNotRegular;
    close(fd_);
    fd_ = -1;
    return;
  }
  // A regular file ignores O_NONBLOCK; cleared all the same for readers
  // handed the descriptor.
  const int flags = fcntl(fd_, F_GETFL);
  if (flags >= 0) fcntl(fd_, F_SETFL, flags & ~O_NONBLOCK);
  size_ = std::uint64_t(st.st_size);
}

InputFile::~InputFile() {
  if (fd_ >= 0) close(fd_);
}

std::size_t InputFile::read(std::uint64_t offset, void* into, std::size_t bytes) const {
  if (fd_ < 0 || offset >= size_) return 0;
  bytes = std::size_t(std::min<std::uint64_t>(bytes, size_ - offset));
  std::size_t done = 0;
  while (done < bytes) {
    const ssize_t n = pread(fd_, static_cast<char*>(into) + done, bytes - done, off_t(offset + done));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // an error, or the file cut short meanwhile
    done += std::size_t(n);
  }
  return done;
}

std::string InputFile::read(std::uint64_t offset, std::size_t bytes) const {
  std::string text(std::size_t(std::min<std::uint64_t>(bytes, offset < size_ ? size_ - offset : 0)), '\0');
  text.resize(read(offset, text.data(), text.size()));
  return text;
}

std::string unreadable_input(const std::string& path) { return InputFile(path).why(); }

std::string file_head(const std::string& path, std::size_t bytes) { return InputFile(path).read(0, bytes); }

std::string file_tail(const std::string& path, std::size_t bytes) {
  const InputFile file(path);
  return file.read(file.size() - std::min<std::uint64_t>(file.size(), bytes), bytes);
}

std::string file_named_in(const std::string& from, const std::string& named) {
  const std::filesystem::path p(named);
  return (p.is_absolute() ? p : std::filesystem::path(from).parent_path() / p).lexically_normal().string();
}

}  // namespace hsb
