"""SfePy problem description: a cantilever beam 1.0 x 0.1 x 0.1 (x along the
beam, centred on y = z = 0) of 40 x 4 x 4 hexahedra with tri-quadratic (Q2)
displacements, clamped at x = 0 and loaded at the free end x = 1 by a uniform
downward traction (0, 0, -2) on the end face (total tip force 0.02).
E = 200e3, nu = 0.3; stresses in the units of E. Beam theory: bending stress
sigma_xx = M z / I, at the root about +-0.12 * 1e3 = +-120 (tension on top,
z > 0, compression below).

Standalone:  sfepy-run simple beam_bending_conf.py ; the generator
beam_bending.py solves it and writes ../generated/beam_bending.vtu.
"""
import numpy as nm

from sfepy.base.base import Struct
from sfepy.discrete.fem.meshio import UserMeshIO
from sfepy.mechanics.matcoefs import stiffness_from_youngpoisson
from sfepy.mesh.mesh_generators import gen_block_mesh

TRACTION = 2.0


def mesh_hook(mesh, mode):
    if mode == 'read':
        return gen_block_mesh([1.0, 0.1, 0.1], [41, 5, 5], [0.5, 0.0, 0.0],
                              name='beam', verbose=False)


filename_mesh = UserMeshIO(mesh_hook)

regions = {
    'Omega': 'all',
    'Root': ('vertices in (x < 1e-6)', 'facet'),
    'Tip': ('vertices in (x > 0.999999)', 'facet'),
}
materials = {
    'solid': ({'D': stiffness_from_youngpoisson(3, 200e3, 0.3)},),
    'load': ({'val': nm.array([[0.0], [0.0], [-TRACTION]])},),
}
fields = {'displacement': ('real', 'vector', 'Omega', 2)}
integrals = {'i': 4}
variables = {'u': ('unknown field', 'displacement', 0),
             'v': ('test field', 'displacement', 'u')}
ebcs = {'Clamped': ('Root', {'u.all': 0.0})}
equations = {'balance_of_forces':
             'dw_lin_elastic.i.Omega(solid.D, v, u) = dw_surface_ltr.i.Tip(load.val, v)'}
solvers = {'ls': ('ls.scipy_direct', {}),
           'newton': ('nls.newton', {'i_max': 1, 'eps_a': 1e-10})}


def post_process(out, pb, state, extend=False):
    stress = pb.evaluate('ev_cauchy_stress.i.Omega(solid.D, u)', mode='el_avg')
    out['cauchy_stress'] = Struct(name='output_data', mode='cell', data=stress,
                                  dofs=None)
    return out


options = {'nls': 'newton', 'ls': 'ls', 'post_process_hook': 'post_process',
           'output_format': 'vtk'}
