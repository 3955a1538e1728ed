"""zero_stress_regions.vti: a 33^3 grid on the unit cube (spacing 1/32) where
the tensor is non-zero only inside a ball of radius R = 0.3628 around
(0.5, 0.5, 0.5) (20% of the volume) and EXACTLY zero everywhere else
(about 80% of the points). Inside the ball (p = x - centre, r = |p|):

    sigma = 1e3 * (1 - r^2/R^2)^2 * (0.5 I - 2 p p^T / R^2 + 0.8 (e_x e_y^T + e_y e_x^T))

so it fades smoothly (C1) to zero at the sphere: values near the sphere are
tiny but non-zero, values outside are exactly 0.0. Magnitude ~1e3.
6 components in VTK order XX, YY, ZZ, XY, YZ, XZ, point data, array
"stress", active tensors."""
import numpy as np
import vtk

import common

N = 33
R = (0.2 * 3 / (4 * np.pi)) ** (1 / 3)
axis = np.linspace(0.0, 1.0, N)
z, y, x = np.meshgrid(axis, axis, axis, indexing='ij')   # x varies fastest
p = np.stack([x, y, z], axis=-1).reshape(-1, 3) - 0.5
r2 = (p ** 2).sum(axis=1)
inside = r2 < R * R
taper = np.where(inside, (1 - r2 / (R * R)) ** 2, 0.0)

full = np.zeros((len(p), 3, 3))
full += 0.5 * np.eye(3)
full -= 2 * p[:, :, None] * p[:, None, :] / (R * R)
full[:, 0, 1] += 0.8
full[:, 1, 0] += 0.8
full *= 1e3 * taper[:, None, None]
full[~inside] = 0.0   # exactly zero, not -0.0 or round-off
sym = common.full_to_vtk_sym(full.reshape(-1, 9))

image = vtk.vtkImageData()
image.SetDimensions(N, N, N)
image.SetSpacing(1.0 / (N - 1), 1.0 / (N - 1), 1.0 / (N - 1))
image.SetOrigin(0.0, 0.0, 0.0)
image.GetPointData().SetTensors(common.vtk_array(sym, 'stress'))
common.write_xml(image, common.out_path('zero_stress_regions.vti'))
print('points with non-zero tensor: %d of %d (%.1f%%)'
      % (inside.sum(), len(p), 100.0 * inside.mean()))
