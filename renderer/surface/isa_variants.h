#pragma once
// One variant of a SIMD loop per instruction set, each compiled for that set
// alone (GCC's target_clones would pick one when the program loads, with no
// way to force another for a test or a reproduction): KERNEL(suffix,
// "target") for each set, in InstructionSet order (instruction_set.h).
// Files that use it are compiled without fused multiply-adds
// (renderer/CMakeLists.txt), so every variant rounds alike.
#define HSB_FOR_EACH_ISA(KERNEL)                          \
  KERNEL(sse2, "sse2")                                    \
  KERNEL(sse42, "sse4.2,popcnt")                          \
  KERNEL(avx, "avx")                                      \
  KERNEL(avx2, "avx2,fma,bmi,bmi2")                       \
  KERNEL(avx512, "avx512f,avx512cd,avx512dq,avx512bw,avx512vl")
