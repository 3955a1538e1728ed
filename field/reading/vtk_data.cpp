#include "field/reading/vtk_data.h"

#include "base/huge_pages.h"

#include <vtkCellData.h>
#include <vtkCellDataToPointData.h>
#include <vtkCellTypes.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkDataSet.h>
#include <vtkDataSetReader.h>
#include <vtkDataSetSurfaceFilter.h>
#include <vtkImageData.h>
#include <vtkMatrix3x3.h>
#include <vtkPointData.h>
#include <vtkPolyDataNormals.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkCell.h>
#include <vtkCellType.h>
#include <vtkGenericCell.h>
#include <vtkCellArray.h>
#include <vtkIdList.h>
#include <vtkPoints.h>
#include <vtkTriangleFilter.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLGenericDataObjectReader.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "base/child_process.h"
#include "field/reading/file_records.h"
#include "base/input_file.h"
#include "field/reading/block_merging.h"
#include "field/reading/component_arrays.h"
#include "field/reading/component_order.h"
#include "field/reading/data_error.h"
#include "field/reading/data_region.h"
#include "field/reading/dataset_reading.h"
#include "field/reading/noisy_diffusion.h"
#include "field/reading/plane_data.h"
#include "field/reading/tensor_storage.h"
#include "field/reading/vtk_session.h"
#include "field/sampling/mesh_field.h"
#include "field/sampling/mesh_locator.h"
#include "field/sampling/uniform_grid.h"
#include "field/tensor/eigenvalue_range.h"

