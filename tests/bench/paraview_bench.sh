#!/usr/bin/env bash
# hsb against ParaView's Tensor Glyph filter on Teem's helix.
#
#   tests/bench/paraview_bench.sh [RESOLUTION [SIZE]...]
#   RUNS=1 ROUNDNESS="0.58 0.30" tests/bench/paraview_bench.sh 16 768
#
# The data and camera of teem_bench.sh: `tend helix -s 88³` (33,768 voxels
# with FA ≥ 0.3), one glyph per voxel with FA ≥ 0.3, semi-axes 150 λ,
# Kindlmann's superquadrics at sharpness 3 in hsb, and ParaView 5.11's
# `pvbatch` (tests/bench/paraview_glyphs.py: Tensor Glyph with its
# superquadric source, RESOLUTION × RESOLUTION facets each, 16 by default)
# on a rasteriser: no anti-aliasing (FXAA off), one headlight, no shadows.
# ParaView's superquadric has one fixed pair of roundnesses for every
# glyph, not Kindlmann's per-tensor exponents: the default is the helix's
# median glyph at sharpness 3 (see paraview_glyphs.py; ROUNDNESS="θ φ"
# sets others). The helix is converted once to a legacy VTK file (ParaView's
# NRRD reader takes no tensors): the same tensors at the same points.
#
# Debian's python3-paraview conflicts with python3-vtk9, and installing
# paraview would take libvtk9-dev and python3-vtk9, which the build needs,
# away. So only ParaView's dependencies are installed (after a simulation
# shows apt would remove nothing), and the paraview and python3-paraview
# packages are unpacked with `dpkg -x` into a private root,
# build/bench/paraview/root, run from there; a second run reuses it. Debian's
# ParaView renders with GLX only (no EGL, no OSMesa), so pvbatch runs under
# xvfb-run (Mesa's llvmpipe, which rasterises on every core; pvbatch itself
# is one process, its filters one thread). hsb renders on both cores.
#
# Prints, per image size, both whole-process times (the median of RUNS
# runs, 3 by default; ParaView's including xvfb-run's X server start, and
# pvbatch's own time apart), both peak resident memories (ParaView's the
# largest of its processes: pvbatch), the ratio of the times (ParaView's
# over hsb's), of the memories (hsb's over ParaView's) and the fraction of
# pixels where the two pictures agree on glyph against background. Not part
# of the test suite: it measures, it does not judge.
set -euo pipefail
cd "$(dirname "$0")/../.."
source tests/bench/helix_glyph_field.sh
scripts/setup.sh > /dev/null
sudo=(); [[ $(id -u) -eq 0 ]] || sudo=(sudo)
apt_install() {
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -q --no-install-recommends "$@" > /dev/null
}
installed() { dpkg-query -W -f='${Status}' "$1" 2> /dev/null | grep -q 'ok installed'; }
# Debian's own Python (a pyenv or venv python3 first on PATH may lack numpy).
python=/usr/bin/python3
if ! command -v teem-tend > /dev/null || [[ ! -x /usr/bin/time ]] || ! command -v xvfb-run > /dev/null ||
   ! command -v xauth > /dev/null || ! "$python" -c 'import numpy' 2> /dev/null; then
  apt_install teem-apps time xvfb xauth python3-numpy
fi

