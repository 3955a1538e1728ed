#include "field/reading/dataset_reading.h"

#include <vtkAppendFilter.h>
#include <vtkCell.h>
#include <vtkCellData.h>
#include <vtkDataSetAttributes.h>
#include <vtkCellTypes.h>
#include <vtkCompositeDataIterator.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataSetReader.h>
#include <vtkGenericCell.h>
#include <vtkIdList.h>
#include <vtkMergePoints.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLDataSetWriter.h>
#include <vtkXMLGenericDataObjectReader.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iterator>
#include <map>
#include <sstream>

#include "base/child_process.h"
#include "base/input_file.h"
#include "base/partial_file.h"
#include "field/reading/component_arrays.h"
#include "field/reading/data_error.h"
#include "field/reading/data_formats.h"
#include "field/reading/exodus_reading.h"
#include "field/reading/nifti_reading.h"
#include "field/reading/nrrd_reading.h"
#include "field/reading/plane_data.h"
#include "field/reading/vtk_data.h"

namespace hsb {
namespace {

double trial_base_seconds = 30.0;

// A file of random bytes, or of another format, gets a clear message
// before VTK's readers see it: legacy files start with their version
// line, XML files with "<?xml" or "<VTKFile", Exodus files with netCDF's
// or HDF5's signature. (NRRD and NIfTI are read by readers that check
// their own headers.)
void check_header(const std::string& path, const DataFormat& format) {
  std::ifstream in(path, std::ios::binary);
  std::string head(256, '\0');
  in.read(head.data(), std::streamsize(head.size()));
  head.resize(std::size_t(in.gcount()));
  if (format.reader == VtkReaderKind::exodus) {
    if (head.rfind("CDF", 0) != 0 && head.rfind("\x89HDF\r\n\x1a\n", 0) != 0)
      throw DataError(path + ": not an Exodus II file: it is neither netCDF (\"CDF\") nor HDF5 inside");
    return;
  }
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
// coordinates, cells of their type's size that name existing points.
void check_cells(vtkDataSet* data, const std::string& path) {
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
  if (data->GetNumberOfCells() == 0)
    throw DataError(path + ": the data set has no cells: there is no volume to sample tensors in");
}

// Some volume to sample in: one cell with volume is enough (2-D results
// are made a slab first: field/reading/plane_data.h).
void check_volume(vtkDataSet* data, const std::string& path) {
  const vtkIdType cells = data->GetNumberOfCells();
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
  if (three_d == 0 && data->GetNumberOfCells() > 0 && data->GetCell(0)->GetCellDimension() < 2) {
    message << path << ": its " << cells << " cells are points or lines, with no area or volume: tensors are "
            << "sampled in 3-D cells, or 2-D cells in a plane (a point cloud of tensors has nothing to trace in)";
    throw DataError(message.str());
  }
  message << path << ": none of its " << cells << " cells has any volume ("
          << (three_d ? std::to_string(three_d) + " are 3D cells, all flat" : std::string("none is a 3D cell"))
          << "): tensors are sampled inside 3D cells";
  throw DataError(message.str());
}

// Pieces (.pvtu) and blocks (.vtm) as one unstructured grid, their ghost
// cells left out. Arrays that not every block has are dropped (VTK's
// append keeps the common ones).
vtkSmartPointer<vtkDataSet> merged(vtkDataObject* read, const std::string& path) {
  auto append = vtkSmartPointer<vtkAppendFilter>::New();
  int blocks = 0;
  const auto add = [&](vtkDataSet* block) {
    if (!block || block->GetNumberOfCells() == 0) return;
    // Ghost cells are a piece's copies of its neighbours' cells, for the
    // parallel filters that wrote it: here they would be cells twice over.
    auto* grid = vtkUnstructuredGrid::SafeDownCast(block);
    if (grid && grid->GetCellGhostArray()) {
      auto copy = vtkSmartPointer<vtkUnstructuredGrid>::New();
      copy->DeepCopy(grid);
      copy->RemoveGhostCells();
      copy->GetCellData()->RemoveArray(vtkDataSetAttributes::GhostArrayName());
      append->AddInputData(copy);
    } else {
      append->AddInputData(block);
    }
    ++blocks;
  };
  if (auto* composite = vtkCompositeDataSet::SafeDownCast(read)) {
    vtkSmartPointer<vtkCompositeDataIterator> it = vtkSmartPointer<vtkCompositeDataIterator>::Take(composite->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem()) add(vtkDataSet::SafeDownCast(it->GetCurrentDataObject()));
  } else {
    add(vtkDataSet::SafeDownCast(read));
  }
  if (blocks == 0) throw DataError(path + ": none of its blocks holds a data set with cells");
  append->Update();
  return vtkDataSet::SafeDownCast(append->GetOutputDataObject(0));
}

// `grid` with the points at the same place joined into one, as pieces
// share them: otherwise each piece's faces at its neighbours read as the
// body's boundary, and a trajectory stops at them. The cells must name
// existing points (check_cells).
vtkSmartPointer<vtkUnstructuredGrid> joined(vtkUnstructuredGrid* grid) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  auto locator = vtkSmartPointer<vtkMergePoints>::New();
  locator->InitPointInsertion(points, grid->GetBounds(), grid->GetNumberOfPoints());
  auto out = vtkSmartPointer<vtkUnstructuredGrid>::New();
  out->GetPointData()->CopyAllocate(grid->GetPointData(), grid->GetNumberOfPoints());
  std::vector<vtkIdType> to(std::size_t(grid->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i) {
    vtkIdType id = 0;
    if (locator->InsertUniquePoint(grid->GetPoint(i), id)) out->GetPointData()->CopyData(grid->GetPointData(), i, id);
    to[std::size_t(i)] = id;
  }
  out->SetPoints(points);
  out->Allocate(grid->GetNumberOfCells());
  auto ids = vtkSmartPointer<vtkIdList>::New();
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) {
    grid->GetCellPoints(c, ids);
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k) ids->SetId(k, to[std::size_t(ids->GetId(k))]);
    out->InsertNextCell(grid->GetCellType(c), ids);
  }
  out->GetCellData()->ShallowCopy(grid->GetCellData());
  out->GetFieldData()->ShallowCopy(grid->GetFieldData());
  return out;
}

// A time series' data sets: (time, file) in the order of time.
std::vector<std::pair<double, std::string>> series_files(const std::string& path) {
  auto parser = vtkSmartPointer<vtkXMLDataParser>::New();
  parser->SetFileName(path.c_str());
  vtkXMLDataElement* collection = parser->Parse() ? parser->GetRootElement() : nullptr;
  if (collection) collection = collection->FindNestedElementWithName("Collection");
  if (!collection) throw DataError(path + ": not a ParaView time series: no <Collection> in its <VTKFile>");
  std::vector<std::pair<double, std::string>> steps;
  for (int i = 0; i < collection->GetNumberOfNestedElements(); ++i) {
    vtkXMLDataElement* data_set = collection->GetNestedElement(i);
    const char* file = data_set->GetAttribute("file");
    if (std::string(data_set->GetName()) != "DataSet" || !file) continue;
    double time = double(steps.size());
    data_set->GetScalarAttribute("timestep", time);
    // Parts of one step beyond the first are not read: a series of one
    // part each is what ParaView writes for a single data set.
    if (const char* part = data_set->GetAttribute("part"); part && std::string(part) != "0") continue;
    steps.emplace_back(time, file_named_in(path, file));
  }
  std::stable_sort(steps.begin(), steps.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  if (steps.empty()) throw DataError(path + ": its <Collection> lists no <DataSet file=...>");
  return steps;
}

// A legacy file written with the type names of VTK's 5.1 format that
// VTK 9.1's reader does not know (meshio, and so SfePy, write
// "vtktypeint32" for an int array) copied with the older names of the same
// types, to `copy`; false when the file has none. Only whole words that
// end a header line are renamed, and only in files of version 5, the only
// ones that have them: no other file is read twice.
bool with_known_type_names(const std::string& path, const std::string& copy) {
  static const std::pair<const char*, const char*> names[] = {
      {" vtktypeint8\n", " signed_char\n"}, {" vtktypeuint8\n", " unsigned_char\n"},
      {" vtktypeint16\n", " short\n"},      {" vtktypeuint16\n", " unsigned_short\n"},
      {" vtktypeint32\n", " int\n"},        {" vtktypeuint32\n", " unsigned_int\n"},
      {" vtktypefloat32\n", " float\n"},    {" vtktypefloat64\n", " double\n"}};
  std::ifstream in(path, std::ios::binary);
  std::string version;
  std::getline(in, version);
  if (version.rfind("# vtk DataFile Version 5", 0) != 0) return false;
  in.seekg(0);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (text.find(" vtktype") == std::string::npos) return false;
  bool renamed = false;
  for (const auto& [from, to] : names)
    for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + std::strlen(to))) {
      text.replace(at, std::strlen(from), to);
      renamed = true;
    }
  if (renamed) std::ofstream(copy, std::ios::binary) << text;
  return renamed;
}

