"""fenics_shaft.xdmf + .h5, fenics_shaft_dg0.xdmf + .h5, fenics_shaft.pvd +
fenics_shaft000000.vtu: a real FEniCS (dolfin 2019.2) linear-elasticity
solve, written the way FEniCS users write results.

Body: a round shaft with a circumferential U-groove, under axial tension.
Shaft diameter D = 20 (radius 10) along z, from z = -25 to z = 25. At z = 0
a semicircular groove of radius r = 2 is cut round it (a torus of major
radius 10 and minor radius 2 taken away), so the root diameter is d = 16
(D/d = 1.25, r/d = 0.125, depth t = r = 2). Units: mm, N, MPa; E = 210e3
MPa, nu = 0.3.

Mesh: gmsh 4.8 (OpenCASCADE cylinder minus torus, Delaunay tetrahedra,
single-threaded, fixed seed), refined at the groove (0.7 mm on the groove
surface, growing to 3.5 mm at 8 mm from it): 2,267 vertices and 8,998
linear tetrahedra (checked). A node is embedded at the centre of the end
face z = -25.

Loads and supports: the end z = -25 slides in its plane (u_z = 0), its
centre node is held in x and y and its node (10, 0, -25) in y (no rigid
motion, no restraint of the Poisson contraction). The end z = +25 carries
a uniform axial traction of 64 MPa, which is a nominal (net-section)
stress of 100 MPa at the groove root: 64 * (20/16)^2 = 100.

Solve: displacement in continuous P2 (quadratic tetrahedra, 45,096 dofs),
conjugate gradients with PETSc's GAMG and the six rigid-body modes as the
near-nullspace (31 iterations to a relative residual of 1e-10). Then, as
FEniCS users do for output:
  "displacement"  the P2 solution interpolated into a CG1 vector space
                  (mm; u_z from 0 at z = -25 to 0.0162 at z = 25),
  "stress"        sigma(u) L2-projected into a CG1 TensorFunctionSpace
                  (nodal values, MPa; 9 components, row-major XX XY XZ YX
                  YY YZ ZX ZY ZZ, exactly symmetric in the file), and for
                  the cell file into a DG0 TensorFunctionSpace (the mean of
                  sigma(u) over each cell).

Files:
  fenics_shaft.xdmf + fenics_shaft.h5   XDMFFile.write(f, t) with
      functions_share_mesh = True and rewrite_function_mesh = False: XDMF
      3.0, one temporal collection Grid "TimeSeries" of 2 uniform grids,
      Time 1.0 and 2.0 (load factors 1 and 2). The mesh is written once
      (h5 /Mesh/0/mesh/geometry 2267 x 3 float64; /Mesh/0/mesh/topology
      8998 x 4 int32, XDMF TopologyType Tetrahedron, NumberType "UInt" with
      no Precision); the second grid pulls it in with an xi:include (an
      XPointer to the first grid's Topology and Geometry). Per grid:
      Attribute "displacement" AttributeType Vector Center Node (2267 x 3)
      and Attribute "stress" AttributeType Tensor Center Node (2267 x 9),
      datasets /VisualisationVector/0 and /1 (t = 1), /2 and /3 (t = 2).
      Step 2 is exactly (bit for bit) twice step 1.
  fenics_shaft_dg0.xdmf + .h5   XDMFFile.write(stress_dg0, 1.0): a temporal
      collection "TimeSeries_stress" of one grid, Attribute "stress"
      AttributeType Tensor Center Cell (8998 x 9, row-major), the same mesh
      written again into this .h5.
  fenics_shaft.pvd + fenics_shaft000000.vtu   File("fenics_shaft.pvd") <<
      (stress, 1.0): the CG1 stress only, ASCII VTK XML (dolfin's default),
      PointData Tensors="stress", 9 components (row-major), timestep 1.

Not written: a symmetric "Tensor6" attribute. dolfin 2019.2's XDMFFile
cannot write a TensorFunctionSpace(mesh, "DG", 0, symmetry=True) function:
it stops with "interpolate_vertex_values: Failed to set physical value size
correctly for subelements" (the script tries it in a scratch folder and
prints the outcome).

Expected picture: a uniform axial tension in both shanks (sigma_zz = 64, the
gross stress; 61 to 65 at |z| > 15 because the coarse tetrahedra facet the
round surface), trajectories along z. At the groove the force crowds
through the reduced section and the stress peaks at the groove root, the
ring r = 8, z = 0, all round the shaft. Nodal peak in the file (load factor
1): max principal 224.0 MPa (sigma_zz 223.2) at the vertex (6.95, 3.97,
0.135), r = 8.005, so Kt = 224 / 100 = 2.24; von Mises 201.9 at the same
vertex. Along the root ring (the 49 vertices with r > 7.95, |z| < 0.25)
sigma_zz varies from 177 to 223 (mean 196) round the circumference: the
scatter of a projected stress on a coarse mesh; the hoop stress there is
tensile, about 50. Refining the groove mesh (0.6 and 0.35 mm) gives nodal
peaks of 220 and 224: Kt is about 2.2. The groove's flanks near the shaft
surface are nearly unloaded (max principal 0 to 5). The DG0 cell means peak
lower, sigma_zz up to 191.3. Step 2: everything doubled (peak 448.0).

HDF5 determinism: the HDF5 library stamps every dataset's object header
with its modification time (dolfin creates datasets with HDF5's default
obj_track_times = true): two runs differed in those 4 bytes per dataset
and nowhere else. After dolfin has closed the files, the script sets those
"Object Modification Time" fields (message 0x0012) to zero in place
(version-1 object headers, no checksums), so two runs give identical bytes.
It does this, and every read-back check, in a second Python process (h5py,
meshio, vtk), because dolfin links the MPI build of HDF5 and h5py the
serial one.

Checks (the second process): h5py reads every dataset (shapes, dtypes,
step 2 = 2 x step 1 exactly, symmetry, the peak and where it is); meshio's
XDMF TimeSeriesReader reads both .xdmf files (meshio.read cannot: it does
not take a temporal collection); VTK's XML reader reads the .vtu and its
stress equals the h5 step 1. (Debian's python3-xdmf, the XDMF library's own
bindings, fails to import: undefined symbols; Debian's VTK 9.1 has no XDMF
reader.)

Run with /usr/bin/python3 (python3-dolfin, python3-gmsh, python3-h5py,
python3-meshio, python3-vtk9). The first run also compiles the forms (FFC,
cached in ~/.cache/dijitso): about 60 s in all; after that the whole script
takes about 22 s, the P2 solve (with assembly) about 18 s of it.
"""
import os
import subprocess
import sys
import tempfile
import time

