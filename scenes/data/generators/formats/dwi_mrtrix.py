"""dwi_mrtrix_dt.mif, dwi_mrtrix_dt_masked.nii.gz, dwi_mrtrix_dt_unmasked.nii.gz:
diffusion tensors fitted by MRtrix 3.0.3's dwi2tensor (the real tool, its
default fit: WLS then 2 IWLS iterations) to the simulated oblique LAS DWI of
dwi_simulation.py (40 x 40 x 20 voxels of 2.5 mm, 30 directions at
b = 1000 s/mm^2 + 3 b = 0, SNR 20, a head ellipsoid with isotropic tissue
and two straight bundles; Rician noise only outside the head). The DWI goes
in as NIfTI with FSL bvecs/bvals (mrconvert -fslgrad), as users have it.

Commands (run in a temporary folder, relative file names, single thread):
    mrconvert dwi.nii.gz -fslgrad bvecs bvals dwi.mif -nthreads 1
    dwi2tensor dwi.mif -mask mask.nii.gz dwi_mrtrix_dt.mif -nthreads 1
    mrconvert dwi_mrtrix_dt.mif dwi_mrtrix_dt_masked.nii.gz -nthreads 1
    dwi2tensor dwi.mif dwi_mrtrix_dt_unmasked.nii.gz -nthreads 1

The files:
  * dwi_mrtrix_dt.mif: MRtrix's own format, uncompressed: a text header
    (`mrtrix image`, dim 40,40,20,6, vox 2.5,2.5,2.5,1, layout -0,+1,+2,+3,
    datatype Float32LE, 3 `transform:` rows, command_history,
    mrtrix_version, 33 prior_dw_scheme rows, `file: . OFFSET`, END) then
    raw little-endian float32. MRtrix realigns the image on load: the
    header's transform is the NIfTI affine with voxel axis 0 reversed (its
    3 x 3 has det > 0, near the identity rotated by 20 degrees), and the
    layout's `-0` says that axis 0 is stored in reverse, so the bytes are
    in the NIfTI's order. Zeros outside the head mask.
  * dwi_mrtrix_dt_masked.nii.gz: the same tensors as NIfTI-1 (gzip,
    float32, 4-D 40 x 40 x 20 x 6, the input's LAS affine, sform = qform
    code 1, descrip "MRtrix version: 3.0.3", no intent, no scaling).
  * dwi_mrtrix_dt_unmasked.nii.gz: the same fit without a mask: noise
    tensors in the air around the head, most of them not positive
    definite (88.6% of the 18,912 air voxels have a negative eigenvalue;
    eigenvalues from -3.1e-3 to +2.6e-3; inside the head it is identical
    to the masked fit).
The 6 volumes are in MRtrix's order D11 D22 D33 D12 D13 D23 (XX YY ZZ XY
XZ YZ), units mm^2/s, in the WORLD (scanner, RAS+) frame: no voxel-frame
or FSL conversion applies, whatever the file's affine.

Expected picture: inside an ellipsoidal head (tilted 20 degrees with the
voxel grid) nearly isotropic glyphs (MD 0.7e-3, noise FA ~ 0.1), and two
straight tubes of prolate glyphs (eigenvalues ~1.7e-3, 0.3e-3, 0.3e-3, FA
~ 0.8) along the world directions A = (0.9407, 0.2822, 0.1881) (mostly
left-right, red) and B = (0.0000, 0.1961, 0.9806) (mostly up, blue). The
glyphs follow the tubes (median angle 2 degrees, the noise; the mean
tensor of each tube's core is 0.06 degrees off). Read wrongly as FSL
voxel-frame tensors (turned by the affine) they turn 48.6 (A) and 19.9 (B)
degrees off the tubes. In the unmasked file, the air around the head is
full of random noise tensors, mostly indefinite (FA computed from signed
eigenvalues exceeds 1), as large as the tissue's.

Determinism: the .mif header's command_history holds the commands above
with relative names only (the tools run in the temporary folder), so it is
the same from run to run; MRtrix's NIfTI gzip has no time stamp.
"""
import os
import shutil
import tempfile

import nibabel as nib
import numpy as np

import dwi_simulation as sim
import formats_common as fc

MRTRIX_ORDER = [(0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2)]
NAMES = ['dwi_mrtrix_dt.mif', 'dwi_mrtrix_dt_masked.nii.gz', 'dwi_mrtrix_dt_unmasked.nii.gz']

with tempfile.TemporaryDirectory(prefix='hsb_dwi_mrtrix_') as tmp:
    sim.write_dwi(tmp)
    one = ['-nthreads', '1']
    sim.run(['mrconvert', 'dwi.nii.gz', '-fslgrad', 'bvecs', 'bvals', 'dwi.mif'] + one, tmp)
    sim.run(['dwi2tensor', 'dwi.mif', '-mask', 'mask.nii.gz', NAMES[0]] + one, tmp)
    sim.run(['mrconvert', NAMES[0], NAMES[1]] + one, tmp)
    sim.run(['dwi2tensor', 'dwi.mif', NAMES[2]] + one, tmp)
    paths = []
    for name in NAMES:
        paths.append(fc.out_path(name))
        shutil.copyfile(os.path.join(tmp, name), paths[-1])
        fc.report(paths[-1])

# ------------------------------------------------------------ checks
mif, a_mif, hdr = sim.read_mif(paths[0])
assert mif.shape == sim.SHAPE + (6,), mif.shape
for line in hdr['command_history']:
    assert 'hsb_dwi' not in line and '/' not in line.split('(version')[0], line
D_mif = sim.full(mif, MRTRIX_ORDER)
print('%s: layout %s, transform det %+.3f' % (NAMES[0], hdr['layout'][0], np.linalg.det(a_mif[:3, :3])))
sim.check_tensors(NAMES[0], D_mif, a_mif, mif.shape, np.eye(3),
                  wrong={'in FSL voxel frame': sim.fsl_frame(a_mif).T})

imgs = []
for path, name, bg in [(paths[1], NAMES[1], False), (paths[2], NAMES[2], True)]:
    img = nib.load(path)
    assert img.shape == sim.SHAPE + (6,) and img.get_data_dtype() == np.float32
    assert int(img.header['sform_code']) == 1 and int(img.header['qform_code']) == 1
    assert np.allclose(img.affine, sim.affine(), atol=1e-4), img.affine
    v = np.asarray(img.dataobj, dtype=np.float64)
    imgs.append(v)
    print('%s: shape %s, descrip %r, affine det %+.3f' % (name, img.shape, img.header['descrip'].item(),
                                                          np.linalg.det(img.affine[:3, :3])))
    sim.check_tensors(name, sim.full(v, MRTRIX_ORDER), img.affine, img.shape, np.eye(3),
                      wrong={'in FSL voxel frame': sim.fsl_frame(img.affine).T},
                      background_expected=bg)

# the .mif and the masked NIfTI hold the same numbers at the same places:
# the .mif's axis 0 runs the other way (its transform's first column is
# minus the NIfTI's)
assert np.allclose(a_mif[:3, 0], -sim.affine()[:3, 0], atol=1e-4)
assert np.array_equal(mif[::-1], imgs[0]), 'mif and NIfTI differ'
# masked and unmasked agree inside the mask
mask = sim.truth_at(sim.voxel_world(sim.affine(), sim.SHAPE))[0]
print('masked vs unmasked inside the head: max |difference| %.2e' % np.abs(imgs[0] - imgs[1])[mask].max())
