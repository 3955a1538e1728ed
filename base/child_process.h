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

}  // namespace hsb
