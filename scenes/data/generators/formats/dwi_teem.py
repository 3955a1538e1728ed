"""dwi_teem_tensors.nrrd: diffusion tensors fitted by Teem 1.12's
`tend estim` (the real tool, its default linear least-squares fit) to the
simulated oblique LAS DWI of dwi_simulation.py (40 x 40 x 20 voxels of
2.5 mm, 30 directions at b = 1000 s/mm^2 + 3 b = 0, SNR 20, a head
ellipsoid with isotropic tissue and two straight bundles; Rician noise only
outside the head), given to it as a NRRD DWI in the layout 3D Slicer and
DWIConvert use: 4-D, the 33 volumes on axis 0 (kind `list`), space
right-anterior-superior, space directions = the NIfTI affine's columns,
`modality:=DWMRI`, `DWMRI_b-value:=1000`, `DWMRI_gradient_NNNN:=gx gy gz`,
and a NON-IDENTITY `measurement frame`: the gradients are given in the
frame of ROT, the affine's rotation (20 degrees about normalize(1, 1, 0);
det +1), g_meas = ROT^T g_world. Note that ROT is not the unit space
directions: those are ROT diag(-1, 1, 1) (the LAS x flip).

Commands (in a temporary folder):
    teem-tend estim -est lls -B kvp -knownB0 true -i dwi.nrrd -o raw.nrrd
    teem-unu save -f nrrd -e gzip -i raw.nrrd -o dwi_teem_tensors.nrrd

The file: NRRD0005, attached header, gzip, float32, sizes 7 40 40 20,
kinds `3D-masked-symmetric-matrix space space space`, space
right-anterior-superior, the DWI's space directions (LAS, oblique) and
space origin, and the DWI's measurement frame, which `tend estim` copies.
Per voxel Teem's 7 values: a confidence (1 where the mean DWI exceeds a
threshold that tend estim picks from the histogram, else 0), then XX XY XZ
YY YZ ZZ. Units mm^2/s. FRAME: the tensors are in the MEASUREMENT FRAME's
coordinates (the frame of the gradients), as the NRRD spec and Teem's
tenMeasurementFrameReduce() say: D_world = MF D MF^T, where the header's
`measurement frame: (v0) (v1) (v2)` vectors are the COLUMNS of MF. Tensors
are fitted everywhere, also outside the head (confidence 0 there): noise
tensors, mostly not positive definite.

Expected picture (confidence-masked, measurement frame applied): inside an
ellipsoidal head (tilted 20 degrees with the voxel grid) nearly isotropic
glyphs (MD 0.7e-3), and two straight tubes of prolate glyphs (eigenvalues
~1.7e-3, 0.3e-3, 0.3e-3) along the world directions
A = (0.9407, 0.2822, 0.1881) (mostly left-right, red) and
B = (0.0000, 0.1961, 0.9806) (mostly up, blue); median angle 2.4 degrees
(the noise; the mean tensor of each core is 0.1 degree off). Ignoring the
measurement frame turns the glyphs 10.2 (A) and 20.0 (B) degrees off the
tubes; the space directions in its place, 58.0 and 26.8; MF^T (its vectors
taken as rows), 19.8 and 39.8. The confidence is 1 exactly in the head's
13,088 voxels (tend estim's threshold: mean DWI 251.4); outside, 82.9% of
the tensors have a negative eigenvalue.

Determinism: Teem's gzip stream carries no time stamp; the fit is plain C.
"""
import os
import shutil
import tempfile

import numpy as np

import dwi_simulation as sim
import formats_common as fc

NAME = 'dwi_teem_tensors.nrrd'
TEEM_ORDER = [(0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2)]


def vec(v):
    return '(' + ','.join('%.17g' % x for x in v) + ')'


