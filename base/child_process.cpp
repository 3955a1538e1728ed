#include "base/child_process.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define HSB_SANITIZED 1
#include <sanitizer/common_interface_defs.h>
#endif
#endif

namespace hsb {
namespace {

// Whether thread `tid` of this process is running, from its stat line
// ("tid (name) S ..."; the state follows the last parenthesis).
bool thread_running(const std::string& tid) {
  std::ifstream stat("/proc/self/task/" + tid + "/stat");
  std::string line;
  std::getline(stat, line);
  const std::size_t close = line.rfind(')');
  return close != std::string::npos && close + 2 < line.size() && line[close + 2] == 'R';
}

}  // namespace

void wait_for_quiet_threads() {
  const std::string self = std::to_string(syscall(SYS_gettid));
  for (int tries = 0; tries < 300; ++tries) {
    bool quiet = true;
    std::error_code error;
    for (std::filesystem::directory_iterator it("/proc/self/task", error), end; quiet && !error && it != end;
         it.increment(error)) {
      const std::string tid = it->path().filename().string();
      quiet = tid == self || !thread_running(tid);
    }
    if (quiet) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
}

ChildResult run_in_child(const std::function<void()>& work, double seconds) {
  wait_for_quiet_threads();
  const pid_t pid = fork();
  if (pid < 0) return {};  // no child to be had: run it only for real
  if (pid == 0) {
    // The child dies with its parent (Ctrl-C, a scheduler's SIGKILL): it
    // is only ever a trial of the parent's next step. If the parent died
    // before this line, the child is an orphan already and stops now.
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() == 1) _exit(0);
    // Whatever the child says (a crash report) is not for the user.
    const int null = open("/dev/null", O_WRONLY);
    if (null >= 0) dup2(null, STDERR_FILENO), dup2(null, STDOUT_FILENO);
#if HSB_SANITIZED
    // A crash here is the answer the parent waits for, not a finding: no
    // sanitizer (or fuzzer) report of it.
    __sanitizer_set_death_callback(nullptr);
#endif
    try {
      work();
    } catch (...) {
      // An exception is an answer, not a crash: the real run repeats it.
    }
    _exit(0);  // no destructors, no atexit handlers: they belong to the parent
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  auto pause = std::chrono::microseconds(200);
  for (;;) {
    int status = 0;
    const pid_t done = waitpid(pid, &status, WNOHANG);
    if (done == pid) {
      if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return {};
      return {ChildOutcome::crashed, WIFSIGNALED(status) ? WTERMSIG(status) : 0};
    }
    if (done < 0) return {};
    if (std::chrono::steady_clock::now() > deadline) {
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      return {ChildOutcome::timed_out, 0};
    }
    std::this_thread::sleep_for(pause);
    pause = std::min(pause * 2, std::chrono::microseconds(20000));
  }
}

}  // namespace hsb
