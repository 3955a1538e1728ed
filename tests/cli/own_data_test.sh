#!/usr/bin/env bash
# A new user's first steps: render a data file with no scene, look at the
# automatic values with hsb info, save them as a scene, render that: the
# same pixels (the metadata names the other scene). Export works on the
# file too.
source "$(dirname "$0")/common.sh"

cp "$src/scenes/data/generated/plate_with_hole_mm_pa.vtu" "$work/plate.vtu"
cd "$work"
size=(--set render.width=96 --set render.height=64)

"$hsb" render plate.vtu -o direct "${size[@]}" > log 2>&1 || fail "render of a data file: $(cat log)"
[[ -s direct/plate.png ]] || fail "no image: $(ls direct)"

"$hsb" info plate.vtu "${size[@]}" > plate.toml 2> err || fail "info: $(cat err)"
grep -q '^# .*vtkUnstructuredGrid' plate.toml || fail "no description: $(head plate.toml)"
grep -q '^scale = ' plate.toml || fail "glyphs.scale not written out: $(cat plate.toml)"
grep -q '^position = ' plate.toml || fail "camera.position not written out"

"$hsb" render plate.toml -o pinned > log 2>&1 || fail "render of the pinned scene: $(cat log)"
idiff -fail 0 -failpercent 0 direct/plate.png pinned/plate.png > diff 2>&1 \
  || fail "the pinned scene renders a different picture: $(cat diff)"

"$hsb" export plate.vtu -o exported > log 2>&1 || fail "export: $(cat log)"
[[ -s exported/plate_sources.vtp && -s exported/plate_trajectories.vtp ]] || fail "export wrote: $(ls exported)"
echo "PASS"