// The one data set the file at `path` holds, before any check.
vtkSmartPointer<vtkDataSet> read_one(const std::string& path, const DataFormat& format, const VtkSession& vtk,
                                     int step) {
  // A file of another known format under this one's name is said as what it is.
  if (const std::string other = unreadable_format_message(path); !other.empty()) throw DataError(other);
  if (format.reader == VtkReaderKind::nrrd) return read_nrrd(path);
  if (format.reader == VtkReaderKind::nifti) return read_nifti(path);
  check_header(path, format);
  if (format.reader == VtkReaderKind::exodus) {
    const vtkSmartPointer<vtkDataObject> read = read_exodus(path, step);
    if (const std::string error = vtk.first_error(); !error.empty())
      throw DataError(path + ": cannot read it as Exodus II: " + error);
    return merged(read, path);
  }
  vtkSmartPointer<vtkAlgorithm> reader;
  const PartialFile renamed((std::filesystem::temp_directory_path() / ("hsb-types-" + std::to_string(::getpid()) + ".vtk")).string());
  if (format.reader == VtkReaderKind::legacy) {
    auto legacy = vtkSmartPointer<vtkDataSetReader>::New();
    legacy->SetFileName(with_known_type_names(path, renamed.path()) ? renamed.path().c_str() : path.c_str());
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
  reader->Update();
  vtkDataObject* read = reader->GetOutputDataObject(0);
  // A reader's warning is a file it could not read as declared (a
  // truncated array reads as garbage, with only a warning): an error here.
  const auto complaint = [&] {
    std::string error = vtk.first_error();
    return error.empty() ? vtk.first_warning() : error;
  };
  if (const std::string error = complaint(); !error.empty())
    throw DataError(path + ": cannot read it as a VTK data set: " + error);
  vtkSmartPointer<vtkDataSet> data =
      format.reader == VtkReaderKind::xml_pieces ? merged(read, path)
                                                  : vtkSmartPointer<vtkDataSet>(vtkDataSet::SafeDownCast(read));
  if (const std::string error = complaint(); !error.empty() || !data || data->GetNumberOfPoints() == 0)
    throw DataError(path + ": cannot read it as a VTK data set: " + (error.empty() ? "no points in it" : error));
  return data;
}

// The files that `element` and the elements in it name (a piece's Source,
// a block's or a step's file), as named in the file `from`.
void named_files(vtkXMLDataElement* element, const std::string& from, std::vector<std::string>& out) {
  for (const char* attribute : {"Source", "file"})
    if (const char* file = element->GetAttribute(attribute)) out.push_back(file_named_in(from, file));
  for (int i = 0; i < element->GetNumberOfNestedElements(); ++i) named_files(element->GetNestedElement(i), from, out);
}

// The file read, checked and made whole: what runs in the child.
vtkSmartPointer<vtkDataSet> read_checked(const std::string& path, const DataFormat& format, const VtkSession& vtk,
                                         int step) {
  vtkSmartPointer<vtkDataSet> data = read_one(path, format, vtk, step);
  check_cells(data, path);
  if (format.reader == VtkReaderKind::xml_pieces || format.reader == VtkReaderKind::exodus)
    data = joined(vtkUnstructuredGrid::SafeDownCast(data));
  join_component_arrays(data->GetPointData(), data->GetFieldData());
  join_component_arrays(data->GetCellData(), data->GetFieldData());
  record_writer_orders(data);
  if (const std::optional<PlaneOfData> plane = find_plane(data, path)) data = extruded(data, *plane);
  check_volume(data, path);
  return data;
}

// The time a child may take on `path`: generous, a few seconds more than
// a read should take, however large the file.
double child_seconds(const std::string& path) {
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  return trial_base_seconds + (error ? 0.0 : double(size) * 1e-6);
}

// A crash or a hang of VTK in a child process, as one error naming the file.
void refuse_failed_child(const ChildResult& child, const std::string& path, const char* what) {
  if (child.outcome == ChildOutcome::crashed)
    throw DataError(path + ": the file is corrupt: VTK's " + what + " crashed on it" +
                    (child.signal ? " (signal " + std::to_string(child.signal) + ")" : std::string()));
  if (child.outcome == ChildOutcome::timed_out)
    throw DataError(path + ": the file is corrupt: VTK's " + what + " did not finish it in " +
                    std::to_string(int(child_seconds(path))) + " s");
}

// Runs `work` on the user's file `path` in a child process: a crash or a
// hang there is one DataError naming `what` ran, and so is an exception
// `work` throws (its message, passed back through a file). `work` leaves
// its result in files of its own.
void run_on_file_in_child(const std::string& path, const char* what, const std::function<void()>& work) {
  const PartialFile failure(
      (std::filesystem::temp_directory_path() / ("hsb-failure-" + std::to_string(::getpid()) + ".txt")).string());
  const ChildResult child = run_in_child(
      [&] {
        try {
          work();
        } catch (const std::exception& e) {
          std::ofstream(failure.path()) << e.what();
        }
      },
      child_seconds(path));
  refuse_failed_child(child, path, what);
  if (std::ifstream said{failure.path()}) {
    std::stringstream text;
    text << said.rdbuf();
    throw DataError(text.str());
  }
}

// The user's file is parsed only in a child process: VTK's readers trust
// the counts a file declares, so a corrupt file can make them read or
// write past their buffers, loop, or corrupt the heap without crashing
// (the data fuzzer found all four; a write the child survives would go
// unseen in a trial run). The child writes what it read, checked, as a
// plain VTK XML file of VTK's own making, which this process then reads.
vtkSmartPointer<vtkDataSet> read_in_child(const std::string& path, const DataFormat& format, const VtkSession& vtk,
                                          int step) {
  const PartialFile clean(
      (std::filesystem::temp_directory_path() / ("hsb-read-" + std::to_string(::getpid()) + ".vtkxml")).string());
  run_on_file_in_child(path, "reader", [&] {
    const vtkSmartPointer<vtkDataSet> data = read_checked(path, format, vtk, step);
    auto writer = vtkSmartPointer<vtkXMLDataSetWriter>::New();
    writer->SetInputData(data);
    writer->SetFileName(clean.path().c_str());
    writer->SetDataModeToAppended();
    writer->EncodeAppendedDataOff();
    writer->SetCompressorTypeToNone();
    if (!writer->Write()) std::filesystem::remove(clean.path());
  });
  // No child to be had (or it could not write): read it here after all.
  if (!std::filesystem::exists(clean.path())) return read_checked(path, format, vtk, step);
  auto reader = vtkSmartPointer<vtkXMLGenericDataObjectReader>::New();
  reader->SetFileName(clean.path().c_str());
  reader->Update();
  vtkSmartPointer<vtkDataSet> data = vtkDataSet::SafeDownCast(reader->GetOutputDataObject(0));
  if (!data) throw DataError(path + ": cannot read back what VTK read of it");
  return data;
}

// The times of an Exodus file's steps, asked of VTK in a child process
// like every parse of a user's file; none for a file of one step.
std::vector<double> exodus_steps(const std::string& path) {
  const VtkSession vtk;
  const PartialFile said(
      (std::filesystem::temp_directory_path() / ("hsb-times-" + std::to_string(::getpid()) + ".txt")).string());
  run_on_file_in_child(path, "Exodus reader", [&] {
    std::ofstream out(said.path());
    for (double t : exodus_times(path)) out << std::setprecision(17) << t << "\n";
  });
  std::vector<double> times;
  std::ifstream in(said.path());
  if (!in) times = exodus_times(path);  // no child to be had
  for (double t; in >> t;) times.push_back(t);
  if (times.size() < 2) times.clear();
  return times;
}

}  // namespace

