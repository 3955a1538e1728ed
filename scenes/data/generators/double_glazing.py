"""double_glazing.vtu: steady natural convection of air between a hot and a
cold glass pane (a double-glazing gap), solved with SfePy
(double_glazing_conf.py: Navier-Stokes + Boussinesq buoyancy + heat
advection-diffusion, 2D, non-dimensional) and written as a thin 3D slab of
hexahedra in SI units:

    x across the gap, 0 (hot pane) .. W (cold pane), metres
    y up, 0 .. H (gravity along -y), metres
    z depth, 0 .. DEPTH, three identical layers of points, metres

POINT data: "velocity" (m/s, 3 components, z = 0; active vectors),
"temperature" (K; active scalars) and "speed" (|velocity|, m/s).

    /usr/bin/python3 double_glazing.py [OUTDIR] [--benchmark]

OUTDIR defaults to ../generated. --benchmark only re-solves de Vahl Davis's
square-cavity benchmark with the same SfePy problem and prints the
comparison (nothing is written). Deterministic: single-threaded BLAS, a direct
solver, no random input.
"""
import os
import sys

# Single-threaded BLAS (same bits on every run) and no display for the
# matplotlib that SfePy imports.
for _var in ('OPENBLAS_NUM_THREADS', 'OMP_NUM_THREADS', 'MKL_NUM_THREADS'):
    os.environ.setdefault(_var, '1')
os.environ.setdefault('MPLBACKEND', 'Agg')
sys.dont_write_bytecode = True      # no __pycache__ for the imported conf file

import time

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

import common

HERE = os.path.dirname(os.path.abspath(__file__))
CONF = os.path.join(HERE, 'double_glazing_conf.py')

# --- The physical problem -------------------------------------------------
W = 0.04            # gap width (m): pane to pane
H = 0.16            # height (m); aspect ratio H / W = 4
DEPTH = 0.005       # thickness of the written slab (m); the flow is 2D
T_HOT = 303.15      # pane at x = 0 (K), 30 C
T_COLD = 288.15     # pane at x = W (K), 15 C
G = 9.81            # gravity (m/s^2), along -y

# Mesh of the 2D solve: NX x NY Q2 elements, graded towards the walls. The
# solution changes by < 0.2% in speed and heat flux from 24 x 64 to 40 x 120.
NX, NY, GRADING = 24, 64, 0.6
RA_START = 1e4      # Newton from rest converges here; then one step to Ra


def air_properties(t_mean, pressure=101325.0):
    """Dry air at t_mean (K), 1 atm: ideal gas, Sutherland's laws for the
    viscosity and the thermal conductivity (constants from F. M. White,
    Viscous Fluid Flow), cp = 1006 J/(kg K). Returns nu, kappa, beta."""
    rho = pressure / (287.05 * t_mean)
    mu = 1.716e-5 * (t_mean / 273.15) ** 1.5 * (273.15 + 110.4) / (t_mean + 110.4)
    k = 0.0241 * (t_mean / 273.15) ** 1.5 * (273.15 + 194.0) / (t_mean + 194.0)
    cp = 1006.0
    return mu / rho, k / (rho * cp), 1.0 / t_mean


def make_problem(**define_args):
    from sfepy.base.conf import ProblemConf, get_standard_keywords
    from sfepy.discrete import Problem
    required, other = get_standard_keywords()
    conf = ProblemConf.from_file(CONF, required, other, define_args=define_args)
    return Problem.from_conf(conf)


def solve_continuation(ras, **define_args):
    """Solve at each Rayleigh number in turn, each from the previous
    solution. Returns the last Problem and State."""
    from sfepy.base.base import IndexedStruct
    state = None
    for ra in ras:
        t0 = time.time()
        pb = make_problem(ra=ra, **define_args)
        status = IndexedStruct()
        state = pb.solve(state0=state, save_results=False, status=status)
        nls = status.nls_status
        print('  Ra = %.4g: %d Newton iterations, residual %.1e, %.1f s'
              % (ra, nls.n_iter, nls.err, time.time() - t0))
        if nls.condition != 0 or nls.err > 1e-7:
            raise RuntimeError('Newton did not converge at Ra = %g' % ra)
    return pb, state


