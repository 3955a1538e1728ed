#pragma once
// A file name's extension in lower case (".vtu", ".png"): how the
// program tells data files, scenes and image formats apart.

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

namespace hsb {

inline std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

}  // namespace hsb
