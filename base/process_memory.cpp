#include "base/process_memory.h"

#include <fstream>
#include <string>

namespace hsb {
namespace {

double status_kib(const char* field) {
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key) {
    if (key == field) {
      double kib = 0.0;
      status >> kib;
      return kib;
    }
    status.ignore(1 << 20, '\n');
  }
  return 0.0;
}

}  // namespace

double resident_bytes() { return status_kib("VmRSS:") * 1024.0; }
double peak_resident_bytes() { return status_kib("VmHWM:") * 1024.0; }
double file_resident_bytes() { return status_kib("RssFile:") * 1024.0; }
double virtual_bytes() { return status_kib("VmSize:") * 1024.0; }
void reset_peak_resident() { std::ofstream("/proc/self/clear_refs") << "5"; }

}  // namespace hsb
