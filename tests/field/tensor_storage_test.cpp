// A volume reader's tensor array on the field's own storage
// (field/reading/tensor_storage.h): what is written through the array is
// what the vector taken over holds, at the same address (not copied), and
// the array is left empty; arrays made any other way, copies included,
// are not taken.

#include <gtest/gtest.h>

#include <vtkDoubleArray.h>
#include <vtkSmartPointer.h>

#include "field/reading/tensor_storage.h"

namespace hsb {
namespace {

TEST(TensorStorage, TheArraysMemoryIsTakenOverNotCopied) {
  const vtkSmartPointer<vtkDoubleArray> array = tensor_array_on_storage(1000);
  ASSERT_EQ(array->GetNumberOfTuples(), 1000);
  ASSERT_EQ(array->GetNumberOfComponents(), 6);
  EXPECT_EQ(array->GetComponent(999, 5), 0.0);  // zero until written
  for (vtkIdType i = 0; i < 1000; ++i) {
    const double t[6] = {double(i), 1.0, 2.0, 3.0, 4.0, -double(i)};  // XX YY ZZ XY YZ XZ
    array->SetTuple(i, t);
  }
  const double* written = array->GetPointer(0);
  const std::vector<Sym3> tensors = take_tensor_storage(array);
  ASSERT_EQ(tensors.size(), 1000u);
  EXPECT_EQ(reinterpret_cast<const double*>(tensors.data()), written);
  EXPECT_EQ(tensors[7].xx, 7.0);
  EXPECT_EQ(tensors[7].yy, 1.0);
  EXPECT_EQ(tensors[7].zz, 2.0);
  EXPECT_EQ(tensors[7].xy, 3.0);
  EXPECT_EQ(tensors[7].yz, 4.0);
  EXPECT_EQ(tensors[7].xz, -7.0);
  EXPECT_EQ(array->GetNumberOfTuples(), 0);  // nothing left to read through it
  EXPECT_TRUE(take_tensor_storage(array).empty());  // taken once
}

TEST(TensorStorage, OtherArraysAreNotTaken) {
  auto plain = vtkSmartPointer<vtkDoubleArray>::New();
  plain->SetNumberOfComponents(6);
  plain->SetNumberOfTuples(10);
  plain->FillValue(1.0);
  EXPECT_TRUE(take_tensor_storage(plain).empty());
  EXPECT_EQ(plain->GetNumberOfTuples(), 10);

  const vtkSmartPointer<vtkDoubleArray> stored = tensor_array_on_storage(10);
  auto copy = vtkSmartPointer<vtkDoubleArray>::New();
  copy->DeepCopy(stored);
  EXPECT_TRUE(take_tensor_storage(copy).empty());  // its own memory, whatever its keys say
  EXPECT_EQ(copy->GetNumberOfTuples(), 10);
  EXPECT_EQ(take_tensor_storage(stored).size(), 10u);
}

}  // namespace
}  // namespace hsb