std::vector<std::string> data_files_read(const std::string& path, int step) {
  const DataFormat* format = format_by_extension(path);
  if (format && format->reader == VtkReaderKind::series) {
    std::vector<std::string> files{path};
    const VtkSession vtk;
    const std::vector<std::pair<double, std::string>> steps = series_files(path);
    if (std::size_t(std::max(step, 0)) < steps.size()) {
      const std::vector<std::string> inner = data_files_read(steps[std::size_t(std::max(step, 0))].second, -1);
      files.insert(files.end(), inner.begin(), inner.end());
    }
    return files;
  }
  if (format && format->reader == VtkReaderKind::nrrd) return nrrd_files(path);
  std::vector<std::string> files{path};
  if (format && format->reader == VtkReaderKind::xml_pieces) {
    const VtkSession vtk;
    auto parser = vtkSmartPointer<vtkXMLDataParser>::New();
    parser->SetFileName(path.c_str());
    if (parser->Parse() && parser->GetRootElement())
      named_files(parser->GetRootElement(), path, files);
  }
  return files;
}

void update_safely(vtkAlgorithm* algorithm, const std::string& path, const char* what) {
  refuse_failed_child(run_in_child([&] { algorithm->Update(); }, child_seconds(path)), path, what);
  algorithm->Update();
}


