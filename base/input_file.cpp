#include "base/input_file.h"

#include <filesystem>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>

namespace hsb {

std::string unreadable_input(const std::string& path) {
  struct stat st {};
  if (stat(path.c_str(), &st) != 0)
    return errno == ENOENT || errno == ENOTDIR ? "no such file" : std::string("cannot be read: ") + std::strerror(errno);
  if (S_ISDIR(st.st_mode)) return "a directory, not a file";
  if (!S_ISREG(st.st_mode)) return "not a regular file (a FIFO, socket or device)";
  // Opened, not only stat'ed: permissions, ACLs and read-only mounts all
  // decide, and only open() asks them all. A regular file never blocks.
  const int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return std::string("cannot be read: ") + std::strerror(errno);
  close(fd);
  return "";
}

std::string file_head(const std::string& path, std::size_t bytes) {
  std::ifstream in(path, std::ios::binary);
  std::string head(bytes, '\0');
  in.read(head.data(), std::streamsize(head.size()));
  head.resize(std::size_t(std::max<std::streamsize>(0, in.gcount())));
  return head;
}

std::string file_named_in(const std::string& from, const std::string& named) {
  const std::filesystem::path p(named);
  return (p.is_absolute() ? p : std::filesystem::path(from).parent_path() / p).lexically_normal().string();
}

}  // namespace hsb
