#!/usr/bin/env bash
# The field side of a diffusion volume as MRtrix fits it, masked and not,
# at the sizes of real scans: a simulated acquisition
# (scenes/data/generators/formats/dwi_simulation.py) of NX×NY×NZ voxels,
# fitted by dwi2tensor, rendered by hsb given the file alone. Prints, for
# each, hsb's build time (reading, seeding, tracing, placing: the field
# side), the whole process's time and its peak memory. Figures, not a
# test: it never fails on a number.
#
#   tests/bench/diffusion_field_bench.sh [NX NY NZ]...   # default: 64 64 30 and 128 128 70
set -euo pipefail
cd "$(dirname "$0")/../.."
hsb=$PWD/build/hsb
sizes=("$@")
((${#sizes[@]})) || sizes=(64 64 30 128 128 70)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
printf '%-12s %-9s %10s %10s %10s %s\n' size mask build_s total_s peak_MB warning
while ((${#sizes[@]} >= 3)); do
  nx=${sizes[0]} ny=${sizes[1]} nz=${sizes[2]}
  sizes=("${sizes[@]:3}")
  dir=$work/${nx}x${ny}x${nz}
  mkdir -p "$dir"
  /usr/bin/python3 scenes/data/generators/formats/dwi_simulation.py "$dir" "$nx" "$ny" "$nz" > /dev/null
  (cd "$dir" && mrconvert -quiet dwi.nii.gz -fslgrad bvecs bvals dwi.mif &&
     dwi2tensor -quiet dwi.mif -mask mask.nii.gz masked.nii.gz && dwi2tensor -quiet dwi.mif unmasked.nii.gz)
  for mask in masked unmasked; do
    /usr/bin/time -f '%e %M' -o "$dir/time" "$hsb" render "$dir/$mask.nii.gz" -o "$dir/out" \
      --set render.width=320 --set render.height=240 > "$dir/log" 2> "$dir/err" || { cat "$dir/err"; exit 1; }
    read -r total peak < "$dir/time"
    build=$(sed -n 's/.*(build \([0-9.]*\)s.*/\1/p' "$dir/log")
    said=$(grep -c 'warning' "$dir/err" || true)
    printf '%-12s %-9s %10s %10s %10d %s\n' "${nx}x${ny}x${nz}" "$mask" "$build" "$total" $((peak / 1024)) "$said"
  done
done
