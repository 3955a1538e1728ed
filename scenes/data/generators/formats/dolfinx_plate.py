"""dolfinx_plate.xdmf + dolfinx_plate.h5: a real FEniCSx (dolfinx 0.5.2)
linear-elasticity solve, written the way dolfinx users write results.

Body: the Kirsch plate of the other plate files as a solid, 20 x 10 x 1
(x from -10 to 10, y from -5 to 5, z from 0 to 1) with a through hole of
radius 1 on the z axis. Units: mm, N, MPa; E = 200e3 MPa, nu = 0.3.

Mesh: the tetrahedra of kirsch_plate.vtkhdf (gmsh 4.8, OpenCASCADE box
minus cylinder, Delaunay, single thread, fixed seed; 0.2 at the hole
growing to 1.0 at 5 from it): 1,712 vertices, 5,795 linear tetrahedra
(checked), handed to dolfinx.mesh.create_mesh. dolfinx renumbers the
vertices and cells (its own graph reordering), so the file's order is not
gmsh's; every tetrahedron has a positive volume in VTK's node order
(checked).

Loads and supports: uniaxial tension S = 10 MPa along x, as a traction
(10, 0, 0) on the end x = +10. The end x = -10 has u_x = 0 (it slides in
its plane); its corner (-10, -5, 0) is held in y and z and its corner
(-10, 5, 0) in z (no rigid motion, no restraint of the Poisson
contraction).

Solve: displacement in continuous P2 (31,956 dofs), conjugate gradients
with PETSc's GAMG and the six rigid-body modes as the near-nullspace
(71 iterations to a relative residual of 1e-10; 2.7 s with assembly).
Then, as dolfinx users do for output:
  "displacement"  the P2 solution interpolated into a P1 vector space
                  (mm; u_x from 0 at x = -10 to 1.05e-3 at x = +10),
  "stress"        sigma(u) L2-projected (CG + Jacobi) into a P1
                  TensorFunctionSpace, shape (3, 3) (nodal values, MPa;
                  9 components, row-major XX XY XZ YX YY YZ ZX ZY ZZ,
                  exactly symmetric in the file).
Load factor 2 is the same solution doubled: its arrays are exactly (bit for
bit) twice those of load factor 1.

File: `with dolfinx.io.XDMFFile(comm, path, "w") as f: f.write_mesh(mesh);
f.write_function(displacement, t); f.write_function(stress, t)` for t = 1
and t = 2. XDMF 3.0. dolfinx's layout, unlike dolfin 2019's (one temporal
collection holding every function):
  * a uniform Grid "mesh" with the Topology (Tetrahedron, 5795 x 4,
    NumberType "Int" without Precision; int64 in the .h5) and the Geometry
    (XYZ, 1712 x 3, no NumberType; float64 in the .h5), and no attributes;
  * then one temporal collection per function, named after it: Grid
    "displacement" and Grid "stress" (GridType "Collection",
    CollectionType "Temporal"), each holding two uniform grids of that
    name with <Time Value="1"/> and <Time Value="2"/>. Each takes the
    mesh by an xi:include, xpointer(/Xdmf/Domain/Grid[@GridType='Uniform']
    [1]/*[self::Topology or self::Geometry]), and carries one Attribute:
    "displacement" AttributeType Vector Center Node (1712 x 3), or
    "stress" AttributeType Tensor Center Node (1712 x 9).
  HDF5 datasets: /Mesh/mesh/geometry, /Mesh/mesh/topology,
  /Function/displacement/1, /Function/displacement/2, /Function/stress/1,
  /Function/stress/2 (named by the time). 2,399 + 564,840 bytes.
So a reader must join attributes from sibling temporal collections at the
same time onto the one mesh; read naively as a spatial collection of grids,
the file is three copies of the mesh, one without any attribute.

Expected picture: sigma_xx about 10 away from the hole (9.8 to 10.3 at
|x| > 8), trajectories along x bending round the hole. The stress peaks at
the top and bottom of the hole (0, +-1, z): sigma_xx from 29.8 on the faces
z = 0 and z = 1 to 32.4 at mid-thickness; the largest nodal max principal
is 32.44 (sigma_xx, von Mises 31.7) at the vertex (0.008, 1.000, 0.545).
That is Kirsch's 3 S = 30 raised by the finite width (hole diameter / width
= 0.2, Kt about 3.14 on the gross stress) and by the through-thickness
effect of a solid plate, which is largest at mid-thickness. At the hole's
left and right (+-1, 0, z) sigma_yy is compressive, -9.6 on the faces to
-11.9 inside (min principal -11.89 at (-1.000, -0.002, 0.661)). Step 2
(t = 2): everything doubled (peak 64.9).

HDF5 determinism: dolfinx, like dolfin, creates its datasets with HDF5's
default obj_track_times, so each object header carries its modification
time. After dolfinx has closed the file, the script sets those 6 fields
(message 0x0012; version-1 object headers, no checksums) to 0 in place, so
two runs give identical bytes (checked). One process, one thread: PETSc's
GAMG and CG give the same bits from run to run.

Checks, in a second Python process (dolfinx links the MPI build of HDF5,
h5py the serial one): h5py reads every dataset (names, shapes, dtypes,
step 2 = 2 x step 1 exactly, symmetry, the peak and where it is, the cell
volumes); meshio's xdmf.TimeSeriesReader reads the mesh and both steps, but
of the LAST temporal collection only: it returns "stress" and silently
drops "displacement" (meshio.read cannot read a temporal collection).
(Debian's python3-xdmf fails to import and VTK 9.1 has no XDMF reader.)

Run with /usr/bin/python3 (python3-dolfinx 0.5.2, python3-gmsh,
python3-h5py, python3-meshio). About 5 s, the solve 2.7 s of it; the first
run also compiles the forms with FFCx (cached in ~/.cache/fenics), a few
seconds more.
"""
import logging
import os
import subprocess
import sys
import time

