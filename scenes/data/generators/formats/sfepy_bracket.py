"""sfepy_bracket.vtk: SfePy 2021.4's OWN output file (Problem.save_state,
which hands it to meshio 5's legacy VTK writer: "# vtk DataFile Version
5.1", binary, big-endian) for a linear-elastic L-shaped bracket. Nothing is
converted: the arrays are exactly as SfePy writes them.

Geometry (mm): an L in the x-z plane, 10 mm thick in y (0 <= y <= 10): the
vertical arm 0 <= x <= 10, 0 <= z <= 40 and the horizontal arm
0 <= x <= 40, 0 <= z <= 10, meshed with 2 mm cubes (875 hexahedra '3_8',
1,296 vertices), built with numpy and sfepy.discrete.fem.Mesh.from_data.
Node groups (SfePy's ngroups): 1 = nodes of the clamped face z = 40, 2 =
nodes of the loaded face x = 40, 0 = the rest. Cell groups (SfePy's
mat_ids): 1 = the vertical arm with the corner (x < 10), 2 = the
horizontal arm (x > 10).

Problem: steel, E = 200e3 MPa, nu = 0.3, tri-quadratic (Q2) displacements;
the end face z = 40 of the vertical arm clamped, the end face x = 40 of the
horizontal arm pushed down by the traction (0, 0, -10) MPa (a force of
1 kN); linear solve (scipy direct).

Arrays (as SfePy writes them):
  point data  "u"             3 components, the displacement (mm) at the
                              vertices
              "node_groups"   1 component, int, SfePy's node groups
  cell data   "cauchy_stress" 6 components, element averages of the Cauchy
                              stress (MPa) in SFEPY'S ORDER
                              11 22 33 12 13 23 (= XX YY ZZ XY XZ YZ; NOT
                              VTK's XX YY ZZ XY YZ XZ: the last two are
                              swapped)
              "mat_id"        1 component, int, SfePy's cell groups
None is marked as active tensors (a legacy file written by meshio uses
FIELD data).

Extra arrays: meshio 5.0 turns SfePy's point and cell sets into two more
integer arrays, oddly named "00-1-210-1-22" (point data) and "1-2" (cell
data); they are part of SfePy's raw output and are kept.

Expected picture: both arms bend. The horizontal arm is a cantilever off the
corner (moment 1 kN x its distance from x = 40): tension along x on its top
face z = 10 and compression on its bottom z = 0 (element averages +-72 MPa
at x = 25, up to +170 / -130 near the corner). The vertical arm carries the
moment 35 kN mm up to the clamp plus a 10 MPa tension: stress along z,
tension on its inner face x = 10 and compression on its outer face x = 0
(+178 / -158 at z = 25, up to +209 / -161). The largest values are at the
re-entrant inner corner (10, y, 10) and at the clamp; shear (13) up to 60
near the corner. The tip of the horizontal arm moves down by 0.32 mm.
"""
import numpy as np

import formats_common as fc

from sfepy.base.base import IndexedStruct, Struct, output
from sfepy.discrete import (Equation, Equations, FieldVariable, Integral,
                            Material, Problem)
from sfepy.discrete.conditions import Conditions, EssentialBC
from sfepy.discrete.fem import FEDomain, Field, Mesh
from sfepy.mechanics.matcoefs import stiffness_from_youngpoisson
from sfepy.solvers.ls import ScipyDirect
from sfepy.solvers.nls import Newton
from sfepy.terms import Term

output.set_output(quiet=True)

H = 2.0                      # cube edge, mm
NX, NY, NZ = 20, 5, 20       # lattice of the bounding box 40 x 10 x 40
ARM = 10.0                   # arm width (mm)
E, NU, TRACTION = 200e3, 0.3, 10.0

# Cubes of the L, then its vertices (lattice numbering compacted).
cubes = [(i, j, k) for k in range(NZ) for j in range(NY) for i in range(NX)
         if (i + 0.5) * H < ARM or (k + 0.5) * H < ARM]


