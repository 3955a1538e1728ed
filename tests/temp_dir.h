#pragma once
// A scratch folder of the test process's own. CTest runs every test case as
// a process of its own, two at a time: folders named only after the test
// file would be shared, and one case could read another's half-written file.

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace hsb {

// <temp>/hsb_<tag>_<pid>, created, and emptied first when `fresh`;
// removed when the test process exits (a suite run makes thousands).
inline std::filesystem::path test_temp_dir(const std::string& tag, bool fresh = false) {
  struct RemovedAtExit {
    std::vector<std::filesystem::path> dirs;
    ~RemovedAtExit() {
      std::error_code ignored;
      for (const auto& d : dirs) std::filesystem::remove_all(d, ignored);
    }
  };
  static RemovedAtExit created;
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("hsb_" + tag + "_" + std::to_string(::getpid()));
  if (fresh) std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  if (std::find(created.dirs.begin(), created.dirs.end(), dir) == created.dirs.end()) created.dirs.push_back(dir);
  return dir;
}

}  // namespace hsb