namespace hsb {
namespace {


std::string list_arrays(vtkDataSet* data) {
  std::ostringstream out;
  auto list = [&](vtkDataSetAttributes* attributes, const char* where) {
    out << where << " data: ";
    if (attributes->GetNumberOfArrays() == 0) out << "none";
    for (int i = 0; i < attributes->GetNumberOfArrays(); ++i) {
      vtkAbstractArray* a = attributes->GetAbstractArray(i);
      out << (i ? ", " : "") << (a->GetName() ? a->GetName() : "(unnamed)") << " ("
          << a->GetNumberOfComponents() << " components)";
    }
  };
  list(data->GetPointData(), "point");
  out << "; ";
  list(data->GetCellData(), "cell");
  return out.str();
}

struct ChosenArray {
  vtkDataArray* array = nullptr;
  bool on_points = true;
  std::string name;
  int components = 0;
  std::string note;  // how it was chosen among others, for the user; "" when there was no choice
};

// Every array of 6 or 9 components, point data first (as `association`
// allows), the active tensors of each ahead of the rest.
std::vector<ChosenArray> tensor_candidates(vtkDataSet* data, TensorAssociation association) {
  std::vector<ChosenArray> found;
  for (const bool points : {true, false}) {
    if ((points && association == TensorAssociation::cell) || (!points && association == TensorAssociation::point))
      continue;
    vtkDataSetAttributes* a = points ? data->GetPointData() : static_cast<vtkDataSetAttributes*>(data->GetCellData());
    std::vector<vtkDataArray*> arrays;
    if (vtkDataArray* active = a->GetTensors()) arrays.push_back(active);
    for (int i = 0; i < a->GetNumberOfArrays(); ++i)
      if (vtkDataArray* array = a->GetArray(i); array && array != a->GetTensors()) arrays.push_back(array);
    for (vtkDataArray* array : arrays)
      if (array->GetNumberOfComponents() == 6 || array->GetNumberOfComponents() == 9)
        found.push_back({array, points, array->GetName() ? array->GetName() : "(unnamed)", array->GetNumberOfComponents(), ""});
  }
  return found;
}

// Among several arrays of tensors: the active tensors (point data, then
// cell data), else the first whose name says stress, else strain, else
// the first; with a note naming the others.
ChosenArray pick_tensors(vtkDataSet* data, TensorAssociation association) {
  const std::vector<ChosenArray> candidates = tensor_candidates(data, association);
  if (candidates.empty()) return {};
  const auto active = [&](const ChosenArray& c) {
    return c.array == (c.on_points ? data->GetPointData()->GetTensors() : data->GetCellData()->GetTensors());
  };
  auto best = std::find_if(candidates.begin(), candidates.end(), active);
  if (best == candidates.end())
    best = std::min_element(candidates.begin(), candidates.end(), [](const ChosenArray& a, const ChosenArray& b) {
      return tensor_name_rank(a.name) < tensor_name_rank(b.name);
    });
  ChosenArray chosen = *best;
  // The same quantity at the cells as well as at the points is no choice
  // worth a word: point data is drawn (interpolated, not piecewise).
  std::string others;
  int named = 1;
  for (const ChosenArray& c : candidates)
    if (c.name != chosen.name) {
      others += (others.empty() ? "\"" : ", \"") + c.name + "\" (" + std::to_string(c.components) + " components, " +
                (c.on_points ? "point" : "cell") + " data)";
      ++named;
    }
  if (!others.empty()) {
    chosen.note = "of " + std::to_string(named) + " arrays of tensors, \"" + chosen.name + "\" (" +
                  (chosen.on_points ? "point" : "cell") + " data) is drawn, " +
                  (active(chosen) ? std::string("the active tensors")
                   : tensor_name_rank(chosen.name) == 0 ? std::string("its name says stress")
                   : tensor_name_rank(chosen.name) == 1 ? std::string("its name says strain (none says stress)")
                                                        : std::string("the first (no name says stress or strain)")) +
                  "; also in the file: " + others + ". Set data.array for another";
  }
  return chosen;
}

// The one array of `allowed` components among `attributes`' arrays; null
// when there is none or more than one.
vtkDataArray* only_array_of(vtkDataSetAttributes* attributes, std::initializer_list<int> allowed) {
  vtkDataArray* found = nullptr;
  for (int i = 0; i < attributes->GetNumberOfArrays(); ++i) {
    vtkDataArray* a = attributes->GetArray(i);
    if (!a || std::find(allowed.begin(), allowed.end(), a->GetNumberOfComponents()) == allowed.end()) continue;
    if (found) return nullptr;
    found = a;
  }
  return found;
}

// `name` among the point data, then the cell data (as `association` allows).
ChosenArray named_array(vtkDataSet* data, const std::string& name, TensorAssociation association) {
  ChosenArray chosen;
  if (association != TensorAssociation::cell) chosen.array = data->GetPointData()->GetArray(name.c_str());
  if (!chosen.array && association != TensorAssociation::point) {
    chosen.array = data->GetCellData()->GetArray(name.c_str());
    chosen.on_points = false;
  }
  if (chosen.array) {
    chosen.name = name;
    chosen.components = chosen.array->GetNumberOfComponents();
  }
  return chosen;
}

const char* where_looked(TensorAssociation association) {
  return association == TensorAssociation::point  ? " in its point data"
         : association == TensorAssociation::cell ? " in its cell data"
                                                   : "";
}

// The array the field is made of. Named: that array, whose components say
// what it is (6 or 9: tensors, 3: vectors). Not named: tensors by
// pick_tensors(); only when the file has no array of 6 or 9 components
// (and unless tensors were asked for), the active vectors, else the only
// array of 3, with a note that the picture is of a flow.
ChosenArray choose_field_array(vtkDataSet* data, const VtkFileSpec& spec) {
  const TensorAssociation assoc = spec.association;
  ChosenArray chosen;
  if (!spec.array.empty()) {
    chosen = named_array(data, spec.array, assoc);
    if (!chosen.array)
      throw DataError(spec.path + ": no array named \"" + spec.array + "\" (data.array)" + where_looked(assoc) + "; the file has " +
                      list_arrays(data));
  } else {
    const auto pick_vectors = [&]() {
      for (const bool points : {true, false}) {
        if ((points && assoc == TensorAssociation::cell) || (!points && assoc == TensorAssociation::point)) continue;
        vtkDataSetAttributes* a = points ? data->GetPointData() : static_cast<vtkDataSetAttributes*>(data->GetCellData());
        vtkDataArray* found = a->GetVectors() ? a->GetVectors() : only_array_of(a, {3});
        if (found) return ChosenArray{found, points, found->GetName() ? found->GetName() : "(unnamed)",
                                      found->GetNumberOfComponents(), ""};
      }
      return ChosenArray{};
    };
    if (spec.kind != FieldKind::vector) chosen = pick_tensors(data, assoc);
    if (!chosen.array && spec.kind != FieldKind::tensor) {
      chosen = pick_vectors();
      if (chosen.array && spec.kind == FieldKind::automatic)
        chosen.note = "the file has no array of 6 or 9 components: its vectors \"" + chosen.name +
                      "\" are drawn as a flow (streamballs along streamlines); data.field = \"vector\" says so";
    }
    if (!chosen.array) {
      const std::string what = spec.kind == FieldKind::tensor ? "no active tensors and no single array of 6 or 9 components"
                               : spec.kind == FieldKind::vector
                                   ? "no active vectors and no single array of 3 components"
                                   : "no tensors (active, or a single array of 6 or 9 components) and no vectors "
                                     "(active, or a single array of 3)";
      throw DataError(spec.path + ": " + what + where_looked(assoc) + "; the file has " + list_arrays(data));
    }
  }
  const int c = chosen.components;
  const bool tensor = c == 6 || c == 9;
  if ((spec.kind == FieldKind::tensor && !tensor) || (spec.kind == FieldKind::vector && c != 3) || (!tensor && c != 3))
    throw DataError(spec.path + ": array \"" + chosen.name + "\" has " + std::to_string(c) + " components; " +
                    (spec.kind == FieldKind::vector ? "a vector needs 3"
                     : spec.kind == FieldKind::tensor ? "a tensor needs 9, or 6 (XX, YY, ZZ, XY, YZ, XZ)"
                                                      : "a tensor needs 9, or 6 (XX, YY, ZZ, XY, YZ, XZ); a vector 3"));
  return chosen;
}

// The order the six components of `chosen` come in: the one the file
// records (then already VTK's: field/reading/component_arrays.h), else the
// scene's, else the one its format implies, else VTK's.
const ComponentOrder& order_of(const VtkFileSpec& spec, vtkDataSet* data, const ChosenArray& chosen) {
  const std::string recorded = recorded_component_order(data, chosen.name);
  if (!recorded.empty() && !spec.components.empty() && spec.components != "vtk")
    throw DataError(spec.path + ": array \"" + chosen.name + "\" says which component is which (" + recorded +
                    "): data.components = \"" + spec.components + "\" does not apply; leave it out");
  std::string name = "vtk";
  if (recorded.empty() && !spec.components.empty()) name = spec.components;
  else if (recorded.empty()) name = recorded_default_order(data, chosen.name).order;
  const ComponentOrder* order = component_order(name.empty() ? "vtk" : name);
  if (!order) throw DataError(spec.path + ": no component order \"" + name + "\" (data.components)");
  return *order;
}

// The values of a vector or scalar array, checked for finiteness.
template <class T>
std::vector<T> read_values(const ChosenArray& chosen, const std::string& path) {
  const vtkIdType n = chosen.array->GetNumberOfTuples();
  const int components = chosen.array->GetNumberOfComponents();
  std::vector<T> out(static_cast<std::size_t>(n));
  double t[3] = {0, 0, 0};
  for (vtkIdType i = 0; i < n; ++i) {
    chosen.array->GetTuple(i, t);
    for (int c = 0; c < components; ++c)
      if (!std::isfinite(t[c])) {
        std::ostringstream message;
        message << path << ": array \"" << chosen.name << "\" has a non-finite value (" << t[c] << ") at "
                << (chosen.on_points ? "point " : "cell ") << i << ", component " << c;
        throw DataError(message.str());
      }
    if constexpr (std::is_same_v<T, Vec3>)
      out[std::size_t(i)] = Vec3(t[0], t[1], t[2]);
    else
      out[std::size_t(i)] = t[0];
  }
  return out;
}

// What reading a band of an array's tuples found: where its first
// non-finite value is, how many tuples are NaN (no data), and the largest
// asymmetry of a 9-component tensor (its first tuple where equal).
struct TensorBand {
  vtkIdType bad_at = -1;
  int bad_component = 0;
  double bad_value = 0.0;
  vtkIdType missing = 0;
  double worst = 0.0, worst_norm = 0.0;
  vtkIdType worst_at = -1;
};

// Reads tuples [first, last) of an array of `components` (6 or 9) into
// `tensors` through `tuple(i, t)`; stops at a non-finite value.
template <class Tuple>
TensorBand read_tensor_band(const Tuple& tuple, int components, const ComponentOrder& order, vtkIdType first,
                            vtkIdType last, Sym3* tensors) {
  TensorBand band;
  double t[9];
  for (vtkIdType i = first; i < last; ++i) {
    tuple(i, t);
    // NaN is "no data" (outside a brain mask, a failed fit): the tensor is
    // kept as NaN and the fields sample nothing where it counts.
    if (std::any_of(t, t + components, [](double v) { return std::isnan(v); })) {
      tensors[i] = Sym3{NAN, NAN, NAN, NAN, NAN, NAN};
      ++band.missing;
      continue;
    }
    for (int c = 0; c < components; ++c)
      if (!std::isfinite(t[c])) {
        band.bad_at = i;
        band.bad_component = c;
        band.bad_value = t[c];
        return band;
      }
    if (components == 6) {
      tensors[i] = tensor_in_order(t, order);
      continue;
    }
    // Row- or column-major does not matter: the symmetric part is the same.
    Mat3 m;
    for (int k = 0; k < 9; ++k) m(k / 3, k % 3) = t[k];
    tensors[i] = Sym3::symmetric_part(m);
    const double asymmetry = (m - m.transpose()).cwiseAbs().maxCoeff();
    if (asymmetry > band.worst) {
      band.worst = asymmetry;
      band.worst_at = i;
      band.worst_norm = m.norm();
    }
  }
  return band;
}

// Tensors of `array`, checked for finiteness, symmetrised when given as 9
// components (with one warning for the largest asymmetry found). Read in
// bands on every core, straight from the array's memory where it is a
// plain float or double array (VTK's per-tuple getter is a virtual call
// and a conversion): a diffusion volume has millions of voxels.
std::vector<Sym3> read_tensors(const ChosenArray& chosen, const std::string& path, const ComponentOrder& order,
                               std::vector<std::string>& warnings) {
  vtkDataArray* array = chosen.array;
  const char* item = chosen.on_points ? "point" : "cell";
  const vtkIdType n = array->GetNumberOfTuples();
  const int components = array->GetNumberOfComponents();
  // A volume reader's own storage is read in place (each tuple is copied
  // out before its tensor is written back), not copied.
  std::vector<Sym3> tensors = take_tensor_storage(array);
  const bool in_place = !tensors.empty();
  if (!in_place) assign_on_huge_pages(tensors, std::size_t(n), Sym3{});
  constexpr vtkIdType kBand = 1 << 15;
  std::vector<TensorBand> bands(std::size_t((n + kBand - 1) / kBand));
  const auto read_all = [&](const auto& tuple) {
    tbb::parallel_for(std::size_t{0}, bands.size(), [&](std::size_t b) {
      const vtkIdType first = vtkIdType(b) * kBand;
      bands[b] = read_tensor_band(tuple, components, order, first, std::min(n, first + kBand), tensors.data());
    });
  };
  const auto from = [&](const auto* values) {
    return [values, components](vtkIdType i, double* t) {
      const auto* tuple = values + std::size_t(i) * std::size_t(components);
      for (int c = 0; c < components; ++c) t[c] = double(tuple[c]);
    };
  };
  if (in_place) read_all(from(reinterpret_cast<const double*>(tensors.data())));
  else if (auto* floats = vtkFloatArray::FastDownCast(array)) read_all(from(floats->GetPointer(0)));
  else if (auto* doubles = vtkDoubleArray::FastDownCast(array)) read_all(from(doubles->GetPointer(0)));
  else read_all([array](vtkIdType i, double* t) { array->GetTuple(i, t); });

  TensorBand all;
  for (const TensorBand& band : bands) {
    if (band.bad_at >= 0) {
      std::ostringstream message;
      message << path << ": array \"" << chosen.name << "\" has a non-finite value (" << band.bad_value << ") at "
              << item << " " << band.bad_at << ", component " << band.bad_component;
      throw DataError(message.str());
    }
    all.missing += band.missing;
    if (band.worst > all.worst) {
      all.worst = band.worst;
      all.worst_at = band.worst_at;
      all.worst_norm = band.worst_norm;
    }
  }
  if (all.missing == n)
    throw DataError(path + ": array \"" + chosen.name + "\" holds no data: every " + item + "'s tensor is NaN");
  if (all.missing > 0) {
    std::ostringstream message;
    message << path << ": " << all.missing << " of " << n << " " << item << "s have no tensor (NaN in array \""
            << chosen.name << "\"): no data there, as outside the data set";
    warnings.push_back(message.str());
  }
  if (all.worst_at >= 0) {
    std::ostringstream message;
    message << path << ": array \"" << chosen.name << "\" is not symmetric; using its symmetric part "
            << "(T + Tᵀ)/2. Largest asymmetry |T_ij − T_ji| = " << all.worst << " at " << item << " "
            << all.worst_at << " (where |T| = " << all.worst_norm << ")";
    warnings.push_back(message.str());
  }
  return tensors;
}

// The rotation that takes `name`'s tensors into the data's space: the
// scene's data.frame, else the one the reader recorded (none: they are in
// it). A frame the reader guessed is said once, with the key.
std::optional<Mat3> tensor_frame(const VtkFileSpec& spec, vtkDataSet* data, const std::string& name,
                                 std::vector<std::string>& warnings) {
  if (spec.frame == TensorFrame::automatic) {
    if (const FrameNote note = recorded_frame_note(data, name); note.guess)
      warnings.push_back(spec.path + ": array \"" + name + "\" read in " + note.text +
                         "; set data.frame (\"world\", \"voxel\", \"fsl\") where its tensors are in other axes");
    return recorded_tensor_frame(data, name);
  }
  if (spec.frame == TensorFrame::world) return std::nullopt;
  const std::optional<Mat3> axes = recorded_voxel_axes(data, name);
  if (!axes)
    throw DataError(spec.path + ": data.frame = \"" + (spec.frame == TensorFrame::voxel ? "voxel" : "fsl") +
                    "\" turns a volume's tensors from its voxel axes, and this file's data is no volume of voxels "
                    "(it is a " + data->GetClassName() + ")");
  return spec.frame == TensorFrame::voxel ? *axes : fsl_axes(*axes);
}

// The tensors of `chosen` in the data's space: in their order, and
// turned from the axes they were written in where the file says (FSL's).
std::vector<Sym3> tensors_of(const ChosenArray& chosen, const VtkFileSpec& spec, vtkDataSet* data,
                             std::vector<std::string>& warnings) {
  const ComponentOrder& order = order_of(spec, data, chosen);
  std::vector<Sym3> tensors = read_tensors(chosen, spec.path, order, warnings);
  // An order no file states, only its writer implies: said, as a choice the scene can overrule.
  if (const DefaultOrder implied = recorded_default_order(data, chosen.name);
      chosen.components == 6 && spec.components.empty() && !implied.why.empty())
    warnings.push_back(spec.path + ": array \"" + chosen.name + "\" read in the order " + order.layout + " (\"" +
                       order.name + "\"): " + implied.why + "; set data.components for another");
  if (const std::string note = recorded_reading_note(data, chosen.name); !note.empty())
    warnings.push_back(spec.path + ": array \"" + chosen.name + "\" " + note);
  // On every core: FSL's tensors are all turned, millions of them.
  if (const std::optional<Mat3> frame = tensor_frame(spec, data, chosen.name, warnings))
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, tensors.size(), 8192),
                      [&](const tbb::blocked_range<std::size_t>& band) {
                        for (std::size_t i = band.begin(); i < band.end(); ++i)
                          if (Sym3& t = tensors[i]; t.is_finite())
                            t = Sym3::symmetric_part(*frame * t.matrix() * frame->transpose());
                      });
  return tensors;
}

