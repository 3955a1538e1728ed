"""l_bracket.vtu: a real finite-element result, as a user's first SfePy
model would give it: an L-shaped steel bracket in MILLIMETRES and MPa
(problem: l_bracket_conf.py; gmsh linear tetrahedra, ~9k (full) or ~3k
(`--cells small`), P2 displacements, E = 210000 MPa, nu = 0.3).

L in the x-z plane, 20 mm thick in y: vertical arm x in [0, 20],
z in [0, 100], clamped at its end z = 100; horizontal arm x in [0, 100],
z in [0, 20], its end face x = 100 pushed down (-z, across the arm) by
2 kN. The element-averaged Cauchy stress is averaged onto the points (each
point: the plain mean of its cells, common.cell_to_point, as the parent
folder does) and stored as POINT data "stress", 9 components row-major,
active tensors; the displacement (mm, at the vertices) as point data.

Beam estimate: the bending moment grows from 0 at the loaded end to
2 kN x 80 mm = 160 N m at the corner and stays 160 N m up the vertical arm
(plus 2 kN of tension in it); section modulus 20 x 20^2 / 6 = 1333 mm^3,
so +-120 MPa (+125 / -115 with the tension) at the faces of the vertical
arm, and +-60 MPa at x = 60 on the horizontal arm. The point values (means
of element averages) fall ~5-20% short of these at the faces.

A correct picture shows: the stress concentrated at the sharp re-entrant
inner corner, the edge x = z = 20, in TENSION (both arms bend so that their
inner faces are stretched; the largest major eigenvalue, ~240 MPa on the
full mesh and ~180 MPa on the small one, is there: singular, so it depends
on the mesh); along the horizontal arm, tension on its top face z = 20 and
compression on its bottom face z = 0, growing from 0 at the loaded end
towards the corner; up the vertical arm, tension on its inner face x = 20
and compression on its outer face x = 0 all the way to the clamp (a
constant moment); the neutral planes in between nearly stress-free; major
trajectories along each arm, turning round the corner.
"""
import os

import numpy as np

from vtk.util.numpy_support import vtk_to_numpy

import untuned_common as uc
from untuned_common import common

args = uc.parse_args(__doc__)
pb = common.solve_sfepy(os.path.join(uc.HERE, 'l_bracket_conf.py'), cells=args.cells)
ug, full, point_stress = common.sfepy_stress_grid(pb)

p = pb.domain.mesh.coors
u = vtk_to_numpy(ug.GetPointData().GetVectors())
lam = np.linalg.eigvalsh(point_stress.reshape(-1, 3, 3))
corner = np.argmin(np.hypot(p[:, 0] - 20, p[:, 2] - 20) + np.abs(p[:, 1] - 10))
print('%d vertices, %d tetrahedra; major eigenvalue in [%.4g, %.4g], minor in [%.4g, %.4g] MPa'
      % (len(p), ug.GetNumberOfCells(), lam[:, 2].min(), lam[:, 2].max(),
         lam[:, 0].min(), lam[:, 0].max()))
print('at the re-entrant corner %s: eigenvalues %s MPa' % (p[corner], np.round(lam[corner], 1)))
for name, q in (('horizontal arm top (60, 10, 20)', [60, 10, 20]),
                ('horizontal arm bottom (60, 10, 0)', [60, 10, 0]),
                ('vertical arm inner (20, 10, 60)', [20, 10, 60]),
                ('vertical arm outer (0, 10, 60)', [0, 10, 60])):
    i = np.argmin(np.linalg.norm(p - q, axis=1))
    print('%s: sigma_xx %.1f, sigma_zz %.1f MPa' % (name, point_stress[i, 0], point_stress[i, 8]))
print('tip deflection u_z at x = 100: %.4f mm' % u[p[:, 0] > 100 - 1e-6, 2].mean())
common.write_xml(ug, os.path.join(args.outdir, 'l_bracket.vtu'))