def write_nrrd_dwi(path):
    """The DWI of dwi_simulation as a NRRD DWI with measurement frame ROT;
    returns (affine, MF)."""
    a, dwi, mask, bvals, bvecs = sim.simulate()
    MF = sim.rotation()
    world = sim.unit_columns(a) @ np.linalg.inv(sim.fsl_frame(a) @ sim.unit_columns(a)) @ bvecs
    g = np.round(MF.T @ world, 6)          # bvecs -> world -> measurement frame
    g[g == 0] = 0.0
    head = ['NRRD0005', 'type: float', 'dimension: 4', 'space: right-anterior-superior',
            'sizes: %d %d %d %d' % ((dwi.shape[3],) + dwi.shape[:3]),
            'space directions: none ' + ' '.join(vec(a[:3, c]) for c in range(3)),
            'kinds: list space space space', 'endian: little', 'encoding: raw',
            'space origin: ' + vec(a[:3, 3]),
            'measurement frame: ' + ' '.join(vec(MF[:, c]) for c in range(3)),
            'modality:=DWMRI', 'DWMRI_b-value:=%g' % sim.B_VALUE]
    for v in range(dwi.shape[3]):
        head.append('DWMRI_gradient_%04d:=%s' % (v, ' '.join('%.6f' % x for x in g[:, v])))
    with open(path, 'wb') as f:
        f.write(('\n'.join(head) + '\n\n').encode('ascii'))
        f.write(np.ascontiguousarray(dwi.transpose(2, 1, 0, 3)).astype('<f4').tobytes())
    return a, MF


with tempfile.TemporaryDirectory(prefix='hsb_dwi_teem_') as tmp:
    a, MF = write_nrrd_dwi(os.path.join(tmp, 'dwi.nrrd'))
    sim.run(['/usr/bin/teem-tend', 'estim', '-est', 'lls', '-B', 'kvp', '-knownB0', 'true',
             '-i', 'dwi.nrrd', '-o', 'raw.nrrd'], tmp)
    sim.run(['/usr/bin/teem-unu', 'save', '-f', 'nrrd', '-e', 'gzip', '-i', 'raw.nrrd', '-o', NAME], tmp)
    path = fc.out_path(NAME)
    shutil.copyfile(os.path.join(tmp, NAME), path)
    fc.report(path)

# ------------------------------------------------------------ checks
data, hdr = sim.read_nrrd(path)
assert data.shape == (7,) + sim.SHAPE, data.shape
assert hdr['kinds'].split() == ['3D-masked-symmetric-matrix', 'space', 'space', 'space'], hdr['kinds']
assert hdr['space'] == 'right-anterior-superior'
dirs = sim.nrrd_vectors(hdr['space directions'])
a_file = np.eye(4)
a_file[:3, :3] = np.stack(dirs[1:], axis=1)
a_file[:3, 3] = sim.nrrd_vectors(hdr['space origin'])[0]
assert np.allclose(a_file, a, atol=1e-9), a_file
MF_file = np.stack(sim.nrrd_vectors(hdr['measurement frame']), axis=1)   # vectors = columns
assert np.allclose(MF_file, MF, atol=1e-12), MF_file
conf = data[0]
comp = np.moveaxis(data[1:], 0, -1)
D = sim.full(comp, TEEM_ORDER)
mask = sim.truth_at(sim.voxel_world(a, sim.SHAPE))[0]
print('%s: sizes %s, kinds %s, encoding %s; measurement frame det %+.3f, space directions det %+.3f'
      % (NAME, hdr['sizes'], hdr['kinds'], hdr['encoding'], np.linalg.det(MF_file),
         np.linalg.det(a_file[:3, :3])))
print('  confidence 1 in %d of %d head voxels and %d of %d background voxels'
      % ((conf[mask] > 0.5).sum(), mask.sum(), (conf[~mask] > 0.5).sum(), (~mask).sum()))
sim.check_tensors(NAME, D, a_file, sim.SHAPE, MF_file,
                  wrong={'ignoring the measurement frame': np.eye(3),
                         'with the space directions as the frame': sim.unit_columns(a_file),
                         'with MF^T (rows for columns)': MF_file.T},
                  background_expected=True)
