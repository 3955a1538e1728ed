"""Helpers shared by the "untuned" generators in this folder: the command
line (output folder, --cells) and gmsh's linear tetrahedra.

The house helpers are reused, not copied: ../common.py (VTK arrays, grids,
XML writer, SfePy) and ../formats/formats_common.py (gmsh start-up and
node renumbering, the analytic solutions). Run with Debian's
/usr/bin/python3.
"""
import argparse
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, '..', 'formats'))
sys.path.insert(0, os.path.join(HERE, '..'))
import common  # noqa: E402,F401  (re-exported for the generators)
import formats_common as fc  # noqa: E402

DEFAULT_OUT = '/tmp/hsb-untuned'


def parse_args(doc):
    """OUTDIR (default /tmp/hsb-untuned, created) and --cells full|small.
    The data are too big to commit, so they never go into the source tree
    by default."""
    p = argparse.ArgumentParser(description=doc.split('\n\n')[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument('outdir', nargs='?', default=DEFAULT_OUT)
    p.add_argument('--cells', choices=['full', 'small'], default='full',
                   help='small: a coarse mesh for a quick check')
    args = p.parse_args()
    args.outdir = os.path.abspath(args.outdir)
    os.makedirs(args.outdir, exist_ok=True)
    return args


def positive_tets(points, tets):
    """Reorder gmsh tetrahedra so that every signed volume is positive
    (VTK: (0, 1, 2) counter-clockwise seen from 3)."""
    p = points[tets]
    vol = np.einsum('ij,ij->i', np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]),
                    p[:, 3] - p[:, 0])
    tets = tets.copy()
    tets[vol < 0] = tets[vol < 0][:, [0, 2, 1, 3]]
    return tets


def gmsh_tets(build):
    """Mesh a gmsh model into linear tetrahedra. `build(gmsh)` adds the
    geometry and the size fields to an empty model (fc.gmsh_start: one
    thread, fixed random seed, so the mesh is the same every run). Returns
    points (n, 3) and positively oriented tets (m, 4)."""
    gmsh = fc.gmsh_start('untuned')
    try:
        build(gmsh)
        # Sizes come only from the fields that build() sets, not from the
        # geometry's points or curvature.
        gmsh.option.setNumber('Mesh.MeshSizeExtendFromBoundary', 0)
        gmsh.option.setNumber('Mesh.MeshSizeFromPoints', 0)
        gmsh.option.setNumber('Mesh.MeshSizeFromCurvature', 0)
        gmsh.option.setNumber('Mesh.Algorithm', 6)     # Frontal-Delaunay 2D
        gmsh.option.setNumber('Mesh.Algorithm3D', 1)   # Delaunay
        gmsh.model.mesh.generate(3)
        points, conn = fc.gmsh_mesh(gmsh, 3, 4)
    finally:
        gmsh.finalize()
    tets = np.concatenate([conn[k] for k in sorted(conn)])
    return points, positive_tets(points, tets)


def size_field(gmsh, dim, tags, size_min, size_max, dist_max):
    """Background mesh size growing linearly from size_min on the entities
    `tags` of dimension `dim` (1: curves, 2: surfaces) to size_max at the
    distance dist_max and beyond: fine where the stress concentrates."""
    f = gmsh.model.mesh.field
    f.add('Distance', 1)
    f.setNumbers(1, 'CurvesList' if dim == 1 else 'SurfacesList', tags)
    f.setNumber(1, 'NumPointsPerCurve', 200)
    f.add('Threshold', 2)
    f.setNumber(2, 'InField', 1)
    f.setNumber(2, 'SizeMin', size_min)
    f.setNumber(2, 'SizeMax', size_max)
    f.setNumber(2, 'DistMin', 0.0)
    f.setNumber(2, 'DistMax', dist_max)
    f.setAsBackgroundMesh(2)


def tensor_grid(points, cells, stress, name='stress'):
    """vtkUnstructuredGrid of one cell type (vtk_type, conn) with the (n, 3, 3)
    or (n, 9) point stress as the ACTIVE TENSORS, 9 components row-major;
    fails on a cell of non-positive volume."""
    ug = common.unstructured_grid(points, [cells])
    common.check_positive_volumes(ug)
    ug.GetPointData().SetTensors(common.vtk_array(np.reshape(stress, (-1, 9)), name))
    return ug
