#!/usr/bin/env bash
# Files that are not what they seem: a FIFO or a device where a data file
# names its data (a piece, an xi:include, a .hdr's .img), or where $OCIO
# names the colour configuration or its LUT; an old picture --skip-existing must not
# read whole; a full disk under the POV-Ray export; and what another user
# plants where hsb keeps its temporaries. Each ends in one clear error or
# a right result, never a hang, a half-written file, a file written
# through a link, or a planted file read as the user's.
source "$(dirname "$0")/common.sh"
small=(--set render.width=64 --set render.height=64 --set render.samples=1)
fig07=$src/scenes/fig07_point_load_normalized.toml
formats=$src/scenes/data/formats
not_regular="not a regular file (a FIFO, socket or device)"
host=$(hostname | tr './' '__')

# Runs hsb with the arguments after the first three, within SECONDS (a
# hang is a failure); fails, naming WHAT, unless it exits 1 and says SAID
# (a grep pattern).
refused() {
  local seconds=$1 what=$2 said=$3
  shift 3
  out=$(timeout "$seconds" "$hsb" "$@" 2>&1)
  local status=$?
  [[ $status == 1 ]] || fail "$what: exit $status: $out"
  grep -q -- "$said" <<<"$out" || fail "$what: $out"
}

# --- A detached NRRD header whose data file is a FIFO: render, info and
# export each say so at once (reading it waited for a writer for ever).
mkdir -p "$work/nrrd"
cp "$formats/teem_helix_detached.nhdr" "$formats/teem_helix_detached.raw" "$work/nrrd/"
mkfifo "$work/nrrd/fifo.raw"
sed 's/^data file: .*/data file: fifo.raw/' "$formats/teem_helix_detached.nhdr" > "$work/nrrd/fifo.nhdr"
for command in render info export; do
  args=("$work/nrrd/fifo.nhdr")
  [[ $command == info ]] || args+=(-o "$work/nrrd/out")
  refused 60 "$command of a NRRD whose data is a FIFO" "fifo.nhdr: names $work/nrrd/fifo.raw: $not_regular" \
    $command "${args[@]}"
done
# In a batch it is one scene's error; the next scene still renders.
out=$(timeout 60 "$hsb" render "$work/nrrd/fifo.nhdr" "$work/nrrd/teem_helix_detached.nhdr" "${small[@]}" \
  -o "$work/nrrd/batch" 2>&1); status=$?
[[ $status == 1 ]] || fail "a batch with a FIFO's NRRD: exit $status: $out"
[[ -f $work/nrrd/batch/teem_helix_detached.png ]] || fail "the scene after the FIFO's was not rendered: $out"

# --- --skip-existing hashes the data's files: a device or a FIFO among
# them is refused, where /dev/zero was hashed for ever.
sed 's/^data file: .*/data file: \/dev\/zero/' "$formats/teem_helix_detached.nhdr" > "$work/nrrd/zero.nhdr"
refused 60 "--skip-existing, data /dev/zero" "zero.nhdr: names /dev/zero: $not_regular" \
  render "$work/nrrd/zero.nhdr" "${small[@]}" -o "$work/nrrd/skip" --skip-existing
mkdir -p "$work/pieces"
cp "$formats/lame_cylinder.pvtu" "$formats/lame_cylinder_0.vtu" "$work/pieces/"
mkfifo "$work/pieces/lame_cylinder_1.vtu"
refused 60 "--skip-existing, a piece a FIFO" "lame_cylinder.pvtu: names $work/pieces/lame_cylinder_1.vtu: $not_regular" \
  render "$work/pieces/lame_cylinder.pvtu" "${small[@]}" -o "$work/pieces/out" --skip-existing
sed 's|Source="lame_cylinder_1.vtu"|Source="/dev/zero"|' "$formats/lame_cylinder.pvtu" > "$work/pieces/zero.pvtu"
refused 60 "--skip-existing, a piece /dev/zero" "zero.pvtu: names /dev/zero: $not_regular" \
  render "$work/pieces/zero.pvtu" "${small[@]}" -o "$work/pieces/out" --skip-existing

# --- An XDMF file whose xi:include names a FIFO (at the top or inside an
# included file): libxml2 opened it and waited until the reading child's
# 30 s deadline. A NIfTI .hdr whose .img is a FIFO: the same.
mkdir -p "$work/xdmf"
mkfifo "$work/xdmf/fifo.xml"
printf '<?xml version="1.0"?>\n<Xdmf Version="3.0" xmlns:xi="http://www.w3.org/2001/XInclude"><Domain><xi:include href="%s"/></Domain></Xdmf>\n' \
  fifo.xml > "$work/xdmf/top.xdmf"
printf '<?xml version="1.0"?>\n<Xdmf Version="3.0" xmlns:xi="http://www.w3.org/2001/XInclude"><Domain><xi:include href="%s"/></Domain></Xdmf>\n' \
  inner.xml > "$work/xdmf/nested.xdmf"
