"""SfePy problem description: a steel L-bracket in MILLIMETRES and MPa,
linear elasticity on gmsh's linear tetrahedra with quadratic (P2)
displacements. Solved and written by l_bracket.py.

Geometry: an L in the x-z plane, 20 mm thick (y in [0, 20]): the vertical
arm x in [0, 20], z in [0, 100] and the horizontal arm x in [0, 100],
z in [0, 20]; the re-entrant (inner) corner is the edge x = z = 20, sharp,
no fillet (so the stress there is singular and grows with refinement, as in
any user's sharp-cornered model). Mesh size 1.5 mm (full) or 2.5 mm (small)
along that edge, growing to 5 mm (7 mm) 40 mm from it: ~9k and ~3k
tetrahedra. (1 mm gives 14k tetrahedra, but SciPy's SuperLU then takes 3
minutes and 2.2 GB; 1.5 mm takes 1 minute and 1.3 GB.)

Loads: the end face z = 100 of the vertical arm clamped (u = 0); the end
face x = 100 of the horizontal arm loaded sideways, across the arm, by the
downward traction (0, 0, -5) MPa on its 20 x 20 mm (a force of 2 kN).
E = 210000 MPa, nu = 0.3.

Standalone: sfepy-run simple l_bracket_conf.py -d "cells='small'"
"""
import os
import sys

import numpy as nm

from sfepy.base.base import Struct
from sfepy.discrete.fem import Mesh
from sfepy.discrete.fem.meshio import UserMeshIO
from sfepy.mechanics.matcoefs import stiffness_from_youngpoisson

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import untuned_common as uc  # noqa: E402

ARM, LONG, THICK = 20.0, 100.0, 20.0      # mm
TRACTION = 5.0                            # MPa, on the 20 x 20 end face
E, NU = 210000.0, 0.3


def bracket_tets(h_corner, h_far):
    def build(gmsh):
        occ = gmsh.model.occ
        vertical = occ.addBox(0, 0, 0, ARM, THICK, LONG)
        horizontal = occ.addBox(0, 0, 0, LONG, THICK, ARM)
        occ.fuse([(3, vertical)], [(3, horizontal)])
        occ.synchronize()
        # The re-entrant edge x = z = ARM, y in [0, THICK]: refine towards it.
        corner = [tag for _, tag in gmsh.model.getEntities(1)
                  if nm.allclose(occ.getCenterOfMass(1, tag), [ARM, THICK / 2, ARM])]
        assert len(corner) == 1, corner
        uc.size_field(gmsh, 1, corner, h_corner, h_far, 2 * ARM)
    return uc.gmsh_tets(build)


def define(cells='full'):
    h_corner, h_far = {'full': (1.5, 5.0), 'small': (2.5, 7.0)}[cells]

    def mesh_hook(mesh, mode):
        if mode == 'read':
            points, tets = bracket_tets(h_corner, h_far)
            return Mesh.from_data('l_bracket', points, None, [tets.astype(nm.int32)],
                                  [nm.zeros(len(tets), dtype=nm.int32)], ['3_4'])

    eps = 1e-6
    filename_mesh = UserMeshIO(mesh_hook)
    regions = {
        'Omega': 'all',
        'Clamp': ('vertices in (z > %.8f)' % (LONG - eps), 'facet'),
        'Tip': ('vertices in (x > %.8f)' % (LONG - eps), 'facet'),
    }
    materials = {
        'solid': ({'D': stiffness_from_youngpoisson(3, E, NU)},),
        'load': ({'val': nm.array([[0.0], [0.0], [-TRACTION]])},),
    }
    fields = {'displacement': ('real', 'vector', 'Omega', 2)}
    integrals = {'i': 2}
    variables = {'u': ('unknown field', 'displacement', 0),
                 'v': ('test field', 'displacement', 'u')}
    ebcs = {'Clamped': ('Clamp', {'u.all': 0.0})}
    equations = {'balance_of_forces':
                 'dw_lin_elastic.i.Omega(solid.D, v, u) = dw_surface_ltr.i.Tip(load.val, v)'}
    solvers = {'ls': ('ls.scipy_direct', {}),
               'newton': ('nls.newton', {'i_max': 1, 'eps_a': 1e-8})}

    def post_process(out, pb, state, extend=False):
        stress = pb.evaluate('ev_cauchy_stress.i.Omega(solid.D, u)', mode='el_avg')
        out['cauchy_stress'] = Struct(name='output_data', mode='cell', data=stress,
                                      dofs=None)
        return out

    options = {'nls': 'newton', 'ls': 'ls', 'post_process_hook': post_process,
               'output_format': 'vtk'}
    return locals()
