"""Kirsch's plate with a hole, shared by plate_hole_large.py and
load_series.py: a gmsh tetrahedral mesh of a rectangular plate with a
central circular through hole, and Kirsch's analytic stress on it.

Kirsch's solution (formats_common.kirsch_stress, reused) is for an INFINITE
plate with a hole of radius a under remote uniaxial tension S along x,
plane stress: sigma_zz = sigma_xz = sigma_yz = 0. At the hole's edge the
hoop stress is S (1 - 2 cos 2 theta): 3 S at (0, +-a) and -S at (+-a, 0).
On a plate 10 holes wide (as here) the finite width would raise the peak
by ~10% in a real solve; evaluating the infinite-plate formula at the mesh
points is exact at the points, just not in equilibrium with free plate
edges (their tractions are ~1% of S).
"""
import numpy as np
import vtk

import untuned_common as uc


def plate_tets(length, width, thickness, radius, h_hole, h_far):
    """The plate [-length/2, length/2] x [-width/2, width/2] x [0, thickness]
    minus the cylinder of `radius` about the z axis, meshed into linear
    tetrahedra of size h_hole at the hole growing to h_far at 4 radii from
    it (stress gradients are steep only near the hole). Returns points,
    tets."""
    def build(gmsh):
        occ = gmsh.model.occ
        box = occ.addBox(-length / 2, -width / 2, 0, length, width, thickness)
        hole = occ.addCylinder(0, 0, 0, 0, 0, thickness, radius)
        occ.cut([(3, box)], [(3, hole)])
        occ.synchronize()
        # The hole's wall: the only surface whose centre of mass is on the
        # axis half-way through (the faces z = 0, t have theirs on the axis
        # too, but at z = 0 and t).
        wall = [tag for _, tag in gmsh.model.getEntities(2)
                if np.hypot(*occ.getCenterOfMass(2, tag)[:2]) < radius / 2
                and abs(occ.getCenterOfMass(2, tag)[2] - thickness / 2) < thickness / 4]
        assert len(wall) == 1, wall
        uc.size_field(gmsh, 2, wall, h_hole, h_far, 4 * radius)

    points, tets = uc.gmsh_tets(build)
    points[np.abs(points) < 1e-12 * length] = 0.0   # OCC leaves ~1e-17 noise
    return points, tets


def plate_grid(points, tets, S, radius):
    """vtkUnstructuredGrid of the tetrahedra with Kirsch's stress for the
    remote tension S as POINT data "stress", 9 components, active tensors."""
    stress = uc.fc.kirsch_stress(points, S=S, a=radius)
    return uc.tensor_grid(points, (vtk.VTK_TETRA, tets), stress)


def check_hole(ug, S, radius):
    """Print the stress at the mesh points nearest (0, a) and (a, 0) on the
    hole's edge (expected: sigma_xx = 3 S at the first; sigma_yy = -S, the
    compressive hoop stress, with sigma_xx = 0 at the second) and the range
    of sigma_xx, as a check of the file."""
    from vtk.util.numpy_support import vtk_to_numpy
    p = vtk_to_numpy(ug.GetPoints().GetData())
    t = vtk_to_numpy(ug.GetPointData().GetTensors())
    for name, target in (('(0, a)', (0, radius)), ('(a, 0)', (radius, 0))):
        i = np.argmin(np.hypot(p[:, 0] - target[0], p[:, 1] - target[1]))
        print('at the point nearest %s %s: sigma_xx = %.4g = %.3f S, '
              'sigma_yy = %.4g = %.3f S' % (name, np.round(p[i], 6), t[i, 0], t[i, 0] / S,
                                              t[i, 4], t[i, 4] / S))
    print('sigma_xx in [%.4g, %.4g]; %d points, %d tetrahedra'
          % (t[:, 0].min(), t[:, 0].max(), ug.GetNumberOfPoints(), ug.GetNumberOfCells()))
