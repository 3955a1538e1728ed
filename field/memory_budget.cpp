#include "field/memory_budget.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace hsb {
namespace {

// A control group's memory limit, from cgroup v2 or v1; 0 when there is none.
double cgroup_limit() {
  for (const char* path : {"/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory/memory.limit_in_bytes"}) {
    std::ifstream in(path);
    std::string text;
    if (!(in >> text) || text == "max") continue;
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    // cgroup v1 says "no limit" with a number near 2^63.
    if (end != text.c_str() && value > 0.0 && value < 1e18) return value;
  }
  return 0.0;
}

}  // namespace

std::size_t memory_budget_bytes() {
  double physical = double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGE_SIZE));
  if (!(physical > 0.0)) physical = 8e9;  // unknown: assume a small machine
  const double limit = cgroup_limit();
  return std::size_t(0.75 * (limit > 0.0 ? std::min(physical, limit) : physical));
}

std::string human_bytes(double bytes) {
  const char* units[] = {"bytes", "kB", "MB", "GB", "TB", "PB", "EB"};
  int u = 0;
  while (bytes >= 1000.0 && u < 6) bytes /= 1000.0, ++u;
  char text[32];
  std::snprintf(text, sizeof text, u == 0 ? "%.0f %s" : "%.3g %s", bytes, units[u]);
  return text;
}

void check_memory(double bytes, const std::string& what, const std::string& change) {
  const double budget = double(memory_budget_bytes());
  if (bytes <= budget) return;
  std::ostringstream message;
  message << what << " would take about " << human_bytes(bytes) << ", more than the " << human_bytes(budget)
          << " this machine allows a scene (three quarters of its memory): " << change;
  throw ResourceError(message.str());
}

}  // namespace hsb
