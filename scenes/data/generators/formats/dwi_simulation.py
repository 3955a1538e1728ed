"""A simulated diffusion-weighted (DWI) acquisition of a phantom, shared by
dwi_mrtrix.py, dwi_dipy.py and dwi_teem.py (not a generator itself). Those
scripts fit tensors to it with the real tools (MRtrix's dwi2tensor, DIPY's
dipy_fit_dti, Teem's tend estim); this module writes the DWI to a temporary
folder (it is never committed) and checks the tools' tensors against the
known truth.

Grid: SHAPE = 40 x 40 x 20 voxels of VOXEL = 2.5 mm by default (both are
parameters, so that a benchmark can ask for 64 x 64 x 30 or 128 x 128 x 70),
stored OBLIQUE and LAS: affine[:3, :3] = ROT diag(-2.5, 2.5, 2.5), where ROT
turns by 20 degrees about the world axis normalize(1, 1, 0); so
det(affine[:3, :3]) = -15.625 < 0 and the voxel index i runs (roughly) from
right to left. The offset puts the volume's centre voxel at the world
(scanner, RAS+) point CENTRE = (3, -14, 18) mm. sform_code = qform_code = 1.

Content:
  * the "head": an ellipsoid aligned with the voxel grid (the slab is tilted
    with the head, as in a real oblique acquisition), semi-axes 0.92 of the
    half field of view along each voxel axis (46, 46, 23 mm by default);
  * inside it isotropic tissue, D = 0.7e-3 I mm^2/s;
  * two straight bundles, D = 0.3e-3 I + 1.4e-3 t t^T (eigenvalues 1.7e-3,
    0.3e-3, 0.3e-3 mm^2/s) along their WORLD directions
        A: t = normalize(1, 0.3, 0.2) = (0.9407, 0.2822, 0.1881)
        B: t = normalize(0, 0.2, 1)   = (0.0000, 0.1961, 0.9806)
    each of radius 4 voxels (10 mm): full weight within 2 voxels of the
    axis, a cos^2 fall-off to 0 at 4 voxels, mixed with the tissue at the
    SIGNAL level (two compartments). Their axes pass 0.35 of the half field
    of view off the centre, on either side along the voxel axis j; they do
    not meet (the script checks that their tubes stay apart);
  * outside the head, air: no signal (S0 = 0), so the stored values are
    pure Rician noise, and fits there give noise tensors, many of them not
    positive definite.

Acquisition: b = 1000 s/mm^2 along 30 directions spread by electrostatic
repulsion (antipodally symmetric, from a fixed golden-angle start, 2000
steps; no randomness), plus 3 b = 0 volumes (volumes 0, 11 and 22).
S0 = 1000 in tissue; Rician noise sigma = 50 (SNR 20 on b = 0) drawn from
numpy's default Generator (PCG64) with the fixed seed SEED. The DWI is
stored as float32 NIfTI (no zeros, so log-signal fits never see log 0).

bvecs follow FSL's convention: each direction is given in the image's voxel
axes, b_vox = F R^T g_world, where R is affine[:3, :3] with unit columns and
F = diag(-1, 1, 1) when det(affine[:3, :3]) > 0 (FSL flips x then), else
the identity. Here det < 0, so there is NO flip (F = I); the code computes F
from the affine whatever it is. The simulation uses exactly the written
(rounded, 6 decimals) bvecs, mapped back to the world.
"""
import os

import numpy as np

SHAPE = (40, 40, 20)
VOXEL = 2.5
AXIS = np.array([1.0, 1.0, 0.0]) / np.sqrt(2.0)
ANGLE = np.radians(20.0)
CENTRE = np.array([3.0, -14.0, 18.0])
D_ISO, L_PAR, L_PERP = 0.7e-3, 1.7e-3, 0.3e-3     # mm^2/s
B_VALUE, N_DIRS, B0_AT = 1000.0, 30, (0, 11, 22)
S0, SIGMA, SEED = 1000.0, 50.0, 20240607

BUNDLES = {   # name: (world direction, offset of the axis along voxel j as a fraction of half the FOV)
    'A': (np.array([1.0, 0.3, 0.2]) / np.linalg.norm([1.0, 0.3, 0.2]), +0.35),
    'B': (np.array([0.0, 0.2, 1.0]) / np.linalg.norm([0.0, 0.2, 1.0]), -0.35),
}
RADIUS_VOXELS, CORE_VOXELS = 4.0, 2.0


def rotation():
    """ROT: ANGLE about AXIS (Rodrigues)."""
    k = AXIS
    K = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + np.sin(ANGLE) * K + (1 - np.cos(ANGLE)) * K @ K