os.environ.setdefault('OMP_NUM_THREADS', '1')
os.environ.setdefault('OPENBLAS_NUM_THREADS', '1')

import numpy as np  # noqa: E402

import formats_common as fc  # noqa: E402

W, H, T, A = fc.PLATE_W, fc.PLATE_H, fc.PLATE_T, fc.HOLE_A   # 20 x 10 x 1, hole radius 1
E, NU, S = fc.PLATE_E, fc.PLATE_NU, fc.KIRSCH_S              # 200e3 MPa, 0.3, 10 MPa
H_HOLE, H_FAR, H_DIST = 0.2, 1.0, 5.0                        # mesh sizes (mm)
N_POINTS, N_CELLS = 1712, 5795                               # what gmsh 4.8 gives; checked

XDMF, H5 = 'dolfinx_plate.xdmf', 'dolfinx_plate.h5'


def plate_tets():
    """gmsh tetrahedra of the plate with a hole (the mesh of
    kirsch_plate.vtkhdf): points (n, 3), tets (m, 4)."""
    return fc.solid_plate_tets('dolfinx_plate', H_HOLE, H_FAR, H_DIST)


def rigid_body_modes(V):
    """The six rigid-body modes of the P2 vector space V, as PETSc's near
    nullspace (dolfinx 0.5's elasticity demo)."""
    from petsc4py import PETSc
    import dolfinx.la
    index_map, bs = V.dofmap.index_map, V.dofmap.index_map_bs
    length = index_map.size_local * bs
    basis = [np.zeros(length) for _ in range(6)]
    dofs = [V.sub(i).dofmap.list.array for i in range(3)]
    for i in range(3):
        basis[i][dofs[i]] = 1.0
    x = V.tabulate_dof_coordinates()
    d0, d1, d2 = dofs
    basis[3][d0], basis[3][d1] = -x[d0 // 3, 1], x[d1 // 3, 0]
    basis[4][d0], basis[4][d2] = x[d0 // 3, 2], -x[d2 // 3, 0]
    basis[5][d2], basis[5][d1] = x[d2 // 3, 1], -x[d1 // 3, 2]
    vecs = [PETSc.Vec().createWithArray(b, bsize=bs) for b in basis]
    dolfinx.la.orthonormalize(vecs)
    assert dolfinx.la.is_orthonormal(vecs)
    return PETSc.NullSpace().create(vectors=vecs), vecs, basis


def solve_and_write(folder):
    from mpi4py import MPI
    from petsc4py import PETSc
    import ufl
    import dolfinx.fem.petsc  # noqa: F401  (loads fem.petsc)
    from dolfinx import fem, io, mesh as dmesh
    logging.disable(logging.INFO)   # no JIT compiler chatter (setuptools logs at INFO)

    comm = MPI.COMM_WORLD
    points, tets = plate_tets()
    print('gmsh: %d points, %d tetrahedra' % (len(points), len(tets)))
    assert (len(points), len(tets)) == (N_POINTS, N_CELLS), (len(points), len(tets))
    domain = ufl.Mesh(ufl.VectorElement('Lagrange', 'tetrahedron', 1))
    msh = dmesh.create_mesh(comm, tets, points, domain)
    msh.name = 'mesh'

    mu, lmbda = E / (2 * (1 + NU)), E * NU / ((1 + NU) * (1 - 2 * NU))

    def eps(w):
        return ufl.sym(ufl.grad(w))

    def sigma(w):
        return 2 * mu * eps(w) + lmbda * ufl.tr(eps(w)) * ufl.Identity(3)

    V = fem.VectorFunctionSpace(msh, ('Lagrange', 2))
    u, v = ufl.TrialFunction(V), ufl.TestFunction(V)

    fdim = msh.topology.dim - 1
    left = dmesh.locate_entities_boundary(msh, fdim, lambda x: np.isclose(x[0], -W / 2))
    right = dmesh.locate_entities_boundary(msh, fdim, lambda x: np.isclose(x[0], W / 2))
    order = np.argsort(right)
    tags = dmesh.meshtags(msh, fdim, right[order], np.ones(len(right), dtype=np.int32))
    ds = ufl.Measure('ds', domain=msh, subdomain_data=tags)

    def corner(y):
        return lambda x: np.isclose(x[0], -W / 2) & np.isclose(x[1], y) & np.isclose(x[2], 0.0)
    c0 = dmesh.locate_entities_boundary(msh, 0, corner(-H / 2))
    c1 = dmesh.locate_entities_boundary(msh, 0, corner(H / 2))
    assert len(c0) == 1 and len(c1) == 1, (c0, c1)
    zero = PETSc.ScalarType(0.0)
    bcs = [fem.dirichletbc(zero, fem.locate_dofs_topological(V.sub(0), fdim, left), V.sub(0)),
           fem.dirichletbc(zero, fem.locate_dofs_topological(V.sub(1), 0, c0), V.sub(1)),
           fem.dirichletbc(zero, fem.locate_dofs_topological(V.sub(2), 0, c0), V.sub(2)),
           fem.dirichletbc(zero, fem.locate_dofs_topological(V.sub(2), 0, c1), V.sub(2))]

    traction = fem.Constant(msh, PETSc.ScalarType((S, 0.0, 0.0)))
    a = fem.form(ufl.inner(sigma(u), eps(v)) * ufl.dx)
    L = fem.form(ufl.dot(traction, v) * ds(1))

    t0 = time.time()
    Amat = fem.petsc.assemble_matrix(a, bcs=bcs)
    Amat.assemble()
    b = fem.petsc.assemble_vector(L)
    fem.petsc.apply_lifting(b, [a], bcs=[bcs])
    b.ghostUpdate(addv=PETSc.InsertMode.ADD, mode=PETSc.ScatterMode.REVERSE)
    fem.petsc.set_bc(b, bcs)
    nullspace, _vecs, _basis = rigid_body_modes(V)
    Amat.setNearNullSpace(nullspace)

    opts = PETSc.Options()
    opts['ksp_type'] = 'cg'
    opts['ksp_rtol'] = 1e-10
    opts['ksp_atol'] = 1e-14
    opts['pc_type'] = 'gamg'
    solver = PETSc.KSP().create(comm)
    solver.setFromOptions()
    solver.setOperators(Amat)
    uh = fem.Function(V)
    solver.solve(b, uh.vector)
    uh.x.scatter_forward()
    t_solve = time.time() - t0
    reason, its = solver.getConvergedReason(), solver.getIterationNumber()
    assert reason > 0, reason
    ndofs = V.dofmap.index_map.size_global * V.dofmap.index_map_bs
    print('P2 solve: %d dofs, %d CG iterations (GAMG), converged reason %d, %.1f s (assembly included)'
          % (ndofs, its, reason, t_solve))

    # output fields, as dolfinx users make them
    V1 = fem.VectorFunctionSpace(msh, ('Lagrange', 1))
    T1 = fem.TensorFunctionSpace(msh, ('Lagrange', 1))
    disp = fem.Function(V1, name='displacement')
    disp.interpolate(uh)
    s_, q_ = ufl.TrialFunction(T1), ufl.TestFunction(T1)
    projection = fem.petsc.LinearProblem(
        ufl.inner(s_, q_) * ufl.dx, ufl.inner(sigma(uh), q_) * ufl.dx,
        petsc_options={'ksp_type': 'cg', 'pc_type': 'jacobi', 'ksp_rtol': 1e-12, 'ksp_atol': 1e-14})
    stress = projection.solve()
    stress.name = 'stress'
    disp2 = fem.Function(V1, name='displacement')
    stress2 = fem.Function(T1, name='stress')
    disp2.x.array[:] = 2.0 * disp.x.array       # load factor 2: exactly twice step 1
    stress2.x.array[:] = 2.0 * stress.x.array

    # the peak, from the nodal values (CG1 dofs are at the mesh vertices)
    xs = T1.tabulate_dof_coordinates()
    s = stress.x.array.reshape(-1, 3, 3)
    s = 0.5 * (s + s.transpose(0, 2, 1))
    principal = np.linalg.eigvalsh(s)
    i = int(np.argmax(principal[:, 2]))
    print('peak max principal %.2f MPa (sigma_xx %.2f) at %s; min principal %.2f'
          % (principal[i, 2], s[i, 0, 0], np.round(xs[i], 3), principal[:, 0].min()))

    for ext in ('.xdmf', '.h5'):
        p = os.path.join(folder, XDMF[:-5] + ext)
        if os.path.exists(p):
            os.remove(p)
    with io.XDMFFile(comm, os.path.join(folder, XDMF), 'w') as f:
        f.write_mesh(msh)
        f.write_function(disp, 1.0)
        f.write_function(stress, 1.0)
        f.write_function(disp2, 2.0)
        f.write_function(stress2, 2.0)
    return principal[i, 2], t_solve


# ------------------------------------------------------------ second process

def check(folder, peak):
    """Every read-back check (h5py, meshio), after zeroing the times."""
    import h5py
    import meshio

    h5 = os.path.join(folder, H5)
    print('%s: %d modification times set to 0' % (H5, fc.zero_hdf5_mtimes(h5)))
    for name in (XDMF, H5):
        fc.report(os.path.join(folder, name))
    assert os.path.getsize(h5) < 1_000_000

    with h5py.File(h5, 'r') as f:
        names = []
        f.visititems(lambda n, o: names.append(n) if isinstance(o, h5py.Dataset) else None)
        assert names == ['Function/displacement/1', 'Function/displacement/2', 'Function/stress/1',
                         'Function/stress/2', 'Mesh/mesh/geometry', 'Mesh/mesh/topology'], names
        geo, topo = f['Mesh/mesh/geometry'][:], f['Mesh/mesh/topology'][:]
        assert geo.shape == (N_POINTS, 3) and geo.dtype == np.float64, (geo.shape, geo.dtype)
        assert topo.shape == (N_CELLS, 4) and topo.dtype == np.int64, (topo.shape, topo.dtype)
        assert topo.min() == 0 and topo.max() == N_POINTS - 1
        u1, u2 = f['Function/displacement/1'][:], f['Function/displacement/2'][:]
        s1, s2 = f['Function/stress/1'][:], f['Function/stress/2'][:]
        assert u1.shape == u2.shape == (N_POINTS, 3) and s1.shape == s2.shape == (N_POINTS, 9)
        assert np.array_equal(u2, 2 * u1) and np.array_equal(s2, 2 * s1)
        print('h5: %s; step 2 = 2 x step 1 exactly' % ', '.join(
            '%s %s %s' % (n, f[n].shape, f[n].dtype) for n in names))
    # dolfinx's tetrahedra: positive volume in VTK's node order?
    p = geo[topo]
    vol = np.einsum('ij,ij->i', np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), p[:, 3] - p[:, 0]) / 6
    print('cell volumes: %d positive, %d negative in VTK\'s order; total %.4f (exact %.4f)'
          % ((vol > 0).sum(), (vol < 0).sum(), np.abs(vol).sum(), (W * H - np.pi * A * A) * T))

    t = s1.reshape(-1, 3, 3)
    asym = np.abs(t - t.transpose(0, 2, 1)).max()
    t = 0.5 * (t + t.transpose(0, 2, 1))
    ev = np.linalg.eigvalsh(t)
    i, j = int(np.argmax(ev[:, 2])), int(np.argmin(ev[:, 0]))
    print('step 1: max principal %.2f (sigma_xx %.2f) at %s; min principal %.2f (sigma_yy %.2f) at %s; '
          'asymmetry %.1e' % (ev[i, 2], t[i, 0, 0], np.round(geo[i], 3), ev[j, 0], t[j, 1, 1],
                              np.round(geo[j], 3), asym))
    assert abs(ev[i, 2] - peak) < 1e-9 * peak and asym == 0.0
    assert 32.3 < ev[i, 2] < 32.6 and abs(abs(geo[i, 1]) - A) < 1e-3 and abs(geo[i, 0]) < 0.05
    assert abs(abs(geo[j, 0]) - A) < 1e-3 and abs(geo[j, 1]) < 0.05
    r = np.hypot(geo[:, 0], geo[:, 1])
    top = (r < A + 1e-3) & (np.abs(geo[:, 0]) < 0.05)
    side = (r < A + 1e-3) & (np.abs(geo[:, 1]) < 0.05)
    print('step 1: sigma_xx at the top and bottom of the hole %.2f .. %.2f (%d vertices); '
          'sigma_yy at its sides %.2f .. %.2f (%d)' % (t[top, 0, 0].min(), t[top, 0, 0].max(), top.sum(),
                                                       t[side, 1, 1].min(), t[side, 1, 1].max(), side.sum()))
    far = np.abs(geo[:, 0]) > 8
    print('step 1: sigma_xx at |x| > 8: %.2f .. %.2f (mean %.3f)'
          % (t[far, 0, 0].min(), t[far, 0, 0].max(), t[far, 0, 0].mean()))
    print('step 1: displacement x %.3e .. %.3e, y %.3e .. %.3e, z %.3e .. %.3e'
          % (u1[:, 0].min(), u1[:, 0].max(), u1[:, 1].min(), u1[:, 1].max(), u1[:, 2].min(), u1[:, 2].max()))

    # meshio's XDMF time-series reader takes the mesh from the first uniform
    # grid and the steps from the LAST temporal collection only
    with meshio.xdmf.TimeSeriesReader(os.path.join(folder, XDMF)) as r:
        pts, cells = r.read_points_cells()
        assert np.array_equal(pts, geo) and cells[0].type == 'tetra' and np.array_equal(cells[0].data, topo)
        steps = [r.read_data(k) for k in range(r.num_steps)]
        assert [s for s, _, _ in steps] == [1.0, 2.0]
        assert sorted(steps[0][1]) == ['stress'] and np.array_equal(steps[0][1]['stress'], s1)
        print('meshio TimeSeriesReader: %d points, %d %s, steps %s, point arrays %s (not displacement)'
              % (len(pts), len(cells[0].data), cells[0].type, [s for s, _, _ in steps], sorted(steps[0][1])))


if __name__ == '__main__':
    folder = fc.out_dir()
    if os.environ.get('DOLFINX_PLATE_CHECK'):
        check(folder, float(os.environ['DOLFINX_PLATE_CHECK']))
    else:
        peak, _ = solve_and_write(folder)
        env = dict(os.environ, DOLFINX_PLATE_CHECK=repr(peak))
        subprocess.run([sys.executable, os.path.abspath(__file__), folder], env=env, check=True)
