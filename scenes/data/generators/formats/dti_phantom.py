"""The synthetic diffusion-tensor "brain" shared by dti_fsl_dtifit.py and
dti_symmatrix_intent.py (not a generator itself).

Grid: 40 x 48 x 24 voxels of 2 mm; the affine is a rotation by 10 degrees
about z times 2 mm, with the volume's centre voxel at the world (scanner,
RAS: x left->right, y posterior->anterior, z inferior->superior) point
CENTRE = (1.5, -17, 9) mm. det(affine[:3, :3]) = +8 > 0.

Content, all defined in WORLD coordinates (relative to CENTRE, mm; units
of D: mm^2/s):
  * mask: the ellipsoid (x/32)^2 + (y/40)^2 + (z/20)^2 <= 1 (semi-axes
    along the world axes, so tilted by 10 degrees against the voxel grid);
  * inside, isotropic diffusion 0.7e-3;
  * bundles with D = 0.3e-3 I + (1.7e-3 - 0.3e-3) t t^T along their
    tangent t (major eigenvalue 1.7e-3, the other two 0.3e-3), blended into
    the background with a cos^2 profile across (and at the ends of) each:
      - "corpus callosum": an arc in the coronal (x-z) plane, z = 4 +
        12 (x/26)^2 for |x| <= 26, a U opening upwards, tangent along x at
        the midline and tilting up laterally; 4 mm thick, for
        -22 <= y <= 14;
      - two "corticospinal tracts": straight along z at x = +-14, y = -6,
        radius 4, -18 <= z <= 18; they cross the arc at z ~ 7.5, where
        the blend gives planar (crossing) tensors;
      - two "cingula": straight along y at x = +-6, z = 15, radius 3,
        -30 <= y <= 26.
In a direction-coloured map the arc is red (x), the tracts blue (z) and the
cingula green (y).
"""
import numpy as np

SHAPE = (40, 48, 24)
VOXEL = 2.0
ANGLE = np.radians(10.0)
CENTRE = np.array([1.5, -17.0, 9.0])
D_ISO, L_PAR, L_PERP = 0.7e-3, 1.7e-3, 0.3e-3


def affine():
    c, s = np.cos(ANGLE), np.sin(ANGLE)
    a = np.eye(4)
    a[:3, :3] = np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]]) * VOXEL
    centre_voxel = (np.array(SHAPE) - 1) / 2.0
    a[:3, 3] = CENTRE - a[:3, :3] @ centre_voxel
    return a


def world_points():
    """World coordinates relative to CENTRE of every voxel centre, (nx, ny, nz, 3)."""
    ijk = np.stack(np.meshgrid(*[np.arange(n) for n in SHAPE], indexing='ij'), axis=-1)
    a = affine()
    return ijk @ a[:3, :3].T + a[:3, 3] - CENTRE


def _taper(d, r):
    """cos^2 fall-off from 1 at d = 0 to 0 at d >= r."""
    d = np.clip(np.abs(d) / r, 0, 1)
    return np.cos(0.5 * np.pi * d) ** 2


def _ends(u, lo, hi, ramp=4.0):
    """1 inside [lo + ramp, hi - ramp], tapering to 0 at lo and hi."""
    return _taper(np.maximum(0, np.maximum(lo + ramp - u, u - (hi - ramp))), ramp)


def tensors():
    """mask (nx, ny, nz) bool and D_world (nx, ny, nz, 3, 3)."""
    p = world_points()
    x, y, z = p[..., 0], p[..., 1], p[..., 2]
    mask = (x / 32) ** 2 + (y / 40) ** 2 + (z / 20) ** 2 <= 1.0

    bundles = []   # (weight, unit tangent)
    # corpus callosum: nearest point on the arc z = 4 + k x^2 in the x-z plane
    k = 12.0 / 26.0 ** 2
    s = np.linspace(-26, 26, 521)
    arc = np.stack([s, 4 + k * s * s], axis=1)
    d2 = (x[..., None] - arc[:, 0]) ** 2 + (z[..., None] - arc[:, 1]) ** 2
    nearest = np.argmin(d2, axis=-1)
    dist = np.sqrt(np.take_along_axis(d2, nearest[..., None], axis=-1)[..., 0])
    s0 = s[nearest]
    t = np.stack([np.ones_like(s0), 2 * k * s0, 0 * s0], axis=-1)
    t = t[..., [0, 2, 1]]      # (dx, dz) -> (x, y, z): no y component
    t /= np.linalg.norm(t, axis=-1, keepdims=True)
    w = _taper(dist, 4.0) * _ends(y, -22, 14) * _ends(x, -30, 30)
    bundles.append((w, t))
    # corticospinal tracts along z
    for xc in (-14.0, 14.0):
        w = _taper(np.hypot(x - xc, y + 6), 4.0) * _ends(z, -18, 18)
        bundles.append((w, np.broadcast_to([0.0, 0.0, 1.0], p.shape)))
    # cingula along y
    for xc in (-6.0, 6.0):
        w = _taper(np.hypot(x - xc, z - 15), 3.0) * _ends(y, -30, 26)
        bundles.append((w, np.broadcast_to([0.0, 1.0, 0.0], p.shape)))

    total = sum(w for w, _ in bundles)
    scale = np.where(total > 1, 1 / np.maximum(total, 1e-30), 1.0)
    eye = np.eye(3)
    D = (1 - np.minimum(total, 1))[..., None, None] * D_ISO * eye
    for w, t in bundles:
        Db = L_PERP * eye + (L_PAR - L_PERP) * t[..., :, None] * t[..., None, :]
        D = D + (w * scale)[..., None, None] * Db
    return mask, D


def fsl_frame(a):
    """F R^T, the map from world tensor components to FSL's voxel frame: R is
    affine[:3, :3] with unit columns, F = diag(-1, 1, 1) if the affine's
    determinant is positive (FSL flips x then), else the identity."""
    m = a[:3, :3]
    R = m / np.linalg.norm(m, axis=0)
    F = np.diag([-1.0, 1.0, 1.0]) if np.linalg.det(m) > 0 else np.eye(3)
    return F @ R.T
