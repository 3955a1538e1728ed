"""kirsch_plate_series.pvd + kirsch_plate_series_0.vtu, _1.vtu, _2.vtu: a
ParaView data collection (.pvd, written by hand exactly as ParaView's
vtkPVDWriter does) of three time steps, times 0.5, 1.0 and 2.0, each step
one VTK XML unstructured grid (vtkXMLUnstructuredGridWriter; appended, raw,
zlib) of the same mesh: the plate [-10, 10] x [-5, 5] x [0, 1] with a hole
of radius 1 at the origin, 1,632 hexahedra (gmsh quadrangles extruded in 2
layers), as in kirsch_plate_blocks.vtm but in one piece.

Step k carries Kirsch's solution (infinite plate, plane stress) for the
uniaxial tension sigma = 10 * t along x, i.e. load factors 0.5, 1 and 2
(sigma = 5, 10, 20 MPa), as POINT data:
  "stress"        6 components, VTK order XX YY ZZ XY YZ XZ, ACTIVE TENSORS
  "displacement"  3 components (mm, E = 200e3 MPa, nu = 0.3).

Expected picture (every step the same up to scale): trajectories along x
bending round the hole, the concentration 3 sigma at the top and bottom of
the hole (15, 30, 60) and -sigma at its left and right (-5, -10, -20).
"""
import os

import formats_common as fc
from formats_common import common

points2d, halves = fc.plate_mesh_2d()
import numpy as np  # noqa: E402
pts, hexes = fc.extrude(points2d, np.concatenate(halves), layers=2)
folder = fc.out_dir()
times = [0.5, 1.0, 2.0]
entries = []
for k, t in enumerate(times):
    ug = fc.plate_grid(pts, hexes)
    S = fc.KIRSCH_S * t
    ug.GetPointData().SetTensors(common.vtk_array(fc.vtk6(fc.kirsch_stress(pts, S=S)), 'stress'))
    ug.GetPointData().AddArray(common.vtk_array(fc.kirsch_displacement(pts, S=S), 'displacement'))
    name = 'kirsch_plate_series_%d.vtu' % k
    common.write_xml(ug, os.path.join(folder, name))
    entries.append('    <DataSet timestep="%s" group="" part="0" file="%s"/>\n' % (repr(t), name))

path = os.path.join(folder, 'kirsch_plate_series.pvd')
with open(path, 'w', newline='\n') as f:
    f.write('<?xml version="1.0"?>\n'
            '<VTKFile type="Collection" version="0.1" byte_order="LittleEndian" '
            'header_type="UInt64" compressor="vtkZLibDataCompressor">\n'
            '  <Collection>\n' + ''.join(entries) + '  </Collection>\n</VTKFile>\n')
fc.report(path)

import vtk  # noqa: E402
for k, t in enumerate(times):
    r = vtk.vtkXMLUnstructuredGridReader()
    r.SetFileName(os.path.join(folder, 'kirsch_plate_series_%d.vtu' % k))
    r.Update()
    print('t = %g: %d cells, stress XX in %s' % (
        t, r.GetOutput().GetNumberOfCells(), r.GetOutput().GetPointData().GetTensors().GetRange(0)))
