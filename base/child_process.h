#pragma once
// Third-party code that may crash on hostile input, run where a crash
// cannot take the program down: VTK's readers trust the counts a file
// declares, and a corrupt cell list makes them read past their buffers
// (found by the data fuzzer, tests/fuzz). The work runs once in a forked
// child first; only if the child finishes is it run for real.

#include <functional>
#include <string>

namespace hsb {

enum class ChildOutcome { finished, crashed, timed_out };

struct ChildResult {
  ChildOutcome outcome = ChildOutcome::finished;
  int signal = 0;  // for crashed: the signal, or 0 for a sanitizer's exit
};

// Runs `work` in a child process, waiting at most `seconds`. Call it only
// where no other thread of this process holds a lock `work` needs (the
// child has only the calling thread).
ChildResult run_in_child(const std::function<void()>& work, double seconds);

// Waits, for a few tenths of a second at most, until every other thread of
// this process sleeps; call it just before any fork() whose child goes on
// running this program. fork() copies only the calling thread: another one
// stopped in the middle of the allocator leaves its lock held in the child
// for ever. glibc's malloc guards against that with fork handlers; the
// sanitizers' allocator of clang 14 does not: a pool thread that had just
// finished its work hung one trial read in ten there, and a spare thread
// still starting hung a forked child's first new thread.
void wait_for_quiet_threads();

}  // namespace hsb
