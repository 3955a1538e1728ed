#!/usr/bin/env bash
# Every result file of scenes/data/formats/ given alone, as a user gives
# it: `hsb render FILE` at the automatic settings (a series renders every
# step). Prints a Markdown table: the reader's format, the whole process's
# time and peak memory, the glyphs, and the first warning. Figures, not a
# test: it never fails on a number.
#
#   tests/bench/formats_table.sh [FILE...]     # default: every file of scenes/data/formats
set -uo pipefail
cd "$(dirname "$0")/../.."
hsb=$PWD/build/hsb
files=("$@")
if ((${#files[@]} == 0)); then
  mapfile -t files < <(find scenes/data/formats -maxdepth 1 -type f | sort | grep -Ev '_[0-9]+\.vtu$|\.(h5|raw)$')
fi
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
echo "| file | format | time (s) | peak memory (MB) | glyphs | first warning |"
echo "|---|---|---|---|---|---|"
# The registry's formats: name, then its extensions (hsb info --formats).
"$hsb" info --formats > "$out/formats"
for f in "${files[@]}"; do
  # The format whose extension the name ends in, the longest (.nii.gz before .gz).
  format=$(awk -F'\t' -v name="$(basename "$f")" '{ n = split($2, ext, " ");
             for (i = 1; i <= n; i++) if (length(ext[i]) > best && substr(name, length(name) - length(ext[i]) + 1) == ext[i])
               { best = length(ext[i]); found = $1 } } END { print found }' "$out/formats")
  /usr/bin/time -f '%e %M' -o "$out/time" "$hsb" render "$f" -o "$out/img" > "$out/log" 2> "$out/err"
  status=$?
  read -r seconds peak < "$out/time" 2>/dev/null || { seconds=?; peak=0; }
  [[ $peak =~ ^[0-9]+$ ]] || peak=0
  glyphs=$(sed -n 's/.* sources=\([0-9]*\).*/\1/p' "$out/log" | paste -sd+ -)
  said=$(grep -m1 -o 'warning: .*' "$out/err" | cut -c10-130)
  ((status == 0)) || said="FAILED: $(tail -1 "$out/err" | cut -c1-120)"
  echo "| $(basename "$f") | $format | $seconds | $((peak / 1024)) | $glyphs | $said |"
  rm -rf "$out/img"
done
