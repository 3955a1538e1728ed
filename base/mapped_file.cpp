#include "base/mapped_file.h"

#include <sys/mman.h>

#include <utility>

#include "base/input_file.h"

namespace hsb {

MappedFile::MappedFile(const std::string& path) {
  // Opened as every input is: a FIFO or a device is never opened to wait.
  const InputFile file(path);
  if (file.descriptor() < 0 || file.size() == 0) return;
  // Populated at once: one call maps the cached pages, where touching
  // them would take a fault each few.
  void* mapped = mmap(nullptr, std::size_t(file.size()), PROT_READ, MAP_PRIVATE | MAP_POPULATE, file.descriptor(), 0);
  if (mapped != MAP_FAILED) {
    data_ = static_cast<const unsigned char*>(mapped);
    size_ = std::size_t(file.size());  // kept when `file` closes its descriptor
  }
}

MappedFile::~MappedFile() {
  if (data_) munmap(const_cast<unsigned char*>(data_), size_);
}

MappedFile::MappedFile(MappedFile&& other) noexcept
    : data_(std::exchange(other.data_, nullptr)), size_(std::exchange(other.size_, 0)) {}

MappedFile& MappedFile::operator=(MappedFile&& other) noexcept {
  if (this != &other) {
    MappedFile gone(std::move(*this));
    data_ = std::exchange(other.data_, nullptr);
    size_ = std::exchange(other.size_, 0);
  }
  return *this;
}

}  // namespace hsb
