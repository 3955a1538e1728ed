#pragma once
// How much memory one scene may take, and the error for a scene that
// would take more: refused before anything is allocated, with the estimate
// and the key to change, instead of dying with a bare std::bad_alloc (or
// being killed) minutes later.

#include <cstddef>
#include <stdexcept>
#include <string>

namespace hsb {

class ResourceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Three quarters of the memory this process may use: the machine's
// physical memory, or its control group's limit when lower (a Slurm job's
// allocation, a container's: the lowest from its own cgroup up, see
// base/cgroup_memory.h).
std::size_t memory_budget_bytes();

// "2.3 GB", "512 MB": a size for a message.
std::string human_bytes(double bytes);

// Throws ResourceError when `bytes` exceed the budget. `what` names the
// thing estimated and how ("the trajectories: 10000 seeds × 1602 points"),
// `change` the keys that make it smaller.
void check_memory(double bytes, const std::string& what, const std::string& change);

}  // namespace hsb
