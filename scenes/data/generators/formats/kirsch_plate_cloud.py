"""kirsch_plate_cloud.vtp: a point cloud carrying tensors, as a measurement
(digital image correlation) or a meshless solver leaves it: the nodes of
the Kirsch plate's gmsh mesh (the plate [-10, 10] x [-5, 5] with a hole of
radius 1 at the origin, all in the plane z = 0), one VTK vertex each, NO
other cells, written by vtkXMLPolyDataWriter (appended, raw, zlib).

Point data "stress", 6 components in VTK's order (XX YY ZZ XY YZ XZ),
marked active: the plane-stress Kirsch solution for uniaxial tension
10 (MPa) along x (sigma_zz = 0).

Expected picture: nothing to trace trajectories in, so a glyph at each
point (with a warning saying so), seen from above (the cloud lies in
z = 0): glyphs elongated along x far from the hole, the largest (30) at
its top and bottom (0, +-1), and the densest glyphs round the hole, where
the mesh was finest.
"""
import numpy as np
import vtk

import formats_common as fc
from formats_common import common

points, _ = fc.plate_mesh_2d()
cloud = vtk.vtkPolyData()
vtk_points = vtk.vtkPoints()
vtk_points.SetData(common.vtk_array(points, 'points'))
cloud.SetPoints(vtk_points)
vertices = vtk.vtkCellArray()
for i in range(len(points)):
    vertices.InsertNextCell(1)
    vertices.InsertCellPoint(i)
cloud.SetVerts(vertices)
stress = common.vtk_array(fc.vtk6(fc.kirsch_stress(points)), 'stress')
cloud.GetPointData().SetTensors(stress)
path = fc.out_path('kirsch_plate_cloud.vtp')
common.write_xml(cloud, path)
print('%d points, z in [%g, %g]' % (len(points), points[:, 2].min(), points[:, 2].max()))
