"""kirsch_plate_blocks.vtm + its block files kirsch_plate_blocks/*.vtu: a VTK
XML multiblock data set written by vtkXMLMultiBlockDataWriter, two blocks
named "left" and "right": the halves x <= 0 and x >= 0 of a plate
[-10, 10] x [-5, 5] x [0, 1] with a through hole of radius 1 at the origin,
each its own unstructured grid of hexahedra (816 gmsh quadrangles in
all, extruded in 2 layers through the thickness; the halves share the
nodes of the line x = 0, duplicated in each block).

Load: uniaxial tension sigma = 10 (MPa) along x. Kirsch's solution for an
infinite plate (plane stress, sigma_zz = 0) is the POINT data; NO array is
marked active, so a reader must pick "stress" by name:
  "stress"        9 components, row-major XX XY XZ YX YY YZ ZX ZY ZZ
  "strain"        6 components, VTK order XX YY ZZ XY YZ XZ (tensor strain,
                  Hooke's law with E = 200e3 MPa, nu = 0.3)
  "displacement"  3 components (mm): the exact in-plane Kirsch displacement
                  plus the plane-stress thickness change u_z = -nu/E
                  (s_xx + s_yy) z.
(The formula is for an infinite plate, so on this finite plate's edges it is
only nearly the applied load: sigma_xx = 9.75 to 9.95 on x = +-10, and up
to 0.58 of sigma_yy and 0.22 of shear remain on the free edges y = +-5.)

Expected picture: sigma_xx ~ 10 far from the hole, trajectories of the
major stress running along x and bending round the hole; the stress
concentration 3 sigma = 30 at the top and bottom of the hole (0, +-1),
compression -sigma = -10 (hoop) at its left and right (+-1, 0). The two
blocks meet without a seam at x = 0.
"""
import os

import numpy as np
import vtk

import formats_common as fc
from formats_common import common

points2d, halves = fc.plate_mesh_2d()
n2 = len(points2d)
mb = vtk.vtkMultiBlockDataSet()
mb.SetNumberOfBlocks(2)
for k, (name, quads) in enumerate(zip(('left', 'right'), halves)):
    used = np.unique(quads)
    renumber = np.full(n2, -1)
    renumber[used] = np.arange(len(used))
    pts, hexes = fc.extrude(points2d[used], renumber[quads], layers=2)
    ug = fc.plate_grid(pts, hexes)
    stress = fc.kirsch_stress(pts)
    pd = ug.GetPointData()
    pd.AddArray(common.vtk_array(stress.reshape(-1, 9), 'stress'))
    pd.AddArray(common.vtk_array(fc.vtk6(fc.strain_from_stress(stress, fc.PLATE_E, fc.PLATE_NU)),
                                 'strain'))
    pd.AddArray(common.vtk_array(fc.kirsch_displacement(pts), 'displacement'))
    mb.SetBlock(k, ug)
    mb.GetMetaData(k).Set(vtk.vtkCompositeDataSet.NAME(), name)
    print(name, ug.GetNumberOfCells(), 'hexahedra', ug.GetNumberOfPoints(), 'points',
          'x in [%g, %g]' % ug.GetBounds()[:2])

path = fc.out_path('kirsch_plate_blocks.vtm')
common.write_xml(mb, path)
fc.report(path)
for root, _, files in os.walk(os.path.join(fc.out_dir(), 'kirsch_plate_blocks')):
    for f in sorted(files):
        fc.report(os.path.join(root, f))

r = vtk.vtkXMLMultiBlockDataReader()
r.SetFileName(path)
r.Update()
out = r.GetOutput()
assert out.GetNumberOfBlocks() == 2
for k in range(2):
    b = out.GetBlock(k)
    assert b.GetPointData().GetTensors() is None
    print('read back block', out.GetMetaData(k).Get(vtk.vtkCompositeDataSet.NAME()),
          b.GetNumberOfCells(), 'cells; stress range',
          b.GetPointData().GetArray('stress').GetRange(0),
          b.GetPointData().GetArray('stress').GetRange(4))
