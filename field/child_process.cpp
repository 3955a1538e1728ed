#include "field/child_process.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <thread>

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define HSB_SANITIZED 1
#include <sanitizer/common_interface_defs.h>
#endif
#endif

namespace hsb {

ChildResult run_in_child(const std::function<void()>& work, double seconds) {
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
