// Tensors and vectors stored one component per array are joined by their
// names' suffixes, and nothing else is.
#include "field/reading/component_arrays.h"

#include <gtest/gtest.h>

#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <map>
#include <string>
#include <vector>

namespace hsb {
namespace {

// A data set of two points whose arrays are `values` by name: point 0
// holds the value, point 1 ten times it.
vtkSmartPointer<vtkPolyData> with_arrays(const std::vector<std::pair<std::string, double>>& values) {
  auto data = vtkSmartPointer<vtkPolyData>::New();
  for (const auto& [name, value] : values) {
    auto array = vtkSmartPointer<vtkDoubleArray>::New();
    array->SetName(name.c_str());
    array->InsertNextValue(value);
    array->InsertNextValue(10 * value);
    data->GetPointData()->AddArray(array);
  }
  join_component_arrays(data->GetPointData(), data->GetFieldData());
  return data;
}

// The arrays of `data`: name → the first point's components.
std::map<std::string, std::vector<double>> arrays_of(vtkPolyData* data) {
  std::map<std::string, std::vector<double>> out;
  vtkPointData* points = data->GetPointData();
  for (int i = 0; i < points->GetNumberOfArrays(); ++i) {
    vtkDataArray* a = points->GetArray(i);
    std::vector<double> first;
    for (int c = 0; c < a->GetNumberOfComponents(); ++c) first.push_back(a->GetComponent(0, c));
    out[a->GetName()] = first;
  }
  return out;
}

using Arrays = std::map<std::string, std::vector<double>>;

TEST(ComponentArrays, SierraStyleShearsJoinInVtkOrder) {
  const auto data = with_arrays({{"von_mises", 9}, {"stress_zx", 6}, {"stress_xx", 1}, {"stress_yy", 2},
                                 {"stress_zz", 3}, {"stress_xy", 4}, {"stress_yz", 5}});
  EXPECT_EQ(arrays_of(data), (Arrays{{"stress", {1, 2, 3, 4, 5, 6}}, {"von_mises", {9}}}));
  EXPECT_NE(recorded_component_order(data, "stress").find("stress_zx"), std::string::npos);
  EXPECT_EQ(data->GetPointData()->GetArray("stress")->GetComponent(1, 5), 60.0);  // every point
}

TEST(ComponentArrays, AbaqusDigitsJoin) {
  EXPECT_EQ(arrays_of(with_arrays({{"S11", 1}, {"S22", 2}, {"S33", 3}, {"S12", 4}, {"S13", 6}, {"S23", 5}})),
            (Arrays{{"S", {1, 2, 3, 4, 5, 6}}}));
}

TEST(ComponentArrays, PlaneDataGetsZeroOutOfPlane) {
  EXPECT_EQ(arrays_of(with_arrays({{"sigmaXX", 1}, {"sigmaYY", 2}, {"sigmaXY", 4}})),
            (Arrays{{"sigma", {1, 2, 0, 4, 0, 0}}}));
  EXPECT_EQ(arrays_of(with_arrays({{"u_x", 1}, {"u_y", 2}})), (Arrays{{"u", {1, 2, 0}}}));
}

TEST(ComponentArrays, BothShearsOfEveryPairMakeAFullMatrix) {
  EXPECT_EQ(arrays_of(with_arrays({{"Fxx", 1}, {"Fxy", 2}, {"Fxz", 3}, {"Fyx", 4}, {"Fyy", 5}, {"Fyz", 6}, {"Fzx", 7},
                                   {"Fzy", 8}, {"Fzz", 9}})),
            (Arrays{{"F", {1, 2, 3, 4, 5, 6, 7, 8, 9}}}));
}

TEST(ComponentArrays, VectorsJoinButNeverFromTensorComponents) {
  // An incomplete tensor stays scalars: its xx, xy, xz are not a vector "stress_x".
  const Arrays partial{{"stress_xx", {1}}, {"stress_xy", {2}}, {"stress_xz", {3}}};
  EXPECT_EQ(arrays_of(with_arrays({{"stress_xx", 1}, {"stress_xy", 2}, {"stress_xz", 3}})), partial);
  EXPECT_EQ(arrays_of(with_arrays({{"dispX", 1}, {"dispY", 2}, {"dispZ", 3}, {"temperature", 7}})),
            (Arrays{{"disp", {1, 2, 3}}, {"temperature", {7}}}));
}

TEST(ComponentArrays, AmbiguousOrTakenNamesStayAsTheyAre) {
  // stress_xx and stress_XX at one place; a name already taken; a shear twice over.
  const std::vector<std::pair<std::string, double>> clash{{"s_xx", 1}, {"s_XX", 1}, {"s_yy", 2}, {"s_xy", 3}};
  EXPECT_EQ(arrays_of(with_arrays(clash)).size(), 4u);
  const std::vector<std::pair<std::string, double>> taken{{"e", 0}, {"exx", 1}, {"eyy", 2}, {"exy", 3}};
  EXPECT_EQ(arrays_of(with_arrays(taken)).size(), 4u);
  const std::vector<std::pair<std::string, double>> twice{{"txx", 1}, {"tyy", 2}, {"tzz", 3}, {"txy", 4}, {"tyx", 4}};
  EXPECT_EQ(arrays_of(with_arrays(twice)).size(), 5u);
  EXPECT_EQ(arrays_of(with_arrays({{"xx", 1}, {"yy", 2}, {"xy", 3}})).size(), 3u);  // no name to give it
}

}  // namespace
}  // namespace hsb
