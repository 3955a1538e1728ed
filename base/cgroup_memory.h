#pragma once
// The memory limit of this process's own control group (Linux): the lowest
// memory limit on the chain from its cgroup up to the root of the mounted
// hierarchy. Slurm sets a job's --mem on a cgroup some levels below the
// top (…/slurmstepd.scope/job_12 while the task runs in
// …/job_12/step_0/user/task_0), so the top-level file alone says nothing.
//
// Where the cgroup is comes from /proc/self/cgroup ("0::/path" for cgroup
// v2, "N:memory,…:/path" for v1's memory controller), where its hierarchy
// is mounted from /proc/self/mountinfo (not assumed to be /sys/fs/cgroup).
// The files read are v2's memory.max and v1's memory.limit_in_bytes: the
// hard limits, past which the kernel kills (memory.high only throttles).

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

namespace hsb {

struct CgroupMemoryLimit {
  std::uint64_t bytes = 0;
  std::string file;  // the limit file that set it, for messages
};

// A file's whole text, or nothing when it is missing or cannot be read.
using ReadTextFile = std::function<std::optional<std::string>(const std::string& path)>;

// The lowest limit over both hierarchies (a hybrid system mounts v2 and
// v1's memory controller side by side), or nothing when no level sets one.
// `proc_self_cgroup` and `proc_self_mountinfo` are those files' texts;
// `read` reads a limit file by its path under a mount point. A file that
// is missing, unreadable or not a number is skipped: a level without a
// limit. "max" (v2) and v1's 2^63 rounded down to pages mean no limit.
// A cgroup path outside every mount's root (a container with its own
// cgroup namespace sees "/") is the mount's own directory.
std::optional<CgroupMemoryLimit> cgroup_memory_limit(std::string_view proc_self_cgroup,
                                                     std::string_view proc_self_mountinfo,
                                                     const ReadTextFile& read);

// The reader cgroup_memory_limit() uses: a file's whole text, or nothing
// when it cannot be opened or read (a directory, a file the kernel refuses).
std::optional<std::string> read_cgroup_file(const std::string& path);

// This process's: reads /proc/self/cgroup, /proc/self/mountinfo and the
// limit files themselves. Nothing where there is no limit or no cgroup.
std::optional<CgroupMemoryLimit> cgroup_memory_limit();

}  // namespace hsb
