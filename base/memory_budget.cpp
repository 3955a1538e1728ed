#include "base/memory_budget.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "base/process_memory.h"

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

// The limit that binds, and its name for messages.
struct Limit {
  double bytes;
  const char* what;
};

Limit binding_limit() {
  double physical = double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGE_SIZE));
  if (!(physical > 0.0)) physical = 8e9;  // unknown: assume a small machine
  Limit limit{0.75 * physical, "this machine allows a scene (three quarters of its memory)"};
  if (const double cgroup = cgroup_limit(); cgroup > 0.0 && 0.75 * cgroup < limit.bytes)
    limit = {0.75 * cgroup, "this job's control group allows a scene (three quarters of its limit)"};
  // ulimit -v caps the address space, which holds more than the resident
  // memory (thread stacks, mapped libraries): what the process may still
  // map, on top of what it holds now.
  struct rlimit address_space {};
  if (getrlimit(RLIMIT_AS, &address_space) == 0 && address_space.rlim_cur != RLIM_INFINITY) {
    const double room = double(address_space.rlim_cur) - virtual_bytes() + resident_bytes();
    if (room < limit.bytes) limit = {room, "the address-space limit (ulimit -v) leaves this process"};
  }
  return limit;
}

}  // namespace

std::size_t memory_budget_bytes() { return std::size_t(std::max(0.0, binding_limit().bytes)); }

std::string human_bytes(double bytes) {
  const char* units[] = {"bytes", "kB", "MB", "GB", "TB", "PB", "EB"};
  int u = 0;
  while (bytes >= 1000.0 && u < 6) bytes /= 1000.0, ++u;
  char text[32];
  std::snprintf(text, sizeof text, u == 0 ? "%.0f %s" : "%.3g %s", bytes, units[u]);
  return text;
}

void check_memory(double bytes, const std::string& what, const std::string& change) {
  const Limit limit = binding_limit();
  if (bytes <= limit.bytes) return;
  std::ostringstream message;
  message << what << " would take about " << human_bytes(bytes) << ", more than the "
          << human_bytes(std::max(0.0, limit.bytes)) << " " << limit.what << ": " << change;
  throw ResourceError(message.str());
}

}  // namespace hsb