def lattice(i, j, k):
    return (k * (NY + 1) + j) * (NX + 1) + i


conn = np.array([[lattice(i, j, k), lattice(i + 1, j, k), lattice(i + 1, j + 1, k),
                  lattice(i, j + 1, k), lattice(i, j, k + 1), lattice(i + 1, j, k + 1),
                  lattice(i + 1, j + 1, k + 1), lattice(i, j + 1, k + 1)]
                 for i, j, k in cubes])
used = np.unique(conn)
renumber = np.full((NX + 1) * (NY + 1) * (NZ + 1), -1)
renumber[used] = np.arange(len(used))
conn = renumber[conn].astype(np.int32)
kk, jj, ii = np.unravel_index(used, (NZ + 1, NY + 1, NX + 1))
coors = np.stack([ii * H, jj * H, kk * H], axis=1).astype(np.float64)
ngroups = np.zeros(len(coors), dtype=np.int32)
ngroups[coors[:, 2] > NZ * H - 1e-6] = 1
ngroups[coors[:, 0] > NX * H - 1e-6] = 2
mat_ids = np.array([1 if (i + 0.5) * H < ARM else 2 for i, j, k in cubes], dtype=np.int32)

mesh = Mesh.from_data('sfepy_bracket', coors, ngroups, [conn], [mat_ids], ['3_8'])
domain = FEDomain('domain', mesh)
omega = domain.create_region('Omega', 'all')
clamp = domain.create_region('Clamp', 'vertices in (z > %.6f)' % (NZ * H - 1e-6), 'facet')
load = domain.create_region('Load', 'vertices in (x > %.6f)' % (NX * H - 1e-6), 'facet')

field = Field.from_args('displacement', np.float64, 'vector', omega, approx_order=2)
u = FieldVariable('u', 'unknown', field)
v = FieldVariable('v', 'test', field, primary_var_name='u')
solid = Material('solid', D=stiffness_from_youngpoisson(3, E, NU))
push = Material('push', val=np.array([[0.0], [0.0], [-TRACTION]]))
integral = Integral('i', order=4)
balance = Equation('balance',
                   Term.new('dw_lin_elastic(solid.D, v, u)', integral, omega, solid=solid, v=v, u=u)
                   - Term.new('dw_surface_ltr(push.val, v)', integral, load, push=push, v=v))
pb = Problem('sfepy_bracket', equations=Equations([balance]))
pb.set_bcs(ebcs=Conditions([EssentialBC('clamped', clamp, {'u.all': 0.0})]))
nls_status = IndexedStruct()
pb.set_solver(Newton({'i_max': 1, 'eps_a': 1e-8}, lin_solver=ScipyDirect({}),
                     status=nls_status))
state = pb.solve(save_results=False)
print('Newton: %d iterations, residual %.2e' % (nls_status.n_iter, nls_status.err))

# SfePy's output dictionary plus the element-averaged Cauchy stress, as in
# the problem descriptions' post_process hooks; written by SfePy itself.
out = state.create_output_dict()
stress = pb.evaluate('ev_cauchy_stress.4.Omega(solid.D, u)', mode='el_avg',
                     solid=solid, u=u, copy_materials=False)
out['cauchy_stress'] = Struct(name='output_data', mode='cell', data=stress, dofs=None)
path = fc.out_path('sfepy_bracket.vtk')
pb.save_state(path, out=out)
fc.report(path)

s = stress.reshape(-1, 6)
disp = out['u'].data
print('cells %d, vertices %d; stress (11 22 33 12 13 23) min %s max %s'
      % (len(s), len(coors), np.round(s.min(0), 1), np.round(s.max(0), 1)))
print('tip displacement z: %.3f mm' % disp[ngroups == 2, 2].mean())

import meshio  # noqa: E402
back = meshio.read(path)
print('meshio reads back:', back)
with open(path, 'rb') as f:
    print('header:', f.read(60).split(b'\n')[:3])
assert np.allclose(back.cell_data['cauchy_stress'][0], s)
