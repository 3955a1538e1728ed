"""kirsch_plate.vtkhdf: a VTK HDF file (VTKHDF format version 1.0,
UnstructuredGrid, one piece), written with h5py 3.7 to the format's
specification and read back by VTK 9.1's vtkHDFReader. (VTK 9.1 has a
reader but no writer for this format.)

Mesh: the Kirsch plate as a solid, 20 x 10 x 1 (x from -10 to 10, y from
-5 to 5, z from 0 to 1) with a through hole of radius 1 on the z axis,
meshed by gmsh 4.8 (OpenCASCADE box minus cylinder, Delaunay, single
thread, fixed seed) into 5,795 linear tetrahedra (VTK_TETRA = 10), 1,712
points, 0.2 at the hole growing to 1.0 at 5 from it. Every tetrahedron has
a positive volume in VTK's node order (checked). Units: mm, MPa.

Layout (h5dump-style; every dataset contiguous, no compression; the
groups' links are in name order, as h5py makes them):
  /VTKHDF                           group
    attribute Version  int64 [2] = (1, 0)
    attribute Type     fixed-length ASCII string of 16 bytes, scalar,
                       NULLPAD = "UnstructuredGrid"
    NumberOfPoints           int64 [1]    = 1712
    NumberOfCells            int64 [1]    = 5795
    NumberOfConnectivityIds  int64 [1]    = 23180
    Points                   float64 [1712, 3]
    Types                    uint8 [5795] (all 10)
    Connectivity             int64 [23180] (point ids, 4 per cell)
    Offsets                  int64 [5796] (0, 4, ..., 23180)
    PointData/               group
      stress                 float64 [1712, 6]
    CellData/                group
      von_mises              float64 [5795]

Arrays:
  PointData "stress": 6 components in VTK's order XX YY ZZ XY YZ XZ: Kirsch's
      solution for a hole of radius 1 in an infinite plate under uniaxial
      tension S = 10 MPa along x, plane stress (ZZ = YZ = XZ = 0), evaluated
      at each point (formats_common.kirsch_stress), the same field as the
      other Kirsch files here.
  CellData "von_mises": the von Mises stress of that field at each
      tetrahedron's centroid (one value per cell).
Neither is marked as the active tensors or scalars: the format has no
such notion, and vtkHDFReader only adds the arrays by name.

Expected picture: sigma_xx about 10 far from the hole, trajectories along
x bending round the hole. The largest stress is at the top and bottom of
the hole: sigma_xx = 3 S = 30.0 at the points (0, +-1, 0) and (0, +-1, 1);
at its left and right (+-1, 0, z) sigma_yy = -S = -10. The same through the
thickness. von_mises (per cell) is largest, 27.1, in the cells touching the
top and bottom of the hole.

What VTK 9.1's reader requires (read in its source, vtkHDFReader.cxx and
vtkHDFReaderImplementation.cxx, and tried on altered copies of this file):
  * the group /VTKHDF and its attribute Version, rank 1 with 2 integers of
    any integer type (without it: "Version attribute not found", nothing
    read; a major version above 1 only draws a warning);
  * Type is not read at all: an attribute WholeExtent on /VTKHDF makes the
    file ImageData, its absence UnstructuredGrid (a copy with Type =
    "ImageData" still reads as this grid). Type is written anyway, as the
    specification asks, for later readers, which check it;
  * NumberOfPoints must be 1-D, its length being the number of pieces (a
    scalar dataset: "dataset should have 1 dimension", an empty grid);
    32-bit or unsigned counts are accepted too;
  * Types must be unsigned char ("Error: The Types array element is not
    unsigned char." for int32);
  * Offsets holds NumberOfCells + 1 entries per piece; Connectivity and
    Offsets may be int32 or int64; Points may be float32 or float64;
  * a PointData or CellData array of rank 1 is one component, of rank 2
    (tuples, components); either group may be missing.
So this file, written to the specification, needed no change for VTK 9.1.

Checks: vtkHDFReader reads the file back (counts, cell types, both arrays
equal to what was written, no error or warning); h5py checks the layout.
Determinism: h5py writes no modification times (its track_times is off
unless asked for); two runs give identical bytes.
"""

import h5py
import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

import formats_common as fc

H_HOLE, H_FAR, H_DIST = 0.2, 1.0, 5.0
N_POINTS, N_CELLS = 1712, 5795


def von_mises_of(t):
    """Von Mises stress of (n, 3, 3) tensors, element by element (numpy's
    einsum, in formats_common.von_mises, can round differently from run to
    run with the arrays' memory alignment)."""
    d = (t[:, 0, 0] - t[:, 1, 1]) ** 2 + (t[:, 1, 1] - t[:, 2, 2]) ** 2 + (t[:, 2, 2] - t[:, 0, 0]) ** 2
    return np.sqrt(0.5 * d + 3.0 * (t[:, 0, 1] ** 2 + t[:, 1, 2] ** 2 + t[:, 0, 2] ** 2))


