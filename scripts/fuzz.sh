#!/usr/bin/env bash
# Runs the fuzz targets for as long as you like (the test suite runs each
# for 20 seconds):
#
#   scripts/fuzz.sh [SECONDS] [scene|data]     # default: 600 seconds each, both
#
# Builds build-sanitize/ (clang, AddressSanitizer, UndefinedBehaviorSanitizer,
# libFuzzer) if needed. New inputs that reach new code are added to
# tests/fuzz/corpus/<target>/ (commit the useful ones); a crash leaves its
# input in build-sanitize/fuzz-findings/ and the run stops there; with
# KEEP_GOING=1 it runs in libFuzzer's fork mode and goes on past crashes,
# timeouts and running out of memory, collecting every finding.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-600}
targets=("${@:2}")
(( ${#targets[@]} )) || targets=(scene data)
scripts/setup.sh > /dev/null
if [[ ! -f build-sanitize/build.ninja ]]; then
  CC=clang-14 CXX=clang++-14 cmake -S . -B build-sanitize -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DHSB_SANITIZE=ON
fi
cmake --build build-sanitize -j "${JOBS:-2}" --target scene_fuzzer data_fuzzer
mkdir -p build-sanitize/fuzz-findings
# VTK's filters keep caches that LeakSanitizer reports at exit: not ours.
export ASAN_OPTIONS=detect_leaks=0
for t in "${targets[@]}"; do
  echo "fuzz: ${t}_fuzzer for ${seconds} s"
  keep_going=()
  [[ ${KEEP_GOING:-0} == 1 ]] && keep_going=(-fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1)
  "build-sanitize/tests/fuzz/${t}_fuzzer" "${keep_going[@]}" -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=10 -detect_leaks=0 \
    -artifact_prefix=build-sanitize/fuzz-findings/ "tests/fuzz/corpus/$t"
done