def affine(shape=SHAPE, voxel=VOXEL):
    a = np.eye(4)
    a[:3, :3] = rotation() @ np.diag([-voxel, voxel, voxel])
    a[:3, 3] = CENTRE - a[:3, :3] @ ((np.array(shape[:3]) - 1) / 2.0)
    return a


def unit_columns(a):
    m = np.asarray(a)[:3, :3]
    return m / np.linalg.norm(m, axis=0)


def fsl_frame(a):
    """F R^T: world components -> FSL's voxel frame (the frame of bvecs and
    of FSL-layout tensors). F = diag(-1, 1, 1) if det(affine) > 0."""
    m = np.asarray(a)[:3, :3]
    F = np.diag([-1.0, 1.0, 1.0]) if np.linalg.det(m) > 0 else np.eye(3)
    return F @ unit_columns(a).T


# ---------------------------------------------------------------- geometry

def voxel_world(a, shape):
    """World coordinates of every voxel centre of a grid, (nx, ny, nz, 3)."""
    ijk = np.stack(np.meshgrid(*[np.arange(n) for n in shape[:3]], indexing='ij'), axis=-1)
    return ijk @ np.asarray(a)[:3, :3].T + np.asarray(a)[:3, 3]


def bundle_axes(shape=SHAPE, voxel=VOXEL):
    """{name: (point on the axis (world), unit direction (world))}."""
    half = np.array(shape[:3]) * voxel / 2.0
    R = unit_columns(affine(shape, voxel))
    return {name: (CENTRE + R @ np.array([0.0, f * half[1], 0.0]), t)
            for name, (t, f) in BUNDLES.items()}


def truth_at(points, shape=SHAPE, voxel=VOXEL):
    """The phantom at world points (..., 3): head mask (bool) and the
    bundle weights {name: w} (1 in the core, cos^2 fall-off, 0 outside)."""
    R = unit_columns(affine(shape, voxel))
    q = (points - CENTRE) @ R        # mm along the voxel axes from the centre
    semi = 0.92 * np.array(shape[:3]) * voxel / 2.0
    mask = np.sum((q / semi) ** 2, axis=-1) <= 1.0
    r, core = RADIUS_VOXELS * voxel, CORE_VOXELS * voxel
    weights, dist = {}, {}
    for name, (p0, t) in bundle_axes(shape, voxel).items():
        d = points - p0
        d = np.linalg.norm(d - (d @ t)[..., None] * t, axis=-1)
        u = np.clip((d - core) / (r - core), 0, 1)
        weights[name] = np.where(mask & (u < 1), np.cos(0.5 * np.pi * u) ** 2, 0.0)
        dist[name] = d
    return mask, weights, dist


def check_bundles_apart(shape=SHAPE, voxel=VOXEL):
    """Distance between the two bundle axes (mm); must exceed 2 radii."""
    (pa, ta), (pb, tb) = bundle_axes(shape, voxel).values()
    n = np.cross(ta, tb)
    gap = abs((pb - pa) @ n) / np.linalg.norm(n)
    assert gap > 2 * RADIUS_VOXELS * voxel, gap
    return gap


# ---------------------------------------------------------------- acquisition

def electrostatic_directions(n=N_DIRS, steps=2000):
    """n unit vectors spread by antipodal electrostatic repulsion from a
    fixed golden-angle spiral on the upper hemisphere; deterministic."""
    k = np.arange(n) + 0.5
    z = 1.0 - k / n
    phi = k * np.pi * (3.0 - np.sqrt(5.0))
    x = np.stack([np.sqrt(1 - z * z) * np.cos(phi), np.sqrt(1 - z * z) * np.sin(phi), z], axis=1)
    off = ~np.eye(n, dtype=bool)
    for it in range(steps):
        f = np.zeros_like(x)
        for s in (1.0, -1.0):
            d = x[:, None, :] - s * x[None, :, :]
            r3 = np.linalg.norm(d, axis=-1) ** 3
            f += np.where(off[..., None], d / np.where(off, r3, 1.0)[..., None], 0).sum(axis=1)
        f -= np.sum(f * x, axis=1)[:, None] * x          # tangential part
        step = 0.02 / (1 + it / 200.0)
        x = x + step * f / np.abs(f).max()
        x /= np.linalg.norm(x, axis=1)[:, None]
    x[x[:, 2] < 0] *= -1
    return x


