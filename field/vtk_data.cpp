#include "field/vtk_data.h"

#include <vtkCellData.h>
#include <vtkCellDataToPointData.h>
#include <vtkCellTypes.h>
#include <vtkDataArray.h>
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

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "field/child_process.h"
#include "field/data_error.h"
#include "field/eigenvalue_range.h"
#include "field/data_formats.h"
#include "field/input_file.h"
#include "field/mesh_field.h"
#include "field/mesh_locator.h"
#include "field/vector_field.h"
#include "field/uniform_grid.h"
#include "field/vtk_session.h"

namespace hsb {
namespace {

double trial_base_seconds = 30.0;

// VTK's readers trust the counts a file declares, and its filters the
// cells they are given: a corrupt file can make them read past their
// buffers (the data fuzzer found several). Each runs on the file in a
// child process first, so such a file is a clear error and never a crash.
// A generous time: a few seconds more than a read should take, however
// large the file.
void update_safely(vtkAlgorithm* algorithm, const std::string& path, const char* what) {
  const double seconds = trial_base_seconds + double(std::filesystem::file_size(path)) * 1e-6;
  const ChildResult trial = run_in_child([&] { algorithm->Update(); }, seconds);
  if (trial.outcome == ChildOutcome::crashed)
    throw DataError(path + ": the file is corrupt: VTK's " + what + " crashed on it" +
                    (trial.signal ? " (signal " + std::to_string(trial.signal) + ")" : std::string()));
  if (trial.outcome == ChildOutcome::timed_out)
    throw DataError(path + ": the file is corrupt: VTK's " + what + " did not finish it in " +
                    std::to_string(int(seconds)) + " s");
  algorithm->Update();
}

// A file of random bytes, or of another format, gets a clear message
// before VTK sees it: legacy files start with their version line, XML
// files with "<?xml" or "<VTKFile"; a file of another known format under a
// VTK name is said as what it is.
void check_header(const std::string& path, const DataFormat& format) {
  if (const DataFormat* content = format_by_content(path); content && content != &format &&
                                                             content->reader != format.reader)
    throw DataError(unreadable_format_message(path));
  std::ifstream in(path, std::ios::binary);
  std::string head(256, '\0');
  in.read(head.data(), std::streamsize(head.size()));
  head.resize(std::size_t(in.gcount()));
  if (format.reader == VtkReaderKind::legacy) {
    if (head.rfind("# vtk DataFile Version", 0) != 0)
      throw DataError(path + ": not a legacy VTK file: its first line is not \"# vtk DataFile Version x.y\"");
    return;
  }
  std::size_t start = head.rfind("\xEF\xBB\xBF", 0) == 0 ? 3 : 0;  // a UTF-8 byte-order mark
  start = head.find_first_not_of(" \t\r\n", start);
  if (start == std::string::npos || (head.compare(start, 5, "<?xml") != 0 && head.compare(start, 8, "<VTKFile") != 0))
    throw DataError(path + ": not a VTK XML file: it does not start with \"<?xml\" or \"<VTKFile\"");
}

// VTK's cells index their points by their type's count: a hexahedron
// listed with three points, or a biquadratic wedge with eight, is read past
// its end by every filter. So every cell must have its type's count (VTK's
// own, from an instance of the type), or at least the minimum for the
// types of any size; higher-order Lagrange and Bezier cells and polyhedra,
// whose layout lives in further arrays, are refused.
void check_cell_sizes(vtkUnstructuredGrid* grid, const std::string& path) {
  vtkCellArray* cells = grid->GetCells();
  if (!cells) return;
  const vtkIdType count = grid->GetNumberOfCells();
  if (cells->GetNumberOfCells() != count || (count > 0 && !grid->GetCellTypesArray()))
    throw DataError(path + ": the cell list and the cell types disagree on the number of cells");
  std::map<int, vtkIdType> required;  // by type: the exact count, or −(the least) for any size
  for (vtkIdType i = 0; i < count; ++i) {
    const int type = grid->GetCellType(i);
    auto known = required.find(type);
    if (known == required.end()) {
      const vtkSmartPointer<vtkCell> cell = vtkSmartPointer<vtkCell>::Take(vtkGenericCell::InstantiateCell(type));
      std::ostringstream message;
      if (!cell) {
        message << path << ": cell " << i << " has type " << type << ", which is no VTK cell type";
        throw DataError(message.str());
      }
      if (type == VTK_POLYHEDRON || (type >= VTK_LAGRANGE_CURVE && type <= VTK_BEZIER_WEDGE)) {
        message << path << ": cell " << i << " is a " << cell->GetClassName()
                << "; only linear and quadratic cells are supported (VTK's Tessellator filter turns others into them)";
        throw DataError(message.str());
      }
      const vtkIdType fixed = cell->GetNumberOfPoints();
      vtkIdType least = 1;
      if (type == VTK_POLY_LINE) least = 2;
      if (type == VTK_POLYGON || type == VTK_TRIANGLE_STRIP || type == VTK_QUADRATIC_POLYGON) least = 3;
      if (type == VTK_CONVEX_POINT_SET) least = 4;
      known = required.emplace(type, fixed > 0 ? fixed : -least).first;
    }
    const vtkIdType size = cells->GetCellSize(i);
    const vtkIdType need = known->second;
    if (need > 0 ? size != need : size < -need) {
      std::ostringstream message;
      message << path << ": cell " << i << " is a " << vtkCellTypes::GetClassNameFromTypeId(type) << " with " << size
              << " points; it needs " << (need > 0 ? "" : "at least ") << std::abs(need);
      throw DataError(message.str());
    }
  }
}

// What no reader checks but everything after relies on: finite point
// coordinates, cells that name existing points, and some volume to sample.
void check_dataset(vtkDataSet* data, const std::string& path) {
  const vtkIdType points = data->GetNumberOfPoints();
  for (vtkIdType i = 0; i < points; ++i) {
    double p[3];
    data->GetPoint(i, p);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) {
      std::ostringstream message;
      message << path << ": point " << i << " has a non-finite coordinate (" << p[0] << ", " << p[1] << ", " << p[2]
              << ")";
      throw DataError(message.str());
    }
  }
  if (auto* grid = vtkUnstructuredGrid::SafeDownCast(data)) {
    check_cell_sizes(grid, path);
    vtkDataArray* connectivity = grid->GetCells() ? grid->GetCells()->GetConnectivityArray() : nullptr;
    if (connectivity && connectivity->GetNumberOfTuples() > 0) {
      double range[2];
      connectivity->GetRange(range, 0);
      if (range[0] < 0.0 || range[1] >= double(points)) {
        std::ostringstream message;
        message << path << ": a cell names point " << (range[0] < 0.0 ? range[0] : range[1]) << ", but the points are 0 to "
                << points - 1;
        throw DataError(message.str());
      }
    }
  }
  const vtkIdType cells = data->GetNumberOfCells();
  if (cells == 0) throw DataError(path + ": the data set has no cells: there is no volume to sample tensors in");
  // One cell with volume is enough: degenerate cells among good ones are
  // legal (no point lies inside them). Tetrahedra from VTK's own
  // triangulation of each 3D cell.
  double bounds[6];
  data->GetBounds(bounds);
  const double diagonal = std::hypot(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4]);
  const double tiny = 1e-12 * diagonal * diagonal * diagonal;
  auto ids = vtkSmartPointer<vtkIdList>::New();
  auto corners = vtkSmartPointer<vtkPoints>::New();
  vtkIdType three_d = 0;
  for (vtkIdType i = 0; i < cells; ++i) {
    vtkCell* cell = data->GetCell(i);
    if (cell->GetCellDimension() != 3) continue;
    ++three_d;
    if (!cell->Triangulate(0, ids, corners)) continue;
    for (vtkIdType t = 0; t + 3 < corners->GetNumberOfPoints(); t += 4) {
      double a[3], b[3], c[3], d[3];
      corners->GetPoint(t, a), corners->GetPoint(t + 1, b), corners->GetPoint(t + 2, c), corners->GetPoint(t + 3, d);
      const Vec3 pa(a[0], a[1], a[2]);
      const double volume = std::fabs((Vec3(b[0], b[1], b[2]) - pa).dot(
                                (Vec3(c[0], c[1], c[2]) - pa).cross(Vec3(d[0], d[1], d[2]) - pa))) / 6.0;
      if (volume > tiny) return;
    }
  }
  std::ostringstream message;
  message << path << ": none of its " << cells << " cells has any volume ("
          << (three_d ? std::to_string(three_d) + " are 3D cells, all flat" : std::string("none is a 3D cell"))
          << "): tensors are sampled inside 3D cells";
  throw DataError(message.str());
}

