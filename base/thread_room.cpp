#include "base/thread_room.h"

#include <sys/resource.h>
#include <unistd.h>

#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdlib>
#include <fstream>
#include <mutex>
#include <thread>
#include <vector>

namespace hsb {
namespace {

// ulimit -u below this is measured, by starting the threads; above it, a
// user would need as many threads running already (the usual default is
// tens of thousands). The kernel counts them per user, cheaply only for itself.
constexpr rlim_t kMeasuredBelow = 16384;

// What a pids controller leaves this process's group (a container's, a
// Slurm job's): its limit less the tasks it holds, from cgroup v2 or v1;
// −1 when there is no limit.
long cgroup_tasks_left() {
  const char* const places[][2] = {{"/sys/fs/cgroup/pids.max", "/sys/fs/cgroup/pids.current"},
                                   {"/sys/fs/cgroup/pids/pids.max", "/sys/fs/cgroup/pids/pids.current"}};
  for (const auto& place : places) {
    std::ifstream max_file(place[0]), current_file(place[1]);
    std::string most;
    long current = 0;
    if (!(max_file >> most) || !(current_file >> current)) continue;
    if (most == "max") return -1;
    return std::max(0L, std::strtol(most.c_str(), nullptr, 10) - current);
  }
  return -1;
}

// Keeps TBB to `threads` for the rest of the process. Never destroyed: the
// least active value of max_allowed_parallelism binds, so no later control
// lifts it (--threads' going out of scope made TBB start its workers anew).
void keep_tbb_to(int threads) {
  new tbb::global_control(tbb::global_control::max_allowed_parallelism, std::size_t(std::max(threads, 1)));
}

// "" when there is room for a run's threads (TBB's kept to it); else why not.
std::string measured_room() {
  // TBB's threads at most (the machine's), and as many as it may use now (--threads).
  const int most = std::max(1, tbb::this_task_arena::max_concurrency());
  const int tbb_threads = std::max(1, int(std::min<std::size_t>(
      std::size_t(most), tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism))));
  const int wanted = most - 1 + kThreadsBesideTbb;
  int room = wanted;
  std::string limit, raise;
  if (const long left = cgroup_tasks_left(); left >= 0 && left < room) {
    room = int(left);
    limit = "its control group's pids limit leaves " + std::to_string(left);
    raise = "raise the control group's (container's) pids limit";
  }
  // Root is not held to ulimit -u.
  struct rlimit tasks {};
  if (getuid() != 0 && getrlimit(RLIMIT_NPROC, &tasks) == 0 && tasks.rlim_cur < kMeasuredBelow) {
    const int started = startable_threads(room);
    if (started < room) {
      room = started;
      limit = "ulimit -u is " + std::to_string(tasks.rlim_cur) + ", counting every thread of this user's processes";
      raise = "raise ulimit -u, or end other processes of this user";
    }
  }
  if (room >= wanted) return "";  // TBB cannot take more
  keep_tbb_to(std::min(tbb_threads, room - kThreadsBesideTbb + 1));
  if (room >= kThreadsBesideTbb) return "";
  return "cannot start a thread (ulimit -u?): this process may start " + std::to_string(room) + " more (" + limit +
         "), and a run starts " + std::to_string(kThreadsBesideTbb) +
         " beside its main thread even with --threads 1 (to write the picture, and in the image and text "
         "libraries): " + raise;
}

}  // namespace

void fit_threads_to_room() {
  static const std::string refusal = measured_room();
  if (!refusal.empty()) throw ResourceError(refusal);
}

ResourceError thread_refused(const std::system_error& refused, const std::string& what) {
  return ResourceError("cannot start a thread (ulimit -u?) " + what + ": " + refused.code().message());
}

namespace {

// This process's threads, as the kernel counts them until it has released
// one that ended (/proc/self/status); 0 where unknown.
int threads_now() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("Threads:", 0) == 0) return std::atoi(line.c_str() + 8);
  return 0;
}

}  // namespace

int startable_threads(int wanted) {
  const int before = threads_now();
  std::mutex mutex;
  std::condition_variable released;
  bool all_tried = false;
  std::vector<std::thread> started;
  started.reserve(std::size_t(std::max(wanted, 0)));
  for (int i = 0; i < wanted; ++i) {
    try {
      started.emplace_back([&] {
        std::unique_lock<std::mutex> lock(mutex);
        released.wait(lock, [&] { return all_tried; });
      });
    } catch (const std::system_error&) {
      break;
    }
  }
  {
    const std::lock_guard<std::mutex> lock(mutex);
    all_tried = true;
  }
  released.notify_all();
  for (std::thread& t : started) t.join();
  // A joined thread is counted against the limit until the kernel releases
  // it, a moment after the join: the threads started next must find room.
  for (int wait = 0; wait < 200 && threads_now() > before; ++wait)
    std::this_thread::sleep_for(std::chrono::microseconds(100));
  return int(started.size());
}

}  // namespace hsb
