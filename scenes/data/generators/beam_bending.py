"""beam_bending.vtu: SfePy cantilever beam in bending (problem:
beam_bending_conf.py). The element-averaged Cauchy stress is averaged onto
the points (each point: the mean of its cells, as vtkCellDataToPointData
does) and stored as POINT data, 9 components, array "stress", active
tensors; the (vertex) displacement is point data too."""
import common

ug, full, point_stress = common.sfepy_stress_grid(common.solve_sfepy('beam_bending_conf.py'))
common.write_xml(ug, common.out_path('beam_bending.vtu'))
print('point stress range', point_stress.min(), point_stress.max())
