"""SfePy problem description: unit cube of 8x8x8 hexahedra, bottom face
(z = 0) clamped, a square patch of the top face (0.25 <= x, y <= 0.75,
z = 1) pushed down by 0.03. Linear elasticity, E = 1000, nu = 0.3
(stress in the units of E).

Standalone:  sfepy-run simple hex_cube_patch_load_conf.py  (writes a .vtk with
the element-averaged Cauchy stress); the generator hex_cube_patch_load.py
solves it and writes ../generated/hex_cube_patch_load.vtu.
"""
from sfepy.base.base import Struct
from sfepy.discrete.fem.meshio import UserMeshIO
from sfepy.mechanics.matcoefs import stiffness_from_youngpoisson
from sfepy.mesh.mesh_generators import gen_block_mesh

CELLS = 8
PUSH = -0.03


def mesh_hook(mesh, mode):
    if mode == 'read':
        return gen_block_mesh([1.0, 1.0, 1.0], [CELLS + 1] * 3, [0.5, 0.5, 0.5],
                              name='hex_cube', verbose=False)


filename_mesh = UserMeshIO(mesh_hook)

eps = 1e-6
regions = {
    'Omega': 'all',
    'Bottom': ('vertices in (z < %.8f)' % eps, 'facet'),
    'Patch': ('vertices in (z > %.8f) & (x > %.8f) & (x < %.8f) & (y > %.8f) & (y < %.8f)'
              % (1 - eps, 0.25 - eps, 0.75 + eps, 0.25 - eps, 0.75 + eps), 'facet'),
}
materials = {'solid': ({'D': stiffness_from_youngpoisson(3, 1000.0, 0.3)},)}
fields = {'displacement': ('real', 'vector', 'Omega', 1)}
integrals = {'i': 2}
variables = {'u': ('unknown field', 'displacement', 0),
             'v': ('test field', 'displacement', 'u')}
ebcs = {
    'Clamped': ('Bottom', {'u.all': 0.0}),
    'Pushed': ('Patch', {'u.2': PUSH, 'u.[0,1]': 0.0}),
}
equations = {'balance_of_forces': 'dw_lin_elastic.i.Omega(solid.D, v, u) = 0'}
solvers = {'ls': ('ls.scipy_direct', {}),
           'newton': ('nls.newton', {'i_max': 1, 'eps_a': 1e-10})}


def post_process(out, pb, state, extend=False):
    stress = pb.evaluate('ev_cauchy_stress.i.Omega(solid.D, u)', mode='el_avg')
    out['cauchy_stress'] = Struct(name='output_data', mode='cell', data=stress,
                                  dofs=None)
    return out


options = {'nls': 'newton', 'ls': 'ls', 'post_process_hook': 'post_process',
           'output_format': 'vtk'}
