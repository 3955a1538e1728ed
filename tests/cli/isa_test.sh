#!/usr/bin/env bash
# Every instruction set this processor has gives the same files, byte for
# byte: fig09 (the field, the domain's edges), the cylinder with its
# shell and trajectory tubes, and signed glyphs (the shape tracer), small.
# Also the switch itself: --isa and HSB_ISA, what --version says, and one
# clear error for a bad name.
source "$(dirname "$0")/common.sh"

version=$("$hsb" --version) || fail "--version exits $?"
grep -q '^instruction set: ' <<<"$version" || fail "--version names no instruction set: $version"
grep -q 'Embree 3\.[0-9.]*, .* kernels, [0-9]*-ray packets' <<<"$version" || fail "--version: $version"
best=$(sed -n 's/^instruction set: \([a-z0-9.]*\) (this processor.s best)$/\1/p' <<<"$version")
[[ -n $best ]] || fail "unforced --version should say the processor's best: $version"

supported=()
for isa in sse2 sse4.2 avx avx2 avx512; do
  if out=$("$hsb" --isa "$isa" --version 2>&1); then
    grep -q "^instruction set: $isa (forced; this processor has up to $best)" <<<"$out" || fail "--isa $isa: $out"
    grep -q "  Embree .*, $isa kernels" <<<"$out" || fail "--isa $isa: Embree not told: $out"
    grep -q "  renderer: $isa span kernels" <<<"$out" || fail "--isa $isa: $out"
    [[ $(HSB_ISA=$isa "$hsb" --version | sed -n 2p) == $(sed -n 2p <<<"$out") ]] || fail "HSB_ISA=$isa differs from --isa"
    supported+=("$isa")
  else
    grep -q "not supported by this processor, whose best is $best" <<<"$out" || fail "--isa $isa refused unclearly: $out"
  fi
  [[ $isa == "$best" ]] && break
done
[[ ${supported[-1]} == "$best" ]] || fail "the best set $best cannot be forced"

out=$("$hsb" --isa avx3 --version 2>&1) && fail "--isa avx3 accepted"
grep -q "avx3" <<<"$out" || fail "--isa avx3: $out"
out=$(HSB_ISA=avx3 "$hsb" render "$src/scenes/fig09_point_load_hyperstreamsurface.toml" -o "$work/bad" 2>&1)
[[ $? == 2 ]] || fail "HSB_ISA=avx3 should exit 2: $out"
[[ $(grep -c 'HSB_ISA=avx3 is not an instruction set; expected one of sse2, sse4.2, avx, avx2, avx512' <<<"$out") == 1 ]] ||
  fail "HSB_ISA=avx3: $out"
[[ ! -e $work/bad ]] || [[ -z $(ls -A "$work/bad") ]] || fail "HSB_ISA=avx3 left files"

small=(--set render.width=256 --set render.height=256)
for isa in "${supported[@]}"; do
  "$hsb" --isa "$isa" render "$src/scenes/fig09_point_load_hyperstreamsurface.toml" "${small[@]}" -o "$work/$isa" -q ||
    fail "fig09 on $isa"
  "$hsb" --isa "$isa" render "$src/scenes/fig12_cylinder_hyperstreamlines.toml" --set render.trajectories=true \
    --set render.width=200 --set render.height=150 -o "$work/$isa" -q || fail "fig12 on $isa"
  "$hsb" --isa "$isa" render "$src/tests/golden/scenes/signed_hyperstreamlines.toml" "${small[@]}" -o "$work/$isa" -q ||
    fail "signed glyphs on $isa"
done
for isa in "${supported[@]}"; do
  for image in fig09_point_load_hyperstreamsurface.png fig12_cylinder_hyperstreamlines.png signed_hyperstreamlines.png; do
    cmp -s "$work/${supported[0]}/$image" "$work/$isa/$image" ||
      fail "$image on $isa is not the same bytes as on ${supported[0]}"
  done
done
echo "the same bytes on ${supported[*]}"
