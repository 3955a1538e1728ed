"""dti_fsl_left_hemisphere.nii.gz: a region-of-interest mask for
dti_fsl_dtifit.nii.gz, written into scenes/data/masks/ (the folder
"masks" beside the output folder: a mask is no data set to render alone), laid out as FSL writes masks (nodif_brain_mask, a
seed mask for probtrackx; written with nibabel): NIfTI-1, gzip, uint8,
3-D, shape 40 x 48 x 24, the same sform and qform as the tensors (a 10
degree rotation about z times 2 mm), 1 inside and 0 outside.

Content (dti_phantom.py): the brain's left hemisphere, the voxels inside
the phantom's ellipsoid with world x < CENTRE x (RAS: x runs left to
right). With region.mask = this file, a picture of the phantom keeps to
the left half: the left corticospinal tract and cingulum, and the arc up to
the midline; nothing right of it.
"""
import os

import nibabel as nib
import numpy as np

import dti_phantom
import formats_common as fc

a = dti_phantom.affine()
brain, _ = dti_phantom.tensors()
x = dti_phantom.world_points()[..., 0]
left = (brain & (x < 0.0)).astype(np.uint8)

img = nib.Nifti1Image(left, a)
img.set_sform(a, code=1)
img.set_qform(a, code=1)
img.header.set_xyzt_units('mm', 'sec')
img.header['descrip'] = b'FSL6.0'
masks = os.path.join(os.path.dirname(fc.out_dir()), 'masks')
os.makedirs(masks, exist_ok=True)
path = os.path.join(masks, 'dti_fsl_left_hemisphere.nii.gz')
nib.save(img, path)
fc.report(path)

back = nib.load(path)
assert back.shape == dti_phantom.SHAPE and back.get_data_dtype() == np.uint8
v = np.asarray(back.dataobj)
assert (v == left).all() and 0 < int(v.sum()) < int(brain.sum())
print('read back: shape', back.shape, 'mask voxels', int(v.sum()), 'of the brain', int(brain.sum()))
