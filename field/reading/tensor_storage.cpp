#include "field/reading/tensor_storage.h"

#include <vtkFloatArray.h>
#include <vtkInformation.h>
#include <vtkInformationObjectBaseKey.h>
#include <vtkObject.h>
#include <vtkObjectFactory.h>

#include <type_traits>
#include <utility>

#include "base/huge_pages.h"

namespace hsb {

static_assert(std::is_standard_layout_v<Sym3> && sizeof(Sym3) == 6 * sizeof(double),
              "a Sym3 is six doubles in VTK's order, XX YY ZZ XY YZ XZ");

namespace {

// The vector, held by the array's information so that it lives as long as
// the array does.
class TensorStorage : public vtkObject {
 public:
  static TensorStorage* New();
  vtkTypeMacro(TensorStorage, vtkObject)
  std::vector<Sym3> tensors;

 protected:
  TensorStorage() = default;
};
vtkStandardNewMacro(TensorStorage);

vtkInformationObjectBaseKey* storage_key() {
  // VTK's keys live as long as the process, as its own macros make them.
  static vtkInformationObjectBaseKey* key = new vtkInformationObjectBaseKey("TENSOR_STORAGE", "hsb");
  return key;
}

}  // namespace

vtkSmartPointer<vtkDoubleArray> tensor_array_on_storage(vtkIdType count) {
  auto storage = vtkSmartPointer<TensorStorage>::New();
  assign_on_huge_pages(storage->tensors, std::size_t(count), Sym3{});
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetNumberOfComponents(6);
  // save = 1: the array never frees what it borrows.
  array->SetArray(reinterpret_cast<double*>(storage->tensors.data()), count * 6, 1);
  array->GetInformation()->Set(storage_key(), storage);
  return array;
}

std::vector<Sym3> take_tensor_storage(vtkDataArray* array) {
  auto* doubles = vtkDoubleArray::FastDownCast(array);
  if (!doubles || !doubles->HasInformation()) return {};
  auto* storage = TensorStorage::SafeDownCast(doubles->GetInformation()->Get(storage_key()));
  // A copy of such an array (a filter's output) owns memory of its own.
  if (!storage || reinterpret_cast<double*>(storage->tensors.data()) != doubles->GetPointer(0) ||
      doubles->GetNumberOfComponents() != 6 || std::size_t(doubles->GetNumberOfTuples()) != storage->tensors.size())
    return {};
  std::vector<Sym3> tensors = std::move(storage->tensors);
  doubles->Initialize();
  doubles->GetInformation()->Remove(storage_key());
  return tensors;
}

vtkSmartPointer<vtkDataArray> volume_array(vtkIdType tuples, int components, bool as_float) {
  if (components == 6 && !as_float) return tensor_array_on_storage(tuples);
  vtkSmartPointer<vtkDataArray> array;
  if (as_float) array = vtkSmartPointer<vtkFloatArray>::New();
  else array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(tuples);
  advise_huge_pages(array->GetVoidPointer(0), std::size_t(tuples) * std::size_t(components) * array->GetDataTypeSize());
  return array;
}

}  // namespace hsb