def lattice_values(pb, state):
    """The Q2 nodal values on their tensor-product lattice: the element
    vertices and edge midpoints of the (rectangular) elements. Returns xs
    (nx1,), ys (ny1,) and U, V, THETA (nx1, ny1), non-dimensional."""
    field = pb.get_variables()['u'].field
    coors = field.get_coor()
    assert np.array_equal(coors, pb.get_variables()['t'].field.get_coor())
    parts = state.get_parts()
    uv = parts['u'].reshape(-1, 2)
    theta = parts['t']
    axes = []
    for k in range(2):
        c = np.sort(coors[:, k])
        keep = np.concatenate([[True], np.diff(c) > 1e-9])
        axes.append(c[keep])
    xs, ys = axes
    ix = np.abs(coors[:, 0:1] - xs[None, :]).argmin(axis=1)
    iy = np.abs(coors[:, 1:2] - ys[None, :]).argmin(axis=1)
    assert np.abs(xs[ix] - coors[:, 0]).max() < 1e-9
    assert np.abs(ys[iy] - coors[:, 1]).max() < 1e-9
    shape = (len(xs), len(ys))
    assert len(coors) == shape[0] * shape[1]
    out = []
    for values in (uv[:, 0], uv[:, 1], theta):
        a = np.full(shape, np.nan)
        a[ix, iy] = values
        assert not np.isnan(a).any()
        out.append(a)
    return xs, ys, out[0], out[1], out[2]


def slab_grid(xs, ys, zs):
    """Points (x fastest, then y, then z) and hexahedra of the lattice."""
    nx1, ny1, nz1 = len(xs), len(ys), len(zs)
    Z, Y, X = np.meshgrid(zs, ys, xs, indexing='ij')
    points = np.column_stack([X.ravel(), Y.ravel(), Z.ravel()])
    k, j, i = np.meshgrid(np.arange(nz1 - 1), np.arange(ny1 - 1), np.arange(nx1 - 1),
                          indexing='ij')
    n0 = ((k * ny1 + j) * nx1 + i).ravel()
    dx, dy, dz = 1, nx1, nx1 * ny1
    hexes = np.column_stack([n0, n0 + dx, n0 + dx + dy, n0 + dy,
                             n0 + dz, n0 + dz + dx, n0 + dz + dx + dy, n0 + dz + dy])
    return points, hexes


def nusselt(xs, ys, theta):
    """Mean Nusselt number on the hot wall (x = 0): -mean d(theta)/dx, the
    wall gradient from the quadratic through the first three nodes (one
    element)."""
    h1, h2 = xs[1] - xs[0], xs[2] - xs[0]
    d = ((theta[1] - theta[0]) * h2 / (h1 * (h2 - h1))
         - (theta[2] - theta[0]) * h1 / (h2 * (h2 - h1)))
    return -np.trapz(d, ys) / (ys[-1] - ys[0])


def benchmark():
    """de Vahl Davis (1983), Int. J. Numer. Meth. Fluids 3, 249-264: square
    cavity, Pr = 0.71; velocities in units of kappa / L."""
    ref = {1e3: (3.649, 0.813, 3.697, 0.178, 1.118),
           1e4: (16.178, 0.823, 19.617, 0.119, 2.243),
           1e5: (34.73, 0.855, 68.59, 0.066, 4.519),
           1e6: (64.63, 0.850, 219.36, 0.0379, 8.800)}
    print('de Vahl Davis benchmark, square cavity, 30 x 30 graded Q2 elements')
    state = None
    from sfepy.base.base import IndexedStruct
    for ra, (umax, yu, vmax, xv, nu) in ref.items():
        pb = make_problem(ra=ra, pr=0.71, aspect=1.0, nx=30, ny=30, grading=GRADING)
        status = IndexedStruct()
        state = pb.solve(state0=state, save_results=False, status=status)
        xs, ys, U, V, TH = lattice_values(pb, state)
        i, j = len(xs) // 2, len(ys) // 2
        iu, jv = U[i].argmax(), V[:, j].argmax()
        print('  Ra %.0e: u_max %7.3f at y %.3f (ref %7.3f at %.3f); v_max %7.2f at x %.4f '
              '(ref %7.2f at %.4f); Nu %.3f (ref %.3f)'
              % (ra, U[i, iu], ys[iu], umax, yu, V[jv, j],
                 xs[jv], vmax, xv, nusselt(xs, ys, TH), nu))


