// The memory limit of the process's own control group: found from
// /proc/self/cgroup and /proc/self/mountinfo, the lowest on the chain up to
// the root wins, in cgroup v2 and v1, with files laid out as Slurm and
// containers lay them out.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "base/cgroup_memory.h"
#include "tests/temp_dir.h"

namespace hsb {
namespace {

constexpr std::uint64_t kMiB = std::uint64_t(1) << 20;
constexpr std::uint64_t kGiB = std::uint64_t(1) << 30;
// What cgroup v1 says for "no limit": 2^63 - 1 rounded down to 4 KB pages.
constexpr const char* kV1NoLimit = "9223372036854771712\n";

// Reads files from a table; records every path asked for.
struct FakeFiles {
  std::map<std::string, std::string> files;
  std::vector<std::string> asked;
  ReadTextFile reader() {
    return [this](const std::string& path) -> std::optional<std::string> {
      asked.push_back(path);
      const auto it = files.find(path);
      if (it == files.end()) return std::nullopt;
      return it->second;
    };
  }
};

void write(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path) << text;
}

std::string v2_mount(const std::string& point, const std::string& root = "/") {
  return "30 23 0:26 " + root + " " + point +
         " rw,nosuid,nodev,noexec,relatime shared:4 - cgroup2 cgroup2 rw,nsdelegate,memory_recursiveprot\n";
}

// A Slurm step on a cgroup v2 machine: --mem=800M on the job's cgroup, two
// levels above the task's, "max" on every other level; the top-level
// cgroup has no memory.max at all.
TEST(CgroupMemory, SlurmJobLimitTwoLevelsDownOnV2) {
  const std::filesystem::path dir = test_temp_dir("cgroup_v2_slurm", true);
  const std::filesystem::path mount = dir / "sys/fs/cgroup";
  const std::string chain = "system.slice/slurmstepd.scope/job_12/step_0/user/task_0";
  std::filesystem::path level = mount;
  for (const char* name : {"system.slice", "slurmstepd.scope", "job_12", "step_0", "user", "task_0"}) {
    level /= name;
    write(level / "memory.max", std::string(name) == "job_12" ? "838860800\n" : "max\n");
  }
  const std::string mountinfo = "22 27 0:21 / /proc rw,relatime - proc proc rw\n" + v2_mount(mount.string());
  const std::optional<CgroupMemoryLimit> limit =
      cgroup_memory_limit("0::/" + chain + "\n", mountinfo, read_cgroup_file);
  ASSERT_TRUE(limit);
  EXPECT_EQ(limit->bytes, 800 * kMiB);
  EXPECT_EQ(limit->file, (mount / "system.slice/slurmstepd.scope/job_12/memory.max").string());
}

// cgroup v1 (Slurm's older layout), the memory controller mounted together
// with hugetlb, beside other controllers and a v2 hierarchy without the
// memory controller (a hybrid system: its cgroups have no memory.max).
TEST(CgroupMemory, SlurmJobLimitOnV1WithSharedControllers) {
  const std::string cgroups =
      "12:cpu,cpuacct:/slurm/uid_1000/job_7/step_0/task_0\n"
      "5:name=systemd:/user.slice\n"
      "4:memory,hugetlb:/slurm/uid_1000/job_7/step_0/task_0\n"
      "0::/user.slice\n";
  const std::string mountinfo =
      "31 23 0:28 / /sys/fs/cgroup ro - tmpfs tmpfs ro,mode=755\n"
      "32 31 0:29 / /sys/fs/cgroup/unified rw - cgroup2 cgroup2 rw,nsdelegate\n"
      "33 31 0:30 / /sys/fs/cgroup/cpu,cpuacct rw - cgroup cgroup rw,cpu,cpuacct\n"
      "34 31 0:31 / /sys/fs/cgroup/memory,hugetlb rw shared:9 - cgroup cgroup rw,memory,hugetlb\n";
  const std::string v1 = "/sys/fs/cgroup/memory,hugetlb";
  FakeFiles fake;
  fake.files[v1 + "/memory.limit_in_bytes"] = kV1NoLimit;
  fake.files[v1 + "/slurm/memory.limit_in_bytes"] = kV1NoLimit;
  fake.files[v1 + "/slurm/uid_1000/memory.limit_in_bytes"] = kV1NoLimit;
  fake.files[v1 + "/slurm/uid_1000/job_7/memory.limit_in_bytes"] = "2147483648\n";
  fake.files[v1 + "/slurm/uid_1000/job_7/step_0/memory.limit_in_bytes"] = kV1NoLimit;
  fake.files[v1 + "/slurm/uid_1000/job_7/step_0/task_0/memory.limit_in_bytes"] = kV1NoLimit;
  // Files of controllers that are not memory's: never the limit.
  fake.files["/sys/fs/cgroup/cpu,cpuacct/slurm/uid_1000/job_7/memory.limit_in_bytes"] = "1024\n";
  const std::optional<CgroupMemoryLimit> limit = cgroup_memory_limit(cgroups, mountinfo, fake.reader());
  ASSERT_TRUE(limit);
  EXPECT_EQ(limit->bytes, 2 * kGiB);
  EXPECT_EQ(limit->file, v1 + "/slurm/uid_1000/job_7/memory.limit_in_bytes");
  // The v2 chain was read too (its cgroup, then up to the mount), and found nothing.
  EXPECT_NE(std::find(fake.asked.begin(), fake.asked.end(), "/sys/fs/cgroup/unified/user.slice/memory.max"),
            fake.asked.end());
  EXPECT_NE(std::find(fake.asked.begin(), fake.asked.end(), "/sys/fs/cgroup/unified/memory.max"), fake.asked.end());
}

TEST(CgroupMemory, LowestOfSeveralLevelsWins) {
  FakeFiles fake;
  fake.files["/cg/memory.max"] = "8589934592\n";  // 8 GiB
  fake.files["/cg/a/memory.max"] = "4294967296\n";  // 4 GiB
  fake.files["/cg/a/b/memory.max"] = "1073741824\n";  // 1 GiB: the lowest, in the middle
  fake.files["/cg/a/b/c/memory.max"] = "2147483648\n";  // 2 GiB
  fake.files["/cg/a/b/c/d/memory.max"] = "max\n";
  const std::optional<CgroupMemoryLimit> limit =
      cgroup_memory_limit("0::/a/b/c/d\n", v2_mount("/cg"), fake.reader());
  ASSERT_TRUE(limit);
  EXPECT_EQ(limit->bytes, kGiB);
  EXPECT_EQ(limit->file, "/cg/a/b/memory.max");
  // From the process's own cgroup up to the mount's root, and no further.
  EXPECT_EQ(fake.asked, (std::vector<std::string>{"/cg/a/b/c/d/memory.max", "/cg/a/b/c/memory.max",
                                                  "/cg/a/b/memory.max", "/cg/a/memory.max", "/cg/memory.max"}));
}

// On a hybrid system a limit may be set in either hierarchy: the lower binds.
TEST(CgroupMemory, LowerOfV2AndV1Wins) {
  FakeFiles fake;
  fake.files["/v2/job/memory.max"] = "3221225472\n";  // 3 GiB
  fake.files["/v1/job/memory.limit_in_bytes"] = "1610612736\n";  // 1.5 GiB
  const std::string mountinfo = v2_mount("/v2") + "40 31 0:40 / /v1 rw - cgroup cgroup rw,memory\n";
  const std::optional<CgroupMemoryLimit> limit =
      cgroup_memory_limit("3:memory:/job\n0::/job\n", mountinfo, fake.reader());
  ASSERT_TRUE(limit);
  EXPECT_EQ(limit->bytes, 3 * kGiB / 2);
  EXPECT_EQ(limit->file, "/v1/job/memory.limit_in_bytes");
}

TEST(CgroupMemory, MaxAndV1sHugeNumberMeanNoLimit) {
  FakeFiles fake;
  fake.files["/v2/memory.max"] = "max\n";
  fake.files["/v2/job/memory.max"] = "max\n";
  fake.files["/v1/memory.limit_in_bytes"] = kV1NoLimit;
  fake.files["/v1/job/memory.limit_in_bytes"] = "9223372036854710272\n";  // the same, on 64 KB pages
  const std::string mountinfo = v2_mount("/v2") + "40 31 0:40 / /v1 rw - cgroup cgroup rw,memory\n";
  EXPECT_FALSE(cgroup_memory_limit("3:memory:/job\n0::/job\n", mountinfo, fake.reader()));
}

// A level without the file (v2's root cgroup has no memory.max), a file the
// process may not read (here a directory, which even root cannot read as a
// file), an empty one or one of words: all skipped, the rest still count.
TEST(CgroupMemory, MissingOrUnreadableFilesAreSkipped) {
  const std::filesystem::path dir = test_temp_dir("cgroup_unreadable", true);
  std::filesystem::create_directories(dir / "a/b/c/d/memory.max");  // unreadable as a file
  write(dir / "a/b/c/memory.max", "");
  write(dir / "a/b/memory.max", "lots\n");
  write(dir / "a/memory.max", "536870912\n");  // 512 MiB
  // dir/a/b/c/d/e has no memory.max at all, nor does dir itself.
  std::filesystem::create_directories(dir / "a/b/c/d/e");
  const std::optional<CgroupMemoryLimit> limit =
      cgroup_memory_limit("0::/a/b/c/d/e\n", v2_mount(dir.string()), read_cgroup_file);
  ASSERT_TRUE(limit);
  EXPECT_EQ(limit->bytes, 512 * kMiB);
  // Nothing readable at all: no limit, and no error.
  EXPECT_FALSE(cgroup_memory_limit("0::/a/b/c/d\n", v2_mount((dir / "absent").string()), read_cgroup_file));
  EXPECT_FALSE(read_cgroup_file((dir / "a/b/c/d/memory.max").string()));
}

// In a container with its own cgroup namespace the process sees its cgroup
// as "/": its directory is the mount's root, where the container's limit is.
TEST(CgroupMemory, NamespacedRootIsTheMountsRoot) {
  FakeFiles fake;
  fake.files["/sys/fs/cgroup/memory.max"] = "268435456\n";  // 256 MiB
  const std::optional<CgroupMemoryLimit> limit =
      cgroup_memory_limit("0::/\n", v2_mount("/sys/fs/cgroup"), fake.reader());
  ASSERT_TRUE(limit);
  EXPECT_EQ(limit->bytes, 256 * kMiB);
  EXPECT_EQ(fake.asked, std::vector<std::string>{"/sys/fs/cgroup/memory.max"});

  // The hierarchy mounted from outside the namespace: the mount shows a
  // root the process's "/" is not under.
  fake.asked.clear();
  const std::optional<CgroupMemoryLimit> outside =
      cgroup_memory_limit("0::/\n", v2_mount("/sys/fs/cgroup", "/.."), fake.reader());
  ASSERT_TRUE(outside);
  EXPECT_EQ(outside->bytes, 256 * kMiB);
}

// A container without a cgroup namespace (Docker on cgroup v1): the mount
// shows the container's cgroup as its root, and /proc/self/cgroup names it.
TEST(CgroupMemory, MountOfTheProcesssOwnCgroup) {
  FakeFiles fake;
  fake.files["/sys/fs/cgroup/memory/memory.limit_in_bytes"] = "1073741824\n";
  fake.files["/sys/fs/cgroup/memory/worker/memory.limit_in_bytes"] = "805306368\n";  // 768 MiB
  const std::string mountinfo =
      "35 31 0:32 /docker/0123abcd /sys/fs/cgroup/memory ro,nosuid - cgroup cgroup rw,memory\n";
  const std::optional<CgroupMemoryLimit> limit =
      cgroup_memory_limit("4:memory:/docker/0123abcd/worker\n", mountinfo, fake.reader());
  ASSERT_TRUE(limit);
  EXPECT_EQ(limit->bytes, 768 * kMiB);
  EXPECT_EQ(fake.asked, (std::vector<std::string>{"/sys/fs/cgroup/memory/worker/memory.limit_in_bytes",
                                                  "/sys/fs/cgroup/memory/memory.limit_in_bytes"}));
}

// mountinfo writes a space in a mount point as \040.
TEST(CgroupMemory, EscapedMountPoint) {
  FakeFiles fake;
  fake.files["/mnt/my cgroups/job/memory.max"] = "104857600\n";  // 100 MiB
  const std::optional<CgroupMemoryLimit> limit =
      cgroup_memory_limit("0::/job\n", v2_mount("/mnt/my\\040cgroups"), fake.reader());
  ASSERT_TRUE(limit);
  EXPECT_EQ(limit->bytes, 100 * kMiB);
}

TEST(CgroupMemory, NoCgroupNoLimit) {
  FakeFiles fake;
  fake.files["/sys/fs/cgroup/memory.max"] = "104857600\n";
  EXPECT_FALSE(cgroup_memory_limit("", "", fake.reader()));
  // A cgroup but no mount of its hierarchy (a v1 system with no memory controller).
  EXPECT_FALSE(cgroup_memory_limit("0::/job\n", "22 27 0:21 / /proc rw - proc proc rw\n", fake.reader()));
  EXPECT_FALSE(cgroup_memory_limit("4:cpu:/job\n", "35 31 0:32 / /sys/fs/cgroup rw - cgroup cgroup rw,cpu\n",
                                   fake.reader()));
}

// This process's own: whatever the machine, a limit found is a real one
// and names the file it came from.
TEST(CgroupMemory, ThisProcess) {
  const std::optional<CgroupMemoryLimit> limit = cgroup_memory_limit();
  if (limit) {
    std::cout << "cgroup memory limit: " << limit->bytes << " bytes, from " << limit->file << "\n";
    EXPECT_GT(limit->bytes, 0u);
    EXPECT_TRUE(std::filesystem::exists(limit->file));
  } else {
    std::cout << "cgroup memory limit: none\n";
  }
}

}  // namespace
}  // namespace hsb
