r"""SfePy problem description: steady natural convection of air in a tall 2D
cavity (double glazing): hot wall x = 0, cold wall x = 1, insulated top and
bottom, no-slip walls. Incompressible Navier-Stokes with a Boussinesq
buoyancy force, coupled with the advection-diffusion of heat.

Non-dimensional form: lengths in units of the gap width W, velocity in units
of kappa / W (kappa: thermal diffusivity), pressure in rho kappa^2 / W^2,
temperature theta = (T - T_cold) / (T_hot - T_cold), y pointing up:

    (u . grad) u + grad p = Pr lap u + Ra Pr theta e_y
    div u = 0
    u . grad theta = lap theta

Weak form (Taylor-Hood: Q2 velocity, Q1 pressure; Q2 temperature)::

    dw_div_grad(Pr, v, u) + dw_convect(v, u) - dw_stokes(v, p)
        - de_buoyancy((0, Ra Pr), v, theta) = 0
    dw_stokes(u, q) = 0
    dw_laplace(s, theta) + de_convect_v_grad_s(s, u, theta) = 0

Boundary conditions: u = 0 on all four walls; theta = 1 on x = 0 (hot),
theta = 0 on x = 1 (cold); top and bottom insulated (natural condition);
p = 0 at the bottom-left corner (the pressure of a closed cavity is defined
up to a constant).

The domain [0, 1] x [0, aspect] is meshed with nx x ny quadrilaterals graded
towards all four walls (spacing at a wall 0.4 / 1.6 = 1/4 of the spacing in
the middle) to resolve the thin boundary layers.

Two SfePy 2021.4 terms give wrong results here and are replaced by the
multilinear ('de_') terms defined below: dw_vm_dot_s (the obvious term for
the buoyancy force) assembles into the wrong velocity components, and
dw_convect_v_grad_s (u . grad theta) is wrong on meshes whose elements differ
in size. With the replacements the square cavity reproduces de Vahl Davis's
benchmark (see `double_glazing.py --benchmark`).

define() arguments: ra, pr, aspect, nx, ny, grading. Newton converges from
rest at least up to Ra = 1e5 (13 iterations there); the generator
double_glazing.py still starts at Ra = 1e4 and continues from that solution,
which is as fast and safer. Standalone (default Ra = 1e4; writes SfePy's own legacy VTK
5.1 output, which VTK 9.1 cannot read):

    sfepy-run simple double_glazing_conf.py -o /tmp/double_glazing
"""
import numpy as nm
import scipy.sparse.linalg as sla

from sfepy.discrete.fem import Mesh
from sfepy.discrete.fem.meshio import UserMeshIO
from sfepy.solvers import register_solver
from sfepy.solvers.ls import LinearSolver, standard_call
from sfepy.terms import register_term
from sfepy.terms.terms_multilinear import ETermBase


class BuoyancyTerm(ETermBase):
    r"""Body force proportional to a scalar unknown:
    \int_\Omega \theta \ul{m} \cdot \ul{v} (material vector m, vector test
    v, scalar unknown theta).

    Replaces SfePy 2021.4's dw_vm_dot_s, which puts the force into the wrong
    components (with theta = 1 and m = (0, 1) it also pushes along x)."""
    name = 'de_buoyancy'
    arg_types = ('material', 'virtual', 'state')
    arg_shapes = {'material': 'D, 1', 'virtual': ('D', None), 'state': 1}

    def get_function(self, mat, virtual, state, mode=None, term_mode=None,
                     diff_var=None, **kwargs):
        return self.make_function('i0,i,0', mat, virtual, state,
                                  diff_var=diff_var)


class ConvectVGradSTerm(ETermBase):
    r"""Advection of a scalar by an unknown velocity:
    \int_\Omega s (\ul{u} \cdot \nabla \theta) (scalar test s, vector unknown
    u, scalar unknown theta); differentiated in both unknowns.

    Replaces SfePy 2021.4's dw_convect_v_grad_s, which is right only when all
    elements have the same size: on this graded mesh it is several times too
    small, and the heat transport with it (Nusselt number 1.16 instead of
    2.24 for de Vahl Davis's Ra = 1e4 square cavity)."""
    name = 'de_convect_v_grad_s'
    arg_types = ('virtual', 'state_v', 'state_s')
    arg_shapes = {'virtual': (1, 'state_s'), 'state_v': 'D', 'state_s': 1}

    def get_function(self, virtual, state_v, state_s, mode=None,
                     term_mode=None, diff_var=None, **kwargs):
        return self.make_function('0,i,0.i', virtual, state_v, state_s,
                                  diff_var=diff_var)


class SymmetricSuperLU(LinearSolver):
    """SciPy's SuperLU with the settings SuperLU recommends for matrices with
    a symmetric nonzero pattern: minimum degree ordering of A^T + A and
    pivots kept on the diagonal where possible. About 3x faster here than
    ls.scipy_direct (no UMFPACK in Debian's SciPy), and 200x faster than the
    same ordering without SymmetricMode."""
    name = 'ls.superlu_symmetric'
    _parameters = []

    @standard_call
    def __call__(self, rhs, x0=None, conf=None, eps_a=None, eps_r=None,
                 i_max=None, mtx=None, status=None, **kwargs):
        lu = sla.splu(mtx.tocsc(), permc_spec='MMD_AT_PLUS_A',
                      diag_pivot_thresh=1e-3,
                      options={'SymmetricMode': True})
        return lu.solve(rhs)


