#include "field/reading/file_records.h"

#include <vtkDataSet.h>
#include <vtkFieldData.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>

namespace hsb {

void add_record(vtkFieldData* records, const std::string& key, const std::vector<std::string>& values) {
  auto record = vtkSmartPointer<vtkStringArray>::New();
  record->SetName(key.c_str());
  for (const std::string& value : values) record->InsertNextValue(value);
  records->RemoveArray(key.c_str());
  records->AddArray(record);
}

std::vector<std::string> record_of(vtkDataSet* data, const std::string& key) {
  auto* record = vtkStringArray::SafeDownCast(data->GetFieldData()->GetAbstractArray(key.c_str()));
  std::vector<std::string> values;
  for (vtkIdType i = 0; record && i < record->GetNumberOfValues(); ++i) values.push_back(record->GetValue(i));
  return values;
}

}  // namespace hsb
