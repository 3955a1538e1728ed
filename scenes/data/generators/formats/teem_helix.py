"""teem_helix.nrrd: Teem's own test tensor field, made by Teem's tools:

    teem-tend helix -s 32 32 32 -o - | teem-unu save -f nrrd -e gzip -o teem_helix.nrrd

(Debian's teem-apps names `tend` and `unu` teem-tend and teem-unu.) An
attached-header NRRD (NRRD0005), float32, gzip-compressed, 4-D with sizes
7 32 32 32: the first axis is Teem's 7-value "3D-masked-symmetric-matrix"
kind, (confidence, Dxx, Dxy, Dxz, Dyy, Dyz, Dzz); the other three are
"space" axes with cell centering, 6.25 apart (space directions diagonal),
space origin (-96.875, -96.875, -96.875), space right-anterior-superior,
identity measurement frame. The body is [-100, 100]^3 (unitless, Teem's
defaults).

Content (`tend helix`'s defaults): inside a tube of radius 30 wound as a
right-handed helix of radius 50 and pitch 100, tensors with eigenvalues
0.006 (along the coil), 0.002 (round it) and 0.001 (radial), twisted about
the coil by up to 60 degrees at the tube's surface; outside, an ISOTROPIC
background of 0.5 (much larger than the helix's eigenvalues), blended over a
fuzzy boundary (-b 10). The confidence value is 1 everywhere.

Expected picture (from `tend helix`'s documentation): the region of high
anisotropy is a right-handed helix (DNA-like), and trajectories along the
major eigenvector on the tube's surface are themselves right-handed helices.
Because the isotropic background is ~100 times larger, a picture scaled or
coloured by magnitude shows the background, not the helix; one by
anisotropy (or the background masked) shows the helix.
Deterministic:
Teem's gzip header carries no time stamp.
"""
import os

import formats_common as fc

folder = fc.out_dir()
path = fc.teem_helix('teem_helix.nrrd', 32, 'gzip')
with open(path, 'rb') as f:
    header = f.read(1024).split(b'\n\n')[0].decode()
print(header)
assert 'kinds: 3D-masked-symmetric-matrix space space space' in header
assert 'encoding: gzip' in header and 'sizes: 7 32 32 32' in header
