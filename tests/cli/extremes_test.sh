#!/usr/bin/env bash
# Keys at extreme values end in a located error, a warning or a picture
# with glyphs in it; never a signal (Embree's assertions once aborted on
# lengths of 1e20), a hang, or a silent blank image.
source "$(dirname "$0")/common.sh"
scene=$src/scenes/fig07_point_load_normalized.toml
small=(--set render.width=64 --set render.height=64 --set render.samples=1)

run() {  # run NAME KEY=VALUE...: sets status, out
  local name=$1; shift
  local sets=()
  for s in "$@"; do sets+=(--set "$s"); done
  out=$(timeout 60 "$hsb" render "$scene" "${small[@]}" "${sets[@]}" -o "$work/$name" 2>&1); status=$?
  (( status < 124 )) || fail "$*: exit $status (a signal or the timeout): $out"
}

for case in "camera.position=[1e20,0,0]" "render.shadow_offset=1e20" "surface.influence_radius=1e20"; do
  run far "$case"
  [[ $status == 0 ]] || grep -q "$scene:[0-9]*:[0-9]*: \|--set " <<<"$out" || fail "$case: exit $status unlocated: $out"
  [[ $status != 0 ]] || grep -q "warning: " <<<"$out" || fail "$case: exit 0 without a warning: $out"
done
run far_ground "render.ground=true" "render.ground_height=1e20"

# Every glyph out of view: a warning that names the camera keys.
run away "camera.look_at=[100,100,100]"
[[ $status == 0 ]] || fail "glyphs out of view: exit $status: $out"
grep -q "warning: none of the 139 glyphs is in the picture" <<<"$out" || fail "glyphs out of view, no warning: $out"
# And an ordinary render says nothing of the kind.
run plain
[[ $status == 0 ]] && ! grep -q "warning" <<<"$out" || fail "plain render: exit $status: $out"
echo "extremes: ok"
