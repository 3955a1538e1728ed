#!/usr/bin/env bash
# Generates the "untuned" data sets (see README.md here) that are missing in
# OUTDIR (default /tmp/hsb-untuned; they are too big to commit), renders each
# with hsb given nothing but the file, and prints a Markdown table: data set,
# cells, file size, hsb's whole-process time (/usr/bin/time -f %e) and the
# line hsb prints. hsb's warnings and errors follow the table verbatim.
#
#   scenes/data/generators/untuned/run_all.sh [OUTDIR]
#   UNTUNED_SMALL=1 scenes/data/generators/untuned/run_all.sh OUTDIR   # --cells small
#
# A data set is regenerated only if its file is missing: delete the folder
# (or the file) after switching between small and full. Pictures go to
# OUTDIR/pictures. HSB=path overrides the binary (default build/hsb).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../../../.." && pwd)
out=$(realpath -m "${1:-/tmp/hsb-untuned}")
hsb=${HSB:-$root/build/hsb}
mkdir -p "$out/pictures"

PY=/usr/bin/python3                # Debian's: vtk 9, gmsh, sfepy
export PYTHONDONTWRITEBYTECODE=1   # leave no __pycache__ in the source tree
export MPLBACKEND=Agg              # SfePy imports matplotlib; no display needed
export OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1   # 2-core machine; same sums every run
cells=()
[[ "${UNTUNED_SMALL:-0}" == 1 ]] && cells=(--cells small)

# script: the files it writes
declare -A makes=(
  [plate_hole_large]="plate_hole_large.vtu"
  [l_bracket]="l_bracket.vtu"
  [simply_supported_beam]="simply_supported_beam.vtu"
  [torsion_shaft]="torsion_shaft.vtu"
  [near_isotropic]="near_isotropic.vti"
  [load_series]="plate_050.vtu plate_100.vtu plate_150.vtu plate_series.pvd"
  [helix]="helix.nrrd"
)
for script in plate_hole_large l_bracket simply_supported_beam torsion_shaft \
              near_isotropic load_series helix; do
  missing=0
  for f in ${makes[$script]}; do [[ -e "$out/$f" ]] || missing=1; done
  if ((missing)); then
    echo "run_all: generating $script ${cells[*]}" >&2
    start=$SECONDS
    "$PY" "$here/$script.py" "$out" "${cells[@]}" >&2
    echo "run_all: $script took $((SECONDS - start)) s" >&2
  fi
done

# Another engineer may be relinking build/hsb: wait up to 5 minutes for it.
for _ in $(seq 60); do [[ -x "$hsb" ]] && break; sleep 5; done
[[ -x "$hsb" ]] || { echo "run_all: no $hsb" >&2; exit 1; }

# Cells of a file, from its header (no reader needed), digits grouped.
group() { sed -E ':a; s/([0-9])([0-9]{3})($|[^0-9])/\1,\2\3/; ta'; }
cells_of() {
  local f=$1
  case "$f" in
    *.vtu) head -c 4096 "$f" | grep -a -o -m1 'NumberOfCells="[0-9]*"' | grep -o '[0-9]*' | group ;;
    *.vti) head -c 4096 "$f" | grep -a -o -m1 'WholeExtent="[0-9 ]*"' \
             | awk -F'"' '{split($2, e, " "); printf "%d×%d×%d points (%d voxels)\n", e[2]-e[1]+1,
                 e[4]-e[3]+1, e[6]-e[5]+1, (e[2]-e[1])*(e[4]-e[3])*(e[6]-e[5])}' | group ;;
    *.nrrd) head -c 1024 "$f" | grep -a -m1 '^sizes:' \
             | awk '{printf "%d×%d×%d samples\n", $3, $4, $5}' ;;
    *.pvd) local n; n=$(grep -c '<DataSet' "$f")
           echo "$n × $(cells_of "$(dirname "$f")/$(grep -o -m1 'file="[^"]*"' "$f" | cut -d'"' -f2)")" ;;
  esac
}
human() { numfmt --to=si --suffix=B --format=%.1f "$1"; }   # kB, MB: powers of 1000

notes=$(mktemp) tmp=$(mktemp -d)
trap 'rm -rf "$notes" "$tmp"' EXIT
echo
echo "| data set | cells | file size | hsb time (s) | hsb's line |"
echo "|---|---|---|---|---|"
render() {   # label, then hsb render arguments
  local label=$1; shift
  local files=() f size=0 cellcol=() rc=0
  for f in "$@"; do [[ "$f" == --* ]] || files+=("$out/$f"); done
  for f in "${files[@]}"; do
    size=$((size + $(stat -c %s "$f")))
    [[ "$f" == *.pvd ]] && size=$((size + $(cd "$out" && grep -o 'file="[^"]*"' "$f" | cut -d'"' -f2 | xargs stat -c %s | paste -sd+ | bc)))
    cellcol+=("$(cells_of "$f")")
  done
  local args=()
  for f in "$@"; do [[ "$f" == --* ]] && args+=("$f") || args+=("$out/$f"); done
  /usr/bin/time -f %e -o "$tmp/time" "$hsb" --threads 1 render "${args[@]}" -o "$out/pictures" \
    >"$tmp/stdout" 2>"$tmp/stderr" || rc=$?
  local line
  line=$(sed 's|'"$out/pictures/"'||; s/|/\\|/g' "$tmp/stdout" | paste -sd';' | sed 's/;/<br>/g')
  ((rc)) && line="**exit $rc** $line"
  echo "| $label | $(printf '%s; ' "${cellcol[@]}" | sed 's/; $//') | $(human $size) | $(tail -1 "$tmp/time") | $line |"
  # warnings and errors (not progress lines) for after the table
  if grep -v -E '^\s*$|[0-9]+%|progress' "$tmp/stderr" | grep -v -E '^[0-9.]+$' >"$tmp/warn"; then
    { echo "$label:"; sed 's/^/    /' "$tmp/warn"; } >>"$notes"
  fi
}
render plate_hole_large.vtu       plate_hole_large.vtu
render l_bracket.vtu              l_bracket.vtu
render simply_supported_beam.vtu  simply_supported_beam.vtu
render torsion_shaft.vtu          torsion_shaft.vtu
render near_isotropic.vti         near_isotropic.vti
render "plate_050/100/150.vtu (--series)" --series plate_050.vtu plate_100.vtu plate_150.vtu
render plate_series.pvd           plate_series.pvd
render helix.nrrd                 helix.nrrd
echo
if [[ -s "$notes" ]]; then
  echo "hsb's warnings and errors (standard error, verbatim):"
  echo
  cat "$notes"
fi
echo "pictures in $out/pictures"
