// Which array a data file is drawn from when the scene names none: tensors
// by a stated rule whenever the file has any, said when there was a
// choice; a flow only when there are no tensors, and said.

#include <gtest/gtest.h>

#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLImageDataWriter.h>

#include "field/reading/vtk_data.h"
#include "tests/temp_dir.h"
#include "tests/vtk_written.h"

namespace hsb {
namespace {

// A 4×4×4 image whose point (or cell) array `name` holds `components`
// values, each tuple the same: the diagonal (d, 2, 3) (d its first value).
void add(vtkImageData* image, const char* name, int components, double d, bool cells = false) {
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName(name);
  a->SetNumberOfComponents(components);
  const vtkIdType n = cells ? image->GetNumberOfCells() : image->GetNumberOfPoints();
  a->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
    for (int c = 0; c < components; ++c)
      a->SetComponent(i, c, components == 9 ? (c == 0 ? d : c == 4 ? 2 : c == 8 ? 3 : 0)
                            : components == 6 ? (c == 0 ? d : c == 1 ? 2 : c == 2 ? 3 : 0)
                                              : d);
  (cells ? static_cast<vtkDataSetAttributes*>(image->GetCellData()) : image->GetPointData())->AddArray(a);
}

vtkSmartPointer<vtkImageData> image() {
  auto img = vtkSmartPointer<vtkImageData>::New();
  img->SetDimensions(4, 4, 4);
  return img;
}

std::string write(vtkImageData* img, const std::string& name) {
  return written_by<vtkXMLImageDataWriter>(img, test_temp_dir("array_choice") / name);
}

// The first eigenvalue-defining entry drawn at the middle, and the notes.
std::pair<double, std::string> drawn(const std::string& path) {
  VtkFileSpec spec{path};
  const VtkData data = load_vtk_data(spec);
  EXPECT_TRUE(data.field) << path;
  std::string notes;
  for (const std::string& w : data.warnings) notes += w + "\n";
  return {data.field ? data.field->sample(Vec3(1.5, 1.5, 1.5))->xx : 0.0, notes};
}

TEST(ArrayChoice, TensorsNamedStressWinOverStrainAndNeverAFlow) {
  auto img = image();
  add(img, "strain", 6, 0.001);
  add(img, "displacement", 3, 0.5);
  add(img, "stress", 9, 50.0, true);
  const auto [xx, notes] = drawn(write(img, "stress_strain.vti"));
  EXPECT_DOUBLE_EQ(xx, 50.0);
  EXPECT_NE(notes.find("of 2 arrays of tensors, \"stress\" (cell data) is drawn, its name says stress; also in the "
                       "file: \"strain\" (6 components, point data). Set data.array for another"),
            std::string::npos)
      << notes;
  // Code_Aster's field names (through meshio or ParaView's MED reader).
  auto aster = image();
  add(aster, "EPSI_NOEU", 6, 0.001);
  add(aster, "SIEF_NOEU", 6, 80.0);
  const auto [aster_xx, aster_notes] = drawn(write(aster, "aster.vti"));
  EXPECT_DOUBLE_EQ(aster_xx, 80.0);
  EXPECT_NE(aster_notes.find("\"SIEF_NOEU\" (point data) is drawn, its name says stress"), std::string::npos)
      << aster_notes;
}

TEST(ArrayChoice, ActiveTensorsWinAndAnUnnamedChoiceIsTheFirst) {
  auto img = image();
  add(img, "a", 6, 1.0);
  add(img, "b", 6, 7.0);
  const auto [first, notes] = drawn(write(img, "two.vti"));
  EXPECT_DOUBLE_EQ(first, 1.0);
  EXPECT_NE(notes.find("the first (no name says stress or strain)"), std::string::npos) << notes;
  img->GetPointData()->SetActiveTensors("b");
  const auto [active, why] = drawn(write(img, "active.vti"));
  EXPECT_DOUBLE_EQ(active, 7.0);
  EXPECT_NE(why.find("\"b\" (point data) is drawn, the active tensors"), std::string::npos) << why;
  // One array of tensors: no choice, nothing to say.
  auto one = image();
  add(one, "sigma", 6, 3.0);
  add(one, "velocity", 3, 1.0);
  EXPECT_EQ(drawn(write(one, "one.vti")).second, "");
}

TEST(ArrayChoice, AFlowIsDrawnOnlyWithoutTensorsAndSaidSo) {
  auto img = image();
  add(img, "velocity", 3, 1.0);
  VtkFileSpec spec{write(img, "flow.vti")};
  const VtkData data = load_vtk_data(spec);
  ASSERT_TRUE(data.vectors);
  ASSERT_EQ(data.warnings.size(), 1u);
  EXPECT_NE(data.warnings[0].find("no array of 6 or 9 components: its vectors \"velocity\" are drawn as a flow"),
            std::string::npos)
      << data.warnings[0];
  spec.kind = FieldKind::vector;  // asked for: nothing to say
  EXPECT_TRUE(load_vtk_data(spec).warnings.empty());
}

}  // namespace
}  // namespace hsb
