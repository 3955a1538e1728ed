"""plate_hole_large.vtu: a big, plain plate-with-a-hole result in SI units,
as a new user would bring it: about 1.2 million linear tetrahedra (gmsh),
nobody tuned a scene for it. `--cells small` makes ~50k for a quick run.

Plate 0.2 m x 0.1 m x 0.005 m (x in [-0.1, 0.1], y in [-0.05, 0.05],
z in [0, 0.005]), a through hole of radius 0.01 m at the origin, remote
uniaxial tension 5e7 Pa (50 MPa) along x. Stress: Kirsch's analytic
plane-stress solution (kirsch.py) evaluated at the mesh points, so
sigma_zz = sigma_xz = sigma_yz = 0. POINT data "stress", 9 components
row-major, float64, active tensors; metres and pascals.

A correct picture shows: glyphs/trajectories of the major stress running
along x and bending round the hole; the stress concentrated at the top and
bottom of the hole, (0, +-0.01): sigma_xx = 3 x 5e7 = 1.5e8 Pa, tension
(the hottest colour); at the hole's left and right, (+-0.01, 0), the hoop
stress is compressive, sigma_yy = -5e7 Pa (there sigma_xx = 0 on the edge,
the "-1 x 5e7" of the hoop stress runs along y); about 5e7 Pa tension
everywhere a few radii away. The plate is 40 times wider than thick: a
thin slab, seen best from +z.
"""
import os
import time

import kirsch
import untuned_common as uc

args = uc.parse_args(__doc__)
LENGTH, WIDTH, THICK, RADIUS, S = 0.2, 0.1, 0.005, 0.01, 5e7
# Mesh sizes at the hole and far from it (m); calibrated with gmsh 4.8 to
# ~1.2M (full) and ~50k (small) tetrahedra.
H_HOLE, H_FAR = {'full': (0.00029, 0.00097), 'small': (0.0008, 0.003)}[args.cells]

t0 = time.time()
points, tets = kirsch.plate_tets(LENGTH, WIDTH, THICK, RADIUS, H_HOLE, H_FAR)
print('gmsh: %d points, %d tetrahedra in %.0f s' % (len(points), len(tets), time.time() - t0))
ug = kirsch.plate_grid(points, tets, S, RADIUS)
kirsch.check_hole(ug, S, RADIUS)
uc.common.write_xml(ug, os.path.join(args.outdir, 'plate_hole_large.vtu'))
