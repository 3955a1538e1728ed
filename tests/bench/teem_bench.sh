#!/usr/bin/env bash
# hsb against Teem's own glyph ray tracer on Teem's own data.
#
#   tests/bench/teem_bench.sh [SAMPLES [SIZE]...]
#
# `tend helix -s SAMPLES³` (88 by default: 33,768 voxels with FA ≥ 0.3)
# is rendered as a glyph field, one glyph per voxel with FA ≥ 0.3, by
# `tend glyph -rt` and by hsb, with the same tensors, glyph scale (a
# glyph's semi-axes are 150 λ in both), camera, image size and one sample
# per pixel, without shadows or ambient occlusion, on both cores:
# ellipsoids (Teem's `-g sphere`, a union of hsb's ellipsoids, blend =
# "max") and Kindlmann's superquadrics at sharpness 3. hsb's glyph surface is made the
# ellipsoid's own size (quartic kernel, influence radius 1/√(1 − 1/√2),
# whose level radius at C = ½ is 1). Prints, per shape and size, both
# whole-process times (the median of three runs), both peak resident
# memories, the ratio of the times and the fraction of pixels where the
# two pictures agree on glyph against background. Not part of the test
# suite: it measures, it does not judge.
set -euo pipefail
cd "$(dirname "$0")/../.."
source tests/bench/helix_glyph_field.sh
source tests/bench/measure.sh
scripts/setup.sh > /dev/null
if ! command -v teem-tend > /dev/null || [[ ! -x /usr/bin/time ]]; then
  sudo=(); [[ $(id -u) -eq 0 ]] || sudo=(sudo)
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -q --no-install-recommends teem-apps time > /dev/null
fi

samples=${1:-88}
shift || true
(($# > 0)) || set -- 800 2000
out=build/bench/teem
mkdir -p "$out"
helix=$out/helix$samples.nrrd
[[ -f $helix ]] || teem-tend helix -s "$samples" "$samples" "$samples" -o "$helix" 2> /dev/null

printf '%-13s %6s %7s %8s %8s %8s %8s %7s %10s\n' shape size glyphs hsb_s teem_s hsb_MB teem_MB ratio agreement
for shape in ellipsoid superquadric; do
  teem_shape=(-g sphere); [[ $shape == superquadric ]] && teem_shape=(-g superquad -sh 3)
  for size in "$@"; do
    camera=(-fr 400 -600 300 -at 0 0 0 -up 0 0 1 -fv 30 -rh)  # -rh: V down, as hsb's picture
    teem=(teem-tend glyph -i "$helix" -rt -a fa -atr 0.3 "${teem_shape[@]}" -gsc 150 "${camera[@]}"
          -is "$size" "$size" -ns 1 -nt 2 -bg 1 0 1 -o "$out/teem.nrrd")
    helix_glyph_field "$helix" "$out" "$size" "$shape"
    line=$("${hsb[@]}")
    read -r hsb_s hsb_mb <<< "$(measure "$out/time.txt" "${hsb[@]}")"
    read -r teem_s teem_mb <<< "$(measure "$out/time.txt" "${teem[@]}")"
    teem-unu crop -i "$out/teem.nrrd" -min 0 0 0 -max 2 M M | teem-unu quantize -b 8 -min 0 -max 1 |
      teem-unu save -f png -o "$out/teem.png"
    agreement=$(./build/tests/bench/mask_agreement "$out/hsb.png" "$out/teem.png" | awk '{print $2}')
    glyphs=$(sed -n 's/.*sources=\([0-9]*\).*/\1/p' <<< "$line")
    awk -v s="$shape" -v n="$size" -v g="$glyphs" -v h="$hsb_s" -v t="$teem_s" -v hm="$hsb_mb" -v tm="$teem_mb" -v a="$agreement" \
      'BEGIN { printf "%-13s %6d %7d %8.2f %8.2f %8d %8d %6.2fx %10s\n", s, n, g, h, t, hm, tm, t / h, a }'
  done
done
commit=$(git rev-parse --short HEAD 2> /dev/null || echo unknown)
echo "(tend helix at ${samples}³; 1 sample per pixel, no shadows or ambient occlusion; median whole-process times of 3 runs on $(nproc) cores;"
echo " ratio: Teem's time over hsb's; peak resident memory; hsb at $commit, $(./build/hsb --version | sed -n 2p))"
echo "($(sed -n 's/^model name[^:]*: //p' /proc/cpuinfo | head -1))"
