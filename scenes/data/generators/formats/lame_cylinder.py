"""lame_cylinder.pvtu + lame_cylinder_0.vtu, lame_cylinder_1.vtu: ParaView's
parallel (partitioned) unstructured-grid layout. A thick-walled tube, inner
radius 1, outer radius 2, length 2 along z (0 <= z <= 2), meshed by gmsh
into linear tetrahedra (about 4,600), split into two pieces by the sign of
the x of each cell's centroid: piece 0 holds the cells with x < 0, piece 1
those with x >= 0. As a real parallel writer does, every piece carries its
own copy of the points it uses, so the points on the interface x ~ 0 are
duplicated (once in each piece).

Point data (both pieces):
  "stress"        6 components, VTK order XX YY ZZ XY YZ XZ, ACTIVE TENSORS:
                  Lame's solution for an internal pressure p = 100 MPa (plane
                  strain, nu = 0.3): sigma_rr = A - B/r^2, sigma_tt = A + B/r^2,
                  sigma_zz = 2 nu A, A = 100/3, B = 400/3, rotated into x, y.
  "displacement"  3 components (mm for E = 200e3 MPa): the radial u_r.

The pieces are written by vtkXMLUnstructuredGridWriter (appended, raw,
zlib), the summary .pvtu by vtkXMLPUnstructuredGridWriter (its
PPointData/PPoints and <Piece Source="lame_cylinder_0.vtu"/> lines).

Expected picture: hoop tension everywhere, largest at the inner wall
(sigma_tt = 166.7 at r = 1, 66.7 at r = 2) with radial compression (-100 at
r = 1, 0 at r = 2) and a constant axial 20: major eigenvector
circumferential (trajectories are circles round the axis), minor eigenvector
radial. The two pieces join seamlessly at x = 0.
"""
import os

import numpy as np
import vtk

import formats_common as fc
from formats_common import common

points, tets = fc.tube_mesh(h=0.28)
stress = fc.vtk6(fc.lame_stress(points))
disp = fc.lame_displacement(points)

centroid_x = points[tets].mean(axis=1)[:, 0]
folder = fc.out_dir()


def piece(mask):
    """The cells `mask` with their own points, renumbered in the order of
    the whole mesh's point ids."""
    cells = tets[mask]
    used = np.unique(cells)
    renumber = np.full(len(points), -1)
    renumber[used] = np.arange(len(used))
    ug = common.unstructured_grid(points[used], [(vtk.VTK_TETRA, renumber[cells])])
    common.check_positive_volumes(ug)
    ug.GetPointData().SetTensors(common.vtk_array(stress[used], 'stress'))
    ug.GetPointData().AddArray(common.vtk_array(disp[used], 'displacement'))
    return ug


pieces = [piece(centroid_x < 0), piece(centroid_x >= 0)]
shared = sum(p.GetNumberOfPoints() for p in pieces) - len(np.unique(tets))
print('tetrahedra', len(tets), 'per piece', [p.GetNumberOfCells() for p in pieces],
      'points', [p.GetNumberOfPoints() for p in pieces], 'duplicated', shared)

# The summary file: vtkXMLPUnstructuredGridWriter writes the .pvtu (and,
# because it has no partitioning source upstream, two copies of its input as
# the pieces, which are replaced right below by the real halves).
w = vtk.vtkXMLPUnstructuredGridWriter()
w.SetFileName(os.path.join(folder, 'lame_cylinder.pvtu'))
w.SetInputData(pieces[0])
w.SetNumberOfPieces(2)
w.SetStartPiece(0)
w.SetEndPiece(1)
w.SetDataModeToAppended()
w.EncodeAppendedDataOff()
w.SetCompressorTypeToZLib()
w.SetHeaderTypeToUInt64()
if not w.Write():
    raise RuntimeError('cannot write lame_cylinder.pvtu')
fc.report(os.path.join(folder, 'lame_cylinder.pvtu'))
for k, ug in enumerate(pieces):
    common.write_xml(ug, os.path.join(folder, 'lame_cylinder_%d.vtu' % k))

# Read the whole thing back through VTK's parallel reader.
r = vtk.vtkXMLPUnstructuredGridReader()
r.SetFileName(os.path.join(folder, 'lame_cylinder.pvtu'))
r.Update()
out = r.GetOutput()
assert out.GetNumberOfCells() == len(tets), out.GetNumberOfCells()
assert out.GetNumberOfPoints() == sum(p.GetNumberOfPoints() for p in pieces)
rng = out.GetPointData().GetTensors().GetRange(-1)
print('read back: %d cells, %d points, tensors %s, |stress| up to %.1f'
      % (out.GetNumberOfCells(), out.GetNumberOfPoints(),
         out.GetPointData().GetTensors().GetName(), rng[1]))
