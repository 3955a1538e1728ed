"""gmsh_plate_v41.msh and gmsh_plate_v22.msh: the Kirsch plate as Gmsh 4.8
itself writes a mesh with model-based post-processing views (gmsh's Python
API: gmsh.view.add, gmsh.view.addModelData, gmsh.write for the mesh, then
gmsh.view.write(..., append=True) for each view). The two files hold the
same mesh and the same three views, once in MSH 4.1 and once in MSH 2.2
(Mesh.MshFileVersion), both ASCII.

Mesh: the plate [-10, 10] x [-5, 5] x [0, 1] (mm) with a hole of radius 1
on the z axis, as four quarter volumes (split by the planes x = 0 and y = 0,
so that the CalculiX solve can use those planes as symmetry planes), meshed
by gmsh 4.8 (OpenCASCADE, Mesh.Algorithm 6, Algorithm3D 1, one thread,
RandomSeed 1) with a size of 0.4 at the hole growing to 2.5 at 6 from it:
462 nodes, 1,381 linear tetrahedra (gmsh type 4) in the physical volume 1
"plate", and 128 triangles (gmsh type 2) of the hole's surface in the
physical surface 2 "hole". Only physical elements are saved (Mesh.SaveAll
0), so the files hold exactly these two element types; the triangles carry
no data. Nodes are tagged 1..462 in both files. Element tags: MSH 4.1 keeps
gmsh's own, which have gaps: 8 entity blocks, the triangles tagged 425..1136
(4 blocks of 32), the tetrahedra 1145..2525 (4 blocks, one per quarter);
MSH 2.2 renumbers them 1..1509 in the same order (triangles 1..128,
tetrahedra 129..1509), and its views use those numbers. The $Entities
section of the 4.1 file gives OCC's point coordinates, with round-off
(1.9e-14 for 0); the node coordinates are exact zeros there. The corner
nodes of ccx_plate.frd (numbers 1..462) and the nodes of aster_plate.med are
this same mesh, node for node and cell for cell (to 1e-15).

Views (data type, name in the file's string tag, one time step, time 1):
  0  $NodeData         "stress NodeData (Kirsch)"        9 components, one
                       row per node (all 462);
  1  $ElementData      "stress ElementData (Kirsch)"     9 components, one
                       row per tetrahedron (1,381; none for the triangles),
                       the Kirsch tensor at the cell's centroid;
  2  $ElementNodeData  "stress ElementNodeData (Kirsch)" per tetrahedron 4
                       nodes x 9 components, in the element's node order.
The 9 components are the full tensor, row-major: XX XY XZ YX YY YZ ZX ZY ZZ
(Gmsh's tensor layout), so XY = YX etc. Values are rounded to 6 significant
digits before they are given to gmsh (gmsh prints %.16g: rounding keeps the
ASCII files small). Units MPa.

Stress: Kirsch's solution for an infinite plate with a hole of radius 1 under
uniaxial tension 10 along x, plane stress (SZZ = XZ = YZ = 0), evaluated at
each node (NodeData, ElementNodeData) or centroid (ElementData).

Expected picture: sigma_xx about 10 far from the hole; the peak 3 x 10 = 30
(tension along x) at the top and bottom of the hole, (0, +-1, z); -10 (hoop
compression, sigma_yy) at its sides (+-1, 0, z); trajectories of the major
principal stress run along x and bend round the hole. The ElementData view
shows the same picture cell by cell, its largest value lower (26.1, in the
cells touching (0, +-1)) since it is taken at centroids; ElementNodeData is
NodeData repeated per element (continuous, 30 at the peak).

Read back: the files are opened again by gmsh: 3 views, their types,
component counts, times and names, and every value compared with what was
written (MSH 2.2: by the renumbered element tags, in order); element types
by dimension [], [], [2], [4]; the section headers are counted in the text.

Deterministic: gmsh meshes single-threaded with its fixed seed and writes no
date; two runs give the same bytes.

The helpers `build_plate` and `plate_tet_mesh` here make the same gmsh mesh
for ccx_plate.py (second order) and med_plate.py (first order).
"""
import os

