"""dwi_dipy_tensors_fsl.nii.gz, dwi_dipy_tensors_nifti.nii.gz: diffusion
tensors fitted by DIPY 1.6's command-line workflow dipy_fit_dti (the real
tool, its default WLS fit) to the simulated oblique LAS DWI of
dwi_simulation.py (40 x 40 x 20 voxels of 2.5 mm, 30 directions at
b = 1000 s/mm^2 + 3 b = 0, SNR 20, a head ellipsoid with isotropic tissue
and two straight bundles), with the head mask, from the NIfTI DWI and FSL
bvals/bvecs as users have them. Only the tensor outputs are kept.

Commands (run in a temporary folder, single thread):
    dipy_fit_dti dwi.nii.gz bvals bvecs mask.nii.gz --save_metrics tensor
        --out_dir fsl --out_tensor dwi_dipy_tensors_fsl.nii.gz
    dipy_fit_dti dwi.nii.gz bvals bvecs mask.nii.gz --save_metrics tensor
        --out_dir nifti --out_tensor dwi_dipy_tensors_nifti.nii.gz --nifti_tensor

The files (both written by nibabel inside DIPY: gzip, the input's LAS
affine as the sform with sform_code = 2 (aligned) and qform_code = 0,
empty descrip; zeros outside the head mask):
  * dwi_dipy_tensors_fsl.nii.gz: 4-D 40 x 40 x 20 x 6, float32, no
    intent: FSL's layout, Dxx Dxy Dxz Dyy Dyz Dzz (DIPY's default).
  * dwi_dipy_tensors_nifti.nii.gz: 5-D 40 x 40 x 20 x 1 x 6, FLOAT64,
    intent 1005 (symmetric matrix) with intent_p1 = 3: NIfTI's lower
    triangle, Dxx Dxy Dyy Dxz Dyz Dzz (with --nifti_tensor).
Units mm^2/s. FRAME (both files): DIPY fits in the frame of the bvecs it is
given, here FSL's voxel frame (bvecs along the image's voxel axes; FSL
flips x only when det(affine) > 0, and this affine has det < 0, so no flip).
So D_world = R F D_file F R^T, with R the affine's 3 x 3 with unit columns
and F = diag(-1, 1, 1) if det > 0, else I (here I). The symmetric-matrix
intent file is therefore NOT in world coordinates (the NIfTI standard
names no axes for the matrix): DIPY does not rotate into the world, and no
header field (sform_code 2, empty descrip and intent name) says so.

Expected picture (read with that frame): inside an ellipsoidal head
(tilted 20 degrees with the voxel grid) nearly isotropic glyphs (MD
0.7e-3), and two straight tubes of prolate glyphs (eigenvalues ~1.7e-3,
0.3e-3, 0.3e-3, FA ~ 0.8) along the world directions
A = (0.9407, 0.2822, 0.1881) (mostly left-right, red) and
B = (0.0000, 0.1961, 0.9806) (mostly up, blue). Nothing outside the head.
The glyphs follow the tubes (median angle 2 degrees, the noise; the mean
tensor of each tube's core is 0.06 degrees off). Taken as world
components, the glyphs turn 48.7 (A) and 20.0 (B) degrees off the tubes;
with an x flip (as if det were > 0), 58.0 and 26.8 degrees.

Determinism: nibabel's gzip carries no time stamp; DIPY's fit is plain
numpy (single-threaded BLAS).
"""
import os
import shutil
import tempfile

import nibabel as nib
import numpy as np

import dwi_simulation as sim
import formats_common as fc

FSL_ORDER = [(0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2)]
LOWER_ORDER = [(0, 0), (1, 0), (1, 1), (2, 0), (2, 1), (2, 2)]
NAMES = {'fsl': 'dwi_dipy_tensors_fsl.nii.gz', 'nifti': 'dwi_dipy_tensors_nifti.nii.gz'}

paths = {}
with tempfile.TemporaryDirectory(prefix='hsb_dwi_dipy_') as tmp:
    sim.write_dwi(tmp)
    for layout, name in NAMES.items():
        sim.run(['dipy_fit_dti', 'dwi.nii.gz', 'bvals', 'bvecs', 'mask.nii.gz',
                 '--save_metrics', 'tensor', '--out_dir', layout, '--out_tensor', name,
                 '--log_level', 'WARNING'] + (['--nifti_tensor'] if layout == 'nifti' else []), tmp)
        assert os.listdir(os.path.join(tmp, layout)) == [name], os.listdir(os.path.join(tmp, layout))
        paths[layout] = fc.out_path(name)
        shutil.copyfile(os.path.join(tmp, layout, name), paths[layout])
        fc.report(paths[layout])

# ------------------------------------------------------------ checks
fields = {}
for layout, shape, dtype, intent, order in [('fsl', sim.SHAPE + (6,), np.float32, 0, FSL_ORDER),
                                            ('nifti', sim.SHAPE + (1, 6), np.float64, 1005, LOWER_ORDER)]:
    img = nib.load(paths[layout])
    h = img.header
    assert img.shape == shape and img.get_data_dtype() == dtype, (img.shape, img.get_data_dtype())
    assert int(h['intent_code']) == intent, h['intent_code']
    assert np.allclose(img.affine, sim.affine(), atol=1e-6)
    v = np.asarray(img.dataobj, dtype=np.float64).reshape(sim.SHAPE + (6,))
    fields[layout] = sim.full(v, order)
    print('%s: shape %s, %s, intent %d, sform_code %d, qform_code %d, affine det %+.3f'
          % (NAMES[layout], img.shape, img.get_data_dtype(), intent, h['sform_code'], h['qform_code'],
             np.linalg.det(img.affine[:3, :3])))
    M = sim.fsl_frame(img.affine)       # F R^T: world -> file frame
    R = sim.unit_columns(img.affine)
    sim.check_tensors(NAMES[layout], fields[layout], img.affine, sim.SHAPE, M.T,
                      wrong={'as world components': np.eye(3),
                             'with an x flip (wrong: det < 0)': R @ np.diag([-1.0, 1.0, 1.0])})
err = np.abs(fields['fsl'] - fields['nifti']).max()
print('the two layouts hold the same tensors: max |difference| %.1e (float32 rounding)' % err)
assert err < 1e-9
