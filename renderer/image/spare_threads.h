#pragma once
// Threads made ahead of need, for work that starts while the image module
// loads. A thread made while the dynamic loader runs waits for it to end:
// the new thread's thread-local storage takes the lock the loader holds
// for the whole of a dlopen. A render that made its picture's writing
// thread after the module's load began stood still until the load ended
// (on fig09 with 11,020 sources, 0.06–0.13 s of a 0.5 s run), where it
// could have traced rays.

#include <functional>
#include <future>

namespace hsb {

// Makes one more parked thread now; run_on_spare_thread gives it work.
// Call it before anything that holds the loader's lock long. Makes none
// where the system refuses a thread (ulimit -u): run_on_spare_thread
// tries again, and says so.
void make_spare_thread();

// Runs `job` on a parked thread, or on a new one when none is parked (it
// parks once the job ends). The future is ready when the job has ended,
// holding what it threw. A fork leaves the child with no parked threads.
// Throws ResourceError (base/thread_room.h) when none is parked and the
// system refuses a new one (ulimit -u).
std::future<void> run_on_spare_thread(std::function<void()> job);

}  // namespace hsb