// The point-data version of a cell array, by VTK's averaging filter.
ChosenArray averaged_onto_points(vtkDataSet* data, const ChosenArray& cells, const std::string& path,
                                 vtkSmartPointer<vtkDataSet>& keep_alive) {
  vtkSmartPointer<vtkDataSet> only_this = vtkSmartPointer<vtkDataSet>::Take(data->NewInstance());
  only_this->CopyStructure(data);
  only_this->GetCellData()->AddArray(cells.array);
  auto filter = vtkSmartPointer<vtkCellDataToPointData>::New();
  filter->SetInputData(only_this);
  update_safely(filter, path, "cell-to-point averaging");
  keep_alive = vtkDataSet::SafeDownCast(filter->GetOutputDataObject(0));
  return {keep_alive->GetPointData()->GetArray(cells.array->GetName()), true, cells.name};
}

// Image data a uniform grid can stand for: a volume (two nodes or more on
// every axis) with an invertible direction matrix, turned or not.
// An image's direction matrix: the directions of its i, j and k axes.
Mat3 direction_of(vtkImageData* image) {
  Mat3 direction;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) direction(i, j) = image->GetDirectionMatrix()->GetElement(i, j);
  return direction;
}

bool is_image_volume(vtkDataSet* data) {
  auto* image = vtkImageData::SafeDownCast(data);
  if (!image) return false;
  const int* dims = image->GetDimensions();
  return dims[0] >= 2 && dims[1] >= 2 && dims[2] >= 2 && std::fabs(image->GetDirectionMatrix()->Determinant()) > 1e-12;
}

