#pragma once
// 2-D results: a mesh of triangles, quads or polygons in a plane x, y or
// z = const (plane stress, plane strain, a membrane), with tensors of 3
// or 4 components (in the z plane) or 6 or 9. Such a mesh has no
// volume to trace in, so it is made one: extruded into a thin slab of
// wedges and hexahedra about its plane, its values the same through the
// thickness. Trajectories seeded in the mid-plane stay in it.
//
// The in-plane principal stresses are what a 2-D result is about: the
// tensors' out-of-plane normal component is set to the mean of the
// in-plane ones and their out-of-plane shears to zero, so that the major
// and minor eigenvalues are always the in-plane ones and the medium
// eigenvector is the plane's normal. (The von Mises and mean colours are
// then of that state, not of σzz.) The glyph pipeline flattens glyphs
// along the normal and looks at the plane from its normal
// (field/glyph_pipeline.h). Internal to field/.

#include <optional>

#include <vtkDataSet.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>

namespace hsb {

struct PlaneOfData {
  int axis = 2;             // the normal: 0 x, 1 y, 2 z
  double coordinate = 0.0;  // where the plane is along it
  double thickness = 0.0;   // of the slab it was made into
};

// The plane x, y or z = const `data` lies in, if it has no 3-D cell and
// all its points lie in that plane (2-D cells, or a planar point cloud);
// nothing for a body, nor for a curved or oblique surface (a shell: drawn
// at its points, without volume).
std::optional<PlaneOfData> find_plane(vtkDataSet* data);

// `data` (2-D cells in `plane`) as a slab of `plane.thickness`: triangles
// become wedges, quads hexahedra, other 2-D cells wedges of their
// triangles; 0-D and 1-D cells are left out. Point data is the same on
// both faces, cell data on every cell made from a cell. Its arrays of 3
// or 4 components named as stress or strain become 6-component tensors (z
// plane only: XX YY XY; XX XY YX YY; XX YY ZZ XY), those of 2 components
// vectors (X Y 0), and every tensor array is made planar (above). The plane is
// recorded with the data, for plane_of(). Data without 2-D cells (a
// planar point cloud) has nothing to extrude: it keeps its points and
// cells, its arrays made planar the same way.
vtkSmartPointer<vtkDataSet> extruded(vtkDataSet* data, const PlaneOfData& plane);

// The plane extruded() recorded in `data`, if any.
std::optional<PlaneOfData> plane_of(vtkDataSet* data);

}  // namespace hsb
