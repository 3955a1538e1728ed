#include "field/reading/block_merging.h"

#include <vtkAppendFilter.h>
#include <vtkCellData.h>
#include <vtkCompositeDataIterator.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataSetAttributes.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkInformation.h>
#include <vtkMergePoints.h>
#include <vtkPointData.h>
#include <vtkPoints.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>

#include "field/reading/data_error.h"
#include "field/reading/file_records.h"

namespace hsb {
namespace {

const std::string blocks_key = "hsb blocks";

struct Part {
  vtkDataSet* data = nullptr;
  std::string name;
};

// The leaves of `read` that hold cells, in the file's order, each with its
// name (the file's, else "block N").
std::vector<Part> parts_of(vtkDataObject* read) {
  std::vector<Part> parts;
  auto* composite = vtkCompositeDataSet::SafeDownCast(read);
  if (!composite) {
    if (auto* data = vtkDataSet::SafeDownCast(read); data && data->GetNumberOfCells() > 0) parts.push_back({data, ""});
    return parts;
  }
  const vtkSmartPointer<vtkCompositeDataIterator> it =
      vtkSmartPointer<vtkCompositeDataIterator>::Take(composite->NewIterator());
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem()) {
    auto* data = vtkDataSet::SafeDownCast(it->GetCurrentDataObject());
    if (!data || data->GetNumberOfCells() == 0) continue;
    std::string name;
    if (it->HasCurrentMetaData() && it->GetCurrentMetaData()->Has(vtkCompositeDataSet::NAME()))
      name = it->GetCurrentMetaData()->Get(vtkCompositeDataSet::NAME());
    if (name.empty()) name = "block " + std::to_string(parts.size());
    parts.push_back({data, name});
  }
  return parts;
}

bool is_index(const std::string& text) {
  return !text.empty() && text.size() < 9 &&
         std::all_of(text.begin(), text.end(), [](unsigned char c) { return std::isdigit(c); });
}

// The part `block` names: by name first, then by index.
std::size_t chosen_part(const std::vector<Part>& parts, const std::string& block, const std::string& path) {
  for (std::size_t i = 0; i < parts.size(); ++i)
    if (parts[i].name == block) return i;
  if (is_index(block) && std::stoul(block) < parts.size()) return std::stoul(block);
  std::string names;
  for (std::size_t i = 0; i < parts.size(); ++i) names += (i ? ", " : "") + std::to_string(i) + " \"" + parts[i].name + "\"";
  throw DataError(path + ": data.block \"" + block + "\" names none of its " + std::to_string(parts.size()) +
                  " blocks with cells: " + names);
}

}  // namespace

vtkSmartPointer<vtkDataSet> merged(vtkDataObject* read, const std::string& path, const std::string& block) {
  const std::vector<Part> parts = parts_of(read);
  if (parts.empty()) throw DataError(path + ": none of its blocks holds a data set with cells");
  const bool composite = vtkCompositeDataSet::SafeDownCast(read) != nullptr;
  if (!block.empty() && !composite)
    throw DataError(path + ": data.block \"" + block + "\" is given, but the file holds one data set, not blocks");
  const std::size_t chosen = block.empty() ? parts.size() : chosen_part(parts, block, path);

  auto append = vtkSmartPointer<vtkAppendFilter>::New();
  std::vector<std::string> record;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const bool used = chosen == parts.size() || chosen == i;
    record.push_back(parts[i].name + "\t" + std::to_string(parts[i].data->GetNumberOfCells()) + "\t" + (used ? "1" : "0"));
    if (!used) continue;
    // Ghost cells are a piece's copies of its neighbours' cells, for the
    // parallel filters that wrote it: here they would be cells twice over.
    auto* grid = vtkUnstructuredGrid::SafeDownCast(parts[i].data);
    if (grid && grid->GetCellGhostArray()) {
      auto copy = vtkSmartPointer<vtkUnstructuredGrid>::New();
      copy->DeepCopy(grid);
      copy->RemoveGhostCells();
      copy->GetCellData()->RemoveArray(vtkDataSetAttributes::GhostArrayName());
      append->AddInputData(copy);
    } else {
      append->AddInputData(parts[i].data);
    }
  }
  append->Update();
  vtkSmartPointer<vtkDataSet> out = vtkDataSet::SafeDownCast(append->GetOutputDataObject(0));
  if (out && composite) add_record(out->GetFieldData(), blocks_key, record);
  return out;
}

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

std::vector<BlockOfFile> recorded_blocks(vtkDataSet* data) {
  std::vector<BlockOfFile> blocks;
  for (const std::string& line : record_of(data, blocks_key)) {
    const std::size_t b = line.rfind('\t');
    const std::size_t a = b == std::string::npos || b == 0 ? std::string::npos : line.rfind('\t', b - 1);
    if (a == std::string::npos) continue;
    blocks.push_back({line.substr(0, a), std::atoll(line.c_str() + a + 1), line.substr(b + 1) == "1"});
  }
  return blocks;
}

}  // namespace hsb