// Values at the data set's points or cells (tensors, or scalars), sampled
// as the data set is: trilinearly on an image volume's grid, turned or
// not, else through its cells, by the shared `locator`.
template <class T>
std::unique_ptr<Field<T>> sampled_field(vtkDataSet* data, SharedValues<T> values, ValueLocation where,
                                        const std::function<std::shared_ptr<const MeshLocator>()>& locator) {
  if (where != ValueLocation::points || !is_image_volume(data))
    return std::make_unique<MeshField<T>>(locator(), std::move(values), where);
  auto* image = vtkImageData::SafeDownCast(data);
  const int* extent = image->GetExtent();
  const double* origin = image->GetOrigin();
  const double* spacing = image->GetSpacing();
  const Mat3 direction = direction_of(image);
  // The first node: the extent may start away from index 0.
  const Vec3 first = Vec3(origin[0], origin[1], origin[2]) +
                     direction * Vec3(extent[0] * spacing[0], extent[2] * spacing[1], extent[4] * spacing[2]);
  const int* dims = image->GetDimensions();
  return std::make_unique<UniformGrid<T>>(first, Vec3(spacing[0], spacing[1], spacing[2]),
                                          std::array<int, 3>{dims[0], dims[1], dims[2]}, std::move(values), direction);
}

