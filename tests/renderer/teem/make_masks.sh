#!/usr/bin/env bash
# Teem's own superquadric glyph (Kindlmann 2004, `tend glyph -g sqd`) for
# the tensor diag(1, 0.5, 0.2) at sharpness 3, ray-traced by Teem's echo at
# 256 × 256 over the window [-1.2, 1.2]² seen from afar (eye at 1e5, so the
# rays are parallel to within 1e-6 pixel), down -z and down -x; the alpha
# channel (1 on the glyph) is kept as an 8-bit mask. The test
# teem_silhouette_test.cpp traces hsb's superquadric through the same pixel
# centres and compares. Needs Debian's teem-apps (teem-tend, teem-unu).
# Run from this folder; the masks are committed, so the suite needs no Teem.
set -euo pipefail
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# The 7 values are confidence, xx, xy, xz, yy, yz, zz.
echo "1 1 0 0 0.5 0 0.2" |
  teem-unu make -s 7 1 1 1 -t float -e ascii -k 3D-masked-symmetric-matrix space space space |
  teem-unu axinfo -a 1 2 3 -sp 1 -o "$tmp/tensor.nrrd"
render() {  # name, eye, up
  teem-tend glyph -rt -i "$tmp/tensor.nrrd" -g sqd -sh 3 -gsc 1 -atr 0 -ctr 0 -fr $2 -at 0 0 0 -up $3 -rh \
    -ur -1.2 1.2 -vr -1.2 1.2 -is 256 256 -ns 1 -shadow 0 -o "$tmp/$1.nrrd" 2>/dev/null
  teem-unu slice -i "$tmp/$1.nrrd" -a 0 -p 3 | teem-unu quantize -b 8 -min 0 -max 1 |
    teem-unu save -f png -o "$1.png"
}
# Pixel (i, j) is at u_i = -1.2 + (i + 1/2)·2.4/256 across and v_j down:
# down -z it is the point (x, y) = (u_i, -v_j), down -x it is (y, z) = (u_i, -v_j).
render sqd_down_z "0 0 100000" "0 1 0"
render sqd_down_x "100000 0 0" "0 0 1"
