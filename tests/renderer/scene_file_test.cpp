// Scene files: defaults, overrides, and one clear error per kind of mistake.

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>

#include "renderer/scene/scene_spec.h"
#include "tests/temp_dir.h"

namespace hsb {
namespace {

class SceneFile : public ::testing::Test {
 protected:
  std::string write(const std::string& text) {
    const auto dir = test_temp_dir("scene_test");
    path_ = (dir / (std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + ".toml")).string();
    std::ofstream(path_) << text;
    return path_;
  }
  // The error message load_scene gives, or "" when it succeeds.
  std::string error_of(const std::string& text, const std::vector<std::string>& overrides = {}) {
    try {
      load_scene(write(text), overrides);
    } catch (const SceneError& e) {
      return e.what();
    }
    return "";
  }
  std::string path_;
};

constexpr const char* minimal = "[seeds]\npoints = [[0, 0, 0.5]]\n";

TEST_F(SceneFile, MinimalSceneGetsDocumentedDefaults) {
  const SceneSpec spec = load_scene(write(minimal));
  EXPECT_EQ(spec.surface.kernel, KernelKind::wyvill);
  EXPECT_EQ(spec.surface.blend, Blend::sum);
  EXPECT_DOUBLE_EQ(spec.surface.isovalue, 0.5);
  EXPECT_DOUBLE_EQ(spec.surface.influence_radius, 1.0);
  EXPECT_FALSE(spec.pipeline.color);  // λ3 for tensors, the speed for a flow
  EXPECT_EQ(spec.pipeline.size.mapping, RadiusMapping::sqrt);
  EXPECT_EQ(spec.pipeline.data.kind, DataKind::point_load);
  // Values that depend on the data are automatic until it is read.
  EXPECT_FALSE(spec.pipeline.spacing);
  EXPECT_FALSE(spec.pipeline.trajectory.step);
  EXPECT_FALSE(spec.pipeline.size.scale);
  EXPECT_FALSE(spec.pipeline.size.floor);
  EXPECT_FALSE(spec.pipeline.size.ceiling);
  EXPECT_FALSE(spec.camera.position);
  EXPECT_FALSE(spec.camera.look_at);
  EXPECT_FALSE(spec.context.box);
  EXPECT_FALSE(spec.context.shell);
  EXPECT_FALSE(spec.render.intersector);
  EXPECT_FALSE(spec.output.file);
  EXPECT_FALSE(spec.render.width);  // output.print_size at output.dpi, or 800
  EXPECT_FALSE(spec.render.height);
  EXPECT_DOUBLE_EQ(spec.output.dpi, 300.0);
  EXPECT_EQ(spec.camera.projection, Projection::perspective);
  EXPECT_FALSE(spec.camera.view);
  EXPECT_EQ(spec.pipeline.seeds.points.size(), 1u);
}

TEST_F(SceneFile, ReadsEverySection) {
  const SceneSpec spec = load_scene(write(R"(
[data]
bounds = [0, 2, 0, 4, -1, 0]
load = 3
poisson_ratio = 0.25
sample_grid = [5, 6, 7]
[[seeds.grid]]
corner = [0, 0, -0.5]
edge_u = [2, 0, 0]
edge_v = [0, 4, 0]
n = 7
m = 7
[trajectories]
family = "medium"
step = 0.005
[glyphs]
spacing = 0.02
mapping = "sqrt"
ceiling = 0.3
color_by = "von_mises"
[surface]
kernel = "quartic"
blend = "max"
[color]
map = "coolwarm"
range = [-2, 2]
[camera]
fov = 20
[light]
from = [0, 0, 1]
shadows = false
[render]
width = 64
height = 32
background = "#808080"
[output]
file = "x.exr"
)"));
  EXPECT_EQ(spec.pipeline.data.point_load.bounds.hi, Vec3(2, 4, 0));
  EXPECT_EQ(spec.pipeline.data.sample_grid, (std::array<int, 3>{5, 6, 7}));
  EXPECT_EQ(spec.pipeline.seeds.grids.at(0).n, 7);
  EXPECT_EQ(spec.pipeline.trajectory.families, std::vector<EigenFamily>{EigenFamily::medium});
  EXPECT_EQ(spec.pipeline.trajectory.step.value(), 0.005);
  EXPECT_EQ(spec.pipeline.spacing.value(), 0.02);
  EXPECT_EQ(spec.pipeline.size.ceiling.value(), 0.3);
  EXPECT_EQ(spec.pipeline.size.mapping, RadiusMapping::sqrt);
  EXPECT_EQ(spec.pipeline.color, ColorScalar::von_mises);
  EXPECT_EQ(spec.surface.kernel, KernelKind::quartic);
  EXPECT_EQ(spec.surface.blend, Blend::max);
  EXPECT_EQ(spec.color.range.value()[1], 2.0);
  EXPECT_FALSE(spec.shading.shadows);
  EXPECT_NEAR(spec.shading.background[0], 128 / 255.0, 1e-6);
  EXPECT_EQ(spec.output.file.value(), "x.exr");
}

TEST_F(SceneFile, OverridesReplaceAndAddKeys) {
  const SceneSpec spec = load_scene(write(minimal), {"render.width=123", "glyphs.mapping=sqrt",
                                                     "camera.position=[1, 2, 3]", "output.file=a b.png"});
  EXPECT_EQ(spec.render.width, 123);
  EXPECT_EQ(spec.pipeline.size.mapping, RadiusMapping::sqrt);
  EXPECT_EQ(spec.camera.position.value(), Vec3(1, 2, 3));
  EXPECT_EQ(spec.output.file.value(), "a b.png");
}

TEST_F(SceneFile, WrongTypeNamesFileLineColumnAndKey) {
  const std::string e = error_of(std::string(minimal) + "[glyphs]\nspacing = \"wide\"\n");
  EXPECT_EQ(e, path_ + ":4:11: glyphs.spacing must be a number, got string \"wide\"");
}

TEST_F(SceneFile, OutOfRangeValue) {
  const std::string e = error_of(std::string(minimal) + "[glyphs]\n\nspacing = -0.1\n");
  EXPECT_EQ(e, path_ + ":5:11: glyphs.spacing must be > 0, got -0.1");
}

TEST_F(SceneFile, NonFiniteNumbersAreRefusedExceptAnInfiniteCeiling) {
  const std::string e = error_of(std::string(minimal) + "[data]\nload = inf\n");
  EXPECT_EQ(e, path_ + ":4:8: data.load must be a finite number, got inf");
  EXPECT_NE(error_of(std::string(minimal) + "[data]\nload = nan\n").find("finite"), std::string::npos);
  EXPECT_NE(error_of(std::string(minimal) + "[camera]\nposition = [1, inf, 0]\n").find("camera.position"),
            std::string::npos);
  EXPECT_EQ(error_of(std::string(minimal) + "[glyphs]\nceiling = inf\n"), "");
  const std::string seed = error_of("[seeds]\npoints = [[0, 0, 0.5], [0, nan, 0.5]]\n");
  EXPECT_EQ(seed, path_ + ":2:28: seeds.points must have coordinates within ±1e17 (the ray tracer's single-precision range), got nan");
}

TEST_F(SceneFile, ADirectoryIsNoDataFile) {
  const std::filesystem::path folder = test_temp_dir("scene_test") / "folder.vtu";
  std::filesystem::create_directories(folder);
  const std::string e = error_of("[data]\nfile = \"folder.vtu\"\n");
  EXPECT_EQ(e, path_ + ":2:8: data.file names " + folder.string() + ": a directory, not a file");
}

// A FIFO would block the reader for ever: refused at once, as the scene
// and as its data file.
TEST_F(SceneFile, AFifoIsRefusedWithoutWaiting) {
  const std::filesystem::path fifo = test_temp_dir("scene_test") / "pipe.vtu";
  std::filesystem::remove(fifo);
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  const std::string as_data = error_of("[data]\nfile = \"pipe.vtu\"\n");
  EXPECT_EQ(as_data, path_ + ":2:8: data.file names " + fifo.string() + ": not a regular file (a FIFO, socket or device)");
  try {
    load_scene(fifo.string(), {});
    ADD_FAILURE() << "a FIFO loaded as a scene";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()), fifo.string() + ": not a regular file (a FIFO, socket or device)");
  }
  std::filesystem::remove(fifo);
}

TEST_F(SceneFile, UnknownKeyIsAnErrorNotIgnored) {
  const std::string e = error_of(std::string(minimal) + "[glyphs]\nspaceing = 0.1\n");
  EXPECT_NE(e.find(path_ + ":4:1: unknown key glyphs.spaceing"), std::string::npos) << e;
  EXPECT_NE(e.find("spacing"), std::string::npos) << "should list the known keys: " << e;
  EXPECT_NE(error_of(std::string(minimal) + "[glyph]\nspacing = 0.1\n").find("unknown key glyph"),
            std::string::npos);
}

TEST_F(SceneFile, BadChoiceListsTheChoices) {
  const std::string e = error_of(std::string(minimal) + "[surface]\nkernel = \"gauss\"\n");
  EXPECT_EQ(e, path_ + ":4:10: surface.kernel must be one of \"wyvill\", \"quartic\", \"blinn\", got string \"gauss\"");
}

TEST_F(SceneFile, TomlSyntaxErrorHasItsLocation) {
  const std::string e = error_of("[seeds]\npoints = [[0, 0, 0.5]\n");
  EXPECT_EQ(e.rfind(path_ + ":", 0), 0u) << e;
  EXPECT_NE(e.find(":2:"), std::string::npos) << e;
}

TEST_F(SceneFile, BadOverrideNamesTheOverride) {
  const std::string e = error_of(minimal, {"render.width=-5"});
  EXPECT_EQ(e, "--set render.width=-5: render.width must be in [1, 16384], got -5");
  EXPECT_EQ(error_of(minimal, {"render.widht=5"}),
            "--set render.widht=5: render.widht is not a scene key; did you mean render.width? (hsb keys lists them all)");
  EXPECT_NE(error_of(minimal, {"nonsense"}).find("expected key.path=value"), std::string::npos);
}

TEST_F(SceneFile, ExactIntersectorOnlyWhereItApplies) {
  EXPECT_EQ(load_scene(write(minimal), {"render.intersector=sphere"}).render.intersector, Intersector::sphere);
  const std::string blinn = std::string(minimal) + "[surface]\nkernel = \"blinn\"\n";
  EXPECT_EQ(error_of(blinn + "blend = \"max\"\n[render]\nintersector = \"exact\"\n"), "");
  EXPECT_NE(error_of(blinn + "[render]\nintersector = \"exact\"\n").find("render.intersector = \"exact\" needs"),
            std::string::npos);
}

// The signed glyph: its key, the sign convention it reads, and a
// sharpness that applies to it; a sharpness without a shape that has one
// is located.
TEST_F(SceneFile, SignedGlyphsAndTheSignConvention) {
  const SceneSpec mechanics = load_scene(write(std::string(minimal) + "[glyphs]\nshape = \"signed\"\nsharpness = 2\n"));
  EXPECT_EQ(mechanics.surface.shape, GlyphShape::signed_superquadric);
  EXPECT_EQ(mechanics.surface.sharpness, 2.0);
  EXPECT_EQ(mechanics.pipeline.data.sign, SignConvention::tension_positive);
  const SceneSpec soil = load_scene(write(std::string(minimal) + "[data]\nsign = \"compression-positive\"\n"));
  EXPECT_EQ(soil.pipeline.data.sign, SignConvention::compression_positive);
  EXPECT_NE(error_of(std::string(minimal) + "[data]\nsign = \"positive\"\n").find("compression-positive"),
            std::string::npos);
  EXPECT_NE(error_of(std::string(minimal) + "[glyphs]\nsharpness = 2\n").find("glyphs.shape = \"superquadric\" or \"signed\""),
            std::string::npos);
}

// Beads: signed glyphs ask for them (the pipeline resolves it), a scene
// may give them for any shape, never beside a spacing, and only along
// trajectories.
// Tensorlines: a method of [trajectories], for the major family only.
TEST_F(SceneFile, TensorlinesFollowTheMajorEigenvector) {
  EXPECT_FALSE(load_scene(write(minimal)).pipeline.trajectory.tensorlines);
  const SceneSpec lines =
      load_scene(write(std::string(minimal) + "[trajectories]\nmethod = \"tensorlines\"\npuncture = 0.2\n"));
  EXPECT_TRUE(lines.pipeline.trajectory.tensorlines);
  EXPECT_EQ(lines.pipeline.trajectory.puncture, 0.2);
  const std::string minor =
      error_of(std::string(minimal) + "[trajectories]\nfamily = \"minor\"\nmethod = \"tensorlines\"\n");
  EXPECT_NE(minor.find(":5:10: trajectories.method = \"tensorlines\" follows the major eigenvector only"), std::string::npos)
      << minor;
  EXPECT_NE(error_of(std::string(minimal) + "[trajectories]\npuncture = 2\n").find("trajectories.puncture"),
            std::string::npos);
}

TEST_F(SceneFile, BeadsAlongTrajectories) {
  const SceneSpec signed_glyphs = load_scene(write(std::string(minimal) + "[glyphs]\nshape = \"signed\"\n"));
  EXPECT_TRUE(signed_glyphs.pipeline.signed_shapes);
  EXPECT_FALSE(signed_glyphs.pipeline.beads);
  const SceneSpec given = load_scene(write(std::string(minimal) + "[glyphs]\nbeads = -0.25\n"));
  EXPECT_EQ(given.pipeline.beads, -0.25);
  EXPECT_FALSE(given.pipeline.signed_shapes);
  const std::string both = error_of(std::string(minimal) + "[glyphs]\nspacing = 0.1\nbeads = 0\n");
  EXPECT_NE(both.find(":5:9: glyphs.beads places the glyphs end to end, so glyphs.spacing has no use"),
            std::string::npos)
      << both;
  EXPECT_NE(error_of(std::string(minimal) + "[glyphs]\nplacement = \"seeds\"\nbeads = 0\n")
                .find("glyphs.beads applies only to glyphs.placement = \"trajectories\""),
            std::string::npos);
  EXPECT_NE(error_of(std::string(minimal) + "[glyphs]\nbeads = 0.95\n").find("glyphs.beads"), std::string::npos);
}

TEST_F(SceneFile, DataKindFollowsTheFile) {
  const std::string data = std::string(HSB_SOURCE_DIR) + "/scenes/data/cylinder_stress_coarse.vtu";
  const SceneSpec spec = load_scene(write("[data]\nfile = \"" + data + "\"\n"));
  EXPECT_EQ(spec.pipeline.data.kind, DataKind::vtk_file);
  EXPECT_EQ(spec.pipeline.data.file.path, data);
  // Keys of the other kind are mistakes, not silently ignored.
  EXPECT_NE(error_of("[data]\nfile = \"" + data + "\"\nbounds = [0, 1, 0, 1, 0, 1]\n")
                .find("data.bounds applies only to data.kind = \"point_load\""),
            std::string::npos);
  EXPECT_NE(error_of("[data]\nkind = \"point_load\"\nfile = \"" + data + "\"\n")
                .find("data.file applies only to data.kind = \"vtk\""),
            std::string::npos);
  // A file that is no data format hsb knows: said so, with what it reads.
  std::ofstream(test_temp_dir("scene_test") / "results.csv") << "x,y,z\n1,2,3\n";
  const std::string csv = error_of("[data]\nfile = \"results.csv\"\n");
  EXPECT_NE(csv.find(":2:8: data.file names "), std::string::npos) << csv;
  EXPECT_NE(csv.find("results.csv: not a data file hsb knows by its name or its first bytes. hsb reads legacy VTK (.vtk)"),
            std::string::npos)
      << csv;
}

// region.mask: an array of the data file, read with it, or a file beside
// the scene; each mistake located.
TEST_F(SceneFile, ARegionMaskIsAnArrayOrAFile) {
  const std::string data = std::string(HSB_SOURCE_DIR) + "/scenes/data/formats/dti_fsl_dtifit.nii.gz";
  const std::string head = "[data]\nfile = \"" + data + "\"\n[region]\n";
  const SceneSpec array = load_scene(write(head + "mask = \"array:brain\"\n"));
  EXPECT_EQ(array.pipeline.region.mask, "array:brain");
  EXPECT_EQ(array.pipeline.data.file.mask_array, "brain");
  std::filesystem::copy_file(std::string(HSB_SOURCE_DIR) + "/scenes/data/masks/dti_fsl_left_hemisphere.nii.gz",
                             test_temp_dir("scene_test") / "roi.nii.gz",
                             std::filesystem::copy_options::overwrite_existing);
  const SceneSpec file = load_scene(write(head + "mask = \"roi.nii.gz\"\n"));  // beside the scene
  EXPECT_EQ(file.pipeline.region.mask, (test_temp_dir("scene_test") / "roi.nii.gz").string());
  EXPECT_TRUE(file.pipeline.data.file.mask_array.empty());
  EXPECT_EQ(error_of(head + "mask = \"array:\"\n"),
            path_ + ":4:8: region.mask = \"array:NAME\" needs the array's name after the colon");
  EXPECT_NE(error_of(head + "mask = \"nope.nii\"\n").find(":4:8: region.mask names "), std::string::npos);
  EXPECT_NE(error_of("[region]\nmask = \"array:brain\"\n").find("region.mask needs data.file"), std::string::npos);
}

TEST_F(SceneFile, ADataFileIsASceneNamingOnlyIt) {
  const std::string data = std::string(HSB_SOURCE_DIR) + "/scenes/data/cylinder_stress_coarse.vtu";
  ASSERT_TRUE(is_data_file(data));
  EXPECT_FALSE(is_data_file("scene.toml"));
  const SceneSpec spec = load_scene_or_data_file(data, {"render.width=64"});
  EXPECT_EQ(spec.pipeline.data.kind, DataKind::vtk_file);
  EXPECT_EQ(spec.pipeline.data.file.path, data);
  EXPECT_EQ(spec.render.width, 64);
  EXPECT_EQ(spec.path, data);
}

TEST_F(SceneFile, CameraViewsAndProjection) {
  const SceneSpec named = load_scene(write(std::string(minimal) + "[camera]\nview = \"top\"\nprojection = \"orthographic\"\n"));
  EXPECT_EQ(named.camera.view.value(), Vec3(0, 0, 1));
  EXPECT_EQ(named.camera.projection, Projection::orthographic);
  const SceneSpec direction = load_scene(write(std::string(minimal) + "[camera]\nview = [0, -2, 0]\n"));
  EXPECT_EQ(direction.camera.view.value(), Vec3(0, -1, 0));
  EXPECT_NE(error_of(std::string(minimal) + "[camera]\nview = \"side\"\n").find("camera.view must be one of \"iso\""),
            std::string::npos);
  EXPECT_NE(error_of(std::string(minimal) + "[camera]\nview = [0, 0, 0]\n").find("camera.view must not be zero"),
            std::string::npos);
  EXPECT_NE(error_of(std::string(minimal) + "[camera]\nview = \"top\"\nup = [0, 0, 1]\n").find("parallel"),
            std::string::npos);
}

TEST_F(SceneFile, OpenIntervalsAreShownOpen) {
  const std::string e = error_of(std::string(minimal) + "[surface]\nisovalue = 0\n");
  EXPECT_EQ(e, path_ + ":4:12: surface.isovalue must be in (0, 1], got 0");
}

TEST_F(SceneFile, UnknownKeyFromTheCommandLineNamesTheArgument) {
  const std::string e = error_of(minimal, {"glyphs.spacin=0.1"});
  EXPECT_EQ(e.rfind("--set glyphs.spacin=0.1: glyphs.spacin is not a scene key; did you mean glyphs.spacing?", 0), 0u) << e;
}

TEST_F(SceneFile, MissingDataFileAndBadImageTypeAreLocated) {
  const std::string missing = error_of("[data]\nkind = \"vtk\"\nfile = \"nope.vtu\"\n");
  EXPECT_EQ(missing,
            path_ + ":3:8: data.file names " + (test_temp_dir("scene_test") / "nope.vtu").string() +
                ": no such file (relative paths are relative to the scene file)");
  const std::string image = error_of(std::string(minimal) + "[output]\nfile = \"x.bmp\"\n");
  EXPECT_EQ(image,
            path_ + ":4:8: output.file must end in .png, .tif, .tiff, .exr, .pdf or .svg, got \"x.bmp\"");
}

TEST_F(SceneFile, SeedsOutsideTheDataGiveAWarning) {
  const SceneSpec spec = load_scene(write("[seeds]\npoints = [[5, 5, 5]]\n"));
  const GlyphScene glyphs = build_glyph_scene(spec.pipeline, 0.5);
  EXPECT_TRUE(glyphs.sources.empty());
  ASSERT_EQ(glyphs.warnings.size(), 1u);
  EXPECT_NE(glyphs.warnings[0].find("no glyph sources"), std::string::npos);
}

TEST_F(SceneFile, MissingFile) { EXPECT_THROW(load_scene("/nonexistent/scene.toml"), SceneError); }

// A user's own data with nothing but its path: automatic seeds, lengths and
// camera give a picture.
TEST_F(SceneFile, OnlyADataPathIsEnoughForAPicture) {
  const std::string data = std::string(HSB_SOURCE_DIR) + "/scenes/data/cylinder_stress_coarse.vtu";
  const SceneSpec spec = load_scene(write("[data]\nkind = \"vtk\"\nfile = \"" + data + "\"\n"));
  const GlyphScene glyphs = build_glyph_scene(spec.pipeline, 0.5);
  EXPECT_EQ(glyphs.values.seeds.strategy, SeedStrategy::even);
  EXPECT_GE(glyphs.trajectories.size(), 9u);
  EXPECT_GT(glyphs.sources.size(), 100u);
  // Evenly spaced: every seed in the body, along the whole cylinder.
  double lowest = INFINITY, highest = -INFINITY;
  for (const Trajectory& t : glyphs.trajectories) {
    const Vec3& seed = t.points[t.seed_index];
    EXPECT_TRUE(glyphs.domain.contains(seed));
    lowest = std::min(lowest, seed.x()), highest = std::max(highest, seed.x());
  }
  EXPECT_GT(highest - lowest, 0.5 * glyphs.domain.size().x());
}

TEST_F(SceneFile, SeedsInBoundsFractions) {
  const SceneSpec spec = load_scene(write("[data]\nbounds = [0, 2, 0, 4, 0, 8]\n[seeds]\nframe = \"bounds\"\n"
                                          "points = [[0.5, 0.25, 0.5]]\n[glyphs]\nplacement = \"seeds\"\n"));
  const GlyphScene glyphs = build_glyph_scene(spec.pipeline, 0.5);
  ASSERT_EQ(glyphs.sources.size(), 1u);
  EXPECT_LT((glyphs.sources[0].centre - Vec3(1, 1, 4)).norm(), 1e-12);
}

TEST_F(SceneFile, CrossKeyChecksAreLocated) {
  const std::string e = error_of(std::string(minimal) + "[data]\nbounds = [1, 0, 0, 1, 0, 1]\n");
  EXPECT_EQ(e, path_ + ":4:10: data.bounds must be [xmin, xmax, ymin, ymax, zmin, zmax] with min < max");
}

// Every kind of bad scene a user can write gets one located error saying
// what was expected and what was found.
TEST_F(SceneFile, EveryBadValueIsOneLocatedError) {
  const std::vector<std::pair<std::string, std::string>> cases{
      {"[seeds\npoints = 1\n", ":1:7: Error while parsing table header: expected ']'"},
      {"[glyphs]\nspacingg = 0.1\n", ":2:1: unknown key glyphs.spacingg; did you mean glyphs.spacing?"},
      {"[glyphs]\nwhatever = 0.1\n", ":2:1: unknown key glyphs.whatever (known here:"},
      {"[render]\nwidth = \"big\"\n", ":2:9: render.width must be an integer, got string \"big\""},
      {"[glyphs]\nspacing = -0.1\n", ":2:11: glyphs.spacing must be > 0, got -0.1"},
      {"[glyphs]\nscale = 0\n", ":2:9: glyphs.scale must be > 0, got 0"},
      {"[glyphs]\nscale = -2\n", ":2:9: glyphs.scale must be > 0, got -2"},
      {"[render]\nsamples = 0\n", ":2:11: render.samples must be in [1, 16], got 0"},
      {"[render]\nwidth = 1000000\n", ":2:9: render.width must be in [1, 16384], got 1000000"},
      {"[surface]\nisovalue = 1.5\n", ":2:12: surface.isovalue must be in (0, 1], got 1.5"},
      {"[surface]\nisovalue = 0\n", ":2:12: surface.isovalue must be in (0, 1], got 0"},
      {"[glyphs]\nspacing = nan\n", ":2:11: glyphs.spacing must be a finite number, got nan"},
      {"[camera]\nfov = inf\n", ":2:7: camera.fov must be a finite number, got inf"},
      {"[light]\nfrom = [0, 0, 0]\n", ":2:8: light.from must not be zero"},
      {"[camera]\nposition = [1, 1, 1]\nlook_at = [1, 1, 1]\n", ":2:12: camera.position must differ from camera.look_at"},
      {"[camera]\nposition = [0, 0, 5]\nlook_at = [0, 0, 0]\nup = [0, 0, 1]\n",
       ":4:6: camera.up must not be parallel to the viewing direction"},
      {"[data]\nfile = \"nope.vtu\"\n", ":2:8: data.file names "},
      {"[output]\nfile = \"x.bmp\"\n", ":2:8: output.file must end in .png, .tif, .tiff, .exr, .pdf or .svg"},
      {"[output]\nfile = \"x.exr\"\nbit_depth = 8\n", ":3:13: output.bit_depth must be 16 (half) or 32 (float) for an EXR"},
      {"[color]\nmap = \"jet\"\n", ":2:7: color.map must be one of"},
      {"[glyphs]\nmapping = 3\n", ":2:11: glyphs.mapping must be"},
  };
  for (const auto& [text, expected] : cases) {
    const std::string e = error_of(text);
    EXPECT_EQ(e.rfind(path_ + expected, 0), 0u) << "scene:\n" << text << "gave: " << e;
    EXPECT_EQ(e.find('\n'), std::string::npos) << "one line: " << e;
  }
}

TEST(SceneFiles, EveryShippedSceneLoads) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(HSB_SOURCE_DIR) + "/scenes")) {
    if (entry.path().extension() != ".toml") continue;
    SCOPED_TRACE(entry.path().string());
    EXPECT_NO_THROW(load_scene(entry.path().string()));
    ++count;
  }
  EXPECT_GE(count, 5);
}

}  // namespace
}  // namespace hsb
