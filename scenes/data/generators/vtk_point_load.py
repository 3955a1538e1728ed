"""vtk_point_load.vti: VTK's own vtkPointLoad source (Boussinesq's solution
for a point load on an elastic half-space), sampled at 25^3 points in its
default model bounds [-1, 1]^3. The load (LoadValue 100, Poisson ratio 0.3)
acts at the centre of the top face (0, 0, 1), where vtkPointLoad writes a
marker value of 1e38 into the diagonal of the tensor (and into the scalar)
instead of the singular stress. The marker is kept on purpose.

Arrays (point data, float32): "PointLoadTensors" (9 components, active
tensors) and "ImageScalars" (effective stress, active scalars)."""
import vtk

import common

source = vtk.vtkPointLoad()
source.SetSampleDimensions(25, 25, 25)
# vtkPointLoad warns "Attempting to set singularity, resetting" when a sample
# hits the load point; that is exactly the case we want, so do not print it.
vtk.vtkObject.GlobalWarningDisplayOff()
source.Update()
vtk.vtkObject.GlobalWarningDisplayOn()

image = vtk.vtkImageData()
image.DeepCopy(source.GetOutput())
assert image.GetPointData().GetTensors().GetName() == 'PointLoadTensors'
common.write_xml(image, common.out_path('vtk_point_load.vti'))
