#!/usr/bin/env bash
# The second half of CI: the unit tests built with clang under
# AddressSanitizer and UndefinedBehaviorSanitizer (any finding fails), and
# the fuzz targets for a short bounded time, in build-sanitize/.
#
#   scripts/sanitize.sh
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/lib/packages.sh
scripts/setup.sh > /dev/null  # the packages and a configured project
install_missing clang-14 libclang-rt-14-dev
if [[ ! -f build-sanitize/build.ninja ]]; then
  # Line tables are all a sanitizer's report needs, and build faster than full debug information.
  CC=clang-14 CXX=clang++-14 cmake -S . -B build-sanitize -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DHSB_SANITIZE=ON \
    "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -gline-tables-only -DNDEBUG" "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O2 -gline-tables-only -DNDEBUG"
fi
cmake --build build-sanitize -j "${JOBS:-2}" --target hsb base_tests field_tests renderer_tests golden_tests scene_fuzzer data_fuzzer
# The unit, golden and fuzz tests, and each instruction set's packet and
# golden tests (hsb is built for them to ask which sets the processor has);
# the other command-line and smoke tests run in the main build, and so do
# the two tests that check crossings against dense sampling: their time is
# the test's own sampling (millions of gauges), and the tracer's paths
# they take are taken under the sanitizers by the others (the rays walked
# side by side, the crowds, the exact crossings). Leaks in the libraries'
# one-time globals are not ours.
# An allocation larger than memory fails as it does without the sanitizer
# (std::bad_alloc, which the readers turn into "declares more than memory
# holds"), where AddressSanitizer would abort the process.
export ASAN_OPTIONS=detect_leaks=0:abort_on_error=0:allocator_may_return_null=1 UBSAN_OPTIONS=print_stacktrace=1
ctest --test-dir build-sanitize --output-on-failure -j "${JOBS:-2}" \
  -E '^(cli|scenes)\.|^GlyphShapes\.TracerFindsEveryCrossingDenseSamplingFinds$|^SphereAgainstExact\.DenseBlendedHyperstreamsurface$'
