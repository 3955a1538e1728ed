"""sierra_style.exo: Exodus II (netCDF "64-bit offset" classic file) written
by VTK's vtkExodusIIWriter, with the variable naming of Sandia's Sierra
codes: the stress as six separate ELEMENT variables

    stress_xx, stress_yy, stress_zz, stress_xy, stress_yz, stress_zx

(in that order; one scalar each per element, time step 1, time 0) plus a
NODAL variable "von_mises". The mesh is the Lame tube of
lame_cylinder.pvtu in one piece: inner radius 1, outer 2, length 2 along
z, 4,558 linear tetrahedra (one element block, "TETRA", id 10), 1,224
nodes. Units: MPa.

The element values are Lame's solution (internal pressure 100 MPa, plane
strain, nu = 0.3) evaluated at each tetrahedron's centroid; von_mises is the
von Mises stress of the exact solution at the nodes (sqrt(3 J2): 232 at
r = 1 falling to 59 at r = 2). vtkExodusIIWriter stamps the file's title
with the date; the script replaces it by a fixed title (netCDF4, in place)
so the output is the same from run to run.

Expected picture (if the reader glues the six element variables into a
symmetric tensor "stress"): cell-wise constant tensors of the Lame tube:
hoop tension largest at the inner wall (166.7), radial compression (-100 at
r = 1), axial 20: circumferential major-eigenvector trajectories.
"""
import subprocess

import netCDF4
import numpy as np
import vtk

import formats_common as fc
from formats_common import common

NAMES = ['stress_xx', 'stress_yy', 'stress_zz', 'stress_xy', 'stress_yz', 'stress_zx']
INDEX = [(0, 0), (1, 1), (2, 2), (0, 1), (1, 2), (2, 0)]
TITLE = 'Created by vtkExodusIIWriter: Lame tube, internal pressure 100 MPa'

points, tets = fc.tube_mesh(h=0.28)
ug = common.unstructured_grid(points, [(vtk.VTK_TETRA, tets)])
common.check_positive_volumes(ug)
cell_stress = fc.lame_stress(points[tets].mean(axis=1))
for name, (i, j) in zip(NAMES, INDEX):
    ug.GetCellData().AddArray(common.vtk_array(cell_stress[:, i, j], name))
ug.GetPointData().AddArray(common.vtk_array(fc.von_mises(fc.lame_stress(points)), 'von_mises'))

path = fc.out_path('sierra_style.exo')
w = vtk.vtkExodusIIWriter()
w.SetFileName(path)
w.SetInputData(ug)
w.WriteAllTimeStepsOff()
if not w.Write():
    raise RuntimeError('cannot write ' + path)
with netCDF4.Dataset(path, 'a') as nc:
    nc.title = TITLE
fc.report(path)

with netCDF4.Dataset(path) as nc:
    elem = [b''.join(r).decode() for r in nc.variables['name_elem_var'][:].filled(b'')]
    nod = [b''.join(r).decode() for r in nc.variables['name_nod_var'][:].filled(b'')]
    assert elem == NAMES, elem
    assert nod == ['von_mises'], nod
    assert nc.title == TITLE
print(subprocess.run(['ncdump', '-h', path], capture_output=True, text=True).stdout)

r = vtk.vtkExodusIIReader()
r.SetFileName(path)
r.UpdateInformation()
r.SetAllArrayStatus(vtk.vtkExodusIIReader.ELEM_BLOCK, 1)
r.SetAllArrayStatus(vtk.vtkExodusIIReader.NODAL, 1)
r.Update()
block = r.GetOutput().GetBlock(0).GetBlock(0)
cd = block.GetCellData()
print('vtkExodusIIReader: %d cells; cell arrays %s; point arrays %s' % (
    block.GetNumberOfCells(),
    ['%s(%d)' % (cd.GetArrayName(k), cd.GetArray(k).GetNumberOfComponents())
     for k in range(cd.GetNumberOfArrays())],
    [block.GetPointData().GetArrayName(k) for k in range(block.GetPointData().GetNumberOfArrays())]))
