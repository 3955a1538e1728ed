"""Helpers shared by the data-set generators in this folder.

Run the generators with Debian's interpreter, /usr/bin/python3 (it has
python3-vtk9, python3-numpy, python3-scipy and python3-sfepy); see
scripts/generate-data.sh.
"""
import os
import sys
import tempfile

import numpy as np
import vtk
from vtk.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray

HERE = os.path.dirname(os.path.abspath(__file__))


def out_path(name):
    """Path of generated file `name`: in the folder given as argv[1], else
    in ../generated next to this folder."""
    folder = sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, '..', 'generated')
    os.makedirs(folder, exist_ok=True)
    return os.path.join(folder, name)


def vtk_array(values, name, dtype=np.float64):
    """A named VTK array (deep copy) from a (n,) or (n, k) numpy array."""
    a = np.ascontiguousarray(values, dtype=dtype)
    arr = numpy_to_vtk(a, deep=1)
    arr.SetName(name)
    return arr


# SfePy stores symmetric 3D tensors as [11, 22, 33, 12, 13, 23];
# VTK's 6-component order is [XX, YY, ZZ, XY, YZ, XZ].
SFEPY_TO_FULL = np.array([[0, 3, 4], [3, 1, 5], [4, 5, 2]])


def sfepy_sym_to_full(sym):
    """(n, 6) SfePy symmetric storage -> (n, 9) row-major full tensors."""
    sym = np.asarray(sym).reshape(-1, 6)
    return sym[:, SFEPY_TO_FULL.ravel()]


def full_to_vtk_sym(full):
    """(n, 9) full tensors -> (n, 6) in VTK's order XX, YY, ZZ, XY, YZ, XZ."""
    full = np.asarray(full).reshape(-1, 9)
    return full[:, [0, 4, 8, 1, 5, 2]]


def unstructured_grid(points, cells):
    """vtkUnstructuredGrid from points (n, 3) and a list of
    (vtk_cell_type, conn (m, k)) blocks, kept in the given order."""
    ug = vtk.vtkUnstructuredGrid()
    pts = vtk.vtkPoints()
    pts.SetDataTypeToDouble()
    pts.SetData(vtk_array(points, 'Points'))
    ug.SetPoints(pts)
    types, offsets, conn = [], [0], []
    for cell_type, c in cells:
        c = np.asarray(c, dtype=np.int64)
        for row in c:
            types.append(cell_type)
            conn.extend(row)
            offsets.append(offsets[-1] + len(row))
    ca = vtk.vtkCellArray()
    ca.SetData(numpy_to_vtkIdTypeArray(np.array(offsets, dtype=np.int64), deep=1),
               numpy_to_vtkIdTypeArray(np.array(conn, dtype=np.int64), deep=1))
    ug.SetCells(numpy_to_vtk(np.array(types, dtype=np.uint8), deep=1,
                             array_type=vtk.VTK_UNSIGNED_CHAR), ca)
    return ug


def cell_to_point(ds, name):
    """Average the cell array `name` onto the points: each point gets the
    plain mean of the cells that use it (what vtkCellDataToPointData does,
    but in a fixed summation order; VTK's threaded filter can differ in the
    last bit from run to run). Returns a numpy array."""
    from vtk.util.numpy_support import vtk_to_numpy
    values = vtk_to_numpy(ds.GetCellData().GetArray(name))
    values = values.reshape(ds.GetNumberOfCells(), -1)
    cells = ds.GetCells()
    offsets = vtk_to_numpy(cells.GetOffsetsArray())
    conn = vtk_to_numpy(cells.GetConnectivityArray())
    owner = np.repeat(np.arange(len(offsets) - 1), np.diff(offsets))
    total = np.zeros((ds.GetNumberOfPoints(), values.shape[1]))
    np.add.at(total, conn, values[owner])
    count = np.bincount(conn, minlength=ds.GetNumberOfPoints())
    return total / np.maximum(count, 1)[:, None]


