#include "field/reading/dataset_reading.h"

#include <vtkCell.h>
#include <vtkCellData.h>
#include <vtkDataSetAttributes.h>
#include <vtkCellTypes.h>
#include <vtkGenericCell.h>
#include <vtkIdList.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLDataSetWriter.h>
#include <vtkXMLGenericDataObjectReader.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <map>
#include <mutex>
#include <new>
#include <sstream>

#include "base/child_process.h"
#include "base/input_file.h"
#include "base/partial_file.h"
#include "field/reading/block_merging.h"
#include "field/reading/component_arrays.h"
#include "field/reading/data_error.h"
#include "field/reading/data_formats.h"
#include "field/reading/file_records.h"
#include "field/reading/format_reader.h"
#include "field/reading/plane_data.h"
#include "field/reading/vtk_data.h"

namespace hsb {
namespace {

double trial_base_seconds = 30.0;

const std::string no_volume_key = "hsb no volume";

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

// An image's points are its origin plus a linear map of their index, each
// coordinate largest and least at corners: where the eight corners are
// finite, so is every point. (Asking each of a volume's millions of points
// kept one thread 11 ms on Teem's helix at 136³.)
bool image_corners_finite(vtkImageData* image) {
  const int* extent = image->GetExtent();
  for (int corner = 0; corner < 8; ++corner) {
    const int index[3] = {extent[corner & 1 ? 1 : 0], extent[corner & 2 ? 3 : 2], extent[corner & 4 ? 5 : 4]};
    double p[3];
    image->TransformIndexToPhysicalPoint(index, p);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) return false;
  }
  return true;
}

// What no reader checks but everything after relies on: finite point
// coordinates, cells of their type's size that name existing points.
void check_cells(vtkDataSet* data, const std::string& path) {
  const vtkIdType points = data->GetNumberOfPoints();
  auto* image = vtkImageData::SafeDownCast(data);
  const vtkIdType asked = image && image_corners_finite(image) ? 0 : points;
  for (vtkIdType i = 0; i < asked; ++i) {
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
  if (data->GetNumberOfCells() == 0 && !vtkPolyData::SafeDownCast(data) && !vtkUnstructuredGrid::SafeDownCast(data))
    throw DataError(path + ": the data set has no cells: there is no volume to sample tensors in");
}

// Some volume to sample in: one cell with volume is enough (2-D results
// in an axis plane are made a slab first: field/reading/plane_data.h).
// Data without 3-D cells (a point cloud, lines, a curved shell) has no
// volume to trace in but still a value at each point: that is recorded
// (no_volume_reason), and its picture is a glyph at each point. 3-D cells
// that are all flat are a broken mesh, an error.
void check_volume(vtkDataSet* data, const std::string& path) {
  const vtkIdType cells = data->GetNumberOfCells();
  // One cell with volume is enough: degenerate cells among good ones are
  // legal (no point lies inside them). Tetrahedra from VTK's own
  // triangulation of each 3D cell.
  // Flat measured against each tetrahedron's own size, its longest edge
  // cubed: against the body's diagonal, the unit cubes of a rod 10,000
  // long were "flat" (their volume 10⁻¹² of the diagonal's cube).
  const auto flat = [](const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    const double longest = std::sqrt(std::max({(b - a).squaredNorm(), (c - a).squaredNorm(), (d - a).squaredNorm(),
                                                (c - b).squaredNorm(), (d - b).squaredNorm(), (d - c).squaredNorm()}));
    const double volume = std::fabs((b - a).dot((c - a).cross(d - a))) / 6.0;
    return !(volume > 1e-12 * longest * longest * longest);
  };
  auto ids = vtkSmartPointer<vtkIdList>::New();
  auto corners = vtkSmartPointer<vtkPoints>::New();
  vtkIdType three_d = 0;
  int highest = 0;
  for (vtkIdType i = 0; i < cells; ++i) {
    vtkCell* cell = data->GetCell(i);
    highest = std::max(highest, cell->GetCellDimension());
    if (cell->GetCellDimension() != 3) continue;
    ++three_d;
    if (!cell->Triangulate(0, ids, corners)) continue;
    for (vtkIdType t = 0; t + 3 < corners->GetNumberOfPoints(); t += 4) {
      double a[3], b[3], c[3], d[3];
      corners->GetPoint(t, a), corners->GetPoint(t + 1, b), corners->GetPoint(t + 2, c), corners->GetPoint(t + 3, d);
      if (!flat(Vec3(a[0], a[1], a[2]), Vec3(b[0], b[1], b[2]), Vec3(c[0], c[1], c[2]), Vec3(d[0], d[1], d[2]))) return;
    }
  }
  std::ostringstream message;
  if (three_d == 0) {
    if (cells == 0) message << "it has points but no cells";
    else message << "its " << cells << " cells are " << (highest < 2 ? "points or lines" : "surfaces not in an axis plane");
    message << ", with no volume to trace trajectories in";
    add_record(data->GetFieldData(), no_volume_key, {message.str()});
    return;
  }
  message << path << ": none of its " << cells << " cells has any volume (" << three_d
          << " are 3D cells, all flat): tensors are sampled inside 3D cells";
  throw DataError(message.str());
}

// Every file the data file names (pieces, blocks, a detached header's
// data), asked before any reader opens one: a FIFO would keep the reader
// waiting for a writer for ever, a device would never end. One that is
// missing is left to the reader, which says where the data file names it.
void check_named_files(const std::string& path, const FormatReader& reader) {
  if (!reader.parts) return;
  for (const std::string& part : reader.parts(path))
    if (const std::string why = unreadable_input(part); !why.empty() && why != "no such file")
      throw DataError(path + ": names " + part + ": " + why);
}

// What every data set gets after its reader (a file's or data arrays'):
// its cells checked, pieces joined where `joins_pieces`, component arrays
// joined and the writer's orders recorded, a 2-D result extruded, and a
// body without volume refused. `path` names it in messages.
vtkSmartPointer<vtkDataSet> made_whole(vtkSmartPointer<vtkDataSet> data, const std::string& path, bool joins_pieces) {
  check_cells(data, path);
  if (joins_pieces) data = joined(vtkUnstructuredGrid::SafeDownCast(data));
  join_component_arrays(data->GetPointData(), data->GetFieldData());
  join_component_arrays(data->GetCellData(), data->GetFieldData());
  record_writer_orders(data);
  if (const std::optional<PlaneOfData> plane = find_plane(data)) data = extruded(data, *plane);
  check_volume(data, path);
  return data;
}

// The file read by its format's reader, checked and made whole: what runs
// in the child.
vtkSmartPointer<vtkDataSet> read_checked(const std::string& path, const FormatReader& reader,
                                         const ReadRequest& request, const VtkSession& vtk) {
  // A file of another known format under this one's name is said as what it is.
  if (const std::string other = unreadable_format_message(path); !other.empty()) throw DataError(other);
  check_named_files(path, reader);
  return made_whole(reader.read(path, request, vtk), path, reader.joins_pieces);
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
  // SIGKILL is no crash of VTK's: the kernel's out-of-memory killer (or a
  // job scheduler, or a user) ended the child; a time-out's own is below.
  if (child.outcome == ChildOutcome::crashed && child.signal == SIGKILL)
    throw DataError(path + ": the reading process was killed (out of memory?) while VTK's " + what +
                    " read it: read it where more memory is free, or check the sizes its header declares");
  if (child.outcome == ChildOutcome::crashed)
    throw DataError(path + ": the file is corrupt: VTK's " + what + " crashed on it" +
                    (child.signal ? " (signal " + std::to_string(child.signal) + ")" : std::string()));
  if (child.outcome == ChildOutcome::timed_out)
    throw DataError(path + ": the file is corrupt: VTK's " + what + " did not finish it in " +
                    std::to_string(int(child_seconds(path))) + " s");
}

// Runs `work` on the user's file `path` in a child process: a crash or a
// hang there is one DataError naming `what` ran, and so is an exception
// `work` throws (its message, passed back through a scratch file). `work`
// leaves its result in scratch files of its own. Scratch files are made
// empty, in a folder no one else can write in: what is read back from
// one is what the child wrote, and an empty one means it wrote nothing.
void run_on_file_in_child(const std::string& path, const char* what, const std::function<void()>& work) {
  const ScratchFile failure("failure", ".txt");
  const ChildResult child = run_in_child(
      [&] {
        try {
          work();
        } catch (const std::bad_alloc&) {
          // A reader that meets a count larger than memory with a bare
          // std::bad_alloc (the VTK readers' own are said in vtk_session.h).
          std::ofstream(failure.path()) << path << ": it declares more than memory holds (the " << what
                                        << " could not allocate what its sizes ask for)";
        } catch (const std::exception& e) {
          const std::string message = e.what();
          std::ofstream(failure.path()) << (message.empty() ? path + ": " + what + " failed" : message);
        }
      },
      child_seconds(path));
  refuse_failed_child(child, path, what);
  if (failure.written()) {
    std::ifstream said(failure.path());
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
vtkSmartPointer<vtkDataSet> read_in_child(const std::string& path, const FormatReader& reader,
                                          const ReadRequest& request, const VtkSession& vtk) {
  const ScratchFile clean("read", ".vtkxml");
  run_on_file_in_child(path, "reader", [&] {
    const vtkSmartPointer<vtkDataSet> data = read_checked(path, reader, request, vtk);
    auto writer = vtkSmartPointer<vtkXMLDataSetWriter>::New();
    writer->SetInputData(data);
    writer->SetFileName(clean.path().c_str());
    writer->SetDataModeToAppended();
    writer->EncodeAppendedDataOff();
    writer->SetCompressorTypeToNone();
    if (!writer->Write()) std::filesystem::remove(clean.path());
  });
  // No child to be had (or it could not write): read it here after all.
  if (!clean.written()) return read_checked(path, reader, request, vtk);
  auto copy = vtkSmartPointer<vtkXMLGenericDataObjectReader>::New();
  copy->SetFileName(clean.path().c_str());
  copy->Update();
  vtkSmartPointer<vtkDataSet> data = vtkDataSet::SafeDownCast(copy->GetOutputDataObject(0));
  if (!data) throw DataError(path + ": cannot read back what VTK read of it");
  return data;
}

// What `hook` says of the user's file `path`, worked out in a child
// process like every parse of it, one line an answer. The child writes how
// many lines first: an answer of none is told from no answer.
std::vector<std::string> lines_in_child(const std::string& path, const std::function<std::vector<std::string>()>& hook) {
  const ScratchFile said("said", ".txt");
  run_on_file_in_child(path, "reader", [&] {
    const std::vector<std::string> lines = hook();
    std::ofstream out(said.path());
    out << lines.size() << "\n";
    for (const std::string& line : lines) out << line << "\n";
  });
  std::ifstream in(said.path());
  std::size_t count = 0;
  if (!said.written() || !(in >> count) || in.get() != '\n') return hook();  // no child to be had
  std::vector<std::string> lines;
  for (std::string line; lines.size() < count && std::getline(in, line);) lines.push_back(line);
  if (lines.size() < count) return hook();  // the child could not write it all
  return lines;
}

const FormatReader* reader_of(const std::string& path) {
  const DataFormat* format = format_by_extension(path);
  return format ? format->reader : nullptr;
}

// Every step's file of the series in `path`, listed by one child and
// kept while the series file stays as it was (its size and modification
// time): a 5,000-step .pvd asked a child per step, 5,000 forks of a
// process that may hold gigabytes, each time its steps were hashed or
// read.
std::vector<std::string> step_files_of(const std::string& path, const FormatReader& series) {
  struct Listed {
    std::uintmax_t size = 0;
    std::filesystem::file_time_type modified;
    std::vector<std::string> files;
  };
  static std::mutex guard;
  static std::map<std::string, Listed> listed;
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  const std::filesystem::file_time_type modified = error ? std::filesystem::file_time_type()
                                                         : std::filesystem::last_write_time(path, error);
  const std::lock_guard<std::mutex> lock(guard);
  const auto found = listed.find(path);
  if (!error && found != listed.end() && found->second.size == size && found->second.modified == modified)
    return found->second.files;
  std::vector<std::string> files = lines_in_child(path, [&] { return series.step_files(path); });
  if (!error) listed[path] = {size, modified, files};
  return files;
}

// A series' file of step `step` (-1: the first).
std::string step_file_of(const std::string& path, const FormatReader& series, int step) {
  const std::vector<std::string> all = step_files_of(path, series);
  if (all.empty()) throw DataError(path + ": a time series of no steps");
  if (step >= int(all.size()))
    throw DataError(path + ": data.step " + std::to_string(step) + " is beyond its " + std::to_string(all.size()) +
                    " steps (0 to " + std::to_string(all.size() - 1) + ")");
  return all[std::size_t(std::max(step, 0))];
}

}  // namespace

std::vector<std::string> data_files_read(const std::string& path, int step) {
  std::vector<std::string> files{path};
  const FormatReader* reader = reader_of(path);
  if (!reader) return files;
  std::string step_file;
  if (reader->in_process) {
    // hsb's own parser answers in this process, as it reads, without VTK
    // (whose first session, like a child, would wait for the image
    // module's loading: a render asks this while that runs).
    if (reader->parts) {
      const std::vector<std::string> parts = reader->parts(path);
      files.insert(files.end(), parts.begin(), parts.end());
    }
    return files;
  }
  {
    const VtkSession vtk;
    if (reader->parts) {
      const std::vector<std::string> parts = lines_in_child(path, [&] { return reader->parts(path); });
      files.insert(files.end(), parts.begin(), parts.end());
    }
    if (reader->step_files) step_file = step_file_of(path, *reader, step);
  }
  if (!step_file.empty() && reader_of(step_file) != reader) {
    const std::vector<std::string> inner = data_files_read(step_file, -1);
    files.insert(files.end(), inner.begin(), inner.end());
  }
  return files;
}

std::string no_volume_reason(vtkDataSet* data) {
  const std::vector<std::string> record = record_of(data, no_volume_key);
  return record.empty() ? std::string() : record.front();
}

void update_safely(vtkAlgorithm* algorithm, const std::string& path, const char* what) {
  refuse_failed_child(run_in_child([&] { algorithm->Update(); }, child_seconds(path)), path, what);
  algorithm->Update();
}

void set_trial_read_seconds(double seconds) { trial_base_seconds = seconds; }

std::vector<double> series_times(const std::string& path) {
  const FormatReader* reader = reader_of(path);
  if (!reader || !reader->times) return {};
  const VtkSession vtk;
  std::vector<double> times;
  for (const std::string& line : lines_in_child(path, [&] {
         std::vector<std::string> lines;
         for (double t : reader->times(path)) {
           std::ostringstream text;
           text << std::setprecision(17) << t;
           lines.push_back(text.str());
         }
         return lines;
       }))
    times.push_back(std::strtod(line.c_str(), nullptr));
  return times;
}

vtkSmartPointer<vtkDataSet> read_arrays(const DataArrays& arrays) {
  // The program's own arrays, checked before VTK is given them: read here,
  // with no child (the data is in this process only).
  return made_whole(grid_of_arrays(arrays), arrays.name, false);
}

vtkSmartPointer<vtkDataSet> read_dataset(const std::string& path, const VtkSession& vtk, const ReadRequest& request) {
  if (const std::string why = unreadable_input(path); !why.empty()) throw DataError(path + ": " + why);
  const DataFormat* format = format_by_extension(path);
  if (!format || !format->readable()) throw DataError(unreadable_format_message(path));
  const FormatReader& reader = *format->reader;
  if (reader.step_files) {
    const std::string file = step_file_of(path, reader, request.step);
    if (reader_of(file) == &reader) throw DataError(path + ": its step names another series, " + file);
    return read_dataset(file, vtk, {-1, request.block, request.scalar});
  }
  if (request.step > 0 && !reader.times)
    throw DataError(path +
                    ": data.step applies only to a time series (.pvd; Exodus, XDMF, MED, Gmsh or CalculiX results "
                    "with time steps)");
  if (!request.block.empty() && !reader.has_blocks)
    throw DataError(path + ": data.block applies only to files of blocks (.vtm, Exodus); this is a " + format->name +
                    " file");
  return reader.in_process ? read_checked(path, reader, request, vtk) : read_in_child(path, reader, request, vtk);
}

}  // namespace hsb
