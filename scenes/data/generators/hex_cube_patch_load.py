"""hex_cube_patch_load.vtu: SfePy linear elasticity on a unit cube of 8^3
hexahedra (problem: hex_cube_patch_load_conf.py). Output: the element-averaged
Cauchy stress as CELL data, 6 components in VTK order (XX, YY, ZZ, XY, YZ,
XZ), array "stress", active tensors; the displacement as point data."""

import common

pb = common.solve_sfepy('hex_cube_patch_load_conf.py')
stress = pb.evaluate('ev_cauchy_stress.i.Omega(solid.D, u)', mode='el_avg')
full = common.sfepy_sym_to_full(stress.reshape(-1, 6))
u = pb.get_variables()['u'].get_state_in_region(pb.domain.regions['Omega'])

ug = common.unstructured_grid(pb.domain.mesh.coors, [common.sfepy_cells(pb)])
common.check_positive_volumes(ug)
ug.GetCellData().SetTensors(common.vtk_array(common.full_to_vtk_sym(full), 'stress'))
ug.GetPointData().SetVectors(common.vtk_array(u, 'displacement'))
common.write_xml(ug, common.out_path('hex_cube_patch_load.vtu'))
print('stress range', full.min(), full.max())