os.environ.setdefault('OMP_NUM_THREADS', '1')
os.environ.setdefault('OPENBLAS_NUM_THREADS', '1')

import numpy as np  # noqa: E402

import formats_common as fc  # noqa: E402

R, HALF_L, GROOVE_R = 10.0, 25.0, 2.0          # shaft radius, half length, groove radius
ROOT_R = R - GROOVE_R                         # 8: groove root radius
E, NU = 210e3, 0.3                            # MPa
S_NOM = 100.0                                 # MPa on the net section
TRACTION = S_NOM * (ROOT_R / R) ** 2          # 64 MPa on the end face
H_GROOVE, H_FAR, H_DIST = 0.7, 3.5, 8.0       # mesh sizes (mm)
N_VERTICES, N_CELLS = 2267, 8998              # what gmsh 4.8 gives; checked

XDMF, XDMF_DG0, PVD = 'fenics_shaft.xdmf', 'fenics_shaft_dg0.xdmf', 'fenics_shaft.pvd'
VTU = 'fenics_shaft000000.vtu'


def shaft_mesh():
    """gmsh tetrahedra of the grooved shaft: points (n, 3), tets (m, 4)."""
    gmsh = fc.gmsh_start('notched_shaft')
    try:
        occ = gmsh.model.occ
        cyl = occ.addCylinder(0, 0, -HALF_L, 0, 0, 2 * HALF_L, R)
        torus = occ.addTorus(0, 0, 0, R, GROOVE_R)
        occ.cut([(3, cyl)], [(3, torus)])
        occ.synchronize()
        com = {t: occ.getCenterOfMass(2, t) for _, t in gmsh.model.getEntities(2)}
        groove = [t for t in com if gmsh.model.getType(2, t) == 'Torus']
        bottom = [t for t in com if abs(com[t][2] + HALF_L) < 1e-6]
        assert len(groove) == 1 and len(bottom) == 1, (groove, bottom)
        centre = occ.addPoint(0, 0, -HALF_L)
        occ.synchronize()
        gmsh.model.mesh.embed(0, [centre], 2, bottom[0])
        field = gmsh.model.mesh.field
        field.add('Distance', 1)
        field.setNumbers(1, 'SurfacesList', groove)
        field.setNumber(1, 'NumPointsPerCurve', 100)
        field.add('Threshold', 2)
        field.setNumber(2, 'InField', 1)
        field.setNumber(2, 'SizeMin', H_GROOVE)
        field.setNumber(2, 'SizeMax', H_FAR)
        field.setNumber(2, 'DistMin', 0.0)
        field.setNumber(2, 'DistMax', H_DIST)
        field.setAsBackgroundMesh(2)
        gmsh.option.setNumber('Mesh.MeshSizeExtendFromBoundary', 0)
        gmsh.option.setNumber('Mesh.MeshSizeFromPoints', 0)
        gmsh.option.setNumber('Mesh.MeshSizeFromCurvature', 0)
        gmsh.option.setNumber('Mesh.Algorithm', 6)
        gmsh.option.setNumber('Mesh.Algorithm3D', 1)
        gmsh.model.mesh.generate(3)
        points, conn = fc.gmsh_mesh(gmsh, 3, 4)
    finally:
        gmsh.finalize()
    return points, np.concatenate([conn[k] for k in sorted(conn)])