void set_trial_read_seconds(double seconds) { trial_base_seconds = seconds; }

std::vector<double> series_times(const std::string& path) {
  const DataFormat* format = format_by_extension(path);
  if (format && format->reader == VtkReaderKind::exodus) return exodus_steps(path);
  if (!format || format->reader != VtkReaderKind::series) return {};
  const VtkSession vtk;
  std::vector<double> times;
  for (const auto& [time, file] : series_files(path)) times.push_back(time);
  return times;
}

vtkSmartPointer<vtkDataSet> read_dataset(const std::string& path, const VtkSession& vtk, int step) {
  if (const std::string why = unreadable_input(path); !why.empty()) throw DataError(path + ": " + why);
  const DataFormat* format = format_by_extension(path);
  if (format && format->reader == VtkReaderKind::series) {
    const std::vector<std::pair<double, std::string>> steps = series_files(path);
    if (step >= int(steps.size()))
      throw DataError(path + ": data.step " + std::to_string(step) + " is beyond its " + std::to_string(steps.size()) +
                      " steps (0 to " + std::to_string(steps.size() - 1) + ")");
    const std::string& file = steps[std::size_t(std::max(step, 0))].second;
    const DataFormat* inner = format_by_extension(file);
    if (inner && inner->reader == VtkReaderKind::series)
      throw DataError(path + ": its step names another series, " + file);
    return read_dataset(file, vtk, -1);
  }
  if (!format || !format->readable()) throw DataError(unreadable_format_message(path));
  if (step > 0 && format->reader != VtkReaderKind::exodus)
    throw DataError(path + ": data.step applies only to a time series (.pvd, or Exodus with time steps)");
  return read_in_child(path, *format, vtk, step);
}

}  // namespace hsb
