#!/usr/bin/env bash
# hsb render as a batch tool: every shipped scene with deliberately broken
# ones (good ones render, broken ones are summarised, exit 1); sweeps and
# shards (the shards' union is the batch, each image once); --skip-existing;
# interruption (SIGINT, SIGTERM: stops at once, no temporary file, an old
# image intact); a full disk (an error, no file); progress and --quiet.
source "$(dirname "$0")/common.sh"
small=(--set render.width=48 --set render.height=48 --set render.samples=1)

# --- A batch of every shipped scene plus broken ones.
mkdir -p "$work/broken"
printf '[glyphs]\nspacing = -1\n' > "$work/broken/negative_spacing.toml"
printf '[seeds\n' > "$work/broken/malformed.toml"
printf '[[seeds.grid]]\nn = 10000\nm = 10000\n' > "$work/broken/too_large.toml"
head -c 3000 /dev/urandom > "$work/broken/random.vtu"
printf '[data]\nfile = "random.vtu"\n' > "$work/broken/random_data.toml"
"$hsb" render "$src"/scenes/*.toml "$work"/broken/*.toml -o "$work/all" "${small[@]}" > "$work/log" 2> "$work/err"
status=$?
[[ $status -eq 1 ]] || fail "batch with broken scenes exited $status: $(cat "$work/err")"
for scene in "$src"/scenes/*.toml; do
  name=$(basename "$scene" .toml)
  [[ -s "$work/all/$name.png" ]] || fail "good scene $name not rendered: $(cat "$work/err")"
done
total=$(( $(ls "$src"/scenes/*.toml | wc -l) + 4 ))
grep -q "hsb: 4 of $total images failed:" "$work/err" || fail "no summary: $(cat "$work/err")"
for what in "glyphs.spacing must be > 0" "expected ']'" "would take about" "not a VTK XML file"; do
  [[ $(grep -c -- "$what" "$work/err") -eq 2 ]] || fail "\"$what\" not reported once, then in the summary: $(cat "$work/err")"
done
[[ -z $(ls "$work/all" | grep -v '\.png$') ]] || fail "stray files: $(ls -A "$work/all")"

# --- Sweeps, named after their values, and shards.
"$hsb" render "$src/scenes/fig07_point_load_normalized.toml" -o "$work/sweep" "${small[@]}" \
  --set glyphs.spacing=0.3,0.6 --set color.map=magma,cividis --quiet 2> "$work/err" || fail "sweep: $(cat "$work/err")"
[[ ! -s "$work/err" ]] || fail "--quiet printed: $(cat "$work/err")"
[[ $(ls "$work/sweep" | wc -l) -eq 4 ]] || fail "a 2 x 2 sweep gave: $(ls "$work/sweep")"
[[ -s "$work/sweep/fig07_point_load_normalized_glyphs.spacing=0.6,color.map=magma.png" ]] \
  || fail "sweep names: $(ls "$work/sweep")"
printf '[sweep]\n"glyphs.spacing" = [0.3, 0.6, 0.9]\n' > "$work/swept.toml"
batch=("$src/scenes/fig07_point_load_normalized.toml" "$work/swept.toml" "$src/scenes/fig10_cylinder_ellipsoids.toml")
for k in 1 2 3; do
  "$hsb" render "${batch[@]}" -o "$work/shard$k" "${small[@]}" --set render.samples=1,2 --shard "$k/3" --quiet \
    || fail "shard $k/3"
done
"$hsb" render "${batch[@]}" -o "$work/whole" "${small[@]}" --set render.samples=1,2 --quiet || fail "whole batch"
[[ $(ls "$work/whole" | wc -l) -eq 10 ]] || fail "the batch is not 10 images: $(ls "$work/whole")"
diff <(ls "$work"/shard{1,2,3} | grep png | sort) <(ls "$work/whole" | sort) > /dev/null \
  || fail "shards are not the batch: $(ls "$work"/shard{1,2,3})"
[[ -z $(ls "$work"/shard{1,2,3} | grep png | sort | uniq -d) ]] || fail "an image in two shards"

# The Slurm example script, as three array tasks (indices 4-6), is the batch too.
for task in 4 5 6; do
  SLURM_ARRAY_TASK_ID=$task SLURM_ARRAY_TASK_MIN=4 SLURM_ARRAY_TASK_MAX=6 SLURM_ARRAY_TASK_COUNT=3 SLURM_CPUS_PER_TASK=1 \
    HSB="$hsb" HSB_OUT="$work/slurm" HSB_SET="${small[*]} --set render.samples=1,2 --quiet" \
    bash "$src/scripts/slurm-render.sbatch" "${batch[@]}" || fail "slurm task $task"
done
diff <(ls "$work/slurm" | sort) <(ls "$work/whole" | sort) > /dev/null || fail "the Slurm tasks rendered: $(ls "$work/slurm")"
# With a step (--array=0-6:2: tasks 0, 2, 4, 6), the same batch, nothing twice.
for task in 0 2 4 6; do
  SLURM_ARRAY_TASK_ID=$task SLURM_ARRAY_TASK_MIN=0 SLURM_ARRAY_TASK_MAX=6 SLURM_ARRAY_TASK_STEP=2 \
    SLURM_ARRAY_TASK_COUNT=4 SLURM_CPUS_PER_TASK=1 HSB="$hsb" HSB_OUT="$work/stepped" \
    HSB_SET="${small[*]} --set render.samples=1,2 --quiet" \
    bash "$src/scripts/slurm-render.sbatch" "${batch[@]}" || fail "stepped slurm task $task"
done
diff <(ls "$work/stepped" | sort) <(ls "$work/whole" | sort) > /dev/null || fail "the stepped tasks rendered: $(ls "$work/stepped")"
# An index list (--array=1,3,7) cannot say a task's rank: refused, nothing rendered.
SLURM_ARRAY_TASK_ID=3 SLURM_ARRAY_TASK_MIN=1 SLURM_ARRAY_TASK_MAX=7 SLURM_ARRAY_TASK_COUNT=3 SLURM_CPUS_PER_TASK=1 \
  HSB="$hsb" HSB_OUT="$work/listed" HSB_SET="${small[*]} --quiet" \
  bash "$src/scripts/slurm-render.sbatch" "${batch[@]}" 2> "$work/err"
[[ $? -eq 2 ]] || fail "an index list's task: exit $?"
grep -q "an index list" "$work/err" || fail "an index list's task said: $(cat "$work/err")"
[[ -z $(ls -A "$work/listed" 2>/dev/null) ]] || fail "an index list's task rendered: $(ls "$work/listed")"

# --- --skip-existing: unchanged scenes are skipped, a changed value or data file is not.
cp "$src/scenes/data/generated/beam_bending.vtu" "$work/beam.vtu"
"$hsb" render "$work/beam.vtu" -o "$work/skip" "${small[@]}" --quiet || fail "first render"
before=$(stat -c %Y.%s "$work/skip/beam.png"); sleep 1
"$hsb" render "$work/beam.vtu" -o "$work/skip" "${small[@]}" --skip-existing > "$work/log" || fail "skip run"
grep -q "up to date, skipped" "$work/log" || fail "not skipped: $(cat "$work/log")"
[[ $(stat -c %Y.%s "$work/skip/beam.png") == "$before" ]] || fail "a skipped image was rewritten"
"$hsb" render "$work/beam.vtu" -o "$work/skip" "${small[@]}" --set glyphs.mapping=linear --skip-existing > "$work/log" \
  || fail "changed --set"
grep -q "beam.png  sources=" "$work/log" || fail "a changed --set was skipped: $(cat "$work/log")"
cp "$src/scenes/data/generated/thin_plate_shear.vtu" "$work/beam.vtu"
"$hsb" render "$work/beam.vtu" -o "$work/skip" "${small[@]}" --set glyphs.mapping=linear --skip-existing > "$work/log" \
  || fail "changed data"
grep -q "beam.png  sources=" "$work/log" || fail "changed data was skipped: $(cat "$work/log")"
# A file cut short keeps its hash in the header but not its picture: rendered again.
again=("$work/beam.vtu" -o "$work/skip" "${small[@]}" --set glyphs.mapping=linear --skip-existing)
truncate -s -200 "$work/skip/beam.png"
"$hsb" render "${again[@]}" > "$work/log" || fail "truncated image"
grep -q "beam.png  sources=" "$work/log" || fail "a truncated image was skipped: $(cat "$work/log")"
# Another colour configuration is another picture.
"$hsb" info "$work/beam.vtu" > /dev/null || fail "info"
cp "$src/renderer/image/hyperstreamball.ocio" "$work/other.ocio"
echo "# changed" >> "$work/other.ocio"
OCIO=$work/other.ocio "$hsb" render "${again[@]}" > "$work/log" || fail "changed OCIO config"
grep -q "beam.png  sources=" "$work/log" || fail "a changed OCIO config was skipped: $(cat "$work/log")"
OCIO=$work/other.ocio "$hsb" render "${again[@]}" > "$work/log" || fail "same OCIO config"
grep -q "up to date, skipped" "$work/log" || fail "the same OCIO config was not skipped: $(cat "$work/log")"
# ... and so is a changed LUT the configuration reads (sRGB's curve, here
# an identity table).
sed -e 's|^search_path: ""|search_path: "."|' \
  -e 's|from_reference: !<ExponentWithLinearTransform> {gamma: 2.4, offset: 0.055, direction: inverse}|from_reference: !<FileTransform> {src: curve.spi1d, interpolation: linear}|' \
  "$src/renderer/image/hyperstreamball.ocio" > "$work/lut.ocio"
printf 'Version 1\nFrom 0.0 1.0\nLength 2\nComponents 1\n{\n0.0\n1.0\n}\n' > "$work/curve.spi1d"
OCIO=$work/lut.ocio "$hsb" render "${again[@]}" > "$work/log" || fail "a config with a LUT"
OCIO=$work/lut.ocio "$hsb" render "${again[@]}" > "$work/log" || fail "a config with a LUT, again"
grep -q "up to date, skipped" "$work/log" || fail "the same LUT was not skipped: $(cat "$work/log")"
printf 'Version 1\nFrom 0.0 1.0\nLength 2\nComponents 1\n{\n0.0\n0.5\n}\n' > "$work/curve.spi1d"
OCIO=$work/lut.ocio "$hsb" render "${again[@]}" > "$work/log" || fail "a changed LUT"
grep -q "beam.png  sources=" "$work/log" || fail "a changed LUT was skipped: $(cat "$work/log")"

# --- Interrupted: stops at once, the old image intact, no temporary file.
# A background job of a script starts with SIGINT ignored until hsb installs
# its handler; wait for that (SigCgt in /proc) so the signal is not lost.
wait_for_handler() {
  for _ in $(seq 200); do
    mask=$(awk '/^SigCgt:/ {print $2}' "/proc/$1/status" 2>/dev/null) || return 0
    [[ -n $mask ]] && (( (16#$mask >> 1) & 1 )) && return 0
    sleep 0.05
  done
}
long=("$src/scenes/fig09_point_load_hyperstreamsurface.toml" --set render.width=1400 --set render.height=1400)
for signal in TERM INT QUIT USR1 XCPU; do
  delays=(0.6 2)
  [[ $signal == TERM || $signal == INT ]] || delays=(0.6)  # every catchable terminating signal, once
  for delay in "${delays[@]}"; do
    rm -rf "$work/kill"; mkdir -p "$work/kill"
    echo "the previous image" > "$work/kill/fig09_point_load_hyperstreamsurface.png"
    "$hsb" render "${long[@]}" -o "$work/kill" > /dev/null 2> "$work/err" &
    pid=$!
    wait_for_handler "$pid"
    sleep "$delay"
    kill -s "$signal" "$pid"
    start=$(date +%s%N)
    wait "$pid"; status=$?
    elapsed_ms=$(( ($(date +%s%N) - start) / 1000000 ))
    expected=$((128 + $(kill -l "$signal")))
    [[ $status -eq $expected ]] || fail "SIG$signal after ${delay}s: exit $status, expected $expected: $(cat "$work/err")"
    (( elapsed_ms < 1000 )) || fail "SIG$signal took ${elapsed_ms} ms to stop"
    [[ $(ls -A "$work/kill") == "fig09_point_load_hyperstreamsurface.png" ]] || fail "left: $(ls -A "$work/kill")"
    [[ $(cat "$work/kill/fig09_point_load_hyperstreamsurface.png") == "the previous image" ]] \
      || fail "SIG$signal replaced the previous image"
  done
done

# --- A full disk (here a file size limit): an error and no file, for images and exports.
mkdir -p "$work/full"
( ulimit -f 8; trap '' XFSZ
  "$hsb" render "$src/scenes/fig07_point_load_normalized.toml" -o "$work/full" --set render.width=300 \
    --set render.height=300 2> "$work/err_png"; echo $? > "$work/status_png"
  "$hsb" export "$src/scenes/fig09_point_load_hyperstreamsurface.toml" -o "$work/full" 2> "$work/err_vtp"
  echo $? > "$work/status_vtp" )
[[ $(cat "$work/status_png") -eq 1 ]] || fail "a full disk: PNG exit $(cat "$work/status_png")"
grep -q "cannot write the file" "$work/err_png" || fail "PNG: $(cat "$work/err_png")"
[[ $(cat "$work/status_vtp") -eq 1 ]] || fail "a full disk: export exit $(cat "$work/status_vtp")"
[[ -z $(ls -A "$work/full") ]] || fail "a full disk left: $(ls -lA "$work/full")"

# --- --threads 1 gives the same bytes; progress lines in a log.
"$hsb" --threads 1 render "$src/scenes/fig07_point_load_normalized.toml" -o "$work/t1" "${small[@]}" --quiet || fail "--threads 1"
cmp -s "$work/t1/fig07_point_load_normalized.png" "$work/sweep/../all/fig07_point_load_normalized.png" \
  || fail "--threads 1 changed the picture"
# --- A time series (.pvd): one image per step unless data.step names one;
# --skip-existing renders again only the step whose file changed.
mkdir -p "$work/series"
cp "$src/scenes/data/cylinder_stress_coarse.vtu" "$work/series/s0.vtu"
cp "$src/scenes/data/cylinder_stress_coarse.vtu" "$work/series/s1.vtu"
printf '<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1">\n<Collection>\n%s\n%s\n</Collection>\n</VTKFile>\n' \
  '<DataSet timestep="0" file="s0.vtu"/>' '<DataSet timestep="2.5" file="s1.vtu"/>' > "$work/series/shaft.pvd"
"$hsb" render "$work/series/shaft.pvd" -o "$work/series/out" "${small[@]}" --quiet || fail "a time series"
[[ $(ls "$work/series/out" | tr '\n' ' ') == "shaft_data.step=0.png shaft_data.step=1.png " ]] ||
  fail "a time series made: $(ls "$work/series/out")"
"$hsb" render "$work/series/shaft.pvd" -o "$work/series/one" "${small[@]}" --set data.step=1 --quiet || fail "data.step=1"
[[ $(ls "$work/series/one") == shaft.png ]] || fail "data.step=1 made: $(ls "$work/series/one")"
"$hsb" info "$work/series/shaft.pvd" | grep -q "a time series of 2 steps, at times 0 2.5" || fail "info of a series"
printf '<!-- changed -->\n' >> "$work/series/s1.vtu"
out=$("$hsb" render "$work/series/shaft.pvd" -o "$work/series/out" "${small[@]}" --skip-existing)
grep -q "shaft_data.step=0.png  up to date, skipped" <<<"$out" || fail "step 0 unchanged, not skipped: $out"
grep -q "shaft_data.step=1.png  sources=" <<<"$out" || fail "step 1 changed, not rendered: $out"
# The steps of a series share one glyph scale and colour range: a load
# that grows (0.5, 1, 2) shows as growing glyphs, not as three equal
# pictures with other tick labels.
"$hsb" render "$src/scenes/data/formats/kirsch_plate_series.pvd" -o "$work/series/grows" "${small[@]}" --quiet ||
  fail "the plate's series"
shared() { oiiotool --info -v "$1" | grep -E '^(range|scale|map) = ' | sort; }
first=$(shared "$work/series/grows/kirsch_plate_series_data.step=0.png")
[[ $(grep -c . <<<"$first") == 3 ]] || fail "a series step records its scale, range and map: $first"
for step in 1 2; do
  [[ $(shared "$work/series/grows/kirsch_plate_series_data.step=$step.png") == "$first" ]] ||
    fail "step $step has its own scale or range: $(shared "$work/series/grows/kirsch_plate_series_data.step=$step.png") against $first"
done
# ... and one picture size (an animation's frames must not jump).
sizes=$(for step in 0 1 2; do oiiotool --info "$work/series/grows/kirsch_plate_series_data.step=$step.png" | grep -o '[0-9]* x *[0-9]*'; done | sort -u)
[[ $(grep -c . <<<"$sizes") == 1 ]] || fail "a series' steps differ in size: $sizes"
# The same steps as files given together: --series shares the scale;
# without it each file is scaled on its own.
steps=("$src"/scenes/data/formats/kirsch_plate_series_{0,1,2}.vtu)
"$hsb" render "${steps[@]}" --series -o "$work/series/files" "${small[@]}" --quiet || fail "--series of files"
for step in 0 1 2; do
  [[ $(shared "$work/series/files/kirsch_plate_series_$step.png") == "$first" ]] ||
    fail "--series: file $step has its own scale or range: $(shared "$work/series/files/kirsch_plate_series_$step.png")"
done
"$hsb" render "${steps[0]}" "${steps[2]}" -o "$work/series/apart" "${small[@]}" --quiet || fail "two files apart"
[[ $(shared "$work/series/apart/kirsch_plate_series_0.png") != $(shared "$work/series/apart/kirsch_plate_series_2.png") ]] ||
  fail "files given without --series share a scale"
# The shared scale is that of the step with the largest stresses (the
# third), as it would be alone: only that step is traced for it.
scale_of() { oiiotool --info -v "$1" | grep -E '^scale = '; }
[[ $(scale_of "$work/series/grows/kirsch_plate_series_data.step=0.png") == \
   $(scale_of "$work/series/apart/kirsch_plate_series_2.png") ]] ||
  fail "the series' scale is not its largest step's: $(scale_of "$work/series/grows/kirsch_plate_series_data.step=0.png") against $(scale_of "$work/series/apart/kirsch_plate_series_2.png")"
# The tasks of a job array read the steps once between them: the first
# keeps the shared settings in the output folder, named by what they come
# from; the others (and a resubmitted task) read them from there.
grows="$work/series/grows"
kept=("$grows"/.hsb-series-*.toml)
[[ ${#kept[@]} == 1 && -f ${kept[0]} ]] || fail "the series kept no settings file: $(ls -A "$grows")"
sha=$(basename "${kept[0]}" .toml); sha=${sha#.hsb-series-}
[[ $(head -1 "${kept[0]}") == "# series $sha" ]] || fail "the settings file names another series: $(head -1 "${kept[0]}")"
grep -qx 'color.map="coolwarm"' "${kept[0]}" || fail "the settings file lacks the map: $(cat "${kept[0]}")"
[[ ! -e "$grows/.hsb-series-$sha.lock" ]] || fail "the lock was left behind"
map_of() { oiiotool --info -v "$1" | sed -n "s/^map = '\(.*\)'$/\1/p"; }
# Another task's file is used: one with magma in it makes magma.
sed -i 's/^color.map=.*/color.map="magma"/' "${kept[0]}"
"$hsb" render "$src/scenes/data/formats/kirsch_plate_series.pvd" -o "$grows" "${small[@]}" --shard 2/3 --quiet ||
  fail "task 2 of the plate's series"
