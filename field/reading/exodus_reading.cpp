// Exodus II results (Sierra, MOOSE, Cubit, SEACAS, VTK's own writer),
// through VTK's vtkExodusIIReader: every element block, every nodal and
// element variable, at one time step, on the undeformed mesh (a stress
// belongs to the configuration it was computed on, and the picture of
// each step keeps one frame).
//
// VTK's reader "gloms" variables by their names into arrays, and gets
// tensors wrong: stressXX, stressXY, stressXZ, stressYY, stressYZ, stressZZ
// become a vector "stressX" and three scalars. So the glomming is undone
// here, each array split back into the variables the file names, and
// field/reading/component_arrays.h joins them by a rule that knows tensors.
// Internal to field/; the file is parsed only in a child process
// (field/reading/dataset_reading.h).

#include <vtkCellData.h>
#include <vtkCompositeDataIterator.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkDoubleArray.h>
#include <vtkExodusIIReader.h>
#include <vtkInformation.h>
#include <vtkInformationDoubleVectorKey.h>
#include <vtkPointData.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtk_exodusII.h>

#include <algorithm>
#include <map>
#include <optional>

#include "base/input_file.h"
#include "field/reading/block_merging.h"
#include "field/reading/data_error.h"
#include "field/reading/format_reader.h"
#include "field/reading/netcdf_extent.h"

namespace hsb {
namespace {

// The file as the Exodus library opens it, closed at the end of scope.
class ExodusFile {
 public:
  explicit ExodusFile(const std::string& path) {
    int compute_word = 8, io_word = 0;
    float version = 0.0f;
    id_ = ex_open(path.c_str(), EX_READ, &compute_word, &io_word, &version);
    if (id_ < 0) throw DataError(path + ": the Exodus library cannot open it");
  }
  ~ExodusFile() { ex_close(id_); }
  ExodusFile(const ExodusFile&) = delete;
  ExodusFile& operator=(const ExodusFile&) = delete;
  int id() const { return id_; }

