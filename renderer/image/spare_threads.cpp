#include "renderer/image/spare_threads.h"

#include <pthread.h>

#include <condition_variable>
#include <deque>
#include <mutex>
#include <new>
#include <system_error>
#include <thread>

#include "base/thread_room.h"

namespace hsb {
namespace {

struct SparePool {
  std::mutex mutex;
  std::condition_variable work;
  std::deque<std::packaged_task<void()>> jobs;
  int parked = 0;  // threads waiting for a job and promised none yet
};

// Never destroyed: its parked threads wait on it until the process ends,
// and exit must not destroy a mutex they sleep on.
SparePool* made_pool = nullptr;

// A fork copies only the forking thread: the child's pool must not count
// threads it does not have, nor keep a lock a parent's thread held.
void before_fork() { made_pool->mutex.lock(); }
void after_fork_in_parent() { made_pool->mutex.unlock(); }
void after_fork_in_child() {
  made_pool->mutex.unlock();
  new (&made_pool->work) std::condition_variable;  // its sleepers stayed in the parent
  made_pool->jobs.clear();
  made_pool->parked = 0;
}

SparePool& spare_pool() {
  static std::once_flag made;
  std::call_once(made, [] {
    made_pool = new SparePool;
    pthread_atfork(before_fork, after_fork_in_parent, after_fork_in_child);
  });
  return *made_pool;
}

void serve_jobs() {
  SparePool& pool = spare_pool();
  std::unique_lock<std::mutex> lock(pool.mutex);
  for (;;) {
    pool.work.wait(lock, [&] { return !pool.jobs.empty(); });
    std::packaged_task<void()> job = std::move(pool.jobs.front());
    pool.jobs.pop_front();
    lock.unlock();
    job();
    lock.lock();
    ++pool.parked;
  }
}

}  // namespace

void make_spare_thread() {
  SparePool& pool = spare_pool();
  const std::lock_guard<std::mutex> lock(pool.mutex);
  try {
    std::thread(serve_jobs).detach();
    ++pool.parked;
  } catch (const std::system_error&) {
    // None parked: run_on_spare_thread tries again, and says why it cannot.
  }
}

std::future<void> run_on_spare_thread(std::function<void()> job) {
  SparePool& pool = spare_pool();
  std::packaged_task<void()> task(std::move(job));
  std::future<void> done = task.get_future();
  const std::lock_guard<std::mutex> lock(pool.mutex);
  pool.jobs.push_back(std::move(task));
  if (pool.parked > 0) {
    --pool.parked;
    pool.work.notify_one();
    return done;
  }
  try {
    std::thread(serve_jobs).detach();
  } catch (const std::system_error& refused) {
    pool.jobs.pop_back();
    throw thread_refused(refused, "to write the picture");
  }
  return done;
}

}  // namespace hsb
