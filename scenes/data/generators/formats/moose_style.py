"""moose_style.e: Exodus II written by the Exodus library (VTK's
vtkExodusIIWriter), with MOOSE-style NODAL variables, then extended in
place with netCDF4 to three time steps.

Mesh: a cantilever beam 10 x 1 x 1 (x in [0, 10] along the beam, y, z in
[-0.5, 0.5]), 30 x 6 x 6 = 1,080 HEX8 elements in one block, 1,519 nodes,
built with numpy. Units: mm, N, MPa (E = 200e3 MPa, nu = 0.3).

Nodal variables, in this order (as name_nod_var / vals_nod_var1..6,
float64):
  stress_xx, stress_xy, stress_xz, stress_yy, stress_yz, stress_zz
(VTK's writer leaves out displacement arrays named disp_x, ..., so the
file has none)
Euler-Bernoulli bending of the beam clamped at x = 0 under a DOWNWARD tip
load P = 1 N at x = 10 (I = 1/12 mm^4): sigma_xx = -M(x) z / I with
M(x) = -P (10 - x), i.e. sigma_xx = 12 P (10 - x) z (tension on top, z > 0:
+60 MPa at the root's top edge, -60 at its bottom), the parabolic shear
sigma_xz = -1.5 P (1 - 4 z^2) (-1.5 MPa on the neutral axis, 0 at the top
and bottom), all other components 0.

Time steps: time_whole = 1.0, 2.0, 3.0 with the load scaled by 1, 2 and 3
(the writer writes one step; the script sets the times and appends steps 2
and 3 with netCDF4). The writer's title carries the date; the script
replaces it, so the file is the same from run to run.

Expected picture: trajectories along the beam; tension (positive major
eigenvalue) in the top half and compression in the bottom half, both
growing linearly towards the clamped root x = 0 and vanishing at the tip;
near the neutral plane z = 0 the shear turns the principal directions to
+-45 degrees. Later steps: the same, scaled by 2 and 3.
"""
import netCDF4
import numpy as np

import formats_common as fc

L, B, H = 10.0, 1.0, 1.0
NX, NY, NZ = 30, 6, 6
P, E, NU = 1.0, 200e3, 0.3
I = B * H ** 3 / 12

x, y, z = np.meshgrid(np.linspace(0, L, NX + 1), np.linspace(-B / 2, B / 2, NY + 1),
                      np.linspace(-H / 2, H / 2, NZ + 1), indexing='ij')
points = np.stack([x.ravel(), y.ravel(), z.ravel()], axis=1)


def node(i, j, k):
    return (i * (NY + 1) + j) * (NZ + 1) + k


hexes = []
for i in range(NX):
    for j in range(NY):
        for k in range(NZ):
            # bottom face (z = k) counter-clockwise seen from +z, then the top
            hexes.append([node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k), node(i, j + 1, k),
                          node(i, j, k + 1), node(i + 1, j, k + 1), node(i + 1, j + 1, k + 1),
                          node(i, j + 1, k + 1)])
hexes = np.array(hexes, dtype=np.int32)


def fields(load):
    px, py, pz = points.T
    p = P * load
    M = -p * (L - px)
    sxx = -M * pz / I
    sxz = -1.5 * p / (B * H) * (1 - 4 * pz * pz / (H * H))
    zero = np.zeros_like(px)
    return {'stress_xx': sxx, 'stress_xy': zero, 'stress_xz': sxz,
            'stress_yy': zero, 'stress_yz': zero, 'stress_zz': zero}


# volumes positive? (VTK's check)
import vtk  # noqa: E402
from vtk.util.numpy_support import numpy_to_vtk  # noqa: E402
grid = fc.common.unstructured_grid(points, [(vtk.VTK_HEXAHEDRON, hexes)])
fc.common.check_positive_volumes(grid)

# Written by the Exodus library (through VTK's writer), as MOOSE's files
# are: meshio's own Exodus writer makes files the Exodus library cannot
# read the variables of ("could not find nodal variables"), so it is not
# what a user's solver leaves.
for name, values in fields(1.0).items():
    a = numpy_to_vtk(np.ascontiguousarray(values, dtype=np.float64), deep=1)
    a.SetName(name)
    grid.GetPointData().AddArray(a)
path = fc.out_path('moose_style.e')
w = vtk.vtkExodusIIWriter()
w.SetInputData(grid)
w.SetFileName(path)
w.Write()
TITLE = 'Created by vtkExodusIIWriter: cantilever under a tip load, three load steps'

with netCDF4.Dataset(path, 'a') as nc:
    nc.title = TITLE  # the writer's title carries the date
    names = [b''.join(r).decode().rstrip('\x00') for r in nc.variables['name_nod_var'][:]]
    assert names == list(fields(1.0)), names
    nc.variables['time_whole'][0:3] = [1.0, 2.0, 3.0]
    for step, load in ((1, 2.0), (2, 3.0)):
        values = fields(load)
        for k, name in enumerate(names):
            nc.variables['vals_nod_var%d' % (k + 1)][step] = values[name]
fc.report(path)

with netCDF4.Dataset(path) as nc:
    print('format', nc.data_model, '| title:', nc.title, '| time_whole:',
          list(nc.variables['time_whole'][:]))
    sxx = nc.variables['vals_nod_var1'][:]
    print('stress_xx range per step', [(float(s.min()), float(s.max())) for s in sxx])
r = vtk.vtkExodusIIReader()  # read back by the Exodus library, at the last step
r.SetFileName(path)
r.UpdateInformation()
r.SetAllArrayStatus(vtk.vtkExodusIIReader.NODAL, 1)
r.SetTimeStep(2)
r.Update()
block = r.GetOutput().GetBlock(0).GetBlock(0)
print('read back, step 3: arrays', [block.GetPointData().GetArrayName(i) for i in range(block.GetPointData().GetNumberOfArrays())])
