#pragma once
// A scratch folder of the test process's own. CTest runs every test case as
// a process of its own, two at a time: folders named only after the test
// file would be shared, and one case could read another's half-written file.

#include <unistd.h>

#include <filesystem>
#include <string>

namespace hsb {

// <temp>/hsb_<tag>_<pid>, created, and emptied first when `fresh`.
inline std::filesystem::path test_temp_dir(const std::string& tag, bool fresh = false) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("hsb_" + tag + "_" + std::to_string(::getpid()));
  if (fresh) std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace hsb