// The data set's outer surface as triangles with vertex normals, or
// `region`'s where given (the surface of the part of a grid that holds
// data, data_region.h). Edges sharper than 40° split the normals, so a
// cylinder's faceted wall shades smoothly while its rim stays a rim.
TriangleMesh boundary_surface(vtkDataSet* data, const std::string& path, vtkPolyData* region) {
  auto triangles = vtkSmartPointer<vtkTriangleFilter>::New();
  if (region) {
    triangles->SetInputData(region);
  } else {
    auto surface = vtkSmartPointer<vtkDataSetSurfaceFilter>::New();
    surface->SetInputData(data);
    triangles->SetInputConnection(surface->GetOutputPort());
  }
  triangles->PassVertsOff();
  triangles->PassLinesOff();
  auto normals = vtkSmartPointer<vtkPolyDataNormals>::New();
  normals->SetInputConnection(triangles->GetOutputPort());
  normals->SetFeatureAngle(40.0);
  normals->SplittingOn();
  normals->ConsistencyOn();
  normals->AutoOrientNormalsOff();  // a hollow body has no single outside
  normals->ComputePointNormalsOn();
  normals->ComputeCellNormalsOff();
  update_safely(normals, path, "surface extraction");
  vtkPolyData* poly = normals->GetOutput();
  vtkDataArray* point_normals = poly->GetPointData()->GetNormals();
  TriangleMesh mesh;
  mesh.vertices.reserve(std::size_t(poly->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < poly->GetNumberOfPoints(); ++i) {
    double p[3];
    poly->GetPoint(i, p);
    mesh.vertices.emplace_back(p[0], p[1], p[2]);
    if (point_normals) {
      point_normals->GetTuple(i, p);
      mesh.normals.emplace_back(p[0], p[1], p[2]);
    }
  }
  vtkCellArray* polys = poly->GetPolys();
  polys->InitTraversal();
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  while (polys->GetNextCell(count, ids)) {
    if (count == 3) mesh.triangles.push_back({std::uint32_t(ids[0]), std::uint32_t(ids[1]), std::uint32_t(ids[2])});
  }
  return mesh;
}

// A scalar array's values, and where they stand. Three components (a
// vector) give their magnitude where `vectors` allows, for colouring.
std::pair<std::vector<double>, ValueLocation> scalar_values(const ChosenArray& chosen, const std::string& path,
                                                            bool vectors) {
  const ValueLocation where = chosen.on_points ? ValueLocation::points : ValueLocation::cells;
  if (chosen.components == 1) return {read_values<double>(chosen, path), where};
  if (chosen.components == 3 && vectors) {
    std::vector<double> magnitude;
    for (const Vec3& v : read_values<Vec3>(chosen, path)) magnitude.push_back(v.norm());
    return {std::move(magnitude), where};
  }
  throw DataError(path + ": array \"" + chosen.name + "\" has " + std::to_string(chosen.components) +
                  " components; " +
                  (vectors ? "colouring needs a scalar (1) or a vector (3, by its magnitude)" : "a mask needs a scalar (1)"));
}

// The scalar array `name` of the data set, wanted `use` ("to colour by").
std::pair<std::vector<double>, ValueLocation> named_scalar_values(vtkDataSet* data, const std::string& name,
                                                                  const std::string& path, const std::string& use,
                                                                  bool vectors) {
  const ChosenArray chosen = named_array(data, name, TensorAssociation::automatic);
  if (!chosen.array)
    throw DataError(path + ": no array named \"" + name + "\" " + use + "; the file has " + list_arrays(data));
  return scalar_values(chosen, path, vectors);
}

// Where the values of point data (or cell data) stand: the points (an
// image's as its grid), or the cells' parametric centres.
SitePositions site_positions(vtkDataSet* data, bool on_points) {
  if (auto* image = vtkImageData::SafeDownCast(data); image && on_points) {
    const int* extent = image->GetExtent();
    const int* dims = image->GetDimensions();
    const double* spacing = image->GetSpacing();
    const double* origin = image->GetOrigin();
    return SitePositions(Vec3(origin[0], origin[1], origin[2]), Vec3(spacing[0], spacing[1], spacing[2]),
                         direction_of(image), {extent[0], extent[2], extent[4]}, {dims[0], dims[1], dims[2]});
  }
  std::vector<Vec3> sites;
  double p[3];
  if (on_points) {
    reserve_on_huge_pages(sites, std::size_t(data->GetNumberOfPoints()));
    for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i) {
      data->GetPoint(i, p);
      sites.emplace_back(p[0], p[1], p[2]);
    }
    return sites;
  }
  auto cell = vtkSmartPointer<vtkGenericCell>::New();
  std::vector<double> weights(std::size_t(std::max(data->GetMaxCellSize(), 1)));
  sites.reserve(std::size_t(data->GetNumberOfCells()));
  for (vtkIdType c = 0; c < data->GetNumberOfCells(); ++c) {
    data->GetCell(c, cell);
    double centre[3];
    int sub = 0;
    cell->GetParametricCenter(centre);
    cell->EvaluateLocation(sub, centre, p, weights.data());
    sites.emplace_back(p[0], p[1], p[2]);
  }
  return sites;
}

