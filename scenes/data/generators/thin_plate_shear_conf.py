"""SfePy problem description: a thin square plate 1 x 1 x 0.01 (one layer of
24 x 24 x 1 hexahedra, so it is nearly 2D), its edge y = 0 clamped and its
edge y = 1 moved sideways by u_x = 0.01 (in-plane shear: a squat shear
wall, with in-plane bending tension/compression along the edges x = 0, 1).
E = 1, nu = 0.3, so stresses are small: of order 1e-3 to 1e-2.

Standalone:  sfepy-run simple thin_plate_shear_conf.py ; the generator
thin_plate_shear.py solves it and writes ../generated/thin_plate_shear.vtu.
"""
from sfepy.base.base import Struct
from sfepy.discrete.fem.meshio import UserMeshIO
from sfepy.mechanics.matcoefs import stiffness_from_youngpoisson
from sfepy.mesh.mesh_generators import gen_block_mesh


def mesh_hook(mesh, mode):
    if mode == 'read':
        return gen_block_mesh([1.0, 1.0, 0.01], [25, 25, 2], [0.5, 0.5, 0.005],
                              name='thin_plate', verbose=False)


filename_mesh = UserMeshIO(mesh_hook)

regions = {
    'Omega': 'all',
    'Bottom': ('vertices in (y < 0.000001)', 'facet'),
    'Top': ('vertices in (y > 0.999999)', 'facet'),
}
materials = {'solid': ({'D': stiffness_from_youngpoisson(3, 1.0, 0.3)},)}
fields = {'displacement': ('real', 'vector', 'Omega', 1)}
integrals = {'i': 2}
variables = {'u': ('unknown field', 'displacement', 0),
             'v': ('test field', 'displacement', 'u')}
ebcs = {
    'Clamped': ('Bottom', {'u.all': 0.0}),
    'Sheared': ('Top', {'u.0': 0.01, 'u.[1,2]': 0.0}),
}
equations = {'balance_of_forces': 'dw_lin_elastic.i.Omega(solid.D, v, u) = 0'}
solvers = {'ls': ('ls.scipy_direct', {}),
           'newton': ('nls.newton', {'i_max': 1, 'eps_a': 1e-14, 'eps_r': 1e-10})}


def post_process(out, pb, state, extend=False):
    stress = pb.evaluate('ev_cauchy_stress.i.Omega(solid.D, u)', mode='el_avg')
    out['cauchy_stress'] = Struct(name='output_data', mode='cell', data=stress,
                                  dofs=None)
    return out


options = {'nls': 'newton', 'ls': 'ls', 'post_process_hook': 'post_process',
           'output_format': 'vtk'}
