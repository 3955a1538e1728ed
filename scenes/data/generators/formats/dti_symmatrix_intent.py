"""dti_symmatrix_intent.nii.gz: the same synthetic diffusion-tensor brain as
dti_fsl_dtifit.nii.gz (dti_phantom.py) stored the way the NIfTI-1 standard
itself describes a symmetric-matrix field (written with nibabel): NIfTI-1,
gzip, float32, 5-D, shape 40 x 48 x 24 x 1 x 6 (the 4th, time, axis of
length 1; the 5th holds the matrix), intent_code 1005
(NIFTI_INTENT_SYMMATRIX) with intent_p1 = 3 (the matrix dimension), the
components in NIfTI's row-wise LOWER-triangle order XX, XY, YY, XZ, YZ, ZZ
(A11, A21, A22, A31, A32, A33). The standard names no axes for the
tensors; this file holds them as DIPY writes this layout (dipy_fit_dti
--nifti_tensor fits in the axes of its b-vectors, FSL's): in FSL's voxel
frame, D_fsl = F R^T D_world R F exactly as dti_fsl_dtifit.nii.gz (an
earlier version held world components, which no tool writes; hsb reads the
layout in FSL's axes and says so, data.frame = "world" reads the other).
Same affine as the FSL file
(10 degrees about z, 2 mm voxels, centre at world (1.5, -17, 9) mm;
sform_code = qform_code = 1). Units mm^2/s. Zeros (not NaN) outside the
ellipsoidal mask.

Expected picture: identical to dti_fsl_dtifit.nii.gz read correctly: a
U-shaped arc along world x (red), tracts along z (blue) and cingula along
y (green), isotropic 0.7e-3 elsewhere in the ellipsoid, zero tensors (no
glyphs) outside.
"""
import nibabel as nib
import numpy as np

import dti_phantom
import formats_common as fc

a = dti_phantom.affine()
mask, D = dti_phantom.tensors()
order = [(0, 0), (1, 0), (1, 1), (2, 0), (2, 1), (2, 2)]
M = dti_phantom.fsl_frame(a)                 # F R^T, as for dti_fsl_dtifit.nii.gz
D = M @ D @ M.T                              # DIPY's (FSL's) voxel frame
data = np.stack([D[..., i, j] for i, j in order], axis=-1)
data[~mask] = 0.0
data = data.astype(np.float32)[:, :, :, None, :]

img = nib.Nifti1Image(data, a)
hdr = img.header
img.set_sform(a, code=1)
img.set_qform(a, code=1)
hdr.set_xyzt_units('mm', 'sec')
hdr.set_intent('symmetric matrix', (3,))  # no name, as DIPY's nifti1_symmat
hdr['descrip'] = b''  # as DIPY (nibabel's default) leaves it
path = fc.out_path('dti_symmatrix_intent.nii.gz')
nib.save(img, path)
fc.report(path)

back = nib.load(path)
assert back.shape == dti_phantom.SHAPE + (1, 6)
assert int(back.header['intent_code']) == 1005, back.header['intent_code']
v = np.asarray(back.dataobj)[:, :, :, 0, :]
for c, (i, j) in enumerate(order):
    assert np.abs(v[..., c] - np.where(mask, D[..., i, j], 0)).max() < 1e-9
print('read back: shape', back.shape, 'intent', back.header.get_intent(),
      'dim', back.header['dim'][:6])
