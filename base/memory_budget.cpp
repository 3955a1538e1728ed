#include "base/memory_budget.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>
#include <string>

#include "base/cgroup_memory.h"
#include "base/process_memory.h"

namespace hsb {
namespace {

// The limit that binds, and its name for messages.
struct Limit {
  double bytes;
  std::string what;
};

Limit binding_limit() {
  double physical = double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGE_SIZE));
  if (!(physical > 0.0)) physical = 8e9;  // unknown: assume a small machine
  Limit limit{0.75 * physical, "this machine allows a scene (three quarters of its memory)"};
  // The lowest limit from the process's own cgroup up (Slurm sets --mem
  // on the job's cgroup, levels below the top), not the top-level file's.
  if (const std::optional<CgroupMemoryLimit> cgroup = cgroup_memory_limit();
      cgroup && 0.75 * double(cgroup->bytes) < limit.bytes)
    limit = {0.75 * double(cgroup->bytes),
             "this job's control group allows a scene (three quarters of its limit, " + cgroup->file + ")"};
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