import numpy as np

import formats_common as fc

H_HOLE, H_FAR, DIST_MAX = 0.4, 2.5, 6.0   # mesh size at the hole, far away; mm


def build_plate(gmsh):
    """Build and mesh the plate with a hole in the open gmsh session: four
    quarter volumes fragmented together (conforming on x = 0 and y = 0),
    linear tetrahedra. Returns the tags of the hole's surfaces."""
    occ = gmsh.model.occ
    w, h, t = fc.PLATE_W / 2, fc.PLATE_H / 2, fc.PLATE_T
    quarters = []
    for x0 in (-w, 0.0):
        for y0 in (-h, 0.0):
            box = occ.addBox(x0, y0, 0, w, h, t)
            cyl = occ.addCylinder(0, 0, 0, 0, 0, t, fc.HOLE_A)
            out, _ = occ.cut([(3, box)], [(3, cyl)])
            quarters += out
    occ.fragment(quarters, [])
    occ.synchronize()
    hole = [tag for _, tag in gmsh.model.getEntities(2)
            if np.hypot(*occ.getCenterOfMass(2, tag)[:2]) < fc.HOLE_A]
    field = gmsh.model.mesh.field
    field.add('Distance', 1)
    field.setNumbers(1, 'SurfacesList', hole)
    field.setNumber(1, 'NumPointsPerCurve', 100)
    field.add('Threshold', 2)
    field.setNumber(2, 'InField', 1)
    field.setNumber(2, 'SizeMin', H_HOLE)
    field.setNumber(2, 'SizeMax', H_FAR)
    field.setNumber(2, 'DistMin', 0.0)
    field.setNumber(2, 'DistMax', DIST_MAX)
    field.setAsBackgroundMesh(2)
    gmsh.option.setNumber('Mesh.MeshSizeExtendFromBoundary', 0)
    gmsh.option.setNumber('Mesh.MeshSizeFromPoints', 0)
    gmsh.option.setNumber('Mesh.MeshSizeFromCurvature', 0)
    gmsh.option.setNumber('Mesh.Algorithm', 6)     # 8 segfaults in Debian's 4.8
    gmsh.option.setNumber('Mesh.Algorithm3D', 1)   # Delaunay
    gmsh.model.mesh.generate(3)
    clean_zeros(gmsh)
    return hole


def clean_zeros(gmsh):
    """OCC leaves ~1e-15 where a coordinate is 0 (the planes x = 0, y = 0):
    make those exact zeros in the mesh itself, so that every file has them."""
    tags, coords, _ = gmsh.model.mesh.getNodes()
    coords = np.asarray(coords).reshape(-1, 3)
    for k in np.nonzero(np.any((np.abs(coords) < 1e-12) & (coords != 0), axis=1))[0]:
        coord, par = gmsh.model.mesh.getNode(int(tags[k]))[:2]
        c = np.asarray(coord)
        c[np.abs(c) < 1e-12] = 0.0
        gmsh.model.mesh.setNode(int(tags[k]), c.tolist(), list(par))


