#include "renderer/surface/instruction_set.h"

#include <array>
#include <atomic>
#include <cstdlib>
#include <stdexcept>

namespace hsb {
namespace {

constexpr std::array<const char*, 5> kNames = {"sse2", "sse4.2", "avx", "avx2", "avx512"};

std::atomic<bool> g_forced{false};

std::string unsupported_message(InstructionSet isa, const char* asked_by) {
  return std::string("the instruction set ") + isa_name(isa) + " (" + asked_by +
         ") is not supported by this processor, whose best is " + isa_name(best_supported_isa()) +
         "; choose one of " + isa_names() + " up to that";
}

}  // namespace

const char* isa_name(InstructionSet isa) { return kNames[std::size_t(isa)]; }

std::optional<InstructionSet> parse_isa(const std::string& name) {
  for (std::size_t i = 0; i < kNames.size(); ++i)
    if (name == kNames[i]) return InstructionSet(i);
  return std::nullopt;
}

std::string isa_names() {
  std::string names;
  for (const char* name : kNames) names += (names.empty() ? "" : ", ") + std::string(name);
  return names;
}

bool processor_supports(InstructionSet isa) {
  // __builtin_cpu_supports also checks that the operating system saves the
  // AVX and AVX-512 registers (XGETBV), not only that the processor has them.
  switch (isa) {
    case InstructionSet::sse2:
      return __builtin_cpu_supports("sse2");
    case InstructionSet::sse42:
      return __builtin_cpu_supports("sse4.2") && __builtin_cpu_supports("popcnt");
    case InstructionSet::avx:
      return processor_supports(InstructionSet::sse42) && __builtin_cpu_supports("avx");
    case InstructionSet::avx2:
      return processor_supports(InstructionSet::avx) && __builtin_cpu_supports("avx2") &&
             __builtin_cpu_supports("fma") && __builtin_cpu_supports("bmi") && __builtin_cpu_supports("bmi2");
    case InstructionSet::avx512:
      return processor_supports(InstructionSet::avx2) && __builtin_cpu_supports("avx512f") &&
             __builtin_cpu_supports("avx512cd") && __builtin_cpu_supports("avx512dq") &&
             __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512vl");
  }
  return false;
}

InstructionSet best_supported_isa() {
  InstructionSet best = InstructionSet::sse2;  // every x86-64 processor
  for (InstructionSet isa : supported_isas()) best = isa;
  return best;
}

std::vector<InstructionSet> supported_isas() {
  std::vector<InstructionSet> isas;
  for (std::size_t i = 0; i < kNames.size(); ++i)
    if (processor_supports(InstructionSet(i))) isas.push_back(InstructionSet(i));
  return isas;
}

// −1 until the first active_isa() or force_isa().
std::atomic<int> detail::g_active_isa{-1};

InstructionSet detail::choose_active_isa() {
  InstructionSet isa = best_supported_isa();
  if (const char* asked = std::getenv("HSB_ISA"); asked && *asked) {
    const std::optional<InstructionSet> parsed = parse_isa(asked);
    if (!parsed)
      throw std::runtime_error(std::string("HSB_ISA=") + asked + " is not an instruction set; expected one of " +
                               isa_names());
    if (!processor_supports(*parsed)) throw std::runtime_error(unsupported_message(*parsed, "HSB_ISA"));
    isa = *parsed;
    g_forced.store(true, std::memory_order_relaxed);
  }
  g_active_isa.store(int(isa), std::memory_order_relaxed);
  return isa;
}

void force_isa(InstructionSet isa) {
  if (!processor_supports(isa)) throw std::runtime_error(unsupported_message(isa, "asked for"));
  detail::g_active_isa.store(int(isa), std::memory_order_relaxed);
  g_forced.store(true, std::memory_order_relaxed);
}

bool isa_forced() {
  active_isa();
  return g_forced.load(std::memory_order_relaxed);
}

}  // namespace hsb