printf '<Grid Name="g" xmlns:xi="http://www.w3.org/2001/XInclude"><xi:include href="fifo.xml" parse="text"/></Grid>\n' \
  > "$work/xdmf/inner.xml"
for xdmf in top nested; do
  refused 20 "an xi:include of a FIFO ($xdmf)" "$work/xdmf/fifo.xml: $not_regular" info "$work/xdmf/$xdmf.xdmf"
done
mkdir -p "$work/pair"
gunzip -c "$formats/dti_fsl_dtifit.nii.gz" > "$work/pair/dti.nii"
# The .nii's header as a pair's (magic ni1, voxels from byte 0 of the .img).
head -c 344 "$work/pair/dti.nii" > "$work/pair/dti.hdr"
printf 'ni1\0' >> "$work/pair/dti.hdr"
printf '\0\0\0\0' | dd of="$work/pair/dti.hdr" bs=1 seek=108 conv=notrunc status=none
tail -c +353 "$work/pair/dti.nii" > "$work/pair/voxels"
mkfifo "$work/pair/dti.img"
refused 20 "a .hdr whose .img is a FIFO" "dti.hdr: names $work/pair/dti.img: $not_regular" info "$work/pair/dti.hdr"
# The .img is the data's: --skip-existing renders again when it changes.
rm "$work/pair/dti.img"
cp "$work/pair/voxels" "$work/pair/dti.img"
"$hsb" render "$work/pair/dti.hdr" "${small[@]}" -o "$work/pair/out" --quiet || fail "a .hdr and .img"
printf 'A' | dd of="$work/pair/dti.img" bs=1 seek=1000 conv=notrunc status=none
out=$("$hsb" render "$work/pair/dti.hdr" "${small[@]}" -o "$work/pair/out" --skip-existing 2>&1)
grep -q "dti.png  sources=" <<<"$out" || fail "a changed .img was found up to date: $out"

# --- $OCIO naming a FIFO: refused, with or without --skip-existing
# (which hashes the configuration).
mkfifo "$work/config.ocio"
for skip in "" --skip-existing; do
  OCIO=$work/config.ocio refused 60 "\$OCIO a FIFO $skip" "\$OCIO names $work/config.ocio: $not_regular" \
    render "$fig07" "${small[@]}" -o "$work/ocio" $skip
done

# A configuration whose colour space reads a LUT that is a FIFO: OCIO
# opened it and waited for ever.
mkdir -p "$work/lut"
sed -e 's|^search_path: ""|search_path: "."|' \
  -e 's|from_reference: !<ExponentWithLinearTransform> {gamma: 2.4, offset: 0.055, direction: inverse}|from_reference: !<FileTransform> {src: curve.spi1d, interpolation: linear}|' \
  "$src/renderer/image/hyperstreamball.ocio" > "$work/lut/lut.ocio"
grep -q FileTransform "$work/lut/lut.ocio" || fail "the test's configuration has no LUT"
mkfifo "$work/lut/curve.spi1d"
OCIO=$work/lut/lut.ocio refused 60 "a LUT that is a FIFO" "names the LUT $work/lut/curve.spi1d: $not_regular" \
  render "$fig07" "${small[@]}" -o "$work/lut/out"

# --- --skip-existing reads of an old picture only what tells its hash: a
# 1 GB PDF (sparse) was read whole into memory. Junk under a picture's name
# is no picture of hsb's: both are rendered again.
mkdir -p "$work/old"
truncate -s 1G "$work/old/fig07.pdf"
printf 'P5\n65535 65535\n255\n' > "$work/old/fig07_point_load_normalized.png"
for file in fig07.pdf ""; do
  set_file=()
  [[ -z $file ]] || set_file=(--set "output.file=\"$file\"")
  out=$(timeout 60 "$hsb" render "$fig07" "${small[@]}" "${set_file[@]}" -o "$work/old" --skip-existing 2>&1); status=$?
  [[ $status == 0 ]] || fail "--skip-existing over junk ${file:-.png}: exit $status: $out"
  grep -q "up to date" <<<"$out" && fail "--skip-existing took junk for a picture: $out"
done
[[ $(head -c 5 "$work/old/fig07.pdf") == %PDF- && $(stat -c %s "$work/old/fig07.pdf") -lt 1000000 ]] ||
  fail "the PDF was not rendered again"
[[ $(head -c 4 "$work/old/fig07_point_load_normalized.png" | tail -c 3) == PNG ]] || fail "the PNG was not rendered again"

# --- The POV-Ray export onto a full disk (here a file size limit): an error
# and no file, where a .pov cut short at the limit was left.
( ulimit -f 8; trap '' XFSZ
  "$hsb" export "$fig07" --format pov --set 'surface.kernel="quartic"' -o "$work/pov" 2> "$work/err_pov"
  echo $? > "$work/status_pov" )