def scheme(a):
    """bvals (n,), bvecs (3, n) in FSL's voxel frame rounded to 6 decimals
    as written, and the world gradient directions (n, 3) they mean."""
    g = electrostatic_directions()
    M = fsl_frame(a)
    n = N_DIRS + len(B0_AT)
    bvals = np.full(n, B_VALUE)
    bvecs = np.zeros((3, n))
    dwi_at = [v for v in range(n) if v not in B0_AT]
    bvals[list(B0_AT)] = 0.0
    bvecs[:, dwi_at] = np.round(M @ g.T, 6)
    bvecs[bvecs == 0] = 0.0                               # no "-0.000000"
    world = (M.T @ bvecs).T                               # back to the world
    norm = np.linalg.norm(world, axis=1)
    world[norm > 0] /= norm[norm > 0][:, None]
    return bvals, bvecs, world


def simulate(shape=SHAPE, voxel=VOXEL):
    """The noisy DWI (nx, ny, nz, n) float32, the mask, the scheme."""
    a = affine(shape, voxel)
    check_bundles_apart(shape, voxel)
    mask, weights, _ = truth_at(voxel_world(a, shape), shape, voxel)
    bvals, bvecs, g = scheme(a)
    eye = np.eye(3)
    total = sum(weights.values())
    assert total.max() <= 1.0 + 1e-12
    signal = (1.0 - total)[..., None] * np.exp(-bvals * D_ISO)          # (.., n)
    for name, (t, _) in BUNDLES.items():
        Db = L_PERP * eye + (L_PAR - L_PERP) * np.outer(t, t)
        adc = np.einsum('ni,ij,nj->n', g, Db, g)
        signal = signal + weights[name][..., None] * np.exp(-bvals * adc)
    signal = np.where(mask[..., None], S0 * signal, 0.0)
    rng = np.random.default_rng(SEED)
    n1 = rng.normal(0.0, SIGMA, signal.shape)
    n2 = rng.normal(0.0, SIGMA, signal.shape)
    dwi = np.hypot(signal + n1, n2).astype(np.float32)
    return a, dwi, mask, bvals, bvecs


def write_dwi(folder, shape=SHAPE, voxel=VOXEL):
    """Writes dwi.nii.gz (float32), mask.nii.gz (uint8), bvals and bvecs
    (FSL text files) into `folder`; returns the affine."""
    import nibabel as nib
    a, dwi, mask, bvals, bvecs = simulate(shape, voxel)

    def save(data, name):
        img = nib.Nifti1Image(data, a)
        img.set_sform(a, code=1)
        img.set_qform(a, code=1)
        img.header.set_xyzt_units('mm', 'sec')
        nib.save(img, os.path.join(folder, name))
    save(dwi, 'dwi.nii.gz')
    save(mask.astype(np.uint8), 'mask.nii.gz')
    with open(os.path.join(folder, 'bvals'), 'w') as f:
        f.write(' '.join('%g' % b for b in bvals) + '\n')
    with open(os.path.join(folder, 'bvecs'), 'w') as f:
        for row in bvecs:
            f.write(' '.join('%.6f' % v for v in row) + '\n')
    return a


# ---------------------------------------------------------------- checks

def full(comp, order):
    """(..., 6) components in `order` (a list of (i, j)) -> (..., 3, 3)."""
    T = np.zeros(comp.shape[:-1] + (3, 3))
    for c, (i, j) in enumerate(order):
        T[..., i, j] = T[..., j, i] = comp[..., c]
    return T


def angle_deg(u, t):
    return np.degrees(np.arccos(np.clip(np.abs(u @ t), 0, 1)))


