"""mixed_cells_legacy.vtk: a legacy ASCII VTK 4.2 unstructured grid of a small
part in METRES (1 mm x 0.5 mm x 0.5 mm: [0, 1e-3] x [0, 5e-4] x [0, 5e-4])
built from a 12 x 6 x 6 lattice of cubes: the third x < 1/3 mm is
hexahedra, the middle third wedges (each cube cut in two along its x-y
diagonal), the last third pyramids (each cube cut into 6 pyramids meeting at
an extra point at its centre). The mesh is conforming.

Array "sigma" (point data, 9 components, active tensors): an analytic,
linear-in-position stress in Pa (~1e6; not an equilibrium field) plus a small
antisymmetric part (~1e3 Pa), so the tensor is slightly NON-symmetric. With
xi, eta, zeta = x, y, z in mm:
    s_xx = 1e6 (0.5 + 8 (zeta - 0.25))   s_yy = 1e6 (-0.3 + 0.6 xi)
    s_zz = 1e6 (0.2 - 0.4 eta)           s_xy = 1e6 * 0.4 (1 - xi)
    s_xz = 1e6 (0.3 - 0.6 xi + 0.8 eta)  s_yz = 1e6 * 0.25 zeta
    plus W xi with W = 2e3 [[0, 1, -0.5], [-1, 0, 0.7], [0.5, -0.7, 0]].
The writer is told to write file version 4.2: VTK 9.1 writes 5.1 by default,
which its own legacy reader cannot read back."""
import itertools

import numpy as np
import vtk

import common

H = 1e-3 / 12           # cube edge, m
NX, NY, NZ = 12, 6, 6

lattice = np.array([[i * H, j * H, k * H] for k in range(NZ + 1)
                    for j in range(NY + 1) for i in range(NX + 1)])


def node(i, j, k):
    return (k * (NY + 1) + j) * (NX + 1) + i


points = list(lattice)
hexes, wedges, pyramids = [], [], []
for k, j, i in itertools.product(range(NZ), range(NY), range(NX)):
    a, b, c, d = node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k), node(i, j + 1, k)
    A, B, C, D = node(i, j, k + 1), node(i + 1, j, k + 1), node(i + 1, j + 1, k + 1), node(i, j + 1, k + 1)
    if i < NX // 3:
        hexes.append([a, b, c, d, A, B, C, D])
    elif i < 2 * NX // 3:
        # VTK wedge: the normal of (0, 1, 2) points away from (3, 4, 5).
        wedges.append([a, c, b, A, C, B])
        wedges.append([a, d, c, A, D, C])
    else:
        centre = len(points)
        points.append(lattice[a] + 0.5 * H)
        # VTK pyramid: the base (0, 1, 2, 3) normal points towards the apex;
        # the faces below are listed with outward normals, hence reversed.
        for base in ([a, d, c, b], [A, B, C, D], [a, b, B, A],
                     [d, D, C, c], [a, A, D, d], [b, c, C, B]):
            pyramids.append(base[::-1] + [centre])
points = np.array(points)

ug = common.unstructured_grid(points, [(vtk.VTK_HEXAHEDRON, hexes),
                                       (vtk.VTK_WEDGE, wedges),
                                       (vtk.VTK_PYRAMID, pyramids)])
volumes = common.check_positive_volumes(ug)
assert abs(volumes.sum() - 1e-3 * 5e-4 * 5e-4) < 1e-6 * 1e-3 * 5e-4 * 5e-4

xi, eta, zeta = (points / 1e-3).T
s = np.zeros((len(points), 3, 3))
s[:, 0, 0] = 0.5 + 8 * (zeta - 0.25)
s[:, 1, 1] = -0.3 + 0.6 * xi
s[:, 2, 2] = 0.2 - 0.4 * eta
s[:, 0, 1] = s[:, 1, 0] = 0.4 * (1 - xi)
s[:, 0, 2] = s[:, 2, 0] = 0.3 - 0.6 * xi + 0.8 * eta
s[:, 1, 2] = s[:, 2, 1] = 0.25 * zeta
s *= 1e6
W = 2e3 * np.array([[0, 1, -0.5], [-1, 0, 0.7], [0.5, -0.7, 0]])
s += W[None] * xi[:, None, None]
ug.GetPointData().SetTensors(common.vtk_array(s.reshape(-1, 9), 'sigma'))

path = common.out_path('mixed_cells_legacy.vtk')
writer = vtk.vtkUnstructuredGridWriter()
writer.SetFileName(path)
writer.SetInputData(ug)
writer.SetFileVersion(42)
writer.SetFileTypeToASCII()
writer.SetHeader('mixed hexahedra/wedges/pyramids, 1 mm part in m, sigma in Pa')
if not writer.Write():
    raise RuntimeError('cannot write ' + path)
print('wrote', path, len(hexes), 'hexahedra', len(wedges), 'wedges',
      len(pyramids), 'pyramids')