// The data set in `path`; VTK's complaints end up in `vtk`.
vtkSmartPointer<vtkDataSet> read_dataset(const std::string& path, const VtkSession& vtk) {
  if (const std::string why = unreadable_input(path); !why.empty()) throw DataError(path + ": " + why);

  const DataFormat* format = format_by_extension(path);
  if (!format || !format->readable()) throw DataError(unreadable_format_message(path));
  vtkSmartPointer<vtkAlgorithm> reader;
  if (format->reader == VtkReaderKind::legacy) {
    auto legacy = vtkSmartPointer<vtkDataSetReader>::New();
    legacy->SetFileName(path.c_str());
    legacy->ReadAllTensorsOn();
    legacy->ReadAllScalarsOn();
    legacy->ReadAllVectorsOn();
    legacy->ReadAllFieldsOn();
    reader = legacy;
  } else {
    auto xml = vtkSmartPointer<vtkXMLGenericDataObjectReader>::New();
    xml->SetFileName(path.c_str());
    reader = xml;
  }
  check_header(path, *format);
  update_safely(reader, path, "reader");
  vtkSmartPointer<vtkDataSet> data = vtkDataSet::SafeDownCast(reader->GetOutputDataObject(0));
  // A reader's warning is a file it could not read as declared (a
  // truncated array reads as garbage, with only a warning): an error here.
  std::string error = vtk.first_error();
  if (error.empty()) error = vtk.first_warning();
  if (!error.empty() || !data || data->GetNumberOfPoints() == 0)
    throw DataError(path + ": cannot read it as a VTK data set: " + (error.empty() ? "no points in it" : error));
  check_dataset(data, path);
  return data;
}

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
};

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
// what it is (6 or 9: tensors, 3: vectors). Not named: the active tensors,
// else the only array of 6 or 9 components; failing both (and unless
// tensors were asked for), the active vectors, else the only array of 3.
ChosenArray choose_field_array(vtkDataSet* data, const VtkFileSpec& spec) {
  const TensorAssociation assoc = spec.association;
  ChosenArray chosen;
  if (!spec.array.empty()) {
    chosen = named_array(data, spec.array, assoc);
    if (!chosen.array)
      throw DataError(spec.path + ": no array named \"" + spec.array + "\" (data.array)" + where_looked(assoc) + "; the file has " +
                      list_arrays(data));
  } else {
    const auto pick = [&](bool vectors) {
      for (const bool points : {true, false}) {
        if ((points && assoc == TensorAssociation::cell) || (!points && assoc == TensorAssociation::point)) continue;
        vtkDataSetAttributes* a = points ? data->GetPointData() : static_cast<vtkDataSetAttributes*>(data->GetCellData());
        vtkDataArray* found = vectors ? (a->GetVectors() ? a->GetVectors() : only_array_of(a, {3}))
                                      : (a->GetTensors() ? a->GetTensors() : only_array_of(a, {6, 9}));
        if (found) return ChosenArray{found, points, found->GetName() ? found->GetName() : "(unnamed)",
                                      found->GetNumberOfComponents()};
      }
      return ChosenArray{};
    };
    if (spec.kind != FieldKind::vector) chosen = pick(false);
    if (!chosen.array && spec.kind != FieldKind::tensor) chosen = pick(true);
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

// Tensors of `array`, checked for finiteness, symmetrised when given as 9
// components (with one warning for the largest asymmetry found).
std::vector<Sym3> read_tensors(const ChosenArray& chosen, const std::string& path,
                               std::vector<std::string>& warnings) {
  vtkDataArray* array = chosen.array;
  const char* item = chosen.on_points ? "point" : "cell";
  const vtkIdType n = array->GetNumberOfTuples();
  const int components = array->GetNumberOfComponents();
  std::vector<Sym3> tensors(static_cast<std::size_t>(n));
  double worst = 0.0, worst_norm = 0.0;
  vtkIdType worst_at = -1;
  double t[9];
  for (vtkIdType i = 0; i < n; ++i) {
    array->GetTuple(i, t);
    for (int c = 0; c < components; ++c) {
      if (!std::isfinite(t[c])) {
        std::ostringstream message;
        message << path << ": array \"" << chosen.name << "\" has a non-finite value (" << t[c] << ") at "
                << item << " " << i << ", component " << c;
        throw DataError(message.str());
      }
    }
    Sym3& s = tensors[std::size_t(i)];
    if (components == 6) {
      s = Sym3{t[0], t[1], t[2], t[3], t[4], t[5]};
      continue;
    }
    // Row- or column-major does not matter: the symmetric part is the same.
    Mat3 m;
    for (int k = 0; k < 9; ++k) m(k / 3, k % 3) = t[k];
    s = Sym3::symmetric_part(m);
    const double asymmetry = (m - m.transpose()).cwiseAbs().maxCoeff();
    if (asymmetry > worst) {
      worst = asymmetry;
      worst_at = i;
      worst_norm = m.norm();
    }
  }
  if (worst_at >= 0) {
    std::ostringstream message;
    message << path << ": array \"" << chosen.name << "\" is not symmetric; using its symmetric part "
            << "(T + Tᵀ)/2. Largest asymmetry |T_ij − T_ji| = " << worst << " at " << item << " "
            << worst_at << " (where |T| = " << worst_norm << ")";
    warnings.push_back(message.str());
  }
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
bool is_image_volume(vtkDataSet* data) {
  auto* image = vtkImageData::SafeDownCast(data);
  if (!image) return false;
  const int* dims = image->GetDimensions();
  return dims[0] >= 2 && dims[1] >= 2 && dims[2] >= 2 && std::fabs(image->GetDirectionMatrix()->Determinant()) > 1e-12;
}

// The data set's outer surface as triangles with vertex normals. Edges
// sharper than 40° split the normals, so a cylinder's faceted wall shades
// smoothly while its rim stays a rim.
TriangleMesh boundary_surface(vtkDataSet* data, const std::string& path) {
  auto surface = vtkSmartPointer<vtkDataSetSurfaceFilter>::New();
  surface->SetInputData(data);
  auto triangles = vtkSmartPointer<vtkTriangleFilter>::New();
  triangles->SetInputConnection(surface->GetOutputPort());
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

}  // namespace

namespace {

// The scalar array `name` for colouring: one component (a vector's
// magnitude when it has three).
std::unique_ptr<ScalarField> color_field(vtkDataSet* data, const VtkFileSpec& spec,
                                         const std::shared_ptr<const MeshLocator>& locator) {
  const ChosenArray chosen = named_array(data, spec.color_array, TensorAssociation::automatic);
  if (!chosen.array)
    throw DataError(spec.path + ": no array named \"" + spec.color_array + "\" to colour by; the file has " +
                    list_arrays(data));
  const ValueLocation where = chosen.on_points ? ValueLocation::points : ValueLocation::cells;
  if (chosen.components == 1)
    return std::make_unique<MeshScalarField>(locator, read_values<double>(chosen, spec.path), where);
  if (chosen.components == 3) {
    std::vector<double> magnitude;
    for (const Vec3& v : read_values<Vec3>(chosen, spec.path)) magnitude.push_back(v.norm());
    return std::make_unique<MeshScalarField>(locator, std::move(magnitude), where);
  }
  throw DataError(spec.path + ": array \"" + chosen.name + "\" has " + std::to_string(chosen.components) +
                  " components; colouring needs a scalar (1) or a vector (3, by its magnitude)");
}

}  // namespace

void set_trial_read_seconds(double seconds) { trial_base_seconds = seconds; }

VtkData load_vtk_data(const VtkFileSpec& spec) {
  const VtkSession vtk;
  const vtkSmartPointer<vtkDataSet> data = read_dataset(spec.path, vtk);
  VtkData out;
  ChosenArray chosen = choose_field_array(data, spec);
  // One locator for every array of the data set (all share its cells).
  std::shared_ptr<const MeshLocator> locator;
  const auto mesh_locator = [&] {
    if (!locator) locator = std::make_shared<MeshLocator>(data.Get());
    return locator;
  };
  if (chosen.components == 3) {
    out.vectors = std::make_unique<MeshVectorField>(mesh_locator(), read_values<Vec3>(chosen, spec.path),
                                                    chosen.on_points ? ValueLocation::points : ValueLocation::cells);
  } else {
    vtkSmartPointer<vtkDataSet> averaged;
    std::vector<Sym3> tensors = read_tensors(chosen, spec.path, out.warnings);
    if (!chosen.on_points && spec.cell_tensors == CellTensors::averaged) {
      // The checks and warnings above name cells, which the user can find;
      // the averaged copy would only repeat them for points.
      chosen = averaged_onto_points(data, chosen, spec.path, averaged);
      std::vector<std::string> repeated;
      tensors = read_tensors(chosen, spec.path, repeated);
    }
    if (chosen.on_points && is_image_volume(data)) {
      auto* image = vtkImageData::SafeDownCast(data);
      const int* extent = image->GetExtent();
      const double* origin = image->GetOrigin();
      const double* spacing = image->GetSpacing();
      Mat3 direction;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) direction(i, j) = image->GetDirectionMatrix()->GetElement(i, j);
      // The first node: the extent may start away from index 0.
      const Vec3 first = Vec3(origin[0], origin[1], origin[2]) +
                         direction * Vec3(extent[0] * spacing[0], extent[2] * spacing[1], extent[4] * spacing[2]);
      const int* dims = image->GetDimensions();
      out.field = std::make_unique<UniformGridField>(first, Vec3(spacing[0], spacing[1], spacing[2]),
                                                     std::array<int, 3>{dims[0], dims[1], dims[2]},
                                                     std::move(tensors), direction);
    } else {
      out.field = std::make_unique<MeshField>(mesh_locator(), std::move(tensors),
                                              chosen.on_points ? ValueLocation::points : ValueLocation::cells);
    }
  }
  if (!spec.color_array.empty()) out.color = color_field(data, spec, mesh_locator());
  out.boundary = boundary_surface(data, spec.path);
  return out;
}

std::string describe_vtk_file(const VtkFileSpec& spec) {
  const VtkSession vtk;
  const vtkSmartPointer<vtkDataSet> data = read_dataset(spec.path, vtk);
  std::ostringstream out;
  double b[6];
  data->GetBounds(b);
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

  const ChosenArray chosen = choose_field_array(data, spec);
  const char* where = chosen.on_points ? "point" : "cell";
  if (chosen.components == 3) {
    double lo = INFINITY, hi = 0.0;
    for (const Vec3& v : read_values<Vec3>(chosen, spec.path)) lo = std::min(lo, v.norm()), hi = std::max(hi, v.norm());
    out << "  vectors   \"" << chosen.name << "\" (3 components, " << where << " data)\n";
    out << "  speed     [" << lo << ", " << hi << "]\n";
    return out.str();
  }
  std::vector<std::string> warnings;
  const std::vector<Sym3> tensors = read_tensors(chosen, spec.path, warnings);
  EigenvalueRange range;
  for (const Sym3& s : tensors) range.add(s);
  out << "  tensors   \"" << chosen.name << "\" (" << chosen.components << " components, " << where << " data)\n";
  out << range;
  for (const std::string& w : warnings) out << "  warning: " << w << "\n";
  return out.str();
}

}  // namespace hsb