[[ $(cat "$work/status_pov") -eq 1 ]] || fail "a full disk: POV-Ray export exit $(cat "$work/status_pov")"
[[ -z $(ls -A "$work/pov") ]] || fail "a full disk left: $(ls -lA "$work/pov")"

# --- Scratch files: in a folder of the process's own in $TMPDIR
# (hsb-HOST-PID-XXXXXX, 0700, its files 0600), gone when the run ends.
# A killed run's folder goes with the next run; a live one's stays.
mkdir -p "$work/tmp"
( exit 0 ) & dead=$!; wait "$dead"
mkdir -p "$work/tmp/hsb-$host-$dead-AbCdEf" "$work/tmp/hsb-$host-$$-AbCdEf"
touch "$work/tmp/hsb-$host-$dead-AbCdEf/.said.partial-$host-$dead-XyZ123.txt"
TMPDIR=$work/tmp "$hsb" info "$formats/sfepy_bracket.vtk" > /dev/null || fail "info with TMPDIR"
[[ $(ls -A "$work/tmp") == "hsb-$host-$$-AbCdEf" ]] || fail "scratch left: $(ls -A "$work/tmp")"
rmdir "$work/tmp/hsb-$host-$$-AbCdEf"
# Two runs held in a read that hangs VTK's reader: each has its own folder,
# and SIGTERM removes it.
tail -c +2 "$src/tests/fuzz/corpus/data/legacy-metadata-hangs-vtk-reader" > "$work/hangs.vtk"
TMPDIR=$work/tmp "$hsb" info "$work/hangs.vtk" > /dev/null 2>&1 & first=$!
TMPDIR=$work/tmp "$hsb" info "$work/hangs.vtk" > /dev/null 2>&1 & second=$!
for _ in $(seq 100); do
  [[ $(find "$work/tmp" -mindepth 2 -type f | wc -l) -ge 4 ]] && break
  sleep 0.1
done
for pid in "$first" "$second"; do
  folders=("$work/tmp/hsb-$host-$pid-"??????)
  [[ ${#folders[@]} == 1 && -d ${folders[0]} ]] || fail "no scratch folder of process $pid: $(ls -A "$work/tmp")"
  [[ $(stat -c %a "${folders[0]}") == 700 ]] || fail "scratch folder mode $(stat -c %a "${folders[0]}")"
  for file in "${folders[0]}"/.* ; do
    [[ -f $file ]] || continue
    [[ $(stat -c %a "$file") == 600 ]] || fail "scratch file $file mode $(stat -c %a "$file")"
  done
done
kill -TERM "$first" "$second"
wait "$first" "$second" 2> /dev/null
for _ in $(seq 20); do
  [[ -z $(ls -A "$work/tmp") ]] && break
  sleep 0.05
done
[[ -z $(ls -A "$work/tmp") ]] || fail "SIGTERM left: $(ls -AR "$work/tmp")"

# --- What another user plants at the names the temporaries had
# (".hsb-WHAT-PID.partial-HOST-PID.EXT" in $TMPDIR, ".NAME.partial-HOST-PID.EXT"
# beside the picture), for the next few hundred process IDs: neither read
# nor written through. (They were: the planted message was the data file's
# error, and the picture was written into the file a link named.) Made
# with shell builtins and one cp each, so as to spend few process IDs:
# links to files of the same names in folders of their own.
if [[ -r /proc/sys/kernel/ns_last_pid ]]; then
  mkdir -p "$work/planted/tmp" "$work/planted/out" "$work/planted/victims/tmp" "$work/planted/victims/out"
  last=$(< /proc/sys/kernel/ns_last_pid)
  for ((pid = last + 1; pid <= last + 400; ++pid)); do
    printf 'planted \e[2J\e[31mthe file is corrupt' > "$work/planted/tmp/.hsb-failure-$pid.partial-$host-$pid.txt"
    echo "the victim's" > "$work/planted/victims/tmp/.hsb-read-$pid.partial-$host-$pid.vtkxml"
    echo "the victim's" > "$work/planted/victims/out/.fig07_point_load_normalized.partial-$host-$pid.png"
  done
  cp -rs "$work/planted/victims/tmp/." "$work/planted/tmp/"
  cp -rs "$work/planted/victims/out/." "$work/planted/out/"
  out=$(TMPDIR=$work/planted/tmp "$hsb" info "$formats/sfepy_bracket.vtk" 2>&1) || fail "planted files: info: $out"
  grep -q planted <<<"$out" && fail "a planted message was read: $out"
  "$hsb" render "$fig07" "${small[@]}" -o "$work/planted/out" -q || fail "planted links: render"
  written=$(grep -rL "the victim's" "$work/planted/victims")
  [[ -z $written ]] || fail "written through a planted link: $written"
  [[ -f $work/planted/out/fig07_point_load_normalized.png && ! -L $work/planted/out/fig07_point_load_normalized.png ]] ||
    fail "the picture is not a file of its own"
fi
echo "hostile files: ok"
