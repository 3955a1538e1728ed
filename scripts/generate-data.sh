#!/usr/bin/env bash
# Regenerates the test data sets in scenes/data/generated/ and
# scenes/data/formats/ from the generator scripts in scenes/data/generators/
# and scenes/data/generators/formats/ (see the README.md in each). Installs the
# Debian packages it needs (only those missing). Deterministic: no random
# input without a fixed seed. Not run by the tests; the outputs are committed.
#
#   scripts/generate-data.sh            # regenerate everything
#   scripts/generate-data.sh OUTDIR     # write somewhere else instead
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(python3-sfepy python3-vtk9 python3-numpy python3-scipy
          python3-meshio python3-nibabel python3-netcdf4 python3-gmsh netcdf-bin teem-apps
          mrtrix3 python3-dipy calculix-ccx python3-h5py python3-dolfin python3-dolfinx)
missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "generate-data: installing ${missing[*]}"
  sudo=()
  [[ $(id -u) -eq 0 ]] || sudo=(sudo)
  "${sudo[@]}" apt-get update -q
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

# Debian's interpreter: the python3 first on PATH may be another install
# without Debian's modules.
PY=/usr/bin/python3
export PYTHONDONTWRITEBYTECODE=1   # leave no __pycache__ in the source tree
export MPLBACKEND=Agg              # SfePy imports matplotlib; no display needed

out=$(realpath -m "${1:-scenes/data/generated}")
mkdir -p "$out"
gen=scenes/data/generators
for script in vtk_point_load hex_cube_patch_load beam_bending \
              plate_with_hole_mm_pa random_tensors zero_stress_regions \
              mixed_cells_legacy thin_plate_shear double_glazing; do
  echo "generate-data: $script"
  (cd "$gen" && "$PY" "$script.py" "$out")
done

# The result files of other tools and formats (scenes/data/formats).
if [[ -z ${1:-} ]]; then
  scenes/data/generators/formats/run_all.sh
else
  scenes/data/generators/formats/run_all.sh "$out/formats"
fi

# Re-read every file with VTK (fails on any VTK warning) and print a summary.
"$PY" "$gen/summarize.py" "$out"
du -sh "$out"