def check_positive_volumes(ds):
    """Fail if any 3D cell has a non-positive volume (wrong node order)."""
    f = vtk.vtkCellSizeFilter()
    f.SetInputData(ds)
    f.ComputeVertexCountOff()
    f.ComputeLengthOff()
    f.ComputeAreaOff()
    f.ComputeVolumeOn()
    f.Update()
    from vtk.util.numpy_support import vtk_to_numpy
    v = vtk_to_numpy(f.GetOutput().GetCellData().GetArray('Volume'))
    if v.min() <= 0:
        raise RuntimeError('cells with non-positive volume: %d (min %g)'
                           % ((v <= 0).sum(), v.min()))
    return v


def write_xml(ds, path):
    """Write a VTK XML file (appended, raw binary, zlib) and re-read it."""
    if isinstance(ds, vtk.vtkImageData):
        w = vtk.vtkXMLImageDataWriter()
    elif isinstance(ds, vtk.vtkMultiBlockDataSet):
        w = vtk.vtkXMLMultiBlockDataWriter()  # the blocks in a folder beside it
    elif isinstance(ds, vtk.vtkPolyData):
        w = vtk.vtkXMLPolyDataWriter()
    else:
        w = vtk.vtkXMLUnstructuredGridWriter()
    w.SetFileName(path)
    w.SetInputData(ds)
    w.SetDataModeToAppended()
    w.EncodeAppendedDataOff()
    w.SetCompressorTypeToZLib()
    w.SetHeaderTypeToUInt64()
    if not w.Write():
        raise RuntimeError('cannot write ' + path)
    print('wrote', path, os.path.getsize(path), 'bytes')


def solve_sfepy(conf_name, **define_args):
    """Solve the SfePy problem description `conf_name` (a file in this
    folder) without writing SfePy's own output; returns the Problem."""
    from sfepy.base.base import output
    from sfepy.base.conf import ProblemConf, get_standard_keywords
    from sfepy.applications import solve_pde
    output.set_output(quiet=True)
    required, other = get_standard_keywords()
    conf = ProblemConf.from_file(os.path.join(HERE, conf_name), required, other,
                                 define_args=define_args or None)
    with tempfile.TemporaryDirectory() as tmp:
        pb, state = solve_pde(conf, save_results=False, output_dir=tmp)
    return pb


def sfepy_stress_grid(pb):
    """The solved SfePy problem as a VTK unstructured grid: the
    element-averaged Cauchy stress averaged onto the points (9 components,
    array "stress", active tensors) and the vertex displacement (active
    vectors). Returns (grid, cell stress (n, 9), point stress (n, 9))."""
    stress = pb.evaluate('ev_cauchy_stress.i.Omega(solid.D, u)', mode='el_avg')
    full = sfepy_sym_to_full(stress.reshape(-1, 6))
    mesh = pb.domain.mesh
    u = pb.get_variables()['u'].get_state_in_region(pb.domain.regions['Omega'])
    u = u[:mesh.n_nod]  # a P2/Q2 field: the first n_nod DOFs are the mesh vertices
    ug = unstructured_grid(mesh.coors, [sfepy_cells(pb)])
    check_positive_volumes(ug)
    ug.GetCellData().AddArray(vtk_array(full, 'stress'))
    point_stress = cell_to_point(ug, 'stress')
    ug.GetCellData().RemoveArray('stress')
    ug.GetPointData().SetTensors(vtk_array(point_stress, 'stress'))
    ug.GetPointData().SetVectors(vtk_array(u, 'displacement'))
    return ug, full, point_stress


def sfepy_cells(pb):
    """(vtk_cell_type, conn) of the SfePy problem's (single-type) mesh."""
    mesh = pb.domain.mesh
    desc = mesh.descs[0]
    vtk_type = {'3_4': vtk.VTK_TETRA, '3_8': vtk.VTK_HEXAHEDRON}[desc]
    return vtk_type, mesh.get_conn(desc)
