"""thin_plate_shear.vtu: SfePy thin plate in shear, one hexahedron thick
(problem: thin_plate_shear_conf.py). The element-averaged Cauchy stress is
CELL data, 9 components, array "stress", active tensors; magnitudes ~1e-2."""
import common

pb = common.solve_sfepy('thin_plate_shear_conf.py')
stress = pb.evaluate('ev_cauchy_stress.i.Omega(solid.D, u)', mode='el_avg')
full = common.sfepy_sym_to_full(stress.reshape(-1, 6))
u = pb.get_variables()['u'].get_state_in_region(pb.domain.regions['Omega'])

ug = common.unstructured_grid(pb.domain.mesh.coors, [common.sfepy_cells(pb)])
common.check_positive_volumes(ug)
ug.GetCellData().SetTensors(common.vtk_array(full, 'stress'))
ug.GetPointData().SetVectors(common.vtk_array(u, 'displacement'))
common.write_xml(ug, common.out_path('thin_plate_shear.vtu'))
print('stress range', full.min(), full.max())
