#pragma once
// A file that appears complete or not at all: written under a temporary
// name beside its final path (".NAME.partial.EXT", hidden), then renamed
// into place, which replaces a file of that name only at the very end.

#include <filesystem>
#include <stdexcept>
#include <string>

namespace hsb {

class PartialFile {
 public:
  explicit PartialFile(const std::string& final_path)
      : final_(final_path),
        temp_(final_.parent_path() / ("." + final_.stem().string() + ".partial" + final_.extension().string())) {}
  ~PartialFile() {
    std::error_code ignored;
    if (!done_) std::filesystem::remove(temp_, ignored);
  }
  PartialFile(const PartialFile&) = delete;
  PartialFile& operator=(const PartialFile&) = delete;

  // Where to write.
  std::string path() const { return temp_.string(); }

  // Moves the finished file into place; throws std::runtime_error (and
  // removes it) when that fails.
  void commit() {
    std::error_code error;
    std::filesystem::rename(temp_, final_, error);
    if (error) throw std::runtime_error(final_.string() + ": cannot move the finished file into place: " + error.message());
    done_ = true;
  }

 private:
  std::filesystem::path final_, temp_;
  bool done_ = false;
};

}  // namespace hsb