def solve_and_write(folder):
    import dolfin as df
    df.set_log_level(df.LogLevel.WARNING)

    points, tets = shaft_mesh()
    print('gmsh: %d vertices, %d tetrahedra' % (len(points), len(tets)))
    assert (len(points), len(tets)) == (N_VERTICES, N_CELLS), (len(points), len(tets))
    mesh = df.Mesh()
    editor = df.MeshEditor()
    editor.open(mesh, 'tetrahedron', 3, 3)
    editor.init_vertices(len(points))
    editor.init_cells(len(tets))
    for i, p in enumerate(points):
        editor.add_vertex(i, p)
    for i, c in enumerate(tets):
        editor.add_cell(i, c.astype(np.uintp))
    editor.close()

    mu, lmbda = E / (2 * (1 + NU)), E * NU / ((1 + NU) * (1 - 2 * NU))

    def eps(w):
        return df.sym(df.grad(w))

    def sigma(w):
        return 2 * mu * eps(w) + lmbda * df.tr(eps(w)) * df.Identity(3)

    V = df.VectorFunctionSpace(mesh, 'CG', 2)
    u, v = df.TrialFunction(V), df.TestFunction(V)
    top = df.CompiledSubDomain('on_boundary && near(x[2], L)', L=HALF_L)
    facets = df.MeshFunction('size_t', mesh, 2, 0)
    top.mark(facets, 1)
    ds = df.Measure('ds', domain=mesh, subdomain_data=facets)
    a = df.inner(sigma(u), eps(v)) * df.dx
    rhs = df.dot(df.Constant((0.0, 0.0, TRACTION)), v) * ds(1)
    point = 'near(x[0], %r) && near(x[1], %r) && near(x[2], %r)'
    centre, edge = point % (0.0, 0.0, -HALF_L), point % (R, 0.0, -HALF_L)
    bcs = [df.DirichletBC(V.sub(2), 0.0, 'on_boundary && near(x[2], %r)' % -HALF_L),
           df.DirichletBC(V.sub(0), 0.0, centre, 'pointwise'),
           df.DirichletBC(V.sub(1), 0.0, centre, 'pointwise'),
           df.DirichletBC(V.sub(1), 0.0, edge, 'pointwise')]

    t0 = time.time()
    A, b = df.assemble_system(a, rhs, bcs)
    # rigid-body modes as GAMG's near-nullspace
    x = V.tabulate_dof_coordinates()
    d = [np.asarray(V.sub(i).dofmap().dofs()) for i in range(3)]
    modes = [df.Function(V).vector() for _ in range(6)]
    for i in range(3):
        modes[i][d[i]] = 1.0
    modes[3][d[0]], modes[3][d[1]] = -x[d[0], 1], x[d[1], 0]
    modes[4][d[0]], modes[4][d[2]] = x[d[0], 2], -x[d[2], 0]
    modes[5][d[1]], modes[5][d[2]] = -x[d[1], 2], x[d[2], 1]
    for m in modes:
        m.apply('insert')
    nullspace = df.VectorSpaceBasis(modes)
    nullspace.orthonormalize()
    df.as_backend_type(A).set_near_nullspace(nullspace)
    solver = df.PETScKrylovSolver('cg', 'petsc_amg')
    solver.parameters['relative_tolerance'] = 1e-10
    solver.parameters['absolute_tolerance'] = 1e-14
    solver.set_operator(A)
    uh = df.Function(V)
    iterations = solver.solve(uh.vector(), b)
    t_solve = time.time() - t0
    print('P2 solve: %d dofs, %d CG iterations (GAMG), %.1f s (assembly included)'
          % (V.dim(), iterations, t_solve))

    # output fields, as FEniCS users make them
    V1 = df.VectorFunctionSpace(mesh, 'CG', 1)
    T1 = df.TensorFunctionSpace(mesh, 'CG', 1)
    T0 = df.TensorFunctionSpace(mesh, 'DG', 0)
    disp = df.interpolate(uh, V1)
    stress = df.project(sigma(uh), T1, solver_type='cg', preconditioner_type='jacobi')
    stress0 = df.project(sigma(uh), T0, solver_type='cg', preconditioner_type='jacobi')
    disp.rename('displacement', 'displacement')
    stress.rename('stress', 'stress')
    stress0.rename('stress', 'stress')
    disp2, stress2 = disp.copy(deepcopy=True), stress.copy(deepcopy=True)
    disp2.vector()[:] = 2.0 * disp.vector().get_local()      # exact doubling
    stress2.vector()[:] = 2.0 * stress.vector().get_local()
    disp2.rename('displacement', 'displacement')
    stress2.rename('stress', 'stress')

    # the peak, from the nodal (vertex) values
    s = stress.compute_vertex_values(mesh).reshape(9, -1).T.reshape(-1, 3, 3)
    s = 0.5 * (s + s.transpose(0, 2, 1))
    principal = np.linalg.eigvalsh(s)[:, 2]
    vm = fc.von_mises(s)
    coords = mesh.coordinates()
    i, j = int(np.argmax(principal)), int(np.argmax(vm))
    print('peak max principal %.2f MPa at vertex %d %s (r = %.3f), Kt = %.3f'
          % (principal[i], i, np.round(coords[i], 3), np.hypot(*coords[i, :2]), principal[i] / S_NOM))
    print('peak von Mises %.2f MPa at vertex %d %s' % (vm[j], j, np.round(coords[j], 3)))
    c0 = stress0.vector().get_local().reshape(-1, 9)
    print('DG0 cell stress: largest sigma_zz %.2f MPa' % c0[:, 8].max())

    for path in (XDMF, XDMF_DG0):
        for ext in ('.xdmf', '.h5'):
            p = os.path.join(folder, path[:-5] + ext)
            if os.path.exists(p):
                os.remove(p)     # XDMFFile appends to an existing .h5
    with df.XDMFFile(mesh.mpi_comm(), os.path.join(folder, XDMF)) as f:
        f.parameters['functions_share_mesh'] = True
        f.parameters['rewrite_function_mesh'] = False
        f.parameters['flush_output'] = False
        f.write(disp, 1.0)
        f.write(stress, 1.0)
        f.write(disp2, 2.0)
        f.write(stress2, 2.0)
    with df.XDMFFile(mesh.mpi_comm(), os.path.join(folder, XDMF_DG0)) as f:
        f.write(stress0, 1.0)
    df.File(os.path.join(folder, PVD)) << (stress, 1.0)

    # does dolfin write a symmetric (Tensor6) attribute? (scratch folder)
    T6 = df.TensorFunctionSpace(mesh, 'DG', 0, symmetry=True)
    stress6 = df.project(sigma(uh), T6, solver_type='cg', preconditioner_type='jacobi')
    with tempfile.TemporaryDirectory() as scratch:
        try:
            with df.XDMFFile(mesh.mpi_comm(), os.path.join(scratch, 't6.xdmf')) as f:
                f.write(stress6, 1.0)
            print('dolfin wrote a symmetric DG0 tensor (unexpected: see the docstring)')
        except RuntimeError as e:
            msg = [line for line in str(e).splitlines() if 'Reason' in line]
            print('symmetric DG0 tensor, as expected not written by XDMFFile:',
                  (msg[0].strip() if msg else str(e).splitlines()[-1]))
    return principal[i]


