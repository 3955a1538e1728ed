#!/usr/bin/env bash
# Files and streams a careless or unlucky user hands hsb: a FIFO as the
# scene, two scenes that would write one image, a report piped into head,
# a full disk under standard output, what a killed run left behind, a
# sweep with no values, a killed run's trial-read child, and data of a
# format hsb does not read. Each ends in one clear error or a right result,
# never a hang, a silent overwrite or a death by SIGPIPE.
source "$(dirname "$0")/common.sh"
small=(--set render.width=96 --set render.height=96 --set render.samples=1)
fig07=$src/scenes/fig07_point_load_normalized.toml

# A FIFO as the scene: refused at once (reading it would wait for ever).
mkfifo "$work/scene.toml"
out=$(timeout 20 "$hsb" render "$work/scene.toml" -o "$work/fifo" 2>&1); status=$?
[[ $status == 1 ]] || fail "a FIFO scene: exit $status: $out"
grep -q "scene.toml: not a regular file (a FIFO, socket or device)" <<<"$out" || fail "a FIFO scene: $out"

# Two scenes with one image name in one batch: the second is refused
# before it renders; the first image stays.
mkdir -p "$work/a" "$work/b"
cp "$fig07" "$work/a/same.toml"; cp "$fig07" "$work/b/same.toml"
out=$("$hsb" render "$work/a/same.toml" "$work/b/same.toml" "${small[@]}" -o "$work/same" 2>&1); status=$?
[[ $status == 1 ]] || fail "same image name: exit $status: $out"
grep -q "b/same.toml: its image $work/same/same.png is the one $work/a/same.toml wrote earlier in this batch" <<<"$out" ||
  fail "same image name: $out"
[[ $(ls "$work/same") == same.png ]] || fail "same image name left: $(ls -A "$work/same")"

# The report piped into head: both images still rendered, exit 0, and
# no warning (a closed pipe is the reader's choice). `head -0` closes it
# before the first line, `head -1` after it.
for lines in 0 1; do
  "$hsb" render "$fig07" "$src/scenes/fig02_blending_along_a_curve.toml" "${small[@]}" -o "$work/pipe" 2> "$work/err" |
    head -$lines > /dev/null
  status=${PIPESTATUS[0]}
  [[ $status == 0 ]] || fail "render | head -$lines: exit $status: $(cat "$work/err")"
  [[ ! -s $work/err ]] || fail "render | head -$lines warned: $(cat "$work/err")"
done
[[ -f $work/pipe/fig07_point_load_normalized.png && -f $work/pipe/fig02_blending_along_a_curve.png ]] ||
  fail "render | head: $(ls "$work/pipe")"

# hsb info onto a full disk: its output is the product, so that fails.
if [[ -w /dev/full ]]; then
  out=$("$hsb" info "$fig07" 2>&1 > /dev/full); status=$?
  [[ $status == 1 ]] || fail "info > /dev/full: exit $status"
  grep -q "cannot write to standard output: No space left on device" <<<"$out" || fail "info > /dev/full: $out"
fi

# Temporaries a killed run of this host left are removed by the next run
# into the folder; a live process's are not.
mkdir -p "$work/stale"
host=$(hostname | tr './' '__')
( exit 0 ) & dead=$!; wait "$dead"
touch "$work/stale/.fig07_point_load_normalized.partial-$host-$dead.png"
touch "$work/stale/.other.partial-$host-$$.png"          # this script: alive
touch "$work/stale/.other.partial-elsewhere-$dead.png"    # another node's: not ours to judge
"$hsb" render "$fig07" "${small[@]}" -o "$work/stale" -q || fail "render into a folder with temporaries"
left=$(ls -A "$work/stale" | sort | tr '\n' ' ')
expected=$(printf '%s\n' ".other.partial-$host-$$.png" ".other.partial-elsewhere-$dead.png" \
  fig07_point_load_normalized.png | sort | tr '\n' ' ')
[[ $left == "$expected" ]] || fail "stale temporaries: left $left"

# A sweep with no values: one located error, nothing rendered.
printf '[glyphs]\nscale = 0.2\n[sweep]\n"glyphs.spacing" = []\n' > "$work/empty_sweep.toml"
out=$("$hsb" render "$work/empty_sweep.toml" -o "$work/sweep" 2>&1); status=$?
[[ $status == 1 ]] || fail "empty sweep: exit $status: $out"
grep -q "empty_sweep.toml:4:20: sweep.glyphs.spacing lists no values" <<<"$out" || fail "empty sweep: $out"
# A data file of a format hsb does not read, on the command line or in a
# scene: one line naming the format, never a TOML error; info and export alike.
printf '*Heading\n bracket\n*Node\n' > "$work/bracket.inp"
for command in render info export; do
  args=("$work/bracket.inp")
  [[ $command == info ]] || args+=(-o "$work/formats")
  out=$("$hsb" $command "${args[@]}" 2>&1); status=$?
  [[ $status == 1 ]] || fail "$command of an Abaqus input file: exit $status: $out"
  grep -q "bracket.inp: a file in the Abaqus input format (by its name and content), which hsb does not read: .*hsb reads legacy VTK" <<<"$out" ||
    fail "$command of an Abaqus input file: $out"
done
printf '[data]\nfile = "bracket.inp"\n' > "$work/inp_scene.toml"
out=$("$hsb" render "$work/inp_scene.toml" -o "$work/formats" 2>&1)
grep -q "inp_scene.toml:2:8: data.file names .*bracket.inp: a file in the Abaqus input format" <<<"$out" || fail "a scene naming Abaqus input: $out"
"$hsb" info --formats | grep -q "^Abaqus input	.inp	no: " || fail "hsb info --formats lists no Abaqus input"
"$hsb" info --formats | grep -q "^Gmsh mesh	.msh	yes" || fail "hsb info --formats does not list Gmsh as read"
"$hsb" info --formats | grep -q "^NRRD	.nrrd .nhdr	yes" || fail "hsb info --formats does not list NRRD as read"

# The child that trial-reads a data file (VTK's readers crash or hang on
# some corrupt files) dies with its parent: killed with SIGKILL mid-read,
# nothing of hsb is left running. This file hangs VTK's legacy reader.
tail -c +2 "$src/tests/fuzz/corpus/data/legacy-metadata-hangs-vtk-reader" > "$work/hangs.vtk"
"$hsb" info "$work/hangs.vtk" > /dev/null 2>&1 &
parent=$!
child=
for _ in $(seq 100); do
  child=$(pgrep -P "$parent" | head -1)
  [[ -n $child ]] && break
  sleep 0.1
done
[[ -n $child ]] || fail "no trial-read child of hsb info on a file that hangs VTK"
kill -KILL "$parent"
wait "$parent" 2> /dev/null
# Dead, or a zombie waiting for an init that reaps it (some containers' never does).
running() { local state; state=$(ps -o stat= -p "$1" 2> /dev/null) && [[ $state != Z* ]]; }
for _ in $(seq 20); do
  running "$child" || break
  sleep 0.05
done
running "$child" && { kill -KILL "$child"; fail "the trial-read child outlived its killed parent"; }
echo "files and streams: ok"
