#!/usr/bin/env bash
# Regenerates the file-format test data in scenes/data/formats/ (or in the
# folder given as the first argument) by running every generator in this
# folder with Debian's interpreter, /usr/bin/python3 (it has vtk 9.1, numpy,
# meshio 5, nibabel 5, netCDF4, gmsh and python3-sfepy; the python3 first on
# PATH may lack them). dwi_mrtrix.py, dwi_dipy.py and dwi_teem.py call
# mrtrix3's, python3-dipy's and teem-apps' tools; ccx_*.py CalculiX's ccx;
# fenics_notched_shaft.py needs python3-dolfin, dolfinx_plate.py
# python3-dolfinx, med_plate.py and the HDF5 ones python3-h5py.
# teem_helix*.py call /usr/bin/teem-tend and /usr/bin/teem-unu (Debian's
# teem-apps). The output is deterministic: the
# same bytes from run to run. See README.md here.
#
#   scenes/data/generators/formats/run_all.sh            # -> scenes/data/formats
#   scenes/data/generators/formats/run_all.sh OUTDIR
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
out=$(realpath -m "${1:-$here/../../formats}")
mkdir -p "$out"

PY=/usr/bin/python3
export PYTHONDONTWRITEBYTECODE=1   # leave no __pycache__ in the source tree
export MPLBACKEND=Agg              # SfePy imports matplotlib; no display needed
export OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1   # same sums every run

for script in lame_cylinder kirsch_plate_blocks kirsch_plate_series \
              teem_helix teem_helix_detached dti_fsl_dtifit \
              dti_fsl_left_hemisphere dti_symmatrix_intent sierra_style moose_style sfepy_bracket \
              plane_stress_quads aster_plane_strain kirsch_plate_cloud lame_cylinder_shell \
              dwi_mrtrix dwi_dipy dwi_teem gmsh_views ccx_plate ccx_block med_plate \
              fenics_notched_shaft dolfinx_plate meshio_hex vtkhdf_plate; do
  echo "run_all: $script"
  (cd "$here" && "$PY" "$script.py" "$out")
done

echo "run_all: files in $out"
(cd "$out" && find . -type f | sort | xargs ls -l | awk '{printf "%10d  %s\n", $5, $9; s += $5} END {printf "%10d  total\n", s}')