# ------------------------------------------------------------ second process

def check(folder, peak):
    import h5py
    import meshio
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy

    for name in (XDMF, XDMF_DG0):
        h5 = os.path.join(folder, name[:-5] + '.h5')
        print('%s: %d modification times set to 0' % (os.path.basename(h5), fc.zero_hdf5_mtimes(h5)))
    for name in (XDMF, XDMF[:-5] + '.h5', XDMF_DG0, XDMF_DG0[:-5] + '.h5', PVD, VTU):
        fc.report(os.path.join(folder, name))

    with h5py.File(os.path.join(folder, 'fenics_shaft.h5'), 'r') as f:
        geo, topo = f['Mesh/0/mesh/geometry'], f['Mesh/0/mesh/topology']
        assert geo.shape == (N_VERTICES, 3) and geo.dtype == np.float64, (geo.shape, geo.dtype)
        assert topo.shape == (N_CELLS, 4) and topo.dtype == np.int32, (topo.shape, topo.dtype)
        vv = [f['VisualisationVector/%d' % k][:] for k in range(4)]
        assert [a.shape for a in vv] == [(N_VERTICES, 3), (N_VERTICES, 9)] * 2
        assert np.array_equal(vv[2], 2 * vv[0]) and np.array_equal(vv[3], 2 * vv[1])
        s = vv[1].reshape(-1, 3, 3)
        asym = np.abs(s - s.transpose(0, 2, 1)).max()
        s = 0.5 * (s + s.transpose(0, 2, 1))
        p = np.linalg.eigvalsh(s)[:, 2]
        i = int(np.argmax(p))
        print('h5 step 1: max principal %.2f at %s; asymmetry %.1e; step 2 = 2 x step 1 exactly'
              % (p[i], np.round(geo[i], 3), asym))
        assert abs(p[i] - peak) < 1e-9 * peak and asym < 1e-6
        assert 223.5 < p[i] < 224.5, p[i]     # the value in the docstring
        assert abs(np.hypot(*geo[i, :2]) - ROOT_R) < 0.05 and abs(geo[i, 2]) < 1.0
        far = np.abs(geo[:, 2]) > 15
        print('h5 step 1: sigma_zz far from the groove (|z| > 15): %.2f .. %.2f (gross %.0f)'
              % (s[far, 2, 2].min(), s[far, 2, 2].max(), TRACTION))
        step1, geometry = vv[1], geo[:]
    with h5py.File(os.path.join(folder, 'fenics_shaft_dg0.h5'), 'r') as f:
        c = f['VisualisationVector/0']
        assert c.shape == (N_CELLS, 9), c.shape
        print('h5 DG0: %s, sigma_zz from %.2f to %.2f' % (c.shape, c[:, 8].min(), c[:, 8].max()))

    with meshio.xdmf.TimeSeriesReader(os.path.join(folder, XDMF)) as r:
        pts, cells = r.read_points_cells()
        assert pts.shape == (N_VERTICES, 3) and cells[0].type == 'tetra' and len(cells[0].data) == N_CELLS
        steps = [r.read_data(k) for k in range(r.num_steps)]
        assert [t for t, _, _ in steps] == [1.0, 2.0]
        assert np.array_equal(steps[0][1]['stress'], step1)
        print('meshio TimeSeriesReader: %d points, %d %s, steps %s, point arrays %s'
              % (len(pts), len(cells[0].data), cells[0].type, [t for t, _, _ in steps],
                 sorted(steps[0][1])))
    with meshio.xdmf.TimeSeriesReader(os.path.join(folder, XDMF_DG0)) as r:
        r.read_points_cells()
        t, _, cd = r.read_data(0)
        assert t == 1.0 and cd['stress'][0].shape == (N_CELLS, 9)
        print('meshio TimeSeriesReader (DG0): t = %g, cell array stress %s' % (t, cd['stress'][0].shape))

    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(os.path.join(folder, VTU))
    reader.Update()
    ug = reader.GetOutput()
    assert (ug.GetNumberOfPoints(), ug.GetNumberOfCells()) == (N_VERTICES, N_CELLS)
    t = ug.GetPointData().GetTensors()
    vals = vtk_to_numpy(t).reshape(-1, 9)
    pts = vtk_to_numpy(ug.GetPoints().GetData())
    assert np.abs(pts - geometry).max() < 1e-12
    err = np.abs(vals - step1).max()
    print('vtk .vtu: %d points, %d cells, active tensors %r (%d components), |vtu - h5| <= %.1e'
          % (ug.GetNumberOfPoints(), ug.GetNumberOfCells(), t.GetName(),
             t.GetNumberOfComponents(), err))
    assert err < 1e-9


if __name__ == '__main__':
    folder = fc.out_dir()
    if os.environ.get('FENICS_SHAFT_CHECK'):
        check(folder, float(os.environ['FENICS_SHAFT_CHECK']))
    else:
        peak = solve_and_write(folder)
        env = dict(os.environ, FENICS_SHAFT_CHECK=repr(peak))
        subprocess.run([sys.executable, os.path.abspath(__file__), folder], env=env, check=True)
