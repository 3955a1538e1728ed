"""simply_supported_beam.vtu: a simply supported beam under a uniform load,
Euler-Bernoulli stress on a structured mesh of hexahedra, as a user's
hand-made beam model would give it: metre coordinates, stress in MPa.

Beam 2 m long (x in [0, 2]), 0.1 m wide (y in [0, 0.1]) and 0.2 m high
(z in [0, 0.2]; the neutral axis is z = 0.1), supported at x = 0 and x = 2,
uniform downward load q = 20 kN/m. 200 x 10 x 20 = 40,000 hexahedra
(`--cells small`: 80 x 4 x 8). With e = z - 0.1 (up from the neutral axis),
I = b h^3 / 12, M(x) = q x (L - x) / 2 (sagging positive), V(x) = dM/dx:
    sigma_xx = -M(x) e / I
    tau_xz   = -V(x) Q(e) / (I b),  Q(e) = b (h^2/4 - e^2) / 2
(the signs for z pointing up: they satisfy d sigma_xx/dx + d tau_xz/dz = 0).
q = 8 sigma_max I / (c L^2) with c = h/2 makes the peak |sigma_xx| exactly
15 MPa, at mid-span on the bottom (tension) and top (compression) faces;
|tau_xz| peaks at 1.5 V / A = 1.5 MPa at the supports on the neutral axis.
The other components are 0 (Euler-Bernoulli neglects sigma_zz ~ q/b =
0.2 MPa). POINT data "stress", 9 components row-major, active tensors.

A correct picture shows: TENSION (sigma_xx > 0) in the bottom half and
COMPRESSION in the top half, both largest at mid-span (x = 1) on the outer
faces and fading to zero at the supports and at the neutral axis; major
trajectories along x in the bottom half, in the top half along x for the
minor (compressive) stress; near the supports the principal directions
tilt towards +-45 degrees (shear). The beam is 10 times longer than high:
a long thin box.
"""
import os

import numpy as np
import vtk

import untuned_common as uc

args = uc.parse_args(__doc__)
L, B, H, SIGMA_MAX = 2.0, 0.1, 0.2, 15.0          # m, m, m, MPa
NX, NY, NZ = {'full': (200, 10, 20), 'small': (80, 4, 8)}[args.cells]
I = B * H ** 3 / 12
C = H / 2
Q_LOAD = 8 * SIGMA_MAX * I / (C * L ** 2)       # MN/m, so the stress is in MPa

x, y, z = np.linspace(0, L, NX + 1), np.linspace(0, B, NY + 1), np.linspace(0, H, NZ + 1)
# Points in x-fastest order; hexahedron (i, j, k) in VTK's node order.
Z, Y, X = np.meshgrid(z, y, x, indexing='ij')
points = np.stack([X.ravel(), Y.ravel(), Z.ravel()], axis=1)
idx = np.arange(len(points)).reshape(NZ + 1, NY + 1, NX + 1)
c = idx[:-1, :-1, :-1]
hexes = np.stack([c, c + 1, c + 1 + (NX + 1), c + (NX + 1)], axis=-1).reshape(-1, 4)
hexes = np.hstack([hexes, hexes + (NX + 1) * (NY + 1)])

px, pz = points[:, 0], points[:, 2]
e = pz - C
M = Q_LOAD * px * (L - px) / 2
V = Q_LOAD * (L / 2 - px)
stress = np.zeros((len(points), 3, 3))
stress[:, 0, 0] = -M * e / I
stress[:, 0, 2] = stress[:, 2, 0] = -V * (B * (C * C - e * e) / 2) / (I * B)

ug = uc.tensor_grid(points, (vtk.VTK_HEXAHEDRON, hexes), stress)
print('q = %.4g kN/m; sigma_xx in [%.4g, %.4g] MPa, tau_xz in [%.4g, %.4g] MPa; %d hexahedra'
      % (Q_LOAD * 1e3, stress[:, 0, 0].min(), stress[:, 0, 0].max(),
         stress[:, 0, 2].min(), stress[:, 0, 2].max(), len(hexes)))
mid_bottom = np.argmin(np.hypot(px - L / 2, pz))
print('at mid-span, bottom face: sigma_xx = %.4g MPa (tension)' % stress[mid_bottom, 0, 0])
uc.common.write_xml(ug, os.path.join(args.outdir, 'simply_supported_beam.vtu'))
