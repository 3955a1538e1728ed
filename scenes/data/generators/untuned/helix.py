"""helix.nrrd: Teem's own diffusion-tensor test field, made by Teem's tools
exactly as ../formats/teem_helix.py makes teem_helix.nrrd (its helper
formats_common.teem_helix is reused):

    teem-tend helix -s 32 32 32 -o - | teem-unu save -f nrrd -e gzip -o helix.nrrd

NRRD0005, attached header, gzip, float32, sizes 7 32 32 32: Teem's 7-value
"3D-masked-symmetric-matrix" (confidence, Dxx, Dxy, Dxz, Dyy, Dyz, Dzz)
and three cell-centred space axes 6.25 apart over [-100, 100]^3 (unitless,
tend's defaults). Same size whatever --cells says.

Content: inside a tube of radius 30 wound as a RIGHT-handed helix (radius
50, pitch 100) tensors with eigenvalues 0.006 (along the coil), 0.002 and
0.001; outside an ISOTROPIC background of 0.5, ~100 times larger.

A correct picture shows the right-handed helix of anisotropy (glyphs
elongated along the coil, trajectories winding with it). A picture sized
or coloured by magnitude alone shows the big isotropic background and hides
the helix: that is the trap this data set sets.
"""
import sys

import untuned_common as uc

args = uc.parse_args(__doc__)
sys.argv[1:] = [args.outdir]   # formats_common.out_dir() reads the folder from argv[1]
path = uc.fc.teem_helix('helix.nrrd', 32, 'gzip')
with open(path, 'rb') as f:
    header = f.read(1024).split(b'\n\n')[0].decode()
assert 'kinds: 3D-masked-symmetric-matrix space space space' in header, header
assert 'sizes: 7 32 32 32' in header, header
