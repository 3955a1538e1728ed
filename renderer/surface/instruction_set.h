#pragma once
// The x86-64 instruction set the renderer traces with: Embree's kernels and
// the renderer's own SIMD kernels (span_kernels.h) always use the same one.
//
// By default it is the best the processor has. HSB_ISA in the environment,
// or `hsb --isa`, forces a lower one, so that any machine can run, test and
// reproduce every path a user's processor might take. The pictures are the
// same bytes on every instruction set (tests/cli/isa_test.sh): nothing the
// renderer computes depends on the vector width.

#include <atomic>
#include <optional>
#include <string>
#include <vector>

namespace hsb {

// In increasing order: each includes the ones before it.
enum class InstructionSet { sse2, sse42, avx, avx2, avx512 };

// "sse2", "sse4.2", "avx", "avx2", "avx512": the names HSB_ISA, `hsb --isa`
// and Embree's `isa=` device setting take.
const char* isa_name(InstructionSet isa);
std::optional<InstructionSet> parse_isa(const std::string& name);
// Every name, comma-separated, for messages.
std::string isa_names();

// What Embree requires of the processor for its kernels of that set (for
// avx2 also FMA and BMI1/2; for avx512 the Skylake-X subset F, CD, DQ, BW,
// VL), with the operating system saving the wider registers.
bool processor_supports(InstructionSet isa);
InstructionSet best_supported_isa();
std::vector<InstructionSet> supported_isas();  // in increasing order

// The instruction set in force: the one forced by force_isa() or HSB_ISA,
// else the processor's best. Throws std::runtime_error, naming what was
// asked for and what the processor has, when HSB_ISA is not a known name or
// asks for more than the processor supports.
// Inline once chosen: the shape tracer's bounds and gauges ask it for every
// call, tens of times a ray (0.8 % of fig17's render as a call).
namespace detail {
extern std::atomic<int> g_active_isa;  // −1 until the first choice
InstructionSet choose_active_isa();
}  // namespace detail
inline InstructionSet active_isa() {
  const int active = detail::g_active_isa.load(std::memory_order_relaxed);
  return active >= 0 ? InstructionSet(active) : detail::choose_active_isa();
}
// Whether active_isa() was forced (HSB_ISA or force_isa()) rather than
// the processor's best.
bool isa_forced();

// Forces `isa` for every Embree device created from now on and for the
// renderer's kernels at once. Throws like active_isa() when the processor
// lacks it. Call it between renders, never during one.
void force_isa(InstructionSet isa);

}  // namespace hsb