def check_tensors(label, D, a, shape, to_world, wrong={}, background_expected=False,
                  sim_shape=SHAPE, sim_voxel=VOXEL):
    """Check a fitted tensor field D (nx, ny, nz, 3, 3) on the grid with
    affine `a`: `to_world` (3 x 3) maps the file's tensor frame to the world,
    D_world = M D M^T; `wrong` is {how: matrix} of wrong readings to report
    (e.g. {'as world components': I}). The truth is evaluated at each voxel's
    own world position, so any axis order or flip of the file is fine.
    Prints and returns the statistics; asserts that the bundles' median
    angles are small (< 5 degrees)."""
    mask, weights, dist = truth_at(voxel_world(a, shape), sim_shape, sim_voxel)
    vox = sim_voxel
    # core: full-weight voxels at least 2 voxels inside the head
    from scipy.ndimage import binary_erosion
    inner = binary_erosion(mask, iterations=2)
    stats = {'file': label}
    ev_all = np.linalg.eigvalsh(D)
    for name, (t, _) in BUNDLES.items():
        core = inner & (dist[name] <= CORE_VOXELS * vox - 1e-9)
        res = []
        for M in [to_world] + list(wrong.values()):
            Dw = M @ D[core] @ M.T
            w, v = np.linalg.eigh(Dw)
            res.append(float(np.median(angle_deg(v[:, :, 2], t))))
            if len(res) == 1:   # the major eigenvector of the mean tensor: no noise spread
                mean_angle = float(angle_deg(np.linalg.eigh(Dw.mean(axis=0))[1][:, 2], t))
        stats['bundle %s core voxels' % name] = int(core.sum())
        stats['bundle %s median angle (deg)' % name] = res[0]
        stats['bundle %s angle of the mean tensor (deg)' % name] = mean_angle
        for how, r in zip(wrong, res[1:]):
            stats['bundle %s median angle if read %s (deg)' % (name, how)] = r
        lam = ev_all[core]
        fa = fractional_anisotropy(lam)
        stats['bundle %s FA median' % name] = float(np.median(fa))
        stats['bundle %s eigenvalues median' % name] = [float(x) for x in np.median(lam, axis=0)[::-1]]
        assert res[0] < 5.0, (label, name, res)
    tissue = inner & (sum(weights.values()) == 0)
    bg = ~mask
    fa_t = fractional_anisotropy(ev_all[tissue])
    stats['tissue voxels'] = int(tissue.sum())
    stats['tissue FA median, 95th pct'] = [float(np.median(fa_t)), float(np.percentile(fa_t, 95))]
    stats['tissue MD median'] = float(np.median(ev_all[tissue].mean(axis=1)))
    stats['mask voxels with a negative eigenvalue'] = '%d of %d (%.2f%%)' % (
        (ev_all[mask, 0] < 0).sum(), mask.sum(), 100.0 * (ev_all[mask, 0] < 0).mean())
    nonzero_bg = bg & (np.abs(D).reshape(D.shape[:3] + (9,)).max(axis=-1) > 0)
    stats['background voxels with a nonzero tensor'] = '%d of %d' % (nonzero_bg.sum(), bg.sum())
    stats['background voxels with a negative eigenvalue'] = '%d of %d (%.2f%%)' % (
        (ev_all[bg, 0] < 0).sum(), bg.sum(), 100.0 * (ev_all[bg, 0] < 0).mean())
    if background_expected:
        fa_b = fractional_anisotropy(ev_all[bg])
        stats['background FA median, 5th-95th pct'] = [float(np.median(fa_b)),
                                                        float(np.percentile(fa_b, 5)),
                                                        float(np.percentile(fa_b, 95))]
        stats['background eigenvalue range'] = [float(ev_all[bg].min()), float(ev_all[bg].max())]
    else:
        assert not nonzero_bg.any(), label
    finite = D[np.isfinite(D).all(axis=(-1, -2))]
    stats['component range (mm^2/s)'] = [float(finite.min()), float(finite.max())]
    stats['eigenvalue range in the head (mm^2/s)'] = [float(ev_all[mask].min()), float(ev_all[mask].max())]
    for k, v in stats.items():
        if isinstance(v, float):
            v = '%.4g' % v
        elif isinstance(v, list):
            v = '[' + ', '.join('%.4g' % x for x in v) + ']'
        print('  %s: %s' % (k, v))
    return stats


def run(cmd, cwd):
    """Runs a tool in `cwd` (relative file names only, so that nothing
    that names the temporary folder ends up in a file), single-threaded."""
    import subprocess
    env = dict(os.environ, OMP_NUM_THREADS='1', OPENBLAS_NUM_THREADS='1', MRTRIX_QUIET='1')
    print('  $', ' '.join(cmd))
    done = subprocess.run(cmd, cwd=cwd, env=env, stdout=subprocess.DEVNULL,
                          stderr=subprocess.PIPE, text=True)
    for line in done.stderr.splitlines():      # less tend estim's progress counter
        print('    ' + (line if done.returncode else line[:100]))
    done.check_returncode()


