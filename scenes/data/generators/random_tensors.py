"""random_tensors.vti: a uniform grid of 12 x 10 x 8 points with spacing
(0.3, 0.5, 0.2) and origin (-1.5, 2.0, 0.7) holding independent random
symmetric tensors: every component uniform in [-2, 2] (mixed signs,
magnitude ~1, no spatial correlation at all). 6 components in VTK order
XX, YY, ZZ, XY, YZ, XZ, point data, array "random_tensor", active tensors.
Seeded with numpy's legacy RandomState (its stream never changes)."""
import numpy as np
import vtk

import common

DIMS = (12, 10, 8)
rng = np.random.RandomState(20240611)
values = rng.uniform(-2.0, 2.0, size=(int(np.prod(DIMS)), 6))

image = vtk.vtkImageData()
image.SetDimensions(*DIMS)
image.SetSpacing(0.3, 0.5, 0.2)
image.SetOrigin(-1.5, 2.0, 0.7)
image.GetPointData().SetTensors(common.vtk_array(values, 'random_tensor'))
common.write_xml(image, common.out_path('random_tensors.vti'))
