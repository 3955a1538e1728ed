#pragma once
// The part of a volume that holds data. Diffusion tools write tensors of
// exactly zero outside the brain's mask (FSL's dtifit, MRtrix), and a voxel
// model's void holds no stress: the body is where the tensors are not
// zero, and its outline is that region's surface, not the grid's box (a
// brain's tracts filled a third of a picture framed on its grid).

#include <cstdint>
#include <vector>

#include <vtkSmartPointer.h>

class vtkImageData;
class vtkPolyData;

namespace hsb {

// Whether a grid's values hold data, one flag per point in VTK's point
// order, gives a background worth outlining: at least this share of the
// points without data (a few zero points are no background).
constexpr double kBackgroundShare = 0.05;

// The surface around the points of `image` whose flag is set, in the
// image's physical space (its direction matrix applied): the flags
// blurred by a binomial kernel of about a voxel's width, so the outline
// is smooth rather than a staircase of voxel faces, and contoured
// halfway; a layer of empty points padded around the grid closes the
// surface where the data reaches the grid's edge. Null where the flags
// leave no background (kBackgroundShare) or nothing at all.
vtkSmartPointer<vtkPolyData> data_region_surface(vtkImageData* image, const std::vector<std::uint8_t>& has_data);

}  // namespace hsb
