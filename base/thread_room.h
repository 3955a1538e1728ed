#pragma once
// Room for the threads a run starts. ulimit -u (which counts every thread
// of the user's processes) or a container's pids limit may leave a process
// room for a few, and a thread the system refuses is fatal where it is
// made: std::thread throws std::system_error, a TBB worker that cannot
// start the next one ends the process (std::terminate), GLib (Pango's font
// loading) aborts with SIGTRAP, and log4cplus (loaded with the image
// libraries) hangs. So the room is measured once, before any of them starts
// a thread: TBB is kept to the threads there is room for, and a process
// without room for the few the libraries start is refused with one message.

#include <string>
#include <system_error>

#include "base/memory_budget.h"

namespace hsb {

// The threads a run starts beside TBB's and its own main thread: the
// image module's loader and the picture's writer (2), log4cplus's pool
// (4), Pango's font loading (2 at once).
constexpr int kThreadsBesideTbb = 8;

// Measures the room once per process (later calls give the first answer)
// and keeps TBB within it: TBB's parallelism lowered, for the rest of the
// process, to what leaves kThreadsBesideTbb. Throws ResourceError "cannot
// start a thread (ulimit -u?)" when there is no room for those beside the
// main thread. Call it after any tbb::global_control that sets --threads
// and before the first thread starts.
void fit_threads_to_room();

// The ResourceError for a thread the system refused to start (`refused`,
// as std::thread or std::async throw it), `what` naming what it was for.
ResourceError thread_refused(const std::system_error& refused, const std::string& what);

// How many threads this process can start now, up to `wanted`: each is
// started and waits until the last is (or is refused), then all end.
int startable_threads(int wanted);

}  // namespace hsb
