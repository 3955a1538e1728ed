// Data handed over as arrays (field/reading/data_arrays.h) is read as the
// same data in a file is: the same glyphs, the same component-order rule,
// and every inconsistency one error naming the arrays.

#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "field/glyph_pipeline.h"
#include "field/reading/component_order.h"
#include "field/reading/data_arrays.h"
#include "field/reading/data_error.h"
#include "tests/data_arrays_of.h"

namespace hsb {
namespace {

const std::string kCylinder = std::string(HSB_SOURCE_DIR) + "/scenes/data/cylinder_stress_coarse.vtu";

DataArrays cylinder_arrays() { return data_arrays_of(kCylinder, "the cylinder's arrays"); }

GlyphPipelineSpec scene_of(const std::string& path, std::shared_ptr<const DataArrays> arrays = nullptr) {
  GlyphPipelineSpec spec;
  spec.data.kind = DataKind::vtk_file;
  spec.data.file.path = path;
  spec.data.file.arrays = std::move(arrays);
  return spec;
}

void expect_same_glyphs(const GlyphScene& a, const GlyphScene& b) {
  ASSERT_EQ(a.sources.size(), b.sources.size());
  ASSERT_FALSE(a.sources.empty());
  EXPECT_EQ(a.trajectories.size(), b.trajectories.size());
  for (std::size_t i = 0; i < a.sources.size(); ++i) {
    EXPECT_EQ(a.sources[i].centre, b.sources[i].centre) << "source " << i;
    EXPECT_EQ(a.sources[i].eigenvalues, b.sources[i].eigenvalues) << "source " << i;
  }
  EXPECT_EQ(a.color_extremes, b.color_extremes);
}

TEST(DataArrays, GiveTheGlyphsTheSameDataInAFileGives) {
  const GlyphScene from_file = build_glyph_scene(scene_of(kCylinder), 0.64);
  const GlyphScene from_arrays =
      build_glyph_scene(scene_of("the cylinder's arrays", std::make_shared<DataArrays>(cylinder_arrays())), 0.64);
  expect_same_glyphs(from_file, from_arrays);
  ASSERT_TRUE(from_arrays.boundary.has_value());
  EXPECT_EQ(from_arrays.boundary->triangles.size(), from_file.boundary->triangles.size());
}

TEST(DataArrays, SixComponentsFollowDataComponentsAsAFilesDo) {
  // The cylinder's tensors as six components in Abaqus's order (XX YY ZZ
  // XY XZ YZ): read as such, the glyphs are the nine-component file's.
  DataArrays arrays = cylinder_arrays();
  const ComponentOrder* abaqus = component_order("abaqus");
  ASSERT_NE(abaqus, nullptr);
  for (DataArrays::Array& a : arrays.arrays) {
    std::vector<double> six;
    for (std::size_t t = 0; t < a.values.size() / 9; ++t) {
      const double* m = &a.values[9 * t];
      const Sym3 s = Sym3::symmetric_part((Mat3() << m[0], m[1], m[2], m[3], m[4], m[5], m[6], m[7], m[8]).finished());
      for (double c : components_in_order(s, *abaqus)) six.push_back(c);
    }
    a.values = six;
    a.components = 6;
  }
  GlyphPipelineSpec spec = scene_of("six", std::make_shared<DataArrays>(arrays));
  spec.data.file.components = "abaqus";
  const GlyphScene six = build_glyph_scene(spec, 0.64);
  const GlyphScene nine = build_glyph_scene(scene_of(kCylinder), 0.64);
  ASSERT_EQ(six.sources.size(), nine.sources.size());
  for (std::size_t i = 0; i < six.sources.size(); ++i)
    EXPECT_NEAR((six.sources[i].eigenvalues - nine.sources[i].eigenvalues).norm(), 0.0,
                1e-9 * nine.sources[i].eigenvalues.norm());
}

std::string error_of(const DataArrays& arrays) {
  try {
    make_field(scene_of(arrays.name, std::make_shared<DataArrays>(arrays)).data);
  } catch (const DataError& e) {
    return e.what();
  }
  return "no error";
}

TEST(DataArrays, EveryInconsistencyIsOneErrorNamingThem) {
  const DataArrays good = cylinder_arrays();
  const auto with = [&](auto change) {
    DataArrays a = good;
    change(a);
    return error_of(a);
  };
  const std::string name = "the cylinder's arrays: ";
  EXPECT_EQ(with([](DataArrays& a) { a.points.pop_back(); }),
            name + "points holds 6824 values, not three (x, y, z) for each point");
  EXPECT_EQ(with([](DataArrays& a) { a.points[4] = NAN; }), name + "point 1's y is nan, not a finite coordinate");
  EXPECT_EQ(with([](DataArrays& a) { a.offsets.pop_back(); }),
            name + "offsets holds 10784 entries for 10784 cell types; it needs one more than there are cells");
  EXPECT_EQ(with([](DataArrays& a) { a.connectivity[7] = 99999; }),
            name + "connectivity[7] is 99999, not a point (there are 2275 points)");
  EXPECT_EQ(with([](DataArrays& a) { a.connectivity[7] = -1; }),
            name + "connectivity[7] is -1, not a point (there are 2275 points)");
  EXPECT_EQ(with([](DataArrays& a) { a.cell_types[3] = 42; }),
            name + "cell 3 has VTK cell type 42, which is not one hsb reads (linear and quadratic cells: 1, 3, 5, "
                   "8-14, 21-27)");
  EXPECT_EQ(with([](DataArrays& a) { a.cell_types[3] = 12; }),
            name + "cell 3 (VTK type 12) has 4 points; its type has 8");
  EXPECT_EQ(with([](DataArrays& a) { a.arrays[0].values.pop_back(); }),
            name + "array \"stress\" holds 20474 values; 9 for each of its 2275 points are 20475");
  EXPECT_EQ(with([](DataArrays& a) { a.arrays[1].on_points = true; }),
            name + "two arrays on its points are named \"stress\"");
  EXPECT_EQ(with([](DataArrays& a) { a.arrays[0].components = 4; }),
            name + "array \"stress\" has 4 components; hsb reads 1 (a scalar), 3 (vectors), 6 or 9 (tensors)");
  EXPECT_EQ(error_of(good), "no error");
}

TEST(DataArrays, AreHashedByWhatTheyHold) {
  const DataArrays a = cylinder_arrays();
  DataArrays renamed = a;
  renamed.name = "another name";
  EXPECT_EQ(arrays_sha1(a), arrays_sha1(renamed));
  DataArrays moved = a;
  moved.points[0] += 1e-9;
  EXPECT_NE(arrays_sha1(a), arrays_sha1(moved));
  DataArrays on_cells = a;
  on_cells.arrays[0].on_points = false;
  EXPECT_NE(arrays_sha1(a), arrays_sha1(on_cells));
}

}  // namespace
}  // namespace hsb
