"""teem_helix_detached.nhdr + teem_helix_detached.raw: a DETACHED-header NRRD
made by Teem's tools:

    teem-tend helix -s 16 16 16 -o - | teem-unu save -f nrrd -e raw -o teem_helix_detached.nhdr

The header (text) names its data file with a RELATIVE path ("data file:
teem_helix_detached.raw", next to the header; checked below); the data file
is raw little-endian float32, 7 x 16^3 values (114,688 bytes). Same field
as teem_helix.nrrd at half the resolution: Teem's 7-value
"3D-masked-symmetric-matrix" kind (confidence, Dxx, Dxy, Dxz, Dyy, Dyz,
Dzz), 3 cell-centred space axes 12.5 apart, space origin (-93.75, -93.75,
-93.75), so the body is [-100, 100]^3 (unitless).

Expected picture: as teem_helix.nrrd (an anisotropic right-handed helix,
eigenvalues 0.006 / 0.002 / 0.001, in an isotropic background of 0.5),
coarser: 16 samples across.
"""
import os

import formats_common as fc

folder = fc.out_dir()
path = fc.teem_helix('teem_helix_detached.nhdr', 16, 'raw')
with open(path) as f:
    header = f.read()
print(header, end='')
data_file = [line.split(':', 1)[1].strip() for line in header.splitlines()
             if line.startswith('data file:')]
assert data_file == ['teem_helix_detached.raw'], data_file   # relative, beside the header
raw = os.path.join(folder, data_file[0])
assert os.path.getsize(raw) == 7 * 16 ** 3 * 4
fc.report(raw)
