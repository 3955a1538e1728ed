// Six components in each order real tools write: read with its preset,
// a tensor of six distinct entries comes back whole; read with another
// layout's preset, it does not.

#include <gtest/gtest.h>

#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLImageDataWriter.h>

#include "field/reading/component_order.h"
#include "field/reading/vtk_data.h"
#include "tests/temp_dir.h"
#include "tests/vtk_written.h"

namespace hsb {
namespace {

const Sym3 distinct{1.0, 2.0, 3.0, 4.0, 5.0, 6.0};  // xx, yy, zz, xy, yz, xz

// A 3×3×3 image whose array `name` holds `distinct` laid out as `order`
// says, the active tensors or not.
vtkSmartPointer<vtkImageData> image_in(const ComponentOrder& order, const char* name, bool active) {
  auto img = vtkSmartPointer<vtkImageData>::New();
  img->SetDimensions(3, 3, 3);
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName(name);
  a->SetNumberOfComponents(6);
  a->SetNumberOfTuples(img->GetNumberOfPoints());
  const Mat3 m = distinct.matrix();
  for (vtkIdType p = 0; p < img->GetNumberOfPoints(); ++p)
    for (int k = 0; k < 6; ++k) a->SetComponent(p, k, m(order.entries[std::size_t(k)][0], order.entries[std::size_t(k)][1]));
  if (active) img->GetPointData()->SetTensors(a);
  else img->GetPointData()->AddArray(a);
  return img;
}

std::string written(vtkImageData* img, const std::string& file) {
  return written_by<vtkXMLImageDataWriter>(img, test_temp_dir("component_order") / file);
}

std::string written_in(const ComponentOrder& order) { return written(image_in(order, "t", true), order.name + ".vti"); }

Sym3 read(const std::string& path, const std::string& components) {
  VtkFileSpec spec{path};
  spec.components = components;
  return *load_vtk_data(spec).field->sample(Vec3(1, 1, 1));
}

// A file whose writer implies its order: read whole in it, said once in a
// warning (`said` in it), and a scene's other order still wins.
void expect_default_order(const std::string& path, const std::string& said) {
  const VtkData data = load_vtk_data({path});
  EXPECT_EQ((data.field->sample(Vec3(1, 1, 1))->matrix() - distinct.matrix()).norm(), 0.0) << path;
  ASSERT_EQ(data.warnings.size(), 1u) << path;
  EXPECT_NE(data.warnings[0].find(said), std::string::npos) << data.warnings[0];
  EXPECT_GT((read(path, "vtk").matrix() - distinct.matrix()).norm(), 1.0) << path;  // the scene's word wins
}

TEST(ComponentOrder, EachPresetReadsItsOwnLayoutAndNoOther) {
  ASSERT_GE(component_orders().size(), 5u);
  for (const ComponentOrder& order : component_orders()) {
    const std::string path = written_in(order);
    EXPECT_EQ((read(path, order.name).matrix() - distinct.matrix()).norm(), 0.0) << order.name;
    for (const ComponentOrder& other : component_orders()) {
      if (other.layout == order.layout) continue;
      EXPECT_GT((read(path, other.name).matrix() - distinct.matrix()).norm(), 1.0)
          << order.name << " read as " << other.name;
    }
  }
}

// SfePy's output records no order, but SfePy leaves its node_groups and
// mat_id arrays in every file: its order is then the default, said in a
// warning; a scene may still name another.
TEST(ComponentOrder, SfepyOutputIsReadInSfepyOrderAndSaidSo) {
  auto img = image_in(*component_order("sfepy"), "cauchy_stress", false);
  for (auto [name, on_points] : {std::pair{"node_groups", true}, std::pair{"mat_id", false}}) {
    auto marker = vtkSmartPointer<vtkDoubleArray>::New();
    marker->SetName(name);
    marker->SetNumberOfTuples(on_points ? img->GetNumberOfPoints() : img->GetNumberOfCells());
    marker->FillValue(0.0);
    if (on_points) img->GetPointData()->AddArray(marker);
    else img->GetCellData()->AddArray(marker);
  }
  expect_default_order(written(img, "sfepy_output.vti"), "written by SfePy");
}

// Code_Aster's fields keep their names through meshio's MED reader (after
// the result's, RESU____SIEF_NOEU): its order is then the default too.
TEST(ComponentOrder, CodeAsterFieldsAreReadInCodeAsterOrderAndSaidSo) {
  const ComponentOrder& aster = *component_order("code_aster");
  expect_default_order(written(image_in(aster, "RESU____SIEF_NOEU", false), "aster.vti"), "a Code_Aster field's");
  expect_default_order(written(image_in(aster, "EPSI_ELNO", false), "aster_strain.vti"), "a Code_Aster field's");
  // A name that only contains the letters is not one.
  const VtkData other = load_vtk_data({written(image_in(aster, "BASIEF_X", false), "not_aster.vti")});
  EXPECT_GT((other.field->sample(Vec3(1, 1, 1))->matrix() - distinct.matrix()).norm(), 1.0);
}

// Abaqus's output variables keep their names through its exporters (S,
// E, LE, ...): its order is then the default; other names, or the same
// letters in lower case, say nothing of the writer.
TEST(ComponentOrder, AbaqusVariablesAreReadInAbaqusOrderAndSaidSo) {
  const ComponentOrder& abaqus = *component_order("abaqus");
  expect_default_order(written(image_in(abaqus, "S", false), "abaqus.vti"), "an Abaqus output variable's");
  expect_default_order(written(image_in(abaqus, "LE", false), "abaqus_strain.vti"), "an Abaqus output variable's");
  for (const char* name : {"s", "SE", "Stress"}) {
    const VtkData other = load_vtk_data({written(image_in(abaqus, name, false), std::string("not_abaqus_") + name + ".vti")});
    EXPECT_GT((other.field->sample(Vec3(1, 1, 1))->matrix() - distinct.matrix()).norm(), 1.0) << name;
  }
}

TEST(ComponentOrder, TheLayoutsSayWhatTheEntriesAre) {
  // The words agree with the entries: "XY" is (0, 1), and so on.
  const char* axis = "XYZ";
  for (const ComponentOrder& order : component_orders()) {
    std::string words;
    for (const auto& [i, j] : order.entries) words += std::string(words.empty() ? "" : " ") + axis[i] + axis[j];
    EXPECT_EQ(words, order.layout) << order.name;
  }
  EXPECT_EQ(component_order("sfepy")->layout, "XX YY ZZ XY XZ YZ");
  EXPECT_EQ(component_order("nosuch"), nullptr);
}

}  // namespace
}  // namespace hsb
