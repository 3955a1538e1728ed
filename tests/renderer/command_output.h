#pragma once
// What a shell command prints: tests read PDFs through poppler's
// pdftotext and pdfinfo.

#include <array>
#include <cstdio>
#include <string>

namespace hsb {

inline std::string output_of(const std::string& command) {
  std::string out;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return out;
  std::array<char, 4096> buffer;
  while (std::fgets(buffer.data(), int(buffer.size()), pipe)) out += buffer.data();
  pclose(pipe);
  return out;
}

}  // namespace hsb