// The colour array at the sites: its own values where they stand there
// too, else sampled at each site where there is volume (NaN: none).
std::vector<double> site_colors(const SitePositions& sites, bool on_points, const std::vector<double>& values,
                                ValueLocation where, const ScalarField* color) {
  if ((where == ValueLocation::points) == on_points) return values;
  std::vector<double> colors;
  colors.reserve(sites.size());
  for (std::size_t i = 0; i < sites.size(); ++i) colors.push_back(color ? color->sample(sites[i]).value_or(NAN) : NAN);
  return colors;
}

}  // namespace

VtkData load_vtk_data(const VtkFileSpec& spec) {
  const VtkSession vtk;
  const vtkSmartPointer<vtkDataSet> data =
      spec.arrays ? read_arrays(*spec.arrays) : read_dataset(spec.path, vtk, {spec.step, spec.block});
  VtkData out;
  out.no_volume = no_volume_reason(data);
  const bool volume = out.no_volume.empty();
  const bool sites = spec.sites || !volume;
  ChosenArray chosen = choose_field_array(data, spec);
  if (!chosen.note.empty()) out.warnings.push_back(spec.path + ": " + chosen.note);
  // One locator for every array of the data set (all share its cells).
  std::shared_ptr<const MeshLocator> locator;
  const auto mesh_locator = [&] {
    if (!locator) locator = std::make_shared<MeshLocator>(data.Get());
    return locator;
  };
  double b[6];
  data->GetBounds(b);
  const Box3 bounds{Vec3(b[0], b[2], b[4]), Vec3(b[1], b[3], b[5])};
  vtkSmartPointer<vtkPolyData> region;  // the part of a grid that holds data, where not all of it does
  if (chosen.components == 3) {
    std::vector<Vec3> vectors = read_values<Vec3>(chosen, spec.path);
    if (sites) out.sites.vectors = vectors;
    if (volume)
      out.vectors = std::make_unique<MeshField<Vec3>>(mesh_locator(), std::move(vectors),
                                                      chosen.on_points ? ValueLocation::points : ValueLocation::cells);
    else
      out.vectors = std::make_unique<PointsOnlyField<Vec3>>(bounds);
  } else {
    vtkSmartPointer<vtkDataSet> averaged;
    std::vector<Sym3> tensors = tensors_of(chosen, spec, data, out.warnings);
    if (volume && !chosen.on_points && spec.cell_tensors == CellTensors::averaged) {
      // The checks and warnings above name cells, which the user can find;
      // the averaged copy would only repeat them for points.
      chosen = averaged_onto_points(data, chosen, spec.path, averaged);
      std::vector<std::string> repeated;
      tensors = tensors_of(chosen, spec, data, repeated);
    }
    // Read out, the file's array would only raise the peak memory (by a
    // third for a glyph field of a large volume).
    if (!averaged) {
      vtkDataSetAttributes* holder = chosen.on_points ? static_cast<vtkDataSetAttributes*>(data->GetPointData())
                                                      : static_cast<vtkDataSetAttributes*>(data->GetCellData());
      holder->RemoveArray(chosen.name.c_str());
    }
    // What the tensors are decides how they are read: a diffusion fit's
    // noise is no data (noisy_diffusion.h). Recognised from the file's
    // own values, before interpolation blends noise into its neighbours.
    // Only in a volume: a diffusion study is one, and a 2-D result's
    // out-of-plane entries are made up (plane_data.h), which would make a
    // plate in biaxial tension look like water.
    const bool scan = !record_of(data, kAnatomicalFrame).empty();
    out.quantity = spec.quantity             ? *spec.quantity
                   : volume && !plane_of(data) ? recognised_quantity(tensors, scan)
                                             : DataQuantity::stress;
    if (*out.quantity == DataQuantity::diffusion) {
      auto* image = vtkImageData::SafeDownCast(data);
      std::array<int, 3> dims{};
      if (image && chosen.on_points) std::copy_n(image->GetDimensions(), 3, dims.begin());
      const NoiseLeftOut noise = leave_out_noise(tensors, image && chosen.on_points ? &dims : nullptr);
      if (const std::string said = noise_warning(spec.path, noise); !said.empty()) out.warnings.push_back(said);
    }
    const SharedValues<Sym3> shared(std::move(tensors));
    if (sites) out.sites.tensors = shared;
    // A grid whose tensors are zero over a background: its outline is the
    // surface of the rest.
    if (auto* image = vtkImageData::SafeDownCast(data); image && spec.boundary && chosen.on_points) {
      std::vector<std::uint8_t> has_data(shared.size());
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, shared.size(), 1 << 15),
                        [&](const tbb::blocked_range<std::size_t>& band) {
                          for (std::size_t i = band.begin(); i < band.end(); ++i) has_data[i] = shared[i].holds_data();
                        });
      region = data_region_surface(image, has_data);
    }
    if (!volume) {
      out.field = std::make_unique<PointsOnlyField<Sym3>>(bounds);
    } else {
      out.field = sampled_field(data, shared, chosen.on_points ? ValueLocation::points : ValueLocation::cells,
                                mesh_locator);
    }
  }
  if (sites) out.sites.positions = site_positions(data, chosen.on_points);
  if (!spec.mask_array.empty()) {
    auto [values, where] = named_scalar_values(data, spec.mask_array, spec.path, "for region.mask", false);
    out.mask = sampled_field<double>(data, std::move(values), where, mesh_locator);
  }
  if (!spec.color_array.empty()) {
    auto [values, where] = named_scalar_values(data, spec.color_array, spec.path, "to colour by", true);
    if (volume) out.color = sampled_field<double>(data, values, where, mesh_locator);
    if (sites) out.sites.colors = site_colors(out.sites.positions, chosen.on_points, values, where, out.color.get());
  }
  if (spec.boundary && data->GetNumberOfCells() > 0)
    out.boundary = boundary_surface(data, spec.path, region);  // a shell's own surface too
  if (const std::optional<PlaneOfData> plane = plane_of(data)) out.plane_axis = plane->axis;
  if (const std::vector<std::string> frame = record_of(data, kAnatomicalFrame); !frame.empty())
    out.anatomical_frame = frame.front();
  return out;
}

