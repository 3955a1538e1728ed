"""plane_stress_quads.vtu: a genuinely 2-D data set: the Kirsch plate
[-10, 10] x [-5, 5] with a hole of radius 1 at the origin as 816 gmsh
QUADRILATERALS (VTK_QUAD) lying in the plane z = 0 (no thickness), written
by vtkXMLUnstructuredGridWriter (appended, raw, zlib).

Point data "stress", 3 components (xx, yy, xy): the in-plane (plane stress)
Kirsch solution for uniaxial tension 10 (MPa) along x, the way 2-D solvers
write a 2-D symmetric tensor (Voigt-like, no zz, no shear out of plane).
Not marked active (VTK's attributes accept only 6- or 9-component tensors).

Expected picture (if a reader accepts 2-D cells and 3-component tensors):
the top view of kirsch_plate_series_1.vtu: sigma_xx ~ 10 far from the hole,
30 at the top and bottom of the hole, -10 at its sides; trajectories along
x bending round the hole, all in the plane z = 0.
"""
import numpy as np
import vtk

import formats_common as fc
from formats_common import common

points, halves = fc.plate_mesh_2d()
quads = np.concatenate(halves)
ug = common.unstructured_grid(points, [(vtk.VTK_QUAD, quads)])
t = fc.kirsch_stress(points)
ug.GetPointData().AddArray(common.vtk_array(np.stack([t[:, 0, 0], t[:, 1, 1], t[:, 0, 1]], axis=1),
                                            'stress'))
ug.GetPointData().GetArray('stress').SetComponentName(0, 'xx')
ug.GetPointData().GetArray('stress').SetComponentName(1, 'yy')
ug.GetPointData().GetArray('stress').SetComponentName(2, 'xy')
path = fc.out_path('plane_stress_quads.vtu')
common.write_xml(ug, path)

r = vtk.vtkXMLUnstructuredGridReader()
r.SetFileName(path)
r.Update()
out = r.GetOutput()
print('read back: %d cells (%s), %d points, z in [%g, %g], stress xx in %s'
      % (out.GetNumberOfCells(), out.GetCellType(0), out.GetNumberOfPoints(),
         *out.GetBounds()[4:], out.GetPointData().GetArray('stress').GetRange(0)))
