#!/usr/bin/env bash
# hsb render on bad input: one clear file:line:column error, a non-zero exit,
# no image left behind, and the other scenes of the batch still rendered.
source "$(dirname "$0")/common.sh"

cat > "$work/bad.toml" <<'TOML'
[seeds]
points = [[0, 0, 0.5]]
[glyphs]
spacing = "wide"
TOML
cat > "$work/good.toml" <<'TOML'
[seeds]
points = [[0, 0, 0.5]]
[render]
width = 32
height = 32
TOML

"$hsb" render "$work/bad.toml" -o "$work/out" 2> "$work/err"
status=$?
[[ $status -ne 0 ]] || fail "exit status 0 for a bad scene"
grep -q "$work/bad.toml:4:11: glyphs.spacing must be a number, got string \"wide\"" "$work/err" \
  || fail "unexpected message: $(cat "$work/err")"
[[ $(wc -l < "$work/err") -le 2 ]] || fail "more than one error: $(cat "$work/err")"
[[ -z $(ls -A "$work/out" 2>/dev/null) ]] || fail "files left behind: $(ls -A "$work/out")"

"$hsb" render "$work/bad.toml" "$work/good.toml" -o "$work/out" > "$work/log" 2> "$work/err"
[[ $? -ne 0 ]] || fail "exit status 0 when one of two scenes failed"
[[ -f "$work/out/good.png" ]] || fail "the good scene was not rendered"
grep -q "good.png  sources=" "$work/log" || fail "no summary line: $(cat "$work/log")"

"$hsb" render "$work/good.toml" -o "$work/out" --set render.width=-1 2> "$work/err"
[[ $? -ne 0 ]] || fail "exit status 0 for a bad --set"
grep -q "render.width must be" "$work/err" || fail "unexpected message: $(cat "$work/err")"

"$hsb" render --set render.width=16 "$work/good.toml" -o "$work/out2" > "$work/log" 2>&1
[[ $? -eq 0 && -f "$work/out2/good.png" ]] || fail "--set before the scene: $(cat "$work/log")"

# Tensorlines follow tensors: a flow says so, and renders nothing.
"$hsb" render "$src/scenes/data/generated/double_glazing.vtu" -o "$work/flow" \
  --set 'trajectories.method="tensorlines"' 2> "$work/err"
[[ $? -ne 0 ]] || fail "exit status 0 for tensorlines on a flow"
grep -q 'double_glazing.vtu: trajectories.method = "tensorlines" follows a tensor.s major eigenvector, and this file is read as a flow' \
  "$work/err" || fail "unexpected message: $(cat "$work/err")"
[[ -z $(ls -A "$work/flow" 2>/dev/null) ]] || fail "files left behind: $(ls -A "$work/flow")"

"$hsb" render "$work/missing.toml" -o "$work/out" 2> "$work/err"
[[ $? -ne 0 ]] || fail "exit status 0 for a missing scene"
# A file of no kind hsb knows is said as what its first bytes are, not as
# a TOML syntax error on its first line.
printf 'x y z sxx syy szz\n0 0 0 1 2 3\n' > "$work/result.xyz"
"$hsb" render "$work/result.xyz" -o "$work/unknown" 2> "$work/err"
[[ $? -ne 0 ]] || fail "exit status 0 for a file of no known kind"
grep -q "result.xyz: neither a scene nor a data file hsb knows: it is text beginning \"x y z sxx syy szz\"" "$work/err" \
  || fail "unexpected message: $(cat "$work/err")"
[[ $(wc -l < "$work/err") -eq 1 ]] || fail "more than one line: $(cat "$work/err")"
# info and export on the project's real data.
"$hsb" info "$src/scenes/data/cylinder_stress_coarse.vtu" > "$work/info" 2>&1 || fail "info: $(cat "$work/info")"
grep -q "10784 vtkTetra" "$work/info" || fail "info lacks the cell types: $(cat "$work/info")"
grep -q "stress\" (9 components, point data)" "$work/info" || fail "info lacks the tensors: $(cat "$work/info")"
"$hsb" info "$src/scenes/data/cylinder_stress_coarse.vtu" --array nope 2> "$work/err"
[[ $? -ne 0 ]] || fail "info with a missing array exited 0"
grep -q 'no array named "nope" (data.array); the file has point data: stress' "$work/err" || fail "unexpected: $(cat "$work/err")"
"$hsb" export "$src/scenes/fig10_cylinder_ellipsoids.toml" -o "$work/export" > "$work/log" 2>&1 || fail "export: $(cat "$work/log")"
[[ -s "$work/export/fig10_cylinder_ellipsoids_sources.vtp" && -s "$work/export/fig10_cylinder_ellipsoids_trajectories.vtp" ]] \
  || fail "export wrote: $(ls "$work/export")"
# An empty scene file is the default scene: export works and leaves no
# temporary file (it once crashed in VTK and left a .partial behind).
: > "$work/empty.toml"
"$hsb" export "$work/empty.toml" -o "$work/empty" > "$work/log" 2>&1 || fail "export of an empty scene: $(cat "$work/log")"
[[ -z $(ls -A "$work/empty" | grep partial) ]] || fail "export left: $(ls -A "$work/empty")"
[[ -s "$work/empty/empty_sources.vtp" ]] || fail "export of an empty scene wrote: $(ls -A "$work/empty")"
# A key from the user's file is printed, not obeyed: an escape sequence in
# it reaches the terminal as text.
printf '[glyphs]\n"spacing\\u001b[2J" = 1\n' > "$work/escape_key.toml"
"$hsb" render "$work/escape_key.toml" -o "$work/escape_key" 2> "$work/err"
[[ $? -ne 0 ]] || fail "exit status 0 for an unknown key"
grep -q 'spacing\\x1b\[2J' "$work/err" || fail "the key's escape not shown: $(cat -v "$work/err")"
! grep -q $'\x1b' "$work/err" || fail "an escape byte reached the terminal: $(cat -v "$work/err")"

# A scene writes inside -o only: an absolute output.file, or one that climbs
# out with .., is refused before anything is rendered or made.
mkdir -p "$work/outside"
for name in "$work/outside/escaped.png" "../outside/escaped.png" "sub/../../outside/escaped.png"; do
  printf '[seeds]\npoints = [[0, 0, 0.5]]\n[render]\nwidth = 16\nheight = 16\n[output]\nfile = "%s"\n' "$name" > "$work/escape.toml"
  "$hsb" render "$work/escape.toml" -o "$work/inside" 2> "$work/err"
  [[ $? -ne 0 ]] || fail "exit status 0 for output.file = $name"
  grep -q "escape.toml:7:8: output.file must be a name inside the output folder (-o)" "$work/err" ||
    fail "unexpected message for $name: $(cat "$work/err")"
  [[ -z $(ls -A "$work/outside") ]] || fail "written outside -o: $(ls -A "$work/outside")"
done
echo "PASS"
