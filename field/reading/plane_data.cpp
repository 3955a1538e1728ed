#include "field/reading/plane_data.h"

#include <vtkCell.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkPointData.h>
#include <vtkPoints.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "field/reading/component_arrays.h"
#include "field/reading/component_order.h"
#include "field/tensor/sym3.h"

namespace hsb {
namespace {

const char* const plane_record = "hsb plane of 2-D data";

// The tensor of `t` (6 in VTK's order, or 9) made planar about `axis`:
// the out-of-plane normal the mean of the in-plane ones, no out-of-plane shear.
Mat3 planar(const Mat3& t, int axis) {
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  Mat3 m = t;
  m(axis, axis) = 0.5 * (t(u, u) + t(v, v));
  m(axis, u) = m(u, axis) = m(axis, v) = m(v, axis) = 0.0;
  return m;
}

// The tensor of 9 components (row by row) or 6 in VTK's order.
Mat3 from_components(const double* c, int count) {
  if (count == 9) return Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(c);
  return tensor_in_order(c, *component_order("vtk")).matrix();
}

// How a plane tensor's components are laid out, in the z plane: three
// are XX YY XY; four a 2×2 matrix row by row, XX XY YX YY (numpy's (n, 2, 2)
// as meshio writes it), or XX YY ZZ XY (Code_Aster's SIXX SIYY SIZZ SIXY,
// Abaqus's S11 S22 S33 S12 for plane strain and axisymmetry). A symmetric
// matrix has its second and third alike; XX YY ZZ XY has them differ (σyy
// and σzz) wherever the stress is not the same in y and z.
enum class PlaneLayout { none, three, rows, with_zz };

PlaneLayout plane_layout(vtkDataArray* array, int axis) {
  const int count = array->GetNumberOfComponents();
  if (axis != 2 || (count != 3 && count != 4) || tensor_name_rank(array->GetName()) >= 2) return PlaneLayout::none;
  if (count == 3) return PlaneLayout::three;
  double c[4];
  for (vtkIdType t = 0; t < array->GetNumberOfTuples(); ++t) {
    array->GetTuple(t, c);
    const double size = std::fabs(c[0]) + std::fabs(c[1]) + std::fabs(c[2]) + std::fabs(c[3]);
    if (std::fabs(c[1] - c[2]) > 1e-9 * size) return PlaneLayout::with_zz;
  }
  return PlaneLayout::rows;
}

// A plane tensor's components in `layout` as VTK's six (XX YY ZZ XY YZ XZ),
// in place; a row-by-row matrix's off-diagonal is the mean of its two.
void plane_to_six(PlaneLayout layout, double* c) {
  double xx = c[0], yy = 0.0, zz = 0.0, xy = 0.0;
  switch (layout) {
    case PlaneLayout::three: yy = c[1], xy = c[2]; break;
    case PlaneLayout::rows: yy = c[3], xy = 0.5 * (c[1] + c[2]); break;
    case PlaneLayout::with_zz: yy = c[1], zz = c[2], xy = c[3]; break;
    case PlaneLayout::none: return;
  }
  c[0] = xx, c[1] = yy, c[2] = zz, c[3] = xy, c[4] = 0.0, c[5] = 0.0;
}

const char* layout_words(PlaneLayout layout) {
  switch (layout) {
    case PlaneLayout::three: return "three components of a plane tensor: XX YY XY";
    case PlaneLayout::rows: return "four components of a plane tensor: XX XY YX YY, a 2×2 matrix row by row";
    case PlaneLayout::with_zz: return "four components of a plane tensor: XX YY ZZ XY";
    case PlaneLayout::none: break;
  }
  return "";
}

// In the z plane, an array of 2 components as a vector (X Y 0): a 2-D
// solver's velocity or displacement, as meshio writes it to XML (its
// legacy writer adds the zero itself).
void make_plane_vector(vtkDataSetAttributes* attributes, vtkDataArray* array, vtkFieldData* records) {
  auto out = vtkSmartPointer<vtkDoubleArray>::New();
  out->SetName(array->GetName());
  out->SetNumberOfComponents(3);
  out->SetNumberOfTuples(array->GetNumberOfTuples());
  for (vtkIdType t = 0; t < array->GetNumberOfTuples(); ++t)
    out->SetTuple3(t, array->GetComponent(t, 0), array->GetComponent(t, 1), 0.0);
  attributes->RemoveArray(array->GetName());
  attributes->AddArray(out);
  record_component_order(records, out->GetName(), "two components of a plane vector: X Y");
}

// Every tensor array of `attributes` made planar; in the z plane, an array
// of 3 or 4 components named as stress or strain read as a plane tensor
// (plane_layout), and one of 2 as a vector.
void make_planar(vtkDataSetAttributes* attributes, vtkFieldData* records, int axis) {
  std::vector<vtkSmartPointer<vtkDataArray>> arrays;  // before any is replaced
  for (int i = 0; i < attributes->GetNumberOfArrays(); ++i)
    if (vtkDataArray* array = attributes->GetArray(i); array && array->GetName()) arrays.emplace_back(array);
  for (vtkDataArray* array : arrays) {
    const int count = array->GetNumberOfComponents();
    if (count == 2 && axis == 2) {
      make_plane_vector(attributes, array, records);
      continue;
    }
    const PlaneLayout layout = plane_layout(array, axis);
    if (count != 6 && count != 9 && layout == PlaneLayout::none) continue;
    auto out = vtkSmartPointer<vtkDoubleArray>::New();
    out->SetName(array->GetName());
    out->SetNumberOfComponents(count == 9 ? 9 : 6);
    out->SetNumberOfTuples(array->GetNumberOfTuples());
    double c[9];
    for (vtkIdType t = 0; t < array->GetNumberOfTuples(); ++t) {
      array->GetTuple(t, c);
      plane_to_six(layout, c);
      const Mat3 m = planar(from_components(c, layout != PlaneLayout::none ? 6 : count), axis);
      if (count == 9) {
        for (int k = 0; k < 9; ++k) out->SetComponent(t, k, m(k / 3, k % 3));
      } else {
        out->SetTuple(t, components_in_order(Sym3::symmetric_part(m), *component_order("vtk")).data());
      }
    }
    const bool active = attributes->GetTensors() == array;
    attributes->RemoveArray(array->GetName());
    attributes->AddArray(out);
    if (active) attributes->SetTensors(out);
    if (layout != PlaneLayout::none) record_component_order(records, out->GetName(), layout_words(layout));
    // The one reading the file leaves open: said with every picture.
    if (layout == PlaneLayout::with_zz)
      record_reading_note(records, out->GetName(),
                          "has four components whose second and third differ: read as XX YY ZZ XY, as Code_Aster "
                          "(SIXX SIYY SIZZ SIXY) and Abaqus (S11 S22 S33 S12) write plane strain; a 2×2 matrix "
                          "row by row (XX XY YX YY) that is not symmetric would need its symmetric part written");
  }
}

}  // namespace

std::optional<PlaneOfData> find_plane(vtkDataSet* data) {
  for (vtkIdType c = 0; c < data->GetNumberOfCells(); ++c)
    if (data->GetCell(c)->GetCellDimension() == 3) return std::nullopt;
  if (data->GetNumberOfPoints() < 3) return std::nullopt;
  double b[6];
  data->GetBounds(b);
  const Vec3 size(b[1] - b[0], b[3] - b[2], b[5] - b[4]);
  const double flat = 1e-9 * size.norm();
  int axis = -1, flat_axes = 0;
  for (int a = 0; a < 3; ++a)
    if (size[a] <= flat) axis = a, ++flat_axes;
  // A curved or oblique surface (a shell), or one on a line: no plane to
  // make a slab of; its values are drawn at its points (no volume).
  if (flat_axes != 1 || !(size.norm() > 0)) return std::nullopt;
  PlaneOfData plane;
  plane.axis = axis;
  plane.coordinate = 0.5 * (b[2 * axis] + b[2 * axis + 1]);
  // Thin next to the plane, thick enough for a cell locator's tolerance.
  plane.thickness = 0.01 * size.norm();
  return plane;
}

namespace {

// `data`'s arrays made planar, and the plane recorded.
template <class D>
vtkSmartPointer<D> made_planar(vtkSmartPointer<D> data, const PlaneOfData& plane) {
  make_planar(data->GetPointData(), data->GetFieldData(), plane.axis);
  make_planar(data->GetCellData(), data->GetFieldData(), plane.axis);
  auto record = vtkSmartPointer<vtkDoubleArray>::New();
  record->SetName(plane_record);
  for (double v : {double(plane.axis), plane.coordinate, plane.thickness}) record->InsertNextValue(v);
  data->GetFieldData()->AddArray(record);
  return data;
}

bool has_2d_cells(vtkDataSet* data) {
  for (vtkIdType c = 0; c < data->GetNumberOfCells(); ++c)
    if (data->GetCell(c)->GetCellDimension() == 2) return true;
  return false;
}

}  // namespace

vtkSmartPointer<vtkDataSet> extruded(vtkDataSet* data, const PlaneOfData& plane) {
  if (!has_2d_cells(data)) {
    vtkSmartPointer<vtkDataSet> copy = vtkSmartPointer<vtkDataSet>::Take(data->NewInstance());
    copy->DeepCopy(data);
    return made_planar(copy, plane);
  }
  const vtkIdType n = data->GetNumberOfPoints();
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(2 * n);
  for (vtkIdType i = 0; i < n; ++i) {
    double p[3];
    data->GetPoint(i, p);
    for (int side = 0; side < 2; ++side) {
      p[plane.axis] = plane.coordinate + (side ? 0.5 : -0.5) * plane.thickness;
      points->SetPoint(i + side * n, p);
    }
  }
  auto slab = vtkSmartPointer<vtkUnstructuredGrid>::New();
  slab->SetPoints(points);
  slab->GetFieldData()->DeepCopy(data->GetFieldData());
  slab->GetPointData()->CopyAllocate(data->GetPointData(), 2 * n);
  for (vtkIdType i = 0; i < n; ++i) {
    slab->GetPointData()->CopyData(data->GetPointData(), i, i);
    slab->GetPointData()->CopyData(data->GetPointData(), i, i + n);
  }
  slab->GetCellData()->CopyAllocate(data->GetCellData(), data->GetNumberOfCells());
  auto ids = vtkSmartPointer<vtkIdList>::New();
  auto triangles = vtkSmartPointer<vtkIdList>::New();
  auto corners = vtkSmartPointer<vtkPoints>::New();
  // Each face turned to run counter-clockwise about the normal, as VTK's
  // wedge and hexahedron have their first face towards their second.
  const int u = (plane.axis + 1) % 3, v = (plane.axis + 2) % 3;
  const auto add = [&](int type, std::vector<vtkIdType> face, vtkIdType from) {
    double area = 0.0;
    for (std::size_t k = 0; k < face.size(); ++k) {
      double a[3], b[3];
      data->GetPoint(face[k], a), data->GetPoint(face[(k + 1) % face.size()], b);
      area += a[u] * b[v] - b[u] * a[v];
    }
    if (area < 0.0) std::reverse(face.begin() + 1, face.end());
    std::vector<vtkIdType> cell(face);
    for (vtkIdType id : face) cell.push_back(id + n);
    const vtkIdType made = slab->InsertNextCell(type, vtkIdType(cell.size()), cell.data());
    slab->GetCellData()->CopyData(data->GetCellData(), from, made);
  };
  for (vtkIdType c = 0; c < data->GetNumberOfCells(); ++c) {
    vtkCell* cell = data->GetCell(c);
    if (cell->GetCellDimension() != 2) continue;
    const int type = data->GetCellType(c);
    if (type == VTK_TRIANGLE || type == VTK_QUAD || type == VTK_PIXEL) {
      data->GetCellPoints(c, ids);
      std::vector<vtkIdType> face(ids->GetPointer(0), ids->GetPointer(0) + ids->GetNumberOfIds());
      if (type == VTK_PIXEL) std::swap(face[2], face[3]);  // a pixel's corners go in rows
      add(type == VTK_TRIANGLE ? VTK_WEDGE : VTK_HEXAHEDRON, face, c);
      continue;
    }
    // Polygons, strips and quadratic faces: the wedges of their triangles.
    if (!cell->Triangulate(0, triangles, corners)) continue;
    for (vtkIdType t = 0; t + 2 < triangles->GetNumberOfIds(); t += 3)
      add(VTK_WEDGE, {triangles->GetId(t), triangles->GetId(t + 1), triangles->GetId(t + 2)}, c);
  }
  return made_planar(slab, plane);
}

std::optional<PlaneOfData> plane_of(vtkDataSet* data) {
  auto* record = vtkDoubleArray::SafeDownCast(data->GetFieldData()->GetAbstractArray(plane_record));
  if (!record || record->GetNumberOfValues() != 3) return std::nullopt;
  PlaneOfData plane{int(record->GetValue(0)), record->GetValue(1), record->GetValue(2)};
  if (plane.axis < 0 || plane.axis > 2 || !std::isfinite(plane.coordinate) || !(plane.thickness > 0)) return std::nullopt;
  return plane;
}

}  // namespace hsb
