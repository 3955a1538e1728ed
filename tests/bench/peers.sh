#!/usr/bin/env bash
# hsb beside every peer, in one command, and one table of where it stands.
#
#   tests/bench/peers.sh
#
# Runs, on this machine, each comparison of issue 22 (installing the peers
# that are missing; ParaView only into a private root, paraview_bench.sh):
#   - POV-Ray 3.7's exact `blob` (povray_bench.sh): fig09 at 800² with
#     10³, 10⁴ and 10⁵ sources (below), and Teem's helix at 136³ as
#     123,888 blended ellipsoids, under this processor's best
#     instruction set and, where that is AVX-512, again with AVX2 forced
#     (HSB_ISA);
#   - Teem's `tend glyph -rt` on its own helix at 2000², ellipsoids and
#     superquadrics (teem_bench.sh);
#   - ParaView 5.11's `pvbatch` Tensor Glyph, superquadric against
#     superquadric, at 768² and 2000² (paraview_bench.sh);
#   - the speed of light of this design: the same sources as hard ellipsoids
#     in a minimal Embree geometry (light_speed_bench).
# Each bench's own table is kept in build/bench/peers/; the summary prints
# per comparison both whole-process times, their ratio (the peer's over
# hsb's), both peak memories, the pixel agreement and the instruction set,
# then the speed-of-light fractions. A benchmark, not a test: it never
# fails on a number. About 10 minutes on a 2-core machine; SWEEP="2 7",
# without the 10⁵ sources, 7.
set -euo pipefail
cd "$(dirname "$0")/../.."
scripts/setup.sh > /dev/null
log=build/bench/peers
mkdir -p "$log"

best=$(./build/hsb --version | sed -n 's/.*instruction set: \([a-z0-9.]*\).*/\1/p')
isas=("$best")
[[ $best == avx512 ]] && isas+=(avx2)

# fig09 with a seed grid of n × n instead of 7 × 7: about 840, 11,020 and
# 134,000 sources for n = 2, 7, 21 (SWEEP="2 7" leaves the last out: at
# 21 the lines crowd so near the load that a ray crosses some 330
# supports, and POV-Ray 3.7 stops with "Internal limit exceeded in
# FixedSimpleVector", which its row says).
scenes=()
for n in ${SWEEP:-2 7 21}; do
  scene=$log/fig09_seeds_${n}x$n.toml
  sed "s/^n = 7$/n = $n/; s/^m = 7$/m = $n/" scenes/fig09_point_load_hyperstreamsurface.toml > "$scene"
  scenes+=("$scene" "")
done
# 10⁵ sources POV-Ray can take: Teem's helix at 136³ as a blended field of
# ellipsoid glyphs (123,888 with FA ≥ 0.3, a few supports a ray).
helix=$log/helix136.nrrd
if ! command -v teem-tend > /dev/null; then
  sudo=(); [[ $(id -u) -eq 0 ]] || sudo=(sudo)
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -q --no-install-recommends teem-apps > /dev/null
fi
[[ -f $helix ]] || teem-tend helix -s 136 136 136 -o "$helix" 2> /dev/null
cat > "$log/helix136_glyphs.toml" << 'SCENE'
# Teem's helix at 136³, one ellipsoid glyph a voxel with FA ≥ 0.3, blended.
[data]
file = "helix136.nrrd"
[glyphs]
placement = "points"
stride = 1
shape = "ellipsoid"
mapping = "linear"
scale = 150
floor = 0.01
[region]
above = 0.3
SCENE
scenes+=("$log/helix136_glyphs.toml" "")
for isa in "${isas[@]}"; do
  echo "POV-Ray, hsb with $isa ..." >&2
  HSB_ISA=$isa tests/bench/povray_bench.sh 800 "${scenes[@]}" > "$log/povray_$isa.txt"
done
echo "Teem ..." >&2
tests/bench/teem_bench.sh 88 2000 > "$log/teem.txt"
echo "ParaView ..." >&2
tests/bench/paraview_bench.sh 16 768 2000 > "$log/paraview.txt"
echo "speed of light ..." >&2
./build/tests/bench/light_speed_bench 800 > "$log/light_speed.txt"

printf '%-50s %8s %8s %7s %7s %7s %9s %7s\n' work hsb_s peer_s ratio hsb_MB peer_MB agreement isa
for isa in "${isas[@]}"; do
  # povray_bench: name [(override)] sources hsb_s povray_s ratio hsb_MB pov_MB agreement
  awk -v isa="$isa" '$NF ~ /^[0-9.]+$/ && NF >= 8 && $1 != "scene" {
      printf "%-50s %8.2f %8.2f %6.1fx %7d %7d %9s %7s\n", "POV-Ray blob, " $1 ", " $(NF-6), $(NF-5), $(NF-4),
             $(NF-4) / $(NF-5), $(NF-2), $(NF-1), $NF, isa }
    # a run that failed: name sources "WHO failed: why"
    / failed: / { name = $1; sub(/^[^ ]+ +/, ""); sources = $1; sub(/^[0-9]+ +/, "");
                  printf "%-50s %s (%s)\n", "POV-Ray blob, " name ", " sources, $0, isa }' "$log/povray_$isa.txt"
done
# teem_bench: shape size glyphs hsb_s teem_s hsb_MB teem_MB ratio agreement
awk -v isa="$best" '$1 == "ellipsoid" || $1 == "superquadric" {
    printf "%-50s %8.2f %8.2f %6.1fx %7d %7d %9s %7s\n", "Teem tend glyph, " $3 " " $1 "s, " $2 "²", $4, $5,
           $5 / $4, $6, $7, $9, isa }' "$log/teem.txt"
# paraview_bench: size glyphs pv_glyph hsb_s pv_s pvbatch_s hsb_MB pv_MB ratio mem_ratio agreement
awk -v isa="$best" '$1 ~ /^[0-9]+$/ && NF == 11 {
    printf "%-50s %8.2f %8.2f %6.1fx %7d %7d %9s %7s\n", "ParaView TensorGlyph, " $2 " superquadrics, " $1 "²", $4,
           $5, $5 / $4, $7, $8, $11, isa }' "$log/paraview.txt"
echo "(whole processes, medians of 3 runs on $(nproc) cores; ratio: the peer's time over hsb's; each bench's"
echo " own table, with its settings, is in $log/; $(sed -n 's/^model name[^:]*: //p' /proc/cpuinfo | head -1))"
echo
echo "Speed of light: the field's ray rates as fractions of hard ellipsoids' (targets: union 0.5, blend 0.25)"
awk '/field, / { printf "  %-36s %-20s camera rays %5.2f  shadow rays %5.2f\n", $1, $3 " " $4, $8, $9 }' \
  "$log/light_speed.txt"
