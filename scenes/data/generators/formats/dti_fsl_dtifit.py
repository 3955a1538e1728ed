"""dti_fsl_dtifit.nii.gz: a diffusion-tensor volume laid out as FSL's dtifit
writes its *_tensor.nii.gz (written with nibabel): NIfTI-1, gzip, float32,
4-D, shape 40 x 48 x 24 x 6, voxels 2 x 2 x 2 mm, the 6 volumes in FSL's
order Dxx, Dxy, Dxz, Dyy, Dyz, Dzz (upper triangle, row by row), units
mm^2/s, descrip "FSL6.0", intent none. sform_code = qform_code = 1
(scanner), both the same affine: a 10 degree rotation about z times 2 mm,
plus an offset (the volume's centre voxel at world (1.5, -17, 9) mm);
det(affine[:3, :3]) = +8 > 0.

FSL convention: dtifit's tensor components are in FSL's voxel frame, in
which x is FLIPPED when the affine's determinant is positive. So the file
holds D_fsl = F R^T D_world R F, with R the affine's 3 x 3 with unit
columns and F = diag(-1, 1, 1) (det > 0 here). A reader that maps the
tensors to the world must apply D_world = R F D_fsl F R^T.

Content (dti_phantom.py, defined in WORLD coordinates): a synthetic brain,
inside an ellipsoidal mask (13,412 voxels) isotropic diffusion 0.7e-3 with
bundles of strong anisotropy (major eigenvalue 1.7e-3, minor 0.3e-3): a
corpus-callosum-like arc across x (a U in the coronal plane, above the
centre), two corticospinal tracts along z and two cingula along y. NaN
outside the mask (all 6 volumes).

Expected picture, once the FSL frame is undone: the bundles follow the
WORLD axes, not the 10-degree-rotated voxel grid: the arc's glyphs lie
along world x (red), the tracts along z (blue), the cingula along y
(green); isotropic spheres elsewhere, nothing outside the ellipsoid. A
reader that rotates by R but forgets the flip F draws the arc's and the
cingula's tensors turned by 20 degrees about z off their bundles; one that
takes the components as world components turns them by 10 degrees.
"""
import os

import nibabel as nib
import numpy as np

import dti_phantom
import formats_common as fc

a = dti_phantom.affine()
mask, D = dti_phantom.tensors()
M = dti_phantom.fsl_frame(a)                 # F R^T
D_fsl = M @ D @ M.T                          # F R^T D R F
data = np.stack([D_fsl[..., 0, 0], D_fsl[..., 0, 1], D_fsl[..., 0, 2],
                 D_fsl[..., 1, 1], D_fsl[..., 1, 2], D_fsl[..., 2, 2]], axis=-1)
data[~mask] = np.nan
data = data.astype(np.float32)

img = nib.Nifti1Image(data, a)
hdr = img.header
img.set_sform(a, code=1)
img.set_qform(a, code=1)
hdr.set_xyzt_units('mm', 'sec')
hdr['descrip'] = b'FSL6.0'
path = fc.out_path('dti_fsl_dtifit.nii.gz')
nib.save(img, path)
fc.report(path)

# Read back and undo the convention: the world tensors must come back.
back = nib.load(path)
assert back.shape == dti_phantom.SHAPE + (6,) and back.get_data_dtype() == np.float32
assert int(back.header['sform_code']) == 1 and int(back.header['qform_code']) == 1
v = np.asarray(back.dataobj)
T = np.empty(v.shape[:3] + (3, 3), dtype=np.float64)
for (i, j), c in zip([(0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2)], range(6)):
    T[..., i, j] = T[..., j, i] = v[..., c]
Mb = dti_phantom.fsl_frame(back.affine)
W = Mb.T @ T @ Mb
err = np.abs(W[mask] - D[mask]).max()
assert err < 1e-9, err
assert np.isnan(v[~mask]).all() and not np.isnan(v[mask]).any()
print('read back: shape', back.shape, 'affine det %+.1f' % np.linalg.det(back.affine[:3, :3]),
      'world error %.1e' % err, 'mask voxels', int(mask.sum()))
