#!/usr/bin/env bash
# hsb against POV-Ray's exact blob renderer on the same field.
#
#   tests/bench/povray_bench.sh [SIZE] [SCENE [OVERRIDES]]...
#
# For each scene: `hsb export --format pov` writes the same sources, kernel
# (quartic, POV-Ray's blob density), threshold, camera, light with shadows,
# background and image size as a POV-Ray scene; both programs render it on
# both cores (POV-Ray with +WT2), without anti-aliasing, timed as whole
# processes, each three times (the median is reported: one busy moment on a
# shared machine moves a single run by ±20%). Prints both times, their
# ratio, both peak resident memories, the fraction of pixels where the two
# images agree on surface versus background, and the instruction set hsb
# used (HSB_ISA=avx2 forces one). A scene may be given several times with
# other overrides (glyphs.spacing=0.0011 for 10⁵ sources on fig09).
# Not part of the test suite: it measures, it does not judge.
set -euo pipefail
cd "$(dirname "$0")/../.."
source tests/bench/measure.sh
scripts/setup.sh > /dev/null
if ! command -v povray > /dev/null || [[ ! -x /usr/bin/time ]]; then
  sudo=(); [[ $(id -u) -eq 0 ]] || sudo=(sudo)
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -q --no-install-recommends povray time > /dev/null
fi
mkdir -p build/bench/povray

size=${1:-800}
shift || true
if (($# == 0)); then
  set -- \
    "scenes/fig09_point_load_hyperstreamsurface.toml" "glyphs.spacing=0.02" \
    "scenes/fig07_point_load_normalized.toml" "" \
    "scenes/fig13_cylinder_hyperstreamsurface.toml" ""
fi

# The export's light is one parallel light with hard shadows, and POV-Ray
# traces no ambient occlusion: hsb traces the same, one shadow ray a hit
# (light.size = 0), no occlusion rays and no fill light, where its
# defaults would trace four soft-shadow and two occlusion rays a hit.
common=(--set render.width="$size" --set render.height="$size" --set render.samples=1
        --set 'surface.kernel="quartic"' --set output.colorbar=false --set render.box=false
        --set render.shell=false --set 'render.background=[1,0,1]' --set light.shadows=true
        --set light.size=0 --set light.ambient_occlusion.samples=0 --set light.fill=0)

printf '%-42s %8s %9s %9s %7s %7s %7s %10s\n' scene sources hsb_s povray_s ratio hsb_MB pov_MB agreement
while (($# >= 2)); do
  scene=$1 extra=$2
  shift 2
  name=$(basename "$scene" .toml)
  label=${extra:+ ($extra)}
  out=build/bench/povray/$name${extra:+_${extra//[^a-zA-Z0-9]/_}}
  mkdir -p "$out"
  sets=("${common[@]}")
  [[ -n $extra ]] && sets+=(--set "$extra")
  ./build/hsb export --format pov "$scene" -o "$out" "${sets[@]}" > /dev/null

  # hsb's picture keeps its coverage (a transparent background), which
  # mask_agreement reads where its pixel filter blurs the colour test.
  sets+=(--set 'render.background="transparent"' --set output.file=hsb.png)
  line=$(./build/hsb render "$scene" -o "$out" "${sets[@]}")
  read -r hsb_s hsb_mb <<< "$(measure build/bench/povray/hsb_time.txt ./build/hsb render "$scene" -o "$out" "${sets[@]}")"
  read -r povray_s povray_mb <<< "$(measure build/bench/povray/povray_time.txt povray +WT2 "$out/$name.ini")"

  sources=$(sed -n 's/.*sources=\([0-9]*\).*/\1/p' <<< "$line")
  if [[ $hsb_s == failed || $povray_s == failed ]]; then
    who=POV-Ray err=build/bench/povray/povray_time.txt.err
    [[ $hsb_s == failed ]] && who=hsb err=build/bench/povray/hsb_time.txt.err
    printf '%-42s %8d  %s failed: %s\n' "$name$label" "${sources:-0}" "$who" \
      "$(grep -m1 -iE 'error|limit|fail' "$err" || tail -1 "$err")"
    continue
  fi
  agreement=$(./build/tests/bench/mask_agreement "$out/hsb.png" "$out/$name.povray.png" | awk '{print $2}')
  awk -v n="$name$label" -v s="$sources" -v h="$hsb_s" -v p="$povray_s" -v g="$agreement" -v hm="$hsb_mb" -v pm="$povray_mb" \
    'BEGIN { printf "%-42s %8d %9.2f %9.2f %6.1fx %7d %7d %10s\n", n, s, h, p, p / h, hm, pm, g }'
done
commit=$(git rev-parse --short HEAD 2> /dev/null || echo unknown)
echo "(${size}x${size}, 1 sample per pixel, one light with shadows; median whole-process times of 3 runs on $(nproc) cores; hsb at $commit)"
# What hsb traced with (HSB_ISA forces another set), and on what.
echo "($(sed -n 's/^model name[^:]*: //p' /proc/cpuinfo | head -1); hsb $(./build/hsb --version | sed -n 2p))"
