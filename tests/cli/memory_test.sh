#!/usr/bin/env bash
# The memory a scene is estimated to take is within 25 % of its measured
# peak, at three sizes; and an address-space limit (ulimit -v) is part of
# the budget: a scene beyond it is refused before anything is allocated,
# not killed by a failed allocation midway.
source "$(dirname "$0")/common.sh"
fig09=$src/scenes/fig09_point_load_hyperstreamsurface.toml
size=(--set render.width=400 --set render.height=400 --set render.samples=1)

for spacing in 0.004 0.002 0.001; do
  line=$("$hsb" render "$fig09" --set glyphs.spacing=$spacing "${size[@]}" -o "$work" --stats 2> "$work/err" | grep "peak memory") ||
    fail "spacing $spacing did not render"
  peak=$(sed -n 's/.*peak memory \([0-9]*\) MB.*/\1/p' <<<"$line")
  estimate=$(sed -n 's/.*estimated \([0-9]*\) MB.*/\1/p' <<<"$line")
  [[ -n $peak && -n $estimate ]] || fail "no peak and estimate in: $line"
  awk -v p="$peak" -v e="$estimate" 'BEGIN { exit !(e >= 0.75 * p && e <= 1.25 * p) }' ||
    fail "spacing $spacing: estimated $estimate MB against a peak of $peak MB"
  echo "glyphs.spacing $spacing: estimated $estimate MB, peak $peak MB"
done

# About 2.2 million sources (2.8 GB) under a 3 GB address space.
out=$( (ulimit -v 3000000; "$hsb" render "$fig09" --set glyphs.spacing=0.00005 "${size[@]}" -o "$work/limited") 2>&1)
status=$?
[[ $status == 1 ]] || fail "under ulimit -v: exit $status: $out"
grep -q "the address-space limit (ulimit -v) leaves this process: raise glyphs.spacing" <<<"$out" ||
  fail "under ulimit -v: $out"
echo "memory: ok"