std::unique_ptr<ScalarField> load_mask(const std::string& path) {
  const VtkSession vtk;
  const vtkSmartPointer<vtkDataSet> data = read_dataset(path, vtk, {-1, "", true});
  if (const std::string why = no_volume_reason(data); !why.empty())
    throw DataError(path + ": a mask needs a volume to sample in, and " + why);
  ChosenArray chosen;
  if (vtkDataArray* active = data->GetPointData()->GetScalars(); active && active->GetNumberOfComponents() == 1) {
    chosen.array = active;
  } else if (vtkDataArray* on_points = only_array_of(data->GetPointData(), {1})) {
    chosen.array = on_points;
  } else if (vtkDataArray* on_cells = only_array_of(data->GetCellData(), {1})) {
    chosen.array = on_cells;
    chosen.on_points = false;
  } else {
    throw DataError(path + ": a mask needs one scalar array (one value per point or cell) to be the mask, and the file "
                    "has " + list_arrays(data));
  }
  chosen.name = chosen.array->GetName() ? chosen.array->GetName() : "";
  chosen.components = 1;
  auto [values, where] = scalar_values(chosen, path, false);
  return sampled_field<double>(data.Get(), std::move(values), where,
                       [&] { return std::make_shared<const MeshLocator>(data.Get()); });
}

