"""plate_with_hole_mm_pa.vtu: SfePy plate with a hole, coordinates in mm,
stress in Pa (problem: plate_with_hole_mm_pa_conf.py). Linear tetrahedra.
The element-averaged Cauchy stress is averaged onto the points
(each point: the mean of its cells, as vtkCellDataToPointData does) and
stored as POINT data, 9 components, array "stress", active tensors;
displacement (mm) as point data."""
import common

pb = common.solve_sfepy('plate_with_hole_mm_pa_conf.py')
stress = pb.evaluate('ev_cauchy_stress.i.Omega(solid.D, u)', mode='el_avg')
full = common.sfepy_sym_to_full(stress.reshape(-1, 6))
mesh = pb.domain.mesh
u = pb.get_variables()['u'].get_state_in_region(pb.domain.regions['Omega'])

ug = common.unstructured_grid(mesh.coors, [common.sfepy_cells(pb)])
common.check_positive_volumes(ug)
ug.GetCellData().AddArray(common.vtk_array(full, 'stress'))
point_stress = common.cell_to_point(ug, 'stress')
ug.GetCellData().RemoveArray('stress')
ug.GetPointData().SetTensors(common.vtk_array(point_stress, 'stress'))
ug.GetPointData().SetVectors(common.vtk_array(u, 'displacement'))
common.write_xml(ug, common.out_path('plate_with_hole_mm_pa.vtu'))
print('cell stress range', full.min(), full.max())
print('point stress range', point_stress.min(), point_stress.max())