register_term(BuoyancyTerm)
register_term(ConvectVGradSTerm)
register_solver(SymmetricSuperLU)


def graded(n, length, strength):
    """n + 1 node coordinates on [0, length], clustered towards both ends:
    the spacing is proportional to 1 - strength cos(2 pi xi)."""
    xi = nm.linspace(0.0, 1.0, n + 1)
    x = xi - strength * nm.sin(2.0 * nm.pi * xi) / (2.0 * nm.pi)
    x[0], x[-1] = 0.0, 1.0
    return length * x


def cavity_mesh(nx, ny, aspect, grading):
    """Quadrilateral mesh of [0, 1] x [0, aspect], nx x ny cells; node
    (i, j) is number i * (ny + 1) + j."""
    xs = graded(nx, 1.0, grading)
    ys = graded(ny, aspect, grading)
    X, Y = nm.meshgrid(xs, ys, indexing='ij')
    coors = nm.column_stack([X.ravel(), Y.ravel()])
    i, j = nm.meshgrid(nm.arange(nx), nm.arange(ny), indexing='ij')
    n0 = (i * (ny + 1) + j).ravel()
    conn = nm.column_stack([n0, n0 + ny + 1, n0 + ny + 2, n0 + 1])  # counter-clockwise
    return Mesh.from_data('cavity', coors, nm.zeros(len(coors), dtype=nm.int32),
                          [conn.astype(nm.int32)],
                          [nm.zeros(len(conn), dtype=nm.int32)], ['2_4'])


def define(ra=1e4, pr=0.71, aspect=4.0, nx=24, ny=64, grading=0.6):
    def mesh_hook(mesh, mode):
        if mode == 'read':
            return cavity_mesh(nx, ny, aspect, grading)

    filename_mesh = UserMeshIO(mesh_hook)

    regions = {
        'Omega': 'all',
        'Hot': ('vertices in (x < 1e-8)', 'facet'),
        'Cold': ('vertices in (x > 0.99999999)', 'facet'),
        'Bottom': ('vertices in (y < 1e-8)', 'facet'),
        'Top': ('vertices in (y > %.12g)' % (aspect - 1e-8), 'facet'),
        'Walls': ('r.Hot +v r.Cold +v r.Bottom +v r.Top', 'facet'),
        'Corner': ('vertices in (x < 1e-8) & (y < 1e-8)', 'vertex'),
    }

    materials = {
        'fluid': ({'viscosity': pr, 'conductivity': 1.0,
                   'buoyancy': nm.array([[0.0], [ra * pr]])},),
    }

    fields = {
        'velocity': ('real', 'vector', 'Omega', 2),
        'pressure': ('real', 'scalar', 'Omega', 1),
        'temperature': ('real', 'scalar', 'Omega', 2),
    }

    variables = {
        'u': ('unknown field', 'velocity', 0),
        'v': ('test field', 'velocity', 'u'),
        'p': ('unknown field', 'pressure', 1),
        'q': ('test field', 'pressure', 'p'),
        't': ('unknown field', 'temperature', 2),
        's': ('test field', 'temperature', 't'),
    }

    ebcs = {
        'NoSlip': ('Walls', {'u.all': 0.0}),
        'HotWall': ('Hot', {'t.0': 1.0}),
        'ColdWall': ('Cold', {'t.0': 0.0}),
        'PressureLevel': ('Corner', {'p.0': 0.0}),
    }

    integrals = {'i': 4}

    equations = {
        'momentum':
        """dw_div_grad.i.Omega(fluid.viscosity, v, u)
         + dw_convect.i.Omega(v, u)
         - dw_stokes.i.Omega(v, p)
         - de_buoyancy.i.Omega(fluid.buoyancy, v, t) = 0""",
        'incompressibility':
        """dw_stokes.i.Omega(u, q) = 0""",
        'energy':
        """dw_laplace.i.Omega(fluid.conductivity, s, t)
         + de_convect_v_grad_s.i.Omega(s, u, t) = 0""",
    }

    solvers = {
        'ls': ('ls.superlu_symmetric', {}),
        'newton': ('nls.newton', {
            'i_max': 25,
            'eps_a': 1e-9,
            'eps_r': 1e-12,
            'lin_red': 1e3,         # warn only if |A x - b| > 1e-6
            'ls_on': 0.99999,       # back-tracking line search if the residual grows
            'ls_red': 0.5,
            'ls_min': 1e-4,
        }),
    }

    options = {'nls': 'newton', 'ls': 'ls', 'output_format': 'vtk'}

    return {k: v for k, v in locals().items()
            if k in ('filename_mesh', 'regions', 'materials', 'fields',
                     'variables', 'ebcs', 'integrals', 'equations',
                     'solvers', 'options')}