class Messages(vtk.vtkOutputWindow):
    """Collects VTK's warnings and errors."""
    def __init__(self):
        self.messages = []

    def DisplayText(self, text):
        self.messages.append(text)

    DisplayErrorText = DisplayWarningText = DisplayGenericWarningText = DisplayText


def main():
    from sfepy.base.base import output
    output.set_output(quiet=True)
    args = [a for a in sys.argv[1:] if not a.startswith('--')]
    if '--benchmark' in sys.argv[1:]:
        benchmark()
        return
    folder = args[0] if args else os.path.join(HERE, '..', 'generated')
    os.makedirs(folder, exist_ok=True)
    path = os.path.join(folder, 'double_glazing.vtu')
    t_start = time.time()

    dT = T_HOT - T_COLD
    nu, kappa, beta = air_properties(0.5 * (T_HOT + T_COLD))
    pr = nu / kappa
    ra = G * beta * dT * W ** 3 / (nu * kappa)
    u_scale = kappa / W
    print('air at %.2f K: nu %.4g m2/s, kappa %.4g m2/s, beta %.4g 1/K; '
          'Pr %.3f, Ra %.4g (on W), aspect %g, velocity unit kappa/W %.4g m/s'
          % (0.5 * (T_HOT + T_COLD), nu, kappa, beta, pr, ra, H / W, u_scale))
    pb, state = solve_continuation([RA_START, ra], pr=pr, aspect=H / W,
                                   nx=NX, ny=NY, grading=GRADING)
    xs, ys, U, V, TH = lattice_values(pb, state)

    # FE divergence of the solved velocity (element averages).
    div_el = pb.evaluate('ev_div.i.Omega(u)', mode='el_avg').ravel()
    h_el = np.sqrt(pb.evaluate('ev_volume.i.Omega(u)', mode='el_avg').ravel())

    # --- To SI units and a thin 3D slab ----------------------------------
    zs = np.linspace(0.0, DEPTH, 3)
    points, hexes = slab_grid(xs * W, ys * W, zs)
    nz1 = len(zs)
    vx = np.tile((U * u_scale).T.ravel(), nz1)     # lattice (i, j) -> x fastest
    vy = np.tile((V * u_scale).T.ravel(), nz1)
    temp = np.tile((T_COLD + TH * dT).T.ravel(), nz1)
    velocity = np.column_stack([vx, vy, np.zeros_like(vx)])
    speed = np.sqrt(vx ** 2 + vy ** 2)

    ug = common.unstructured_grid(points, [(vtk.VTK_HEXAHEDRON, hexes)])
    common.check_positive_volumes(ug)
    pd = ug.GetPointData()
    pd.SetVectors(common.vtk_array(velocity, 'velocity'))
    pd.SetScalars(common.vtk_array(temp, 'temperature'))
    pd.AddArray(common.vtk_array(speed, 'speed'))
    common.write_xml(ug, path)

    # --- Read back (no VTK warnings allowed) ------------------------------
    messages = Messages()
    vtk.vtkOutputWindow.SetInstance(messages)
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    ds = reader.GetOutput()
    if messages.messages:
        raise RuntimeError('VTK messages reading %s: %s' % (path, messages.messages))
    rpd = ds.GetPointData()
    assert rpd.GetVectors().GetName() == 'velocity'
    assert rpd.GetScalars().GetName() == 'temperature'
    v_back = vtk_to_numpy(rpd.GetArray('velocity'))
    assert np.array_equal(v_back, velocity)

    # --- Checks of the flow ------------------------------------------------
    X, Y = np.meshgrid(xs * W, ys * W, indexing='ij')
    S = np.hypot(U, V) * u_scale
    Vp = V * u_scale
    mid = (Y > 0.1 * H) & (Y < 0.9 * H)
    hot_band = mid & (X > 0) & (X < 0.15 * W)         # walls (v = 0) excluded
    cold_band = mid & (X < W) & (X > 0.85 * W)
    core = (np.abs(X - 0.5 * W) < 0.2 * W) & (Y > 0.2 * H) & (Y < 0.8 * H)
    jm = len(ys) // 2                                     # y = H / 2
    ip = Vp[:, jm].argmax()
    ic = Vp[:, jm].argmin()
    # Divergence of the point data on the lattice (what a tracer sees),
    # second-order differences; relative to max|v| / local spacing.
    dUdx = np.gradient(U, xs, axis=0, edge_order=2)
    dVdy = np.gradient(V, ys, axis=1, edge_order=2)
    hx = np.gradient(xs)[:, None]
    hy = np.gradient(ys)[None, :]
    smax = np.hypot(U, V).max()
    div_rel_lattice = (np.abs(dUdx + dVdy) * np.minimum(hx, hy)).max() / smax
    div_rel_fe = (np.abs(div_el) * h_el).max() / smax
    # Heat flux through vertical lines (should not depend on x).
    flux = np.trapz(U * TH - np.gradient(TH, xs, axis=0, edge_order=2), ys, axis=1)
    centre = len(xs) // 2

    b = ds.GetBounds()
    print('file %s: %d bytes' % (path, os.path.getsize(path)))
    print('bounds x [%g, %g] y [%g, %g] z [%g, %g] m; %d points, %d hexahedra '
          '(lattice %d x %d x %d points)'
          % (*b, ds.GetNumberOfPoints(), ds.GetNumberOfCells(), len(xs), len(ys), nz1))
    print('speed [%.4g, %.4g] m/s; velocity x [%.4g, %.4g], y [%.4g, %.4g] m/s; '
          'temperature [%.2f, %.2f] K'
          % (speed.min(), speed.max(), vx.min(), vx.max(), vy.min(), vy.max(),
             temp.min(), temp.max()))
    print('mean speed: hot-wall band (x < 0.15 W) %.4g, cold-wall band (x > 0.85 W) %.4g, '
          'core (|x - W/2| < 0.2 W, 0.2 H < y < 0.8 H) %.4g m/s; max in core %.4g m/s'
          % (S[hot_band].mean(), S[cold_band].mean(), S[core].mean(), S[core].max()))
    print('at y = H/2: v up to %+.4g m/s at x = %.2f mm (hot side), down to %+.4g m/s '
          'at x = %.2f mm (cold side), %+.2g m/s at the centre'
          % (Vp[ip, jm], 1e3 * X[ip, jm], Vp[ic, jm], 1e3 * X[ic, jm], Vp[centre, jm]))
    print('v > 0 at %.1f%% of the points of the hot-wall band, v < 0 at %.1f%% of the '
          'cold-wall band (walls excluded)'
          % (100 * (Vp[hot_band] > 0).mean(), 100 * (Vp[cold_band] < 0).mean()))
    print('core stratification: T at x = W/2: %.2f K (y = H/4), %.2f K (H/2), %.2f K (3H/4)'
          % tuple(T_COLD + dT * TH[centre, int(round(f * (len(ys) - 1)))] for f in (0.25, 0.5, 0.75)))
    print('Nusselt number (hot wall) %.3f; heat flux through x = const varies by %.2f%%'
          % (nusselt(xs, ys, TH), 100 * (flux.max() - flux.min()) / flux.mean()))
    print('max |div v| * h / max|v|: %.2g (FE element averages), %.2g (point data, '
          'finite differences on the lattice)' % (div_rel_fe, div_rel_lattice))
    assert S[core].mean() < 0.25 * min(S[hot_band].mean(), S[cold_band].mean())
    assert (Vp[hot_band] > 0).all() and (Vp[cold_band] < 0).all()
    assert Vp[ip, jm] > 0 and Vp[ic, jm] < 0 and X[ip, jm] < 0.25 * W and X[ic, jm] > 0.75 * W
    print('done in %.1f s' % (time.time() - t_start))


if __name__ == '__main__':
    main()
