#pragma once
// A regular file's bytes, mapped read-only instead of read into memory of
// the program's own: a volume's raw data is used where the page cache
// holds it. Reading Teem's helix at 136³ (70 MB) into a buffer cost the
// buffer's page clearing and a copy, an eighth of the whole render.
// (A file cut short by another program while it is mapped would fault on
// the pages it lost: hsb reads a data file while no one writes it.)

#include <cstddef>
#include <string>

namespace hsb {

class MappedFile {
 public:
  MappedFile() = default;
  // Maps the file at `path` whole. Empty (size() 0) where it cannot be:
  // not a regular file, empty, or refused; the caller then reads it.
  explicit MappedFile(const std::string& path);
  ~MappedFile();
  MappedFile(MappedFile&& other) noexcept;
  MappedFile& operator=(MappedFile&& other) noexcept;
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;

  const unsigned char* data() const { return data_; }
  std::size_t size() const { return size_; }

 private:
  const unsigned char* data_ = nullptr;
  std::size_t size_ = 0;
};

}  // namespace hsb