std::string describe_vtk_file(const VtkFileSpec& spec) {
  // Before the session: reading the series takes one of its own.
  const std::vector<double> times = spec.arrays ? std::vector<double>{} : series_times(spec.path);
  const VtkSession vtk;
  const vtkSmartPointer<vtkDataSet> data =
      spec.arrays ? read_arrays(*spec.arrays) : read_dataset(spec.path, vtk, {spec.step, spec.block});
  std::ostringstream out;
  double b[6];
  data->GetBounds(b);
  if (!times.empty()) {
    out << spec.path << ": a time series of " << times.size() << " steps, at times";
    for (double t : times) out << " " << t;
    out << "; step " << std::max(spec.step, 0) << " (data.step) is described\n";
  }
  out << spec.path << ": " << data->GetClassName() << "\n";
  out << "  bounds    x [" << b[0] << ", " << b[1] << "]  y [" << b[2] << ", " << b[3] << "]  z [" << b[4]
      << ", " << b[5] << "]\n";
  out << "  points    " << data->GetNumberOfPoints() << "\n";
  out << "  cells     " << data->GetNumberOfCells();
  std::map<std::string, vtkIdType> types;
  for (vtkIdType i = 0; i < data->GetNumberOfCells(); ++i)
    ++types[vtkCellTypes::GetClassNameFromTypeId(data->GetCellType(i))];
  const char* separator = ": ";
  for (const auto& [name, count] : types) {
    out << separator << count << " " << name;
    separator = ", ";
  }
  out << "\n  arrays    " << list_arrays(data) << "\n";
  if (const std::vector<BlockOfFile> blocks = recorded_blocks(data); !blocks.empty()) {
    out << "  blocks    " << blocks.size() << " with cells:";
    std::string read;
    for (std::size_t i = 0; i < blocks.size(); ++i) {
      out << (i ? ", " : " ") << i << " \"" << blocks[i].name << "\" (" << blocks[i].cells << " cells)";
      if (blocks[i].read) read = blocks[i].name;
    }
    if (spec.block.empty()) out << "; all merged (data.block reads one)\n";
    else out << "; only \"" << read << "\" read (data.block)\n";
  }
  const std::string no_volume = no_volume_reason(data);
  if (const std::optional<PlaneOfData> plane = plane_of(data)) {
    out << "  plane     a 2-D result in " << "xyz"[plane->axis] << " = " << plane->coordinate;
    if (no_volume.empty()) out << ", made a slab " << plane->thickness << " thick";
    out << "; its tensors' out-of-plane entries set planar (the in-plane mean, no shear)\n";
  }
  if (!no_volume.empty())
    out << "  volume    none: " << no_volume << "; drawn as a glyph at each point (glyphs.placement = \"points\")\n";

  const ChosenArray chosen = choose_field_array(data, spec);
  const char* where = chosen.on_points ? "point" : "cell";
  if (!chosen.note.empty()) out << "  chosen    " << chosen.note << "\n";
  if (chosen.components == 3) {
    double lo = INFINITY, hi = 0.0;
    for (const Vec3& v : read_values<Vec3>(chosen, spec.path)) lo = std::min(lo, v.norm()), hi = std::max(hi, v.norm());
    out << "  vectors   \"" << chosen.name << "\" (3 components, " << where << " data)\n";
    out << "  speed     [" << lo << ", " << hi << "]\n";
    return out.str();
  }
  std::vector<std::string> warnings;
  const std::vector<Sym3> tensors = tensors_of(chosen, spec, data, warnings);
  EigenvalueRange range;
  for (const Sym3& s : tensors)
    if (s.is_finite()) range.add(s);
  out << "  tensors   \"" << chosen.name << "\" (" << chosen.components << " components, " << where << " data)\n";
  const std::string recorded = recorded_component_order(data, chosen.name);
  if (!recorded.empty()) {
    out << "  order     recorded in the file: " << recorded << "\n";
  } else if (chosen.components == 6) {
    const ComponentOrder& order = order_of(spec, data, chosen);
    out << "  order     " << order.layout << " (data.components = \"" << order.name << "\": " << order.tools << ")";
    if (const DefaultOrder implied = recorded_default_order(data, chosen.name); spec.components.empty() && !implied.why.empty())
      out << "; " << implied.why;
    out << "\n";
  }
  if (spec.frame != TensorFrame::automatic) {
    const char* frames[] = {"", "the data's space itself", "the volume's voxel axes", "FSL's voxel axes"};
    out << "  frame     " << frames[int(spec.frame)] << " (data.frame)\n";
  } else if (const FrameNote note = recorded_frame_note(data, chosen.name); !note.text.empty()) {
    out << "  frame     " << note.text << (note.guess ? " (a guess: data.frame overrides it)" : "") << "\n";
  } else if (recorded_tensor_frame(data, chosen.name)) {
    out << "  frame     tensors turned from the file's voxel axes into its space\n";
  }
  for (const std::string& w : warnings) out << "  note      " << w.substr(w.find(": ") + 2) << "\n";
  out << range;
  for (const std::string& w : warnings) out << "  warning: " << w << "\n";
  return out.str();
}

}  // namespace hsb
