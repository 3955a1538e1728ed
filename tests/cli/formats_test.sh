#!/usr/bin/env bash
# The result files of scenes/data/formats, each as its tool wrote it, named
# on the command line alone: the right array in the right order, a time
# series as one image per step, a 2-D result seen as one. (Every one of
# them renders, exports and describes: tests/renderer/data_sets_test.cpp.)
source "$(dirname "$0")/common.sh"

cp -r "$src/scenes/data/formats" "$work/formats"
cd "$work/formats"
size=(--set render.width=64 --set render.height=48 --set render.samples=1)
info() { "$hsb" info "$1" 2>&1 | grep '^#' || fail "info $1: $("$hsb" info "$1" 2>&1 | tail -3)"; }

out=$(info kirsch_plate_blocks.vtm)
grep -q 'tensors   "stress" (9 components' <<<"$out" || fail "the multiblock file's stress not chosen: $out"
grep -q 'also in the file: "strain"' <<<"$out" || fail "the other tensor not named: $out"
grep -q 'blocks    2 with cells: 0 "left" (808 cells), 1 "right" (824 cells)' <<<"$out" || fail "the blocks not listed: $out"
out=$("$hsb" info kirsch_plate_blocks.vtm --set data.block=right 2>&1)
grep -q 'cells     824:' <<<"$out" && grep -q 'only "right" read' <<<"$out" || fail "data.block not read alone: $out"
out=$("$hsb" info kirsch_plate_blocks.vtm --set data.block=middle 2>&1) && fail "a block the file lacks was read"
grep -q 'names none of its 2 blocks with cells: 0 "left", 1 "right"' <<<"$out" || fail "the missing block not said: $out"
out=$(info kirsch_plate_cloud.vtp)
grep -q 'volume    none: its 874 cells are points or lines' <<<"$out" && grep -q 'plane     a 2-D result in z = 0;' <<<"$out" ||
  fail "the planar point cloud not described as one: $out"
out=$(info lame_cylinder_shell.vtp)
grep -q 'volume    none: its 1800 cells are surfaces not in an axis plane' <<<"$out" || fail "the shell not described as one: $out"
out=$(info lame_cylinder.pvtu)
grep -q 'cells     4558: 4558 vtkTetra' <<<"$out" || fail "the pieces not merged: $out"
out=$(info sfepy_bracket.vtk)
grep -q 'data.components = "sfepy"' <<<"$out" || fail "SfePy's output not read in SfePy's order: $out"
out=$(info sierra_style.exo)
grep -q 'joined from named components stress_xx, stress_yy, stress_zz, stress_xy, stress_yz, stress_zx' <<<"$out" ||
  fail "the Exodus element variables not joined: $out"
out=$(info teem_helix_detached.nhdr)
grep -q "Teem's 3D-masked-symmetric-matrix" <<<"$out" || fail "the NRRD kind not read: $out"
out=$(info dti_symmatrix_intent.nii.gz)
grep -q "NIfTI's symmetric-matrix intent" <<<"$out" || fail "the NIfTI intent not read: $out"
out=$(info dti_fsl_dtifit.nii.gz)
grep -q 'data.components = "fsl"' <<<"$out" && grep -q "frame     FSL.s voxel axes" <<<"$out" ||
  fail "FSL's layout and frame not taken: $out"
out=$(info plane_stress_quads.vtu)
grep -q 'plane     a 2-D result in z = 0' <<<"$out" || fail "the 2-D result not seen as one: $out"
out=$(info aster_plane_strain.vtu)
grep -q 'tensors   "SIEF_NOEU"' <<<"$out" && grep -q 'four components of a plane tensor: XX YY ZZ XY' <<<"$out" ||
  fail "Code_Aster's plane strain stress not read as XX YY ZZ XY: $out"

# A series, of files or of an Exodus file's steps: one image per step.
for series in kirsch_plate_series.pvd moose_style.e; do
  "$hsb" render "$series" -o steps "${size[@]}" > log 2>&1 || fail "render $series: $(cat log)"
  stem=${series%.*}
  for step in 0 1 2; do
    [[ -s "steps/${stem}_data.step=$step.png" ]] || fail "$series: no image of step $step: $(ls steps)"
  done
  [[ ! -e "steps/${stem}_data.step=3.png" ]] || fail "$series: an image of a step it does not have"
done

# A NIfTI file's image is named without its whole extension.
"$hsb" render dti_fsl_dtifit.nii.gz -o brain "${size[@]}" > log 2>&1 || fail "render the NIfTI file: $(cat log)"
[[ -s brain/dti_fsl_dtifit.png ]] || fail "the NIfTI file's image: $(ls brain)"
echo "PASS"
