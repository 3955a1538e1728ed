"""SfePy problem description: a steel plate in MILLIMETRES with stresses in
PASCALS. Plate 100 mm x 40 mm x 5 mm (x in [-50, 50], y in [-20, 20],
z in [0, 5]) with a through hole of radius 8 mm at its centre, pulled along
x: the face x = -50 is held at u_x = 0, the face x = +50 is moved by
u_x = 0.015 mm (gross strain 1.5e-4). E = 2.1e11 Pa, nu = 0.3, so the far
field is ~3.15e7 Pa and the hole edge at (0, +-8) peaks near 1e8 Pa.
Rigid-body motion is removed by u_y = u_z = 0 at (-50, 0, 0) and u_y = 0 at
(-50, 0, 5) (statically determinate, adds no stress).

Mesh: an O-grid of hexahedra around the hole (straight lines from equally
spaced points on the hole to points on the plate's outline, geometrically
graded towards the hole), each hexahedron
split into 6 tetrahedra along its index-space diagonal (a conforming split).
Linear tetrahedra.

Standalone:  sfepy-run simple plate_with_hole_mm_pa_conf.py ; the generator
plate_with_hole_mm_pa.py solves it and writes
../generated/plate_with_hole_mm_pa.vtu.
"""
import itertools

import numpy as nm

from sfepy.base.base import Struct
from sfepy.discrete.fem import Mesh
from sfepy.discrete.fem.meshio import UserMeshIO
from sfepy.mechanics.matcoefs import stiffness_from_youngpoisson

HALF_X, HALF_Y, THICK, RADIUS = 50.0, 20.0, 5.0, 8.0
N_THETA, N_R, N_Z = 80, 14, 3     # cells around, radially, through the thickness
N_SIDE = 12                       # cells along each short (40 mm) side
GRADING = 1.15                    # radial cell size ratio
PULL = 0.015                      # mm


def plate_mesh():
    # Outline nodes walk the rectangle counter-clockwise from (50, 0), hitting
    # its corners exactly (N_SIDE cells on each short side, the rest on the
    # long ones); hole nodes are equally spaced in angle.
    n_long = N_THETA // 2 - N_SIDE
    corners = nm.array([[HALF_X, 0], [HALF_X, HALF_Y], [-HALF_X, HALF_Y],
                        [-HALF_X, -HALF_Y], [HALF_X, -HALF_Y], [HALF_X, 0]])
    counts = [N_SIDE // 2, n_long, N_SIDE, n_long, N_SIDE - N_SIDE // 2]
    outline = nm.concatenate([
        a + (b - a) * (nm.arange(n) / n)[:, None]
        for a, b, n in zip(corners[:-1], corners[1:], counts)])
    theta = 2 * nm.pi * nm.arange(N_THETA) / N_THETA
    hole = RADIUS * nm.stack([nm.cos(theta), nm.sin(theta)], axis=-1)
    t = (GRADING ** nm.arange(N_R + 1) - 1) / (GRADING ** N_R - 1)
    xy = hole[:, None, :] + t[None, :, None] * (outline - hole)[:, None, :]
    z = nm.linspace(0.0, THICK, N_Z + 1)
    coors = nm.zeros((N_THETA, N_R + 1, N_Z + 1, 3))
    coors[..., :2] = xy[:, :, None, :]
    coors[..., 2] = z[None, None, :]
    coors = coors.reshape(-1, 3)

    def node(i, j, k):
        return ((i % N_THETA) * (N_R + 1) + j) * (N_Z + 1) + k

    tets = []
    for i, j, k in itertools.product(range(N_THETA), range(N_R), range(N_Z)):
        for perm in itertools.permutations(range(3)):
            step = [0, 0, 0]
            ids = [node(i, j, k)]
            for axis in perm[:2]:
                step[axis] = 1
                ids.append(node(i + step[0], j + step[1], k + step[2]))
            ids.append(node(i + 1, j + 1, k + 1))
            tets.append(ids)
    tets = nm.array(tets, dtype=nm.int32)
    # Positive orientation (VTK and SfePy agree): swap two nodes if needed.
    p = coors[tets]
    vol = nm.einsum('ij,ij->i', nm.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]),
                    p[:, 3] - p[:, 0])
    neg = vol < 0
    tets[neg, 1], tets[neg, 2] = tets[neg, 2], tets[neg, 1].copy()
    return Mesh.from_data('plate_with_hole', coors, None, [tets],
                          [nm.zeros(len(tets), dtype=nm.int32)], ['3_4'])


def mesh_hook(mesh, mode):
    if mode == 'read':
        return plate_mesh()


filename_mesh = UserMeshIO(mesh_hook)

eps = 1e-6
regions = {
    'Omega': 'all',
    'Left': ('vertices in (x < %.8f)' % (-HALF_X + eps), 'facet'),
    'Right': ('vertices in (x > %.8f)' % (HALF_X - eps), 'facet'),
    'AnchorBottom': ('vertices in (x < %.8f) & (y > %.8f) & (y < %.8f) & (z < %.8f)'
                     % (-HALF_X + eps, -eps, eps, eps), 'vertex'),
    'AnchorTop': ('vertices in (x < %.8f) & (y > %.8f) & (y < %.8f) & (z > %.8f)'
                  % (-HALF_X + eps, -eps, eps, THICK - eps), 'vertex'),
}
materials = {'solid': ({'D': stiffness_from_youngpoisson(3, 2.1e11, 0.3)},)}
fields = {'displacement': ('real', 'vector', 'Omega', 1)}
integrals = {'i': 1}
variables = {'u': ('unknown field', 'displacement', 0),
             'v': ('test field', 'displacement', 'u')}
ebcs = {
    'HoldLeft': ('Left', {'u.0': 0.0}),
    'PullRight': ('Right', {'u.0': PULL}),
    'AnchorBottom': ('AnchorBottom', {'u.[1,2]': 0.0}),
    'AnchorTop': ('AnchorTop', {'u.1': 0.0}),
}
equations = {'balance_of_forces': 'dw_lin_elastic.i.Omega(solid.D, v, u) = 0'}
solvers = {'ls': ('ls.scipy_direct', {}),
           'newton': ('nls.newton', {'i_max': 1, 'eps_a': 1e-10, 'eps_r': 1e-10})}


def post_process(out, pb, state, extend=False):
    stress = pb.evaluate('ev_cauchy_stress.i.Omega(solid.D, u)', mode='el_avg')
    out['cauchy_stress'] = Struct(name='output_data', mode='cell', data=stress,
                                  dofs=None)
    return out


options = {'nls': 'newton', 'ls': 'ls', 'post_process_hook': 'post_process',
           'output_format': 'vtk'}