def plate_tets():
    """The solid plate's tetrahedra, each wound as VTK winds it."""
    points, tets = fc.solid_plate_tets('kirsch_plate_tets', H_HOLE, H_FAR, H_DIST)
    p = points[tets]
    vol = np.einsum('ij,ij->i', np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), p[:, 3] - p[:, 0])
    tets[vol < 0] = tets[vol < 0][:, [0, 2, 1, 3]]
    return points, tets


points, tets = plate_tets()
print('gmsh: %d points, %d tetrahedra' % (len(points), len(tets)))
assert (len(points), len(tets)) == (N_POINTS, N_CELLS), (len(points), len(tets))
fc.common.check_positive_volumes(fc.common.unstructured_grid(points, [(vtk.VTK_TETRA, tets)]))
stress = fc.vtk6(fc.kirsch_stress(points))
von_mises = von_mises_of(fc.kirsch_stress(points[tets].mean(axis=1)))

path = fc.out_path('kirsch_plate.vtkhdf')
with h5py.File(path, 'w') as f:
    root = f.create_group('VTKHDF')
    root.attrs['Version'] = np.array([1, 0], dtype=np.int64)
    root.attrs['Type'] = np.bytes_('UnstructuredGrid')
    root['NumberOfPoints'] = np.array([len(points)], dtype=np.int64)
    root['NumberOfCells'] = np.array([len(tets)], dtype=np.int64)
    root['NumberOfConnectivityIds'] = np.array([tets.size], dtype=np.int64)
    root['Points'] = points.astype(np.float64)
    root['Types'] = np.full(len(tets), vtk.VTK_TETRA, dtype=np.uint8)
    root['Connectivity'] = tets.ravel().astype(np.int64)
    root['Offsets'] = np.arange(0, tets.size + 1, 4, dtype=np.int64)
    root.create_group('PointData')['stress'] = stress
    root.create_group('CellData')['von_mises'] = von_mises
fc.report(path)

# the layout, as h5py sees it
with h5py.File(path, 'r') as f:
    g = f['VTKHDF']
    t = g.attrs.get_id('Type')
    tt = t.get_type()
    assert t.shape == () and tt.get_size() == 16 and g.attrs['Type'] == b'UnstructuredGrid'
    assert tt.get_strpad() == h5py.h5t.STR_NULLPAD and tt.get_cset() == h5py.h5t.CSET_ASCII
    assert list(g.attrs['Version']) == [1, 0]
    print('h5: /VTKHDF attrs Version %s, Type %r;' % (list(g.attrs['Version']), g.attrs['Type']),
          ', '.join('%s %s %s' % (k, g[k].shape, g[k].dtype) for k in g if isinstance(g[k], h5py.Dataset)))

# read back with VTK 9.1's reader; fail on any error or warning it prints
messages = vtk.vtkStringOutputWindow()
vtk.vtkOutputWindow.SetInstance(messages)
reader = vtk.vtkHDFReader()
assert reader.CanReadFile(path)
reader.SetFileName(path)
reader.Update()
assert messages.GetOutput() == '', messages.GetOutput()
ug = reader.GetOutput()
assert ug.IsA('vtkUnstructuredGrid')
assert (ug.GetNumberOfPoints(), ug.GetNumberOfCells()) == (N_POINTS, N_CELLS)
assert set(vtk_to_numpy(ug.GetCellTypesArray())) == {vtk.VTK_TETRA}
assert np.array_equal(vtk_to_numpy(ug.GetPoints().GetData()), points)
cells = vtk_to_numpy(ug.GetCells().GetConnectivityArray())
assert np.array_equal(cells, tets.ravel())
s = ug.GetPointData().GetArray('stress')
c = ug.GetCellData().GetArray('von_mises')
assert np.array_equal(vtk_to_numpy(s), stress) and np.array_equal(vtk_to_numpy(c), von_mises)
assert ug.GetPointData().GetTensors() is None
top = np.argmax(stress[:, 0])
print('vtkHDFReader: %s, %d points, %d cells (all VTK_TETRA); point array %r (%d components, %s), '
      'cell array %r (%d); no active tensors'
      % (ug.GetClassName(), ug.GetNumberOfPoints(), ug.GetNumberOfCells(), s.GetName(),
         s.GetNumberOfComponents(), s.GetClassName(), c.GetName(), c.GetNumberOfComponents()))
print('stress XX up to %.2f at %s, YY down to %.2f; von_mises (cells) up to %.2f'
      % (stress[top, 0], np.round(points[top], 3), stress[:, 1].min(), von_mises.max()))
