"""torsion_shaft.vtu: a solid circular shaft in pure torsion, SI units:
radius 0.02 m, length 0.3 m along z (z in [0, 0.3], axis x = y = 0),
uniform linear tetrahedra from gmsh (~100k; `--cells small` ~15k).

Stress (Pa), the exact Saint-Venant solution: the only non-zero component
in cylindrical coordinates is tau_thetaz = T r / J, scaled so the peak at
the surface r = 0.02 is 80 MPa: tau = 8e7 r / 0.02; as a tensor
sigma = tau (e_theta e_z^T + e_z e_theta^T), i.e. sigma_xz = -tau sin(theta),
sigma_yz = tau cos(theta). Eigenvalues +tau, 0, -tau: TENSION +tau along
(e_theta + e_z)/sqrt(2) and COMPRESSION -tau along (e_theta - e_z)/sqrt(2),
both at 45 degrees to the axis; zero on the axis. POINT data "stress",
9 components row-major, active tensors.

A correct picture shows: the stress growing linearly from nothing on the
axis to the surface (uniform along z; no end effects); major (tension)
trajectories on the surface are RIGHT-handed helices at 45 degrees to the
axis (pitch 2 pi r, ~0.126 m at the surface, so about 2.4 turns over the
length), the minor (compression) ones LEFT-handed helices crossing them at
90 degrees. Colour by the major eigenvalue: hottest at the surface,
uniformly so along the shaft; the medium eigenvalue is 0 everywhere.
"""
import os

import numpy as np
import vtk

import untuned_common as uc

args = uc.parse_args(__doc__)
RADIUS, LENGTH, TAU_MAX = 0.02, 0.3, 8e7
H = {'full': 0.0026, 'small': 0.005}[args.cells]   # m: ~100k / ~15k tets


def build(gmsh):
    gmsh.model.occ.addCylinder(0, 0, 0, 0, 0, LENGTH, RADIUS)
    gmsh.model.occ.synchronize()
    gmsh.option.setNumber('Mesh.MeshSizeMin', H)
    gmsh.option.setNumber('Mesh.MeshSizeMax', H)


points, tets = uc.gmsh_tets(build)
x, y = points[:, 0], points[:, 1]
r, theta = np.hypot(x, y), np.arctan2(y, x)
tau = TAU_MAX * r / RADIUS
stress = np.zeros((len(points), 3, 3))
stress[:, 0, 2] = stress[:, 2, 0] = -tau * np.sin(theta)
stress[:, 1, 2] = stress[:, 2, 1] = tau * np.cos(theta)

ug = uc.tensor_grid(points, (vtk.VTK_TETRA, tets), stress)
lam = np.linalg.eigvalsh(stress)
print('%d points, %d tetrahedra; eigenvalues in [%.4g, %.4g] Pa, surface r = %.5f m'
      % (len(points), len(tets), lam.min(), lam.max(), r.max()))
uc.common.write_xml(ug, os.path.join(args.outdir, 'torsion_shaft.vtu'))
