#include "base/cgroup_memory.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <vector>

namespace hsb {
namespace {

std::vector<std::string_view> split(std::string_view text, char by) {
  std::vector<std::string_view> parts;
  for (std::size_t start = 0;;) {
    const std::size_t end = text.find(by, start);
    parts.push_back(text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start));
    if (end == std::string_view::npos) return parts;
    start = end + 1;
  }
}

bool starts_with(std::string_view text, std::string_view prefix) {
  return text.substr(0, prefix.size()) == prefix;
}

// mountinfo writes a space, tab, newline or backslash in a path as \ooo.
std::string unescape(std::string_view field) {
  std::string text;
  for (std::size_t i = 0; i < field.size(); ++i) {
    const auto octal = [&](std::size_t k) { return field[k] >= '0' && field[k] <= '7'; };
    if (field[i] == '\\' && i + 3 < field.size() && octal(i + 1) && octal(i + 2) && octal(i + 3)) {
      text += char((field[i + 1] - '0') * 64 + (field[i + 2] - '0') * 8 + (field[i + 3] - '0'));
      i += 3;
    } else {
      text += field[i];
    }
  }
  return text;
}

// Where a hierarchy is mounted: `point` shows the hierarchy's `root`.
struct Mount {
  std::string root;
  std::string point;
};

// The mounts of cgroup v2 or, with `v1_memory`, of v1's memory controller.
// A mountinfo line: id parent major:minor root point options [optional…] -
// type source super-options.
std::vector<Mount> cgroup_mounts(std::string_view mountinfo, bool v1_memory) {
  std::vector<Mount> mounts;
  for (std::string_view line : split(mountinfo, '\n')) {
    std::vector<std::string_view> fields;
    for (std::string_view field : split(line, ' '))
      if (!field.empty()) fields.push_back(field);
    std::size_t dash = 6;
    while (dash < fields.size() && fields[dash] != "-") ++dash;
    if (dash + 1 >= fields.size()) continue;  // no filesystem type
    const std::string_view type = fields[dash + 1];
    bool wanted = type == "cgroup2" && !v1_memory;
    if (type == "cgroup" && v1_memory && dash + 3 < fields.size())
      for (std::string_view option : split(fields[dash + 3], ','))
        wanted = wanted || option == "memory";
    if (wanted) mounts.push_back({unescape(fields[3]), unescape(fields[4])});
  }
  return mounts;
}

// The process's cgroup, "/a/b", in v2 ("0::/a/b") or in the v1 hierarchy
// that holds the memory controller ("4:memory,hugetlb:/a/b").
std::optional<std::string> cgroup_path(std::string_view proc_self_cgroup, bool v1_memory) {
  for (std::string_view line : split(proc_self_cgroup, '\n')) {
    const std::size_t first = line.find(':');
    const std::size_t second = first == std::string_view::npos ? first : line.find(':', first + 1);
    if (second == std::string_view::npos) continue;
    const std::string_view id = line.substr(0, first);
    const std::string_view controllers = line.substr(first + 1, second - first - 1);
    const std::string_view path = line.substr(second + 1);  // may itself hold ':'
    bool wanted = !v1_memory && id == "0" && controllers.empty();
    if (v1_memory)
      for (std::string_view controller : split(controllers, ','))
        wanted = wanted || controller == "memory";
    if (wanted && starts_with(path, "/")) return std::string(path);
  }
  return std::nullopt;
}

// `path` below the mount's `root` ("" for the root itself, else "/a/b"), or
// nothing when it is not below it.
std::optional<std::string> below(std::string_view root, std::string_view path) {
  while (root.size() > 1 && root.back() == '/') root.remove_suffix(1);
  while (!path.empty() && path.back() == '/') path.remove_suffix(1);
  if (root == "/") return std::string(path);
  if (path == root) return std::string();
  if (starts_with(path, root) && path.size() > root.size() && path[root.size()] == '/')
    return std::string(path.substr(root.size()));
  return std::nullopt;
}

// Above this many bytes (an exabyte, more than any machine holds) a number
// means no limit: v1 says so with 2^63 rounded down to its pages.
constexpr std::uint64_t kNoLimit = std::uint64_t(1) << 60;

std::optional<std::uint64_t> parse_limit(std::string_view text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.remove_suffix(1);
  std::uint64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  // "max", nothing or a number out of range: no limit.
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  if (value == 0 || value >= kNoLimit) return std::nullopt;
  return value;
}

// The lowest limit in `file_name` from the process's cgroup up to the root
// of each mount that shows its hierarchy.
void lowest_up_the_chain(const std::vector<Mount>& mounts, const std::optional<std::string>& path,
                         const char* file_name, const ReadTextFile& read, std::optional<CgroupMemoryLimit>& lowest) {
  if (!path) return;
  // The mounts showing the cgroup; none (a cgroup namespace's "/" while
  // the mount shows the hierarchy from above) means the mount's own root.
  std::vector<std::pair<std::string, std::string>> starts;  // point, path below it
  for (const Mount& mount : mounts)
    if (const std::optional<std::string> rest = below(mount.root, *path)) starts.emplace_back(mount.point, *rest);
  if (starts.empty())
    for (const Mount& mount : mounts) starts.emplace_back(mount.point, std::string());
  for (auto& [point, rest] : starts) {
    std::string base = point;
    while (!base.empty() && base.back() == '/') base.pop_back();
    for (;;) {
      const std::string file = base + rest + "/" + file_name;
      if (const std::optional<std::string> text = read(file))
        if (const std::optional<std::uint64_t> bytes = parse_limit(*text); bytes && (!lowest || *bytes < lowest->bytes))
          lowest = CgroupMemoryLimit{*bytes, file};
      if (rest.empty()) break;
      const std::size_t slash = rest.rfind('/');
      rest.erase(slash == std::string::npos ? 0 : slash);
    }
  }
}

}  // namespace

std::optional<CgroupMemoryLimit> cgroup_memory_limit(std::string_view proc_self_cgroup,
                                                     std::string_view proc_self_mountinfo,
                                                     const ReadTextFile& read) {
  std::optional<CgroupMemoryLimit> lowest;
  lowest_up_the_chain(cgroup_mounts(proc_self_mountinfo, false), cgroup_path(proc_self_cgroup, false), "memory.max",
                      read, lowest);
  lowest_up_the_chain(cgroup_mounts(proc_self_mountinfo, true), cgroup_path(proc_self_cgroup, true),
                      "memory.limit_in_bytes", read, lowest);
  return lowest;
}

std::optional<std::string> read_cgroup_file(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return std::nullopt;
  std::string text;
  char buffer[4096];
  for (;;) {
    const ssize_t got = ::read(fd, buffer, sizeof buffer);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) {  // a directory, a file the kernel will not give
      ::close(fd);
      return std::nullopt;
    }
    if (got == 0) break;
    text.append(buffer, std::size_t(got));
  }
  ::close(fd);
  return text;
}

std::optional<CgroupMemoryLimit> cgroup_memory_limit() {
  const std::optional<std::string> cgroup = read_cgroup_file("/proc/self/cgroup");
  const std::optional<std::string> mountinfo = read_cgroup_file("/proc/self/mountinfo");
  if (!cgroup || !mountinfo) return std::nullopt;
  return cgroup_memory_limit(*cgroup, *mountinfo, read_cgroup_file);
}

}  // namespace hsb