out=build/bench/paraview
root=$out/root
# The private ParaView: its dependencies, each group of alternatives
# satisfied by one installed already or else by its first, installed
# through apt only if apt would remove nothing; then the two packages
# themselves unpacked, not installed. The stamp holds the version.
if [[ ! -f $root/.unpacked ]]; then
  mapfile -t dep_groups < <(apt-cache depends paraview python3-paraview | awk '
    function flush() { if (g != "") print g; g = "" }
    $1 == "Depends:" || $1 == "|Depends:" { if (!alt) flush(); alt = $1 == "|Depends:"; dep = 1
                                            if ($2 !~ /^</) g = g " " $2; next }
    /^    / { if (dep) g = g " " $1; next }   # the providers of a virtual package
    { flush(); dep = 0; alt = 0 }
    END { flush() }')
  missing=()
  for group in "${dep_groups[@]}"; do
    read -r -a names <<< "$group"
    first=
    for name in "${names[@]}"; do
      [[ $name == paraview || $name == python3-paraview ]] && continue 2
      installed "$name" && continue 2
      [[ -n $first ]] || first=$name
    done
    [[ -z $first ]] || missing+=("$first")
  done
  if ((${#missing[@]} > 0)); then
    if removed=$(apt-get install --simulate --no-install-recommends "${missing[@]}" 2>&1 | grep '^Remv'); then
      echo "paraview_bench: installing ParaView's dependencies would remove packages, stopping:" >&2
      echo "$removed" >&2
      exit 1
    fi
    apt_install "${missing[@]}"
  fi
  mkdir -p "$out/debs"
  if ! compgen -G "$out/debs/paraview_*.deb" > /dev/null || ! compgen -G "$out/debs/python3-paraview_*.deb" > /dev/null; then
    (cd "$out/debs" && apt-get download paraview python3-paraview > download.log 2>&1) || {
      cat "$out/debs/download.log" >&2
      exit 1
    }
  fi
  rm -rf "$root"
  mkdir -p "$root"
  for deb in "$out"/debs/*.deb; do dpkg -x "$deb" "$root"; done
  dpkg-deb -f "$out"/debs/paraview_*.deb Version > "$root/.unpacked"
fi
pv_version=$(< "$root/.unpacked")
# Its own libraries and Python modules first: PYTHONPATH comes before the
# system's dist-packages, whose vtkmodules (python3-vtk9) are another VTK's.
pv_env=(env LD_LIBRARY_PATH="$root/usr/lib/x86_64-linux-gnu${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
        PYTHONPATH="$root/usr/lib/python3/dist-packages")

samples=88
resolution=${1:-16}
shift || true
(($# > 0)) || set -- 768 2000
runs=${RUNS:-3}
read -r -a roundness <<< "${ROUNDNESS:-}"
mkdir -p build/bench/teem
helix=build/bench/teem/helix$samples.nrrd
[[ -f $helix ]] || teem-tend helix -s "$samples" "$samples" "$samples" -o "$helix" 2> /dev/null

# The helix as ParaView reads it: Teem's seven values per voxel (a
# confidence, then XX XY XZ YY YZ ZZ) become a symmetric 9-component
# TENSORS array and a SCALARS fa array, sqrt(3/2) |D − tr(D)/3 I| / |D|, 0
# where the confidence is below ½ (as hsb and Teem read it), on
# STRUCTURED_POINTS at the NRRD's space origin (the first voxel's centre)
# and spacing, turned from the measurement frame as hsb turns them.
vtk=$out/helix$samples.vtk
if [[ ! -f $vtk || $vtk -ot $helix ]]; then
  "$python" - "$helix" "$vtk" << 'EOF'
import gzip, re, sys
import numpy as np

src, dst = sys.argv[1], sys.argv[2]
raw = open(src, 'rb').read()
end = raw.index(b'\n\n')
fields = dict(re.match(r'([^:]+):=?\s*(.*)', line).groups()
              for line in raw[:end].decode().splitlines()[1:] if line and not line.startswith('#'))
data = raw[end + 2:]
if fields.get('encoding') in ('gzip', 'gz'):
    data = gzip.decompress(data)
elif fields.get('encoding') != 'raw':
    sys.exit('paraview_bench: %s: encoding %s is not read here' % (src, fields.get('encoding')))
dtype = ('<' if fields.get('endian', 'little') == 'little' else '>') + {'float': 'f4', 'double': 'f8'}[fields['type']]
sizes = [int(s) for s in fields['sizes'].split()]
if sizes[0] != 7 or len(sizes) != 4:
    sys.exit('paraview_bench: %s: sizes %s, not seven values per voxel of a volume' % (src, sizes))
vector = lambda s: [float(x) for x in s.strip('() ').split(',')]
directions = [vector(d) for d in re.findall(r'\([^)]*\)', fields['space directions'])]
origin = vector(fields.get('space origin', '(0,0,0)'))
spacing = [directions[k][k] for k in range(3)]
if min(spacing) <= 0 or any(abs(directions[i][j]) > 1e-9 * spacing[i] for i in range(3) for j in range(3) if i != j):
    sys.exit('paraview_bench: %s: space directions are not along +x, +y, +z; STRUCTURED_POINTS cannot place them' % src)
# hsb's reading: the frame's vectors are the rows of F, the tensor F D Fᵀ.
frame = np.array([vector(d) for d in re.findall(r'\([^)]*\)', fields.get('measurement frame', '(1,0,0) (0,1,0) (0,0,1)'))])
values = np.frombuffer(data, dtype, count=int(np.prod(sizes))).reshape(-1, 7).astype(np.float64)
xx, xy, xz, yy, yz, zz = values[:, 1:].T
tensor = np.stack([xx, xy, xz, xy, yy, yz, xz, yz, zz], 1).reshape(-1, 3, 3)
tensor = frame @ tensor @ frame.T
deviator = tensor - np.trace(tensor, axis1=1, axis2=2)[:, None, None] / 3 * np.eye(3)
norm = np.linalg.norm(tensor.reshape(-1, 9), axis=1)
fa = np.sqrt(1.5) * np.linalg.norm(deviator.reshape(-1, 9), axis=1) / np.where(norm > 0, norm, 1)
fa[~(values[:, 0] >= 0.5)] = 0
with open(dst + '.part', 'wb') as f:
    f.write(('# vtk DataFile Version 3.0\n%s\nBINARY\nDATASET STRUCTURED_POINTS\n'
             'DIMENSIONS %d %d %d\nORIGIN %.17g %.17g %.17g\nSPACING %.17g %.17g %.17g\n'
             'POINT_DATA %d\nSCALARS fa float 1\nLOOKUP_TABLE default\n'
             % ((src,) + tuple(sizes[1:]) + tuple(origin) + tuple(spacing) + (len(fa),))).encode())
    f.write(fa.astype('>f4').tobytes())
    f.write(b'\nTENSORS tensors float\n')
    f.write(tensor.astype('>f4').tobytes())
    f.write(b'\n')
EOF
  mv "$vtk.part" "$vtk"
fi

# Median wall time and the largest peak memory (MB) of RUNS runs, and the
# median of the times the command wrote to $out/inner.txt, when it did.
measure() {
  local times=() inner=() peak=0 t m
  for ((run = 0; run < runs; ++run)); do
    rm -f "$out/inner.txt"
    /usr/bin/time -f '%e %M' -o "$out/time.txt" "$@" > "$out/run.log" 2>&1 || {
      cat "$out/run.log" >&2
      exit 1
    }
    read -r t m < "$out/time.txt"
    times+=("$t")
    ((m > peak)) && peak=$m
    if [[ -f $out/inner.txt ]]; then
      read -r t m < "$out/inner.txt"
      inner+=("$t")
    fi
  done
  local middle=$(((runs + 1) / 2)) inner_s=-
  ((${#inner[@]} == 0)) || inner_s=$(printf '%s\n' "${inner[@]}" | sort -g | sed -n "${middle}p")
  echo "$(printf '%s\n' "${times[@]}" | sort -g | sed -n "${middle}p") $((peak / 1024)) $inner_s"
}

printf '%6s %7s %7s %8s %8s %9s %8s %8s %7s %8s %10s\n' \
  size glyphs pv_glyph hsb_s pv_s pvbatch_s hsb_MB pv_MB ratio mem_ratio agreement
for size in "$@"; do
  helix_glyph_field "$helix" "$out" "$size" superquadric
  # An X screen at least the picture's size, 24 bits deep (GLX wants it);
  # the inner `time` is pvbatch's own, without the X server's start.
  screen=$((size > 1280 ? size : 1280))
  paraview=("${pv_env[@]}" xvfb-run -a -s "-screen 0 ${screen}x${screen}x24"
            /usr/bin/time -f '%e %M' -o "$out/inner.txt"
            "$root/usr/bin/pvbatch" tests/bench/paraview_glyphs.py "$vtk" "$out/paraview.png" "$size" "$resolution"
            "${roundness[@]}")
  line=$("${hsb[@]}")
  read -r hsb_s hsb_mb _ <<< "$(measure "${hsb[@]}")"
  read -r pv_s pv_mb pvbatch_s <<< "$(measure "${paraview[@]}")"
  pv_line=$(grep '^glyphs=' "$out/run.log")
  agreement=$(./build/tests/bench/mask_agreement "$out/hsb.png" "$out/paraview.png" | awk '{print $2}')
  glyphs=$(sed -n 's/.*sources=\([0-9]*\).*/\1/p' <<< "$line")
  pv_glyphs=$(sed -n 's/^glyphs=\([0-9]*\).*/\1/p' <<< "$pv_line")
  awk -v n="$size" -v g="$glyphs" -v pg="$pv_glyphs" -v h="$hsb_s" -v p="$pv_s" -v pb="$pvbatch_s" \
      -v hm="$hsb_mb" -v pm="$pv_mb" -v a="$agreement" \
    'BEGIN { printf "%6d %7d %8d %8.2f %8.2f %9.2f %8d %8d %6.2fx %8.2f %10s\n",
             n, g, pg, h, p, pb, hm, pm, p / h, hm / pm, a }'
done
commit=$(git rev-parse --short HEAD 2> /dev/null || echo unknown)
echo "(tend helix at ${samples}³; superquadrics, hsb's at sharpness 3, ParaView's at ${pv_line#glyphs=* };"
echo " 1 sample per pixel, no shadows or ambient occlusion; median whole-process times of $runs run(s) on $(nproc) cores, ParaView's"
echo " with xvfb-run, pvbatch_s without; ratio: ParaView's time over hsb's, mem_ratio: hsb's peak resident"
echo " memory over ParaView's; ParaView $pv_version from $root; hsb at $commit, $(./build/hsb --version | sed -n 2p))"
echo "($(sed -n 's/^model name[^:]*: //p' /proc/cpuinfo | head -1))"
# The build's VTK must have survived ParaView's setup.
if [[ $(dpkg -s libvtk9-dev python3-vtk9 2> /dev/null | grep -c '^Status: install ok installed') -ne 2 ]]; then
  echo "paraview_bench: libvtk9-dev or python3-vtk9 is no longer installed: the build needs them" >&2
  exit 1
fi
echo "(libvtk9-dev and python3-vtk9: still installed)"