[[ $(map_of "$grows/kirsch_plate_series_data.step=1.png") == magma ]] ||
  fail "task 2 read the steps again: map $(map_of "$grows/kirsch_plate_series_data.step=1.png")"
# A file that sets any other key is not hsb's: read again and replaced.
printf '# series %s\noutput.file="../../elsewhere.png"\n' "$sha" > "${kept[0]}"
"$hsb" render "$src/scenes/data/formats/kirsch_plate_series.pvd" -o "$grows" "${small[@]}" --shard 2/3 --quiet ||
  fail "task 2 with a foreign settings file"
grep -qx 'color.map="coolwarm"' "${kept[0]}" || fail "a foreign settings file was kept: $(cat "${kept[0]}")"
[[ $(map_of "$grows/kirsch_plate_series_data.step=1.png") == coolwarm ]] || fail "a foreign settings file was used"
# While one task reads the steps (here: the test holds the lock), another
# waits for its file rather than reading them too.
rm "${kept[0]}"
exec 9> "$grows/.hsb-series-$sha.lock"
flock 9
"$hsb" render "$src/scenes/data/formats/kirsch_plate_series.pvd" -o "$grows" "${small[@]}" --shard 3/3 --quiet 9>&- &
waiter=$!
for _ in $(seq 300); do
  ls -l /proc/$waiter/fd 2>/dev/null | grep -q "hsb-series-$sha.lock" && break
  sleep 0.1
done
ls -l /proc/$waiter/fd 2>/dev/null | grep -q "hsb-series-$sha.lock" || fail "task 3 never reached the lock"
sleep 0.5
kill -0 $waiter 2>/dev/null || fail "task 3 did not wait for the lock"
[[ ! -e ${kept[0]} ]] || fail "task 3 read the steps while another held the lock"
printf '# series %s\ncolor.map="viridis"\n' "$sha" > "${kept[0]}"
exec 9>&-
wait $waiter || fail "task 3, after the lock"
[[ $(map_of "$grows/kirsch_plate_series_data.step=2.png") == viridis ]] ||
  fail "task 3 did not take the file the lock's holder wrote: $(map_of "$grows/kirsch_plate_series_data.step=2.png")"
out=$("$hsb" render "$work/series/shaft.pvd" -o "$work/series/out" "${small[@]}" --set data.step=7 2>&1)
grep -q "shaft.pvd: data.step 7 is beyond its 2 steps (0 to 1)" <<<"$out" || fail "step 7 of 2: $out"

echo PASS
