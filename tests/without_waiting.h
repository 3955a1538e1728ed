#pragma once
// A call that must not wait on a FIFO: a reader that opens one waits for a
// writer for ever. The tests that hand hsb a FIFO run the call beside, and
// should it wait, a writer comes after 10 seconds to release it and the
// test fails, where it would otherwise hang the suite.

#include <fcntl.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <future>

namespace hsb {

// What `call()` returns, which must not wait on the FIFO `fifo`.
template <class Call>
auto without_waiting(const std::filesystem::path& fifo, Call call) {
  auto done = std::async(std::launch::async, call);
  if (done.wait_for(std::chrono::seconds(10)) == std::future_status::timeout) {
    ADD_FAILURE() << "waited for a writer on the FIFO " << fifo;
    const int fd = open(fifo.c_str(), O_WRONLY | O_NONBLOCK);
    if (fd >= 0) close(fd);
  }
  return done.get();
}

}  // namespace hsb
