"""aster_plane_strain.vtu: a 2-D plane-strain result as Code_Aster leaves
it once meshio has converted its MED file to VTK: the Kirsch plate
[-10, 10] x [-5, 5] with a hole of radius 1 (the gmsh mesh of
plane_stress_quads.vtu, each quadrangle split into two TRIA3), in the
plane z = 0, written by meshio (VTU, binary).

Point data as Code_Aster names its nodal fields:
  - "SIEF_NOEU", 4 components in Code_Aster's order SIXX SIYY SIZZ SIXY,
    without component names: the Kirsch solution for tension 10 (MPa)
    along x in plane strain, SIZZ = nu (SIXX + SIYY), nu = 0.3;
  - "DEPL", 2 components (DX, DY): the matching displacement.

Expected picture: the top view of plane_stress_quads.vtu (hsb sets the
out-of-plane normal to the in-plane mean, so SIZZ does not show): sigma_xx
~ 10 far from the hole, 30 at its top and bottom, -10 at its sides; the
four components read as XX YY ZZ XY (the second and third differ), with a
warning that says so.
"""
import meshio
import numpy as np

import formats_common as fc

points, halves = fc.plate_mesh_2d()
quads = np.concatenate(halves)
triangles = np.concatenate([quads[:, [0, 1, 2]], quads[:, [0, 2, 3]]])
t = fc.kirsch_stress(points)
sxx, syy, sxy = t[:, 0, 0], t[:, 1, 1], t[:, 0, 1]
szz = fc.PLATE_NU * (sxx + syy)
u = fc.kirsch_displacement(points)
mesh = meshio.Mesh(points, [('triangle', triangles)],
                   point_data={'SIEF_NOEU': np.stack([sxx, syy, szz, sxy], axis=1),
                               'DEPL': np.asarray(u)[:, :2]})
path = fc.out_path('aster_plane_strain.vtu')
mesh.write(path, binary=True)
fc.report(path)
back = meshio.read(path)
print('read back: %d triangles, SIEF_NOEU %s, SIXX in [%.3g, %.3g]'
      % (len(back.cells_dict['triangle']), back.point_data['SIEF_NOEU'].shape,
         back.point_data['SIEF_NOEU'][:, 0].min(), back.point_data['SIEF_NOEU'][:, 0].max()))
