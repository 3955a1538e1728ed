// A module whose loading holds the dynamic loader's lock until told to let
// go: spare_threads_test.cpp loads it to show that a spare thread takes
// work while a load is under way.
//
// glibc holds the lock a new thread's thread-local storage needs
// (dl_load_tls_lock) while it maps and relocates a module, and lets it go
// before the module's constructors run. So the holding is done by an
// indirect function's resolver, which the loader calls while it relocates
// the module. The module's own relocations may not be done by then: the
// resolver calls the kernel directly and touches only static data. It
// writes a byte to descriptor kHeldFd once it runs, then waits up to 20 s
// for a byte on kReleasedFd.

#include <poll.h>
#include <sys/syscall.h>

namespace {

constexpr int kHeldFd = 1001, kReleasedFd = 1000;
int released = 0;  // 1 when the test let the loader go, 0 when it gave up waiting

long raw_syscall(long number, long a, long b, long c) {
  long result;
  asm volatile("syscall" : "=a"(result) : "a"(number), "D"(a), "S"(b), "d"(c) : "rcx", "r11", "memory");
  return result;
}

void held_function() {}

extern "C" void (*hold_the_loader())() {
  const char byte = 'h';
  raw_syscall(SYS_write, kHeldFd, long(&byte), 1);
  pollfd wait{kReleasedFd, POLLIN, 0};
  released = raw_syscall(SYS_poll, long(&wait), 1, 20000) == 1 ? 1 : 0;
  return held_function;
}

}  // namespace

extern "C" {
void hsb_test_held_function() __attribute__((ifunc("hold_the_loader")));
// A relocation against the indirect function, which the loader resolves
// while it loads the module.
__attribute__((used)) void (*hsb_test_held_pointer)() = hsb_test_held_function;
int hsb_test_released() { return released; }
}
