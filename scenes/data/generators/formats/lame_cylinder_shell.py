"""lame_cylinder_shell.vtp: a curved shell result: the outer skin of the
thick-walled tube of lame_cylinder (inner radius 1, outer 2, length 2 along
z; gmsh), its triangles only, written by vtkXMLPolyDataWriter (appended,
raw, zlib), as a shell solver or a surface export leaves a result: 2-D
cells on curved surfaces, no volume.

Point data "stress", 6 components in VTK's order, NOT active: Lame's
solution for internal pressure 100 (MPa), plane strain: sigma_rr = -100 at
r = 1 and 0 at r = 2, hoop stress 166.7 at r = 1 and 66.7 at r = 2.

Expected picture: the surfaces are curved (in no axis plane), so nothing
to trace in: a glyph at each point (with a warning saying so), on the
translucent shell: large hoop glyphs (tension) round the inner wall,
smaller ones on the outer wall.
"""
import vtk
from vtk.util.numpy_support import vtk_to_numpy

import formats_common as fc
from formats_common import common

points, tets = fc.tube_mesh()
body = common.unstructured_grid(points, [(vtk.VTK_TETRA, tets)])
skin = vtk.vtkDataSetSurfaceFilter()
skin.SetInputData(body)
skin.Update()
shell = skin.GetOutput()
shell.GetPointData().Initialize()
shell.GetCellData().Initialize()
shell_points = vtk_to_numpy(shell.GetPoints().GetData())
shell.GetPointData().AddArray(common.vtk_array(fc.vtk6(fc.lame_stress(shell_points)), 'stress'))
path = fc.out_path('lame_cylinder_shell.vtp')
common.write_xml(shell, path)
print('%d triangles, %d points' % (shell.GetNumberOfCells(), shell.GetNumberOfPoints()))
