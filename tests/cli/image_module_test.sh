#!/usr/bin/env bash
# How the image module (OpenImageIO) is loaded: deep-bound where the build
# has no copy relocations and nothing interposes the allocator, the
# ordinary way under a preloaded allocator (glibc's malloc debugger stands
# in for a cluster's jemalloc), and the same image bytes either way.
#
#   image_module_test.sh HSB EXPECTED   (EXPECTED: deep-bound or ordinary)
source "$(dirname "$0")/common.sh"
expected=$2

version=$("$hsb" --version) || fail "--version exits $?"
grep -qx "  image module: $expected load" <<<"$version" || fail "expected a $expected load: $version"

scene=(render "$src/scenes/fig05_point_load_linear.toml" --set render.width=160 --set render.height=160 -q)
"$hsb" "${scene[@]}" -o "$work/as_built" || fail "render exits $?"

interposer=/usr/lib/x86_64-linux-gnu/libc_malloc_debug.so.0
[[ -f $interposer ]] || fail "no $interposer (glibc 2.34 or later has it)"
version=$(LD_PRELOAD=$interposer "$hsb" --version) || fail "--version under a preloaded allocator exits $?"
grep -qx "  image module: ordinary load" <<<"$version" ||
  fail "a preloaded allocator must rule deep binding out: $version"
LD_PRELOAD=$interposer "$hsb" "${scene[@]}" -o "$work/preloaded" || fail "render under a preloaded allocator exits $?"
cmp -s "$work/as_built/fig05_point_load_linear.png" "$work/preloaded/fig05_point_load_linear.png" ||
  fail "the image differs between the two loads"
echo "image module: $expected load as built, ordinary under $interposer, the same bytes"