def plate_tet_mesh(order=1):
    """The plate's tetrahedra: points (n, 3) and connectivity (m, 4) or
    (m, 10), 0-based, in gmsh's node order (10-node: corners, then the
    midpoints of edges 01 12 20 30 32 31), elements in the order of the four
    volumes. Order 1: the nodes numbered in the order of gmsh's node tags
    (the numbers of gmsh_plate_v41.msh minus 1). Order 2 (gmsh's setOrder 2,
    midside nodes on the curved hole): the same tetrahedra in the same order,
    the corner nodes first with the numbers of order 1, then the midside
    nodes (gmsh itself renumbers all nodes when it raises the order). Every
    tetrahedron has a positive signed volume (VTK's orientation)."""
    gmsh = fc.gmsh_start('kirsch_plate_tets')
    try:
        build_plate(gmsh)
        points, conn = fc.gmsh_mesh(gmsh, 3, 4)
        tets = np.concatenate([conn[k] for k in sorted(conn)])
        if order == 2:
            gmsh.option.setNumber('Mesh.SecondOrderLinear', 0)   # midside nodes on the hole
            gmsh.model.mesh.setOrder(2)
            clean_zeros(gmsh)
            points2, conn2 = fc.gmsh_mesh(gmsh, 3, 11)
            tets2 = np.concatenate([conn2[k] for k in sorted(conn2)])
            corner = {tuple(p): i for i, p in enumerate(points)}
            new = np.full(len(points2), -1)
            for i, p in enumerate(points2):
                new[i] = corner.get(tuple(p), -1)
            mids = np.nonzero(new < 0)[0]
            new[mids] = len(points) + np.arange(len(mids))
            assert len(mids) == len(points2) - len(points)
            points = np.empty_like(points2)
            points[new] = points2
            tets2 = new[tets2]
            if not np.array_equal(tets2[:, :4], tets):
                raise RuntimeError('setOrder(2) changed the tetrahedra')
            tets = tets2
    finally:
        gmsh.finalize()
    if np.any(signed_volumes(points, tets) <= 0):
        raise RuntimeError('gmsh gave a tetrahedron of non-positive volume')
    return points, tets


def signed_volumes(points, tets):
    """VTK's signed volume of each tetrahedron (first 4 nodes):
    ((p1 - p0) x (p2 - p0)) . (p3 - p0) / 6."""
    p = points[tets[:, :4]]
    return np.einsum('ij,ij->i', np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]),
                     p[:, 3] - p[:, 0]) / 6.0


def round6(a):
    """Round to 6 significant digits (so that gmsh's %.16g prints short),
    with what is below 1e-9 of the largest magnitude (round-off of zero
    components) set to 0, and no negative zeros."""
    a = np.asarray(a, dtype=np.float64)
    r = np.array([float('%.6g' % v) for v in a.ravel()]).reshape(a.shape)
    r[np.abs(r) < 1e-9 * np.abs(r).max()] = 0.0
    return r + 0.0


def kirsch9(points):
    """(n, 9) row-major Kirsch tensors, rounded to 6 digits."""
    return round6(fc.kirsch_stress(points).reshape(-1, 9))


VIEWS = [('NodeData', 'stress NodeData (Kirsch)'),
         ('ElementData', 'stress ElementData (Kirsch)'),
         ('ElementNodeData', 'stress ElementNodeData (Kirsch)')]