def read_mif(path):
    """MRtrix .mif (uncompressed): returns (data with the axes in the
    header's order, float64; the voxel-to-scanner affine; the header's
    key: [values])."""
    with open(path, 'rb') as f:
        raw = f.read()
    end = raw.index(b'\nEND\n')
    lines = raw[:end].decode('ascii').split('\n')
    assert lines[0] == 'mrtrix image', lines[0]
    hdr = {}
    for line in lines[1:]:
        k, v = line.split(':', 1)
        hdr.setdefault(k.strip(), []).append(v.strip())
    dim = [int(x) for x in hdr['dim'][0].split(',')]
    vox = [float(x) for x in hdr['vox'][0].split(',')]
    layout = hdr['layout'][0].split(',')
    dtype = {'Float32LE': '<f4', 'Float64LE': '<f8'}[hdr['datatype'][0]]
    name, offset = hdr['file'][0].split()
    assert name == '.', name
    T = np.array([[float(x) for x in row.split(',')] for row in hdr['transform']])
    a = np.eye(4)
    a[:3, :3] = T[:, :3] @ np.diag(vox[:3])
    a[:3, 3] = T[:, 3]
    rank = [int(x[1:]) for x in layout]
    sign = [-1 if x[0] == '-' else 1 for x in layout]
    order = sorted(range(len(dim)), key=lambda ax: rank[ax])      # fastest first
    n = int(np.prod(dim))
    flat = np.frombuffer(raw, dtype=dtype, count=n, offset=int(offset))
    arr = flat.reshape([dim[ax] for ax in reversed(order)])      # C order: slowest first
    arr = arr.transpose([list(reversed(order)).index(ax) for ax in range(len(dim))])
    for ax in range(len(dim)):
        if sign[ax] < 0:
            arr = np.flip(arr, axis=ax)
    return np.asarray(arr, dtype=np.float64), a, hdr


def read_nrrd(path):
    """A NRRD with an attached header, raw or gzip, type float, as Teem
    writes it: returns (data in NRRD axis order (axis 0 fastest) as a numpy
    array indexed [axis0, axis1, ...], float64; header {field: value})."""
    import gzip
    with open(path, 'rb') as f:
        raw = f.read()
    end = raw.index(b'\n\n')
    hdr = {}
    for line in raw[:end].decode('ascii').split('\n')[1:]:
        if line.startswith('#'):
            continue
        if ':=' in line:
            k, v = line.split(':=', 1)
        else:
            k, v = line.split(': ', 1)
        hdr[k] = v
    body = raw[end + 2:]
    if hdr['encoding'] == 'gzip':
        body = gzip.decompress(body)
    assert hdr['type'] == 'float' and hdr['endian'] == 'little', hdr
    sizes = [int(x) for x in hdr['sizes'].split()]
    arr = np.frombuffer(body, dtype='<f4').reshape(sizes[::-1]).transpose()
    return np.asarray(arr, dtype=np.float64), hdr


def nrrd_vectors(text):
    """'none (a,b,c) (d,e,f)' -> list of arrays or None."""
    out = []
    for tok in text.split():
        out.append(None if tok == 'none' else np.array([float(x) for x in tok.strip('()').split(',')]))
    return out


def fractional_anisotropy(lam):
    """FA from eigenvalues (..., 3); defined for any signs (can exceed 1
    when an eigenvalue is negative); 0 for the zero tensor."""
    m = lam.mean(axis=-1, keepdims=True)
    num = np.sqrt(np.sum((lam - m) ** 2, axis=-1))
    den = np.sqrt(np.sum(lam ** 2, axis=-1))
    return np.sqrt(1.5) * num / np.where(den > 0, den, 1.0)


def print_truth(shape=SHAPE, voxel=VOXEL):
    a = affine(shape, voxel)
    mask, weights, _ = truth_at(voxel_world(a, shape), shape, voxel)
    print('affine:\n', np.array2string(a, precision=4, suppress_small=True))
    print('det %.4f' % np.linalg.det(a[:3, :3]), 'head voxels', int(mask.sum()), 'of', mask.size,
          'bundle axes %.2f mm apart' % check_bundles_apart(shape, voxel))
    for name, (p0, t) in bundle_axes(shape, voxel).items():
        print('bundle %s: world direction (%.4f, %.4f, %.4f) through (%.2f, %.2f, %.2f);'
              % ((name,) + tuple(t) + tuple(p0)),
              'voxels with weight 1: %d, > 0: %d' % ((weights[name] >= 1).sum(), (weights[name] > 0).sum()))


if __name__ == '__main__':
    # dwi_simulation.py                     prints the phantom's geometry
    # dwi_simulation.py FOLDER [NX NY NZ]   also writes the DWI there (for
    #                                       benchmarks: 64 64 30, 128 128 70)
    import sys
    shape = tuple(int(n) for n in sys.argv[2:5]) if len(sys.argv) > 4 else SHAPE
    print_truth(shape)
    if len(sys.argv) > 1:
        os.makedirs(sys.argv[1], exist_ok=True)
        write_dwi(sys.argv[1], shape)
        print('wrote dwi.nii.gz, mask.nii.gz, bvals, bvecs in', sys.argv[1])
    g = electrostatic_directions()
    dots = np.abs(g @ g.T)[~np.eye(len(g), dtype=bool)]
    print('directions: smallest angle between two %.2f deg' % np.degrees(np.arccos(dots.max())))
