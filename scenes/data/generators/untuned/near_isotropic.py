"""near_isotropic.vti: a stress field that is ISOTROPIC almost everywhere,
as in a body under uniform pressure with one small disturbed spot: image
data, 40^3 points over the unit cube (origin 0, spacing 1/39 m), Pa.

sigma = -1e5 I (hydrostatic compression everywhere)
        + 2e4 g(p) (e_x e_y^T + e_y e_x^T),   g = exp(-|p - c|^2 / R^2),
with the bump's centre c = (0.65, 0.4, 0.55) (off the cube's centre and off
the grid's symmetry planes) and R = 0.15 m. The added part is a pure shear
(traceless), peak 2e4 Pa at c. Eigenvalues: -1e5 (triple) far from c; at c
-8e4 along (1, 1, 0)/sqrt2, -1e5 along z, -1.2e5 along (1, -1, 0)/sqrt2.
Every eigenvalue is negative everywhere: compression only. Beyond
2.3 R = 0.35 m from c the anisotropy is below 1e-3 of the pressure
(nearly repeated eigenvalues: no principal direction is really defined
there). Grid size 40 x 40 x 40 whatever --cells says. POINT data
"stress", 9 components row-major, active tensors.

A correct picture shows: the bump, a ball of radius ~0.2-0.3 m round
(0.65, 0.4, 0.55), as the only place with anisotropic glyphs or
trajectories: major (least compressive) direction along x + y, minor along
x - y, at 45 degrees in the x-y plane; everywhere else round (isotropic)
glyphs or nothing, all one colour (compression, -1e5). No direction should
be invented in the isotropic part.
"""
import os

import numpy as np
import vtk

import untuned_common as uc

args = uc.parse_args(__doc__)
N, P, TAU, R = 40, -1e5, 2e4, 0.15
CENTRE = np.array([0.65, 0.4, 0.55])

img = vtk.vtkImageData()
img.SetDimensions(N, N, N)
img.SetOrigin(0.0, 0.0, 0.0)
img.SetSpacing(1.0 / (N - 1), 1.0 / (N - 1), 1.0 / (N - 1))
# VTK's point order: x fastest.
g1 = np.linspace(0.0, 1.0, N)
Z, Y, X = np.meshgrid(g1, g1, g1, indexing='ij')
p = np.stack([X.ravel(), Y.ravel(), Z.ravel()], axis=1)
g = np.exp(-np.sum((p - CENTRE) ** 2, axis=1) / R ** 2)
stress = np.zeros((len(p), 3, 3))
stress[:] = P * np.eye(3)
stress[:, 0, 1] = stress[:, 1, 0] = TAU * g
img.GetPointData().SetTensors(uc.common.vtk_array(stress.reshape(-1, 9), 'stress'))

lam = np.linalg.eigvalsh(stress)
print('eigenvalues in [%.6g, %.6g] Pa; anisotropic (|deviator| > 1e-3 |p|) at %d of %d points'
      % (lam.min(), lam.max(), np.sum(TAU * g > 1e-3 * abs(P)), len(p)))
uc.common.write_xml(img, os.path.join(args.outdir, 'near_isotropic.vti'))