 private:
  int id_ = -1;
};

// The variables of one kind (nodal, element) as the file names them, in
// the file's order; none if the file cannot say.
std::vector<std::string> variable_names(const ExodusFile& file, ex_entity_type kind) {
  std::vector<std::string> names;
  int count = 0;
  if (ex_get_variable_param(file.id(), kind, &count) == 0 && count > 0) {
    const int length = std::max(32, int(ex_inquire_int(file.id(), EX_INQ_MAX_READ_NAME_LENGTH)));
    std::vector<std::vector<char>> buffers(std::size_t(count), std::vector<char>(std::size_t(length) + 1, '\0'));
    std::vector<char*> pointers;
    for (auto& b : buffers) pointers.push_back(b.data());
    if (ex_get_variable_names(file.id(), kind, count, pointers.data()) == 0)
      for (const auto& b : buffers) names.emplace_back(b.data());
  }
  return names;
}

// Whether the Exodus library itself reads every nodal variable of the file
// at `step`: VTK's reader does not say when it cannot, and hands on
// uninitialised values (a file meshio wrote reads so). Throws DataError.
void check_nodal_variables(const ExodusFile& file, const std::string& path, int step, std::size_t variables) {
  const int64_t nodes = ex_inquire_int(file.id(), EX_INQ_NODES);
  std::vector<double> values(std::size_t(std::max<int64_t>(nodes, 1)));
  for (std::size_t v = 0; v < variables; ++v) {
    // A warning too: it leaves the values unread.
    if (ex_get_var(file.id(), std::max(step, 0) + 1, EX_NODAL, int(v) + 1, 1, nodes, values.data()) == EX_NOERR)
      continue;
    const char* message = nullptr;
    const char* function = nullptr;
    int code = 0;
    ex_get_err(&message, &function, &code);
    throw DataError(path + ": the Exodus library cannot read its nodal variable " + std::to_string(v + 1) +
                    (message && *message ? std::string(" (") + message + ")" : std::string()) +
                    ": the file does not follow Exodus II as written by the Exodus library; write it with the "
                    "Exodus library (SEACAS, VTK, ParaView), or as .vtu");
  }
}

// Which variables each of the reader's arrays of `type` holds: its arrays
// take the file's variables in order, as many as they have components.
// Empty when they do not add up (a reader that gloms otherwise): the
// arrays then stay as VTK made them.
std::map<std::string, std::vector<std::string>> glommed_variables(vtkExodusIIReader* reader, int type,
                                                                  const std::vector<std::string>& names) {
  std::map<std::string, std::vector<std::string>> parts;
  std::size_t next = 0;
  for (int i = 0; i < reader->GetNumberOfObjectArrays(type); ++i) {
    const int components = reader->GetNumberOfObjectArrayComponents(type, i);
    if (components < 1 || next + std::size_t(components) > names.size()) return {};
    parts[reader->GetObjectArrayName(type, i)].assign(names.begin() + std::ptrdiff_t(next),
                                                      names.begin() + std::ptrdiff_t(next + std::size_t(components)));
    next += std::size_t(components);
  }
  if (next != names.size()) return {};
  return parts;
}

// Each glommed array of `attributes` split back into its variables.
void unglom(vtkDataSetAttributes* attributes, const std::map<std::string, std::vector<std::string>>& parts) {
  for (const auto& [glommed, variables] : parts) {
    vtkDataArray* array = attributes->GetArray(glommed.c_str());
    if (!array || array->GetNumberOfComponents() != int(variables.size()) || variables.size() < 2) continue;
    const vtkSmartPointer<vtkDataArray> keep = array;
    attributes->RemoveArray(glommed.c_str());
    for (std::size_t c = 0; c < variables.size(); ++c) {
      auto variable = vtkSmartPointer<vtkDoubleArray>::New();
      variable->SetName(variables[c].c_str());
      variable->SetNumberOfTuples(keep->GetNumberOfTuples());
      for (vtkIdType t = 0; t < keep->GetNumberOfTuples(); ++t) variable->SetValue(t, keep->GetComponent(t, int(c)));
      attributes->AddArray(variable);
    }
  }
}

// Exodus II is netCDF, classic or version 4 (HDF5 inside): a file of random
// bytes gets a clear message before VTK's reader sees it. A classic file
// must have the bytes its header declares: the netCDF library reads past
// the end as zeros, without an error, so a file cut short, or one whose
// header claims more time steps than it holds, read as a field of zeros.
// (HDF5 refuses a file cut short itself.)
void check_exodus_file(const std::string& path) {
  const std::string head = file_head(path, 8);
  if (head.rfind("CDF", 0) != 0 && head.rfind("\x89HDF\r\n\x1a\n", 0) != 0)
    throw DataError(path + ": not an Exodus II file: it is neither netCDF (\"CDF\") nor HDF5 inside");
  const std::optional<NetcdfExtent> extent = netcdf_classic_extent(path);
  if (!extent) return;
  if (extent->records_held < extent->records)
    throw DataError(path + ": its header declares " + std::to_string(extent->records) + " time steps, but its " +
                    std::to_string(extent->file_size) + " bytes hold " + std::to_string(extent->records_held) +
                    " of them whole: the file is cut short (or its header's step count is wrong)");
  if (extent->file_size < extent->bytes)
    throw DataError(path + ": the file is cut short: its header declares " + std::to_string(extent->bytes) +
                    " bytes, the file has " + std::to_string(extent->file_size));
}

vtkSmartPointer<vtkExodusIIReader> opened_reader(const std::string& path) {
  check_exodus_file(path);
  auto reader = vtkSmartPointer<vtkExodusIIReader>::New();
  reader->SetFileName(path.c_str());
  if (!reader->CanReadFile(path.c_str())) throw DataError(path + ": not an Exodus II file (netCDF or HDF5) VTK can open");
  reader->UpdateInformation();
  return reader;
}

// The blocks of the file at time step `step` (−1: the first), each variable
// its own one-component array. Throws DataError for a file the reader
// refuses (or reports an error for) or a step beyond the file's.
vtkSmartPointer<vtkDataObject> read_exodus(const std::string& path, int step, const VtkSession& vtk) {
  const vtkSmartPointer<vtkExodusIIReader> reader = opened_reader(path);
  reader->SetAllArrayStatus(vtkExodusIIReader::NODAL, 1);
  reader->SetAllArrayStatus(vtkExodusIIReader::ELEM_BLOCK, 1);
  reader->SetApplyDisplacements(0);
  const int steps = reader->GetNumberOfTimeSteps();
  if (step > 0 && step >= steps)
    throw DataError(path + ": data.step " + std::to_string(step) + " is beyond its " + std::to_string(steps) +
                    " time steps" + (steps > 0 ? " (0 to " + std::to_string(steps - 1) + ")" : std::string()));
  reader->SetTimeStep(std::max(step, 0));

  // The variables' own names, and the nodal ones read by the Exodus
  // library before VTK reads them all.
  std::vector<std::string> nodal_names, element_names;
  {
    const ExodusFile file(path);
    nodal_names = variable_names(file, EX_NODAL);
    element_names = variable_names(file, EX_ELEM_BLOCK);
    check_nodal_variables(file, path, step, nodal_names.size());
  }
  update_reader(reader, vtk, path, "Exodus II", false);
  const auto nodal = glommed_variables(reader, vtkExodusIIReader::NODAL, nodal_names);
  const auto element = glommed_variables(reader, vtkExodusIIReader::ELEM_BLOCK, element_names);
  vtkSmartPointer<vtkDataObject> read = reader->GetOutputDataObject(0);
  if (auto* composite = vtkCompositeDataSet::SafeDownCast(read)) {
    const vtkSmartPointer<vtkCompositeDataIterator> it =
        vtkSmartPointer<vtkCompositeDataIterator>::Take(composite->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
      if (auto* block = vtkDataSet::SafeDownCast(it->GetCurrentDataObject())) {
        unglom(block->GetPointData(), nodal);
        unglom(block->GetCellData(), element);
      }
  }
  return read;
}

vtkSmartPointer<vtkDataSet> read_exodus_data(const std::string& path, const ReadRequest& request,
                                             const VtkSession& vtk) {
  return merged(read_exodus(path, request.step, vtk), path, request.block);
}

// The times of the file's steps, in order; none for a file of one step
// (or none: a mesh without results).
std::vector<double> exodus_times(const std::string& path) {
  const vtkSmartPointer<vtkExodusIIReader> reader = opened_reader(path);
  vtkInformation* info = reader->GetOutputInformation(0);
  vtkInformationDoubleVectorKey* key = vtkStreamingDemandDrivenPipeline::TIME_STEPS();
  if (!info || !info->Has(key)) return {};
  const double* times = info->Get(key);
  if (info->Length(key) < 2) return {};
  return std::vector<double>(times, times + info->Length(key));
}

}  // namespace

const FormatReader exodus_reader{read_exodus_data, nullptr, nullptr, exodus_times, true, true};

}  // namespace hsb