def write_files():
    gmsh = fc.gmsh_start('kirsch_plate')
    try:
        hole = build_plate(gmsh)
        volumes = [tag for _, tag in gmsh.model.getEntities(3)]
        gmsh.model.addPhysicalGroup(3, volumes, 1)
        gmsh.model.setPhysicalName(3, 1, 'plate')
        gmsh.model.addPhysicalGroup(2, hole, 2)
        gmsh.model.setPhysicalName(2, 2, 'hole')
        node_tags, coords, _ = gmsh.model.mesh.getNodes()
        coords = np.asarray(coords).reshape(-1, 3)
        elem_tags, elem_nodes = [], []
        for v in volumes:
            types, tags, nodes = gmsh.model.mesh.getElements(3, v)
            assert list(types) == [4]
            elem_tags.append(np.asarray(tags[0]))
            elem_nodes.append(np.asarray(nodes[0]).reshape(-1, 4))
        elem_tags = np.concatenate(elem_tags)
        elem_nodes = np.concatenate(elem_nodes)
        index = {int(t): i for i, t in enumerate(node_tags)}
        conn = np.vectorize(index.get)(elem_nodes)
        tri = sum(len(gmsh.model.mesh.getElements(2, s)[1][0]) for s in hole)

        node_data = kirsch9(coords)
        elem_data = kirsch9(coords[conn].mean(axis=1))
        elno_data = kirsch9(coords[conn].reshape(-1, 3)).reshape(len(conn), 36)
        views = []
        for (kind, name), tags, data in zip(VIEWS, [node_tags, elem_tags, elem_tags],
                                            [node_data, elem_data, elno_data]):
            v = gmsh.view.add(name)
            gmsh.view.addModelData(v, 0, 'kirsch_plate', kind, [int(t) for t in tags],
                                   data.tolist(), time=1.0, numComponents=9)
            views.append(v)
        counts = dict(nodes=len(node_tags), tets=len(elem_tags), triangles=tri)
        paths = []
        for version, name in [(4.1, 'gmsh_plate_v41.msh'), (2.2, 'gmsh_plate_v22.msh')]:
            path = fc.out_path(name)
            gmsh.option.setNumber('Mesh.MshFileVersion', version)
            gmsh.option.setNumber('Mesh.Binary', 0)
            gmsh.option.setNumber('Mesh.SaveAll', 0)   # physical groups only
            gmsh.write(path)
            gmsh.option.setNumber('PostProcessing.SaveMesh', 0)   # mesh is there already
            for v in views:
                gmsh.view.write(v, path, append=True)
            gmsh.option.setNumber('PostProcessing.SaveMesh', 1)
            paths.append(path)
            fc.report(path)
        # what was written, each in the order of its tags (MSH 2.2 renumbers
        # the elements 1, 2, ... but keeps their order)
        written = [d[np.argsort(t)] for t, d in zip([node_tags, elem_tags, elem_tags],
                                                    [node_data, elem_data, elno_data])]
    finally:
        gmsh.finalize()
    return paths, counts, written, coords, node_data


def check(path, counts, written):
    """Read the file back with gmsh (every value of every view compared with
    what was written) and count its sections in the text."""
    text = open(path).read()
    sections = {s: text.count('$' + s + '\n') for s in
                ['MeshFormat', 'Nodes', 'Elements', 'NodeData', 'ElementData', 'ElementNodeData']}
    assert sections == dict(MeshFormat=1, Nodes=1, Elements=1, NodeData=1,
                            ElementData=1, ElementNodeData=1), sections
    version = text.split('$MeshFormat\n')[1].split()[0]
    gmsh = fc.gmsh_start('check')
    try:
        gmsh.open(path)
        tags = gmsh.view.getTags()
        assert len(tags) == 3, tags
        kinds = []
        for v, (kind, name), expect in zip(tags, VIEWS, written):
            dtype, dtags, data, time, ncomp = gmsh.view.getModelData(v, 0)
            kinds.append((dtype, len(dtags), ncomp, time))
            assert dtype == kind and ncomp == 9 and time == 1.0, (dtype, ncomp, time)
            assert gmsh.option.getString('View[%d].Name' % gmsh.view.getIndex(v)) == name
            data = np.asarray(data)[np.argsort(dtags)]
            assert len(dtags) == (counts['nodes'] if kind == 'NodeData' else counts['tets'])
            assert np.array_equal(data, expect), kind
        types = [list(gmsh.model.mesh.getElements(dim)[0]) for dim in (0, 1, 2, 3)]
        assert types == [[], [], [2], [4]], types
    finally:
        gmsh.finalize()
    print('read back %s (MSH %s): sections %s; views %s; element types by dim %s'
          % (os.path.basename(path), version, sections, kinds, types))


def main():
    paths, counts, written, coords, node_data = write_files()
    print('mesh: %(nodes)d nodes, %(tets)d tetrahedra, %(triangles)d hole triangles' % counts)
    k = np.argmax(node_data[:, 0])
    print('NodeData: sigma_xx max %.4g at (%.3g, %.3g, %.3g), min sigma_yy %.4g'
          % (node_data[k, 0], *coords[k], node_data[:, 4].min()))
    for path in paths:
        check(path, counts, written)


if __name__ == '__main__':
    main()
