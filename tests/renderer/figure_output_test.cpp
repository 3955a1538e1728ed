// Figures as files: the colour under every colour-bar tick is the
// colormap's; EXR layers and metadata; DPI and the scene, data and
// resolved settings in every file; a PDF whose labels are text.

#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

#include "field/tensor/tensor_measures.h"
#include "renderer/app/render_job.h"
#include "renderer/image/text.h"
#include "renderer/library/prepared_scene.h"
#include "tests/renderer/command_output.h"
#include "tests/temp_dir.h"

namespace hsb {
namespace {

namespace fs = std::filesystem;

class FigureOutput : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test_temp_dir("figure_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()),
                         true);
  }
  // Writes `text` as a scene beside a copy of the shipped plate data set.
  std::string scene(const std::string& text) {
    fs::copy_file(fs::path(HSB_SOURCE_DIR) / "scenes/data/generated/plate_with_hole_mm_pa.vtu", dir_ / "plate.vtu",
                  fs::copy_options::overwrite_existing);
    const std::string path = (dir_ / "s.toml").string();
    std::ofstream(path) << text;
    return path;
  }
  RenderSummary render(const std::string& path, const std::vector<std::string>& overrides = {}) {
    return run_render_job({path, overrides, (dir_ / "out").string()});
  }
  fs::path dir_;
};

const char* const kPlate = "[data]\nfile = \"plate.vtu\"\n[render]\nwidth = 400\nheight = 300\nsamples = 1\n";

std::unique_ptr<OIIO::ImageInput> open_image(const std::string& path) {
  auto in = OIIO::ImageInput::open(path);
  EXPECT_TRUE(in) << path << ": " << OIIO::geterror();
  return in;
}

// glyphs.color_by = "none": every glyph one grey, and no colour bar to
// explain a colour that says nothing, only the shape key; the signed
// glyphs of the point load still differ where the stress is tension and
// where it is compression.
TEST(UncolouredFigure, HasOneGreyAndOnlyTheShapeKey) {
  SceneSpec spec = load_scene_text(
      "[[seeds.grid]]\ncorner = [-0.8, 0, -0.8]\nedge_u = [1.6, 0, 0]\nedge_v = [0, 0, 1.6]\nn = 4\nm = 4\n"
      "[glyphs]\nplacement = \"seeds\"\nshape = \"signed\"\ncolor_by = \"none\"\n",
      "uncoloured.toml", "");
  const ColorManagement color("", "");
  const std::unique_ptr<PreparedScene> p = prepare_scene(std::move(spec), color);
  ASSERT_EQ(p->field.sources.size(), 16u);
  ASSERT_TRUE(p->output.legend);
  EXPECT_FALSE(p->output.legend->bar);
  ASSERT_EQ(p->output.legend->key.size(), 3u);
  EXPECT_EQ(p->output.legend->key[1].label, "compression");
  // Inside the picture, in the part the camera leaves free.
  const LegendLayout& l = *p->output.legend;
  EXPECT_GE(l.key_x0, p->render.width * (1.0 - l.reserved));
  EXPECT_LE(l.key_x0 + l.key_width, p->render.width);
  EXPECT_GE(l.key_y0, 0.0);
  EXPECT_LE(l.key_y0 + 3.0 * l.key_row, p->render.height);
  for (const BlobSource& s : p->field.sources) EXPECT_EQ(s.color, p->field.sources.front().color);
  int pointed = 0, blunt = 0;
  for (const ShapeParams& shape : p->field.shapes) (shape.pointed ? pointed : blunt) += 1;
  EXPECT_EQ(pointed + blunt, 16);
  EXPECT_GT(pointed, 0);  // the point load compresses somewhere in every glyph's neighbourhood
}

TEST_F(FigureOutput, TheColourUnderEachTickIsTheColormaps) {
  for (const char* placement : {"right", "bottom"}) {
    SCOPED_TRACE(placement);
    const std::string path = scene(kPlate);
    const std::vector<std::string> overrides{"color.map=magma", std::string("output.colorbar_position=") + placement,
                                             "render.width=600", "render.height=500"};
    const RenderSummary summary = render(path, overrides);
    const ColorManagement color("", "");
    const std::unique_ptr<PreparedScene> p = prepare_scene(load_scene(path, overrides), color);
    ASSERT_TRUE(p->output.legend);
    const LegendLayout& legend = *p->output.legend;
    ASSERT_GE(legend.ticks.ticks.size(), 3u);

    auto in = open_image(summary.image_path);
    ASSERT_TRUE(in);
    const OIIO::ImageSpec& spec = in->spec();
    std::vector<float> pixels(std::size_t(spec.width) * std::size_t(spec.height) * std::size_t(spec.nchannels));
    ASSERT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data()));
    const bool right = legend.style.placement == LegendPlacement::right;
    for (const Tick& tick : legend.ticks.ticks) {
      const double along = legend.position(p->scale, tick.value);
      // The middle of the strip across, the pixel whose centre is nearest the tick along.
      const int x = right ? int(0.5 * (legend.bar_x0 + legend.bar_x1)) : int(std::lround(along - 0.5));
      const int y = right ? int(std::lround(along - 0.5)) : int(0.5 * (legend.bar_y0 + legend.bar_y1));
      const float* px = &pixels[(std::size_t(y) * std::size_t(spec.width) + std::size_t(x)) * std::size_t(spec.nchannels)];
      // The colormap's colour at the tick, through the same colour path.
      const Rgb linear = color.to_scene_linear(p->scale.srgb(tick.value));
      std::vector<float> expected{linear[0], linear[1], linear[2], 1.0f};
      color.apply_display(expected, 1, 1);
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(px[c], expected[std::size_t(c)], 3.0 / 255.0) << "tick " << tick.label << " channel " << c;
    }
  }
}

// Stress of both signs: the bar's ends say which is tension, and the
// automatic diverging map keeps tension warm and compression cool under
// either sign convention, so the same state looks the same.
TEST_F(FigureOutput, TheBarsEndsAreNamedByTheSignConvention) {
  const ColorManagement color("", "");
  const std::string path = scene(kPlate);
  for (const char* sign : {"tension-positive", "compression-positive"}) {
    SCOPED_TRACE(sign);
    const bool tension_positive = std::string(sign) == "tension-positive";
    const std::unique_ptr<PreparedScene> p =
        prepare_scene(load_scene(path, {"glyphs.color_by=lambda3", std::string("data.sign=") + sign}), color);
    ASSERT_TRUE(p->output.legend);
    ASSERT_LT(p->scale.lo, 0.0);  // the hole's hoop compression beside the pull
    ASSERT_GT(p->scale.hi, 0.0);
    EXPECT_EQ(p->output.legend->high_word, tension_positive ? "tension" : "compression");
    EXPECT_EQ(p->output.legend->low_word, tension_positive ? "compression" : "tension");
    EXPECT_EQ(p->scale.map->name, tension_positive ? "coolwarm" : "coolwarm_r");
    // The high end's colour is warm exactly when it is tension.
    const Rgb high = p->scale.srgb(p->scale.hi);
    EXPECT_EQ(high[0] > high[2], tension_positive);
    EXPECT_TRUE(p->output.legend->key.empty());  // ellipsoids: the shape says nothing of the sign
  }
  // A map the scene names is kept; a scalar with no sign gets no words.
  const std::unique_ptr<PreparedScene> named = prepare_scene(
      load_scene(path, {"glyphs.color_by=lambda3", "data.sign=compression-positive", "color.map=RdBu"}), color);
  EXPECT_EQ(named->scale.map->name, "RdBu");
  const std::unique_ptr<PreparedScene> mises = prepare_scene(load_scene(path, {"glyphs.color_by=von_mises"}), color);
  ASSERT_TRUE(mises->output.legend);
  EXPECT_TRUE(mises->output.legend->high_word.empty());
}

// Signed glyphs: the key of sample glyphs sits beside the colour bar,
// drawn in a PDF as vector shapes and text; output.shape_key = false
// leaves it out, and asking for it with a shape that has none is an error.
// A bounded measure's bar spans its whole range whatever the data holds,
// so that two pictures compare; a range the scene gives still wins.
TEST_F(FigureOutput, ABoundedMeasureKeepsItsWholeRangeOnTheBar) {
  const ColorManagement color("", "");
  const std::string path = scene(kPlate);
  struct Case {
    const char* name;
    double lo, hi;
    const char* map;
  };
  for (const Case& c : {Case{"fa", 0.0, 1.0, "viridis"}, Case{"cl", 0.0, 1.0, "viridis"},
                        Case{"mode", -1.0, 1.0, "coolwarm"}}) {
    SCOPED_TRACE(c.name);
    const std::unique_ptr<PreparedScene> p =
        prepare_scene(load_scene(path, {std::string("glyphs.color_by=") + c.name}), color);
    EXPECT_EQ(p->scale.lo, c.lo);
    EXPECT_EQ(p->scale.hi, c.hi);
    EXPECT_EQ(p->scale.map->name, c.map);
    // The plate's values fill only part of it, and are each glyph's own.
    EXPECT_GE(p->scale.data_lo, c.lo);
    EXPECT_LE(p->scale.data_hi, c.hi);
    EXPECT_LT(p->scale.data_hi - p->scale.data_lo, c.hi - c.lo);
    for (const GlyphSource& g : p->glyphs.sources)
      ASSERT_EQ(g.scalar, color_scalar(g.eigenvalues, p->glyphs.color));
    ASSERT_TRUE(p->output.legend);
    EXPECT_TRUE(p->output.legend->high_word.empty());  // not a stress: no tension or compression
  }
  const std::unique_ptr<PreparedScene> given =
      prepare_scene(load_scene(path, {"glyphs.color_by=fa", "color.range=[0.2, 0.6]"}), color);
  EXPECT_EQ(given->scale.lo, 0.2);
  EXPECT_EQ(given->scale.hi, 0.6);
}

TEST_F(FigureOutput, SignedGlyphsGetAShapeKeyBesideTheBar) {
  const ColorManagement color("", "");
  const std::string path = scene(std::string(kPlate) + "[output]\nfile = \"x.pdf\"\n");
  const std::unique_ptr<PreparedScene> p = prepare_scene(load_scene(path, {"glyphs.shape=signed"}), color);
  ASSERT_TRUE(p->output.legend);
  const LegendLayout& l = *p->output.legend;
  EXPECT_TRUE(l.bar);
  ASSERT_EQ(l.key.size(), 3u);
  // The key under the bar, clear of it and of the bar's low end's word.
  EXPECT_GT(l.key_y0, l.bar_y1);
  EXPECT_LE(l.key_y0 + 3.0 * l.key_row, p->render.height);
  EXPECT_TRUE(p->resolved["output"]["shape_key"].value_or(false));

  const RenderSummary summary = render(path, {"glyphs.shape=signed"});
  const std::string text = output_of("pdftotext '" + summary.image_path + "' -");
  for (const char* word : {"tension", "compression", "shear"}) EXPECT_NE(text.find(word), std::string::npos) << text;
  const std::unique_ptr<PreparedScene> off =
      prepare_scene(load_scene(path, {"glyphs.shape=signed", "output.shape_key=false"}), color);
  ASSERT_TRUE(off->output.legend);
  EXPECT_TRUE(off->output.legend->key.empty());
  try {
    load_scene(path, {"output.shape_key=true"});
    ADD_FAILURE() << "no error";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("output.shape_key = true needs glyphs.shape = \"signed\""), std::string::npos)
        << e.what();
  }
}

// Teem's helix given alone is read as diffusion: direction colours with
// their key, and its glyph field as superquadrics unless a shape is named.
TEST(DiffusionFigure, TeemsHelixAloneGetsDirectionColourAndSuperquadricGlyphs) {
  const ColorManagement color("", "");
  const std::string helix = std::string(HSB_SOURCE_DIR) + "/scenes/data/formats/teem_helix.nrrd";
  const auto prepared = [&](const std::vector<std::string>& overrides) {
    return prepare_scene(load_scene_or_data_file(helix, overrides), color);
  };
  const std::unique_ptr<PreparedScene> lines = prepared({"render.width=200"});
  EXPECT_EQ(lines->glyphs.quantity, DataQuantity::diffusion);
  EXPECT_EQ(lines->glyphs.color, ColorScalar::direction);
  ASSERT_TRUE(lines->output.legend);
  EXPECT_TRUE(lines->output.legend->direction);
  EXPECT_EQ(lines->spec.surface.shape, GlyphShape::ellipsoid);  // hyperstreamballs keep the paper's glyph
  // Its NRRD says its space is right-anterior-superior: the key's ends say so.
  EXPECT_EQ(lines->output.legend->direction->labels, (std::array<std::string, 3>{"R", "A", "S"}));
  const std::unique_ptr<PreparedScene> field = prepared({"render.width=200", "glyphs.placement=points"});
  EXPECT_EQ(field->spec.surface.shape, GlyphShape::superquadric);
  EXPECT_EQ(field->resolved["glyphs"]["shape"].value_or(std::string()), "superquadric");
  EXPECT_EQ(prepared({"render.width=200", "glyphs.placement=points", "glyphs.shape=ellipsoid"})->spec.surface.shape,
            GlyphShape::ellipsoid);
  EXPECT_EQ(prepared({"render.width=200", "glyphs.placement=points", "data.quantity=stress"})->spec.surface.shape,
            GlyphShape::ellipsoid);
}

// Direction colour (the default for diffusion data, asked for here on the
// plate's stress): each glyph the colour of its major eigenvector, faded
// to grey as FA falls, and a key of the data's axes as the camera sees
// them instead of the bar, in the picture's pixels and as vector lines and
// text in a PDF.
TEST_F(FigureOutput, DirectionColourHasAnAxisKeyInsteadOfTheBar) {
  const ColorManagement color("", "");
  const std::string path = scene(std::string(kPlate) +
                                 "[glyphs]\ncolor_by = \"direction\"\n[camera]\nposition = [0, -2000, 0]\n"
                                 "look_at = [0, 0, 0]\nup = [0, 0, 1]\n");
  const std::unique_ptr<PreparedScene> p = prepare_scene(load_scene(path), color);
  ASSERT_TRUE(p->output.legend);
  const LegendLayout& l = *p->output.legend;
  EXPECT_FALSE(l.bar);
  ASSERT_TRUE(l.direction);
  for (std::size_t i = 0; i < p->glyphs.sources.size(); ++i) {
    const GlyphSource& g = p->glyphs.sources[i];
    const Rgb expected = color.to_scene_linear(direction_srgb(g.axes.col(0), fractional_anisotropy(g.eigenvalues)));
    for (int c = 0; c < 3; ++c) ASSERT_FLOAT_EQ(p->field.sources[i].color[std::size_t(c)], expected[std::size_t(c)]);
  }
  // Seen along +y, x runs right, z up and y away.
  const auto& axes = l.direction->axes;
  EXPECT_NEAR(axes[0][0], 1.0, 1e-9);
  EXPECT_NEAR(axes[2][1], 1.0, 1e-9);
  EXPECT_NEAR(std::hypot(axes[1][0], axes[1][1]), 0.0, 1e-9);
  EXPECT_EQ(l.direction->labels, (std::array<std::string, 3>{"x", "y", "z"}));  // a VTK file has no anatomy
  // The key lies inside the picture, in the part the camera leaves it.
  EXPECT_GT(l.triad_x - l.triad_r, (1.0 - l.reserved) * p->render.width);
  EXPECT_LT(l.triad_x + l.triad_r, p->render.width);
  EXPECT_GT(l.triad_y - l.triad_r, 0.0);
  EXPECT_LT(l.triad_title_y, p->render.height);

  // The x axis' line is red in the picture, the z axis' blue.
  const RenderSummary png = render(path);
  auto in = open_image(png.image_path);
  ASSERT_TRUE(in);
  const int w = in->spec().width, h = in->spec().height;
  std::vector<float> pixels(std::size_t(w) * std::size_t(h) * 3);
  ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, pixels.data()));
  const auto at = [&](double x, double y) {
    const std::size_t i = (std::size_t(std::lround(y)) * std::size_t(w) + std::size_t(std::lround(x))) * 3;
    return std::array<float, 3>{pixels[i], pixels[i + 1], pixels[i + 2]};
  };
  const auto red = at(l.triad_x + 0.7 * l.triad_r, l.triad_y), blue = at(l.triad_x, l.triad_y - 0.7 * l.triad_r);
  EXPECT_GT(red[0], red[1] + 0.3f);
  EXPECT_GT(red[0], red[2] + 0.3f);
  EXPECT_GT(blue[2], blue[0] + 0.3f);
  EXPECT_GT(blue[2], blue[1] + 0.3f);

  const RenderSummary pdf = render(path, {"output.file=\"d.pdf\""});
  const std::string text = output_of("pdftotext '" + pdf.image_path + "' -");
  for (const char* word : {"direction of e", "FA"}) EXPECT_NE(text.find(word), std::string::npos) << text;
}

// A colour bar's title longer than the bar (a short picture, a long
// name) is wrapped at the bar's length, its lines side by side in a
// column wide enough for them; a title that fits is left whole.
TEST_F(FigureOutput, ATitleLongerThanTheBarIsWrappedBesideIt) {
  const ColorManagement color("", "");
  const std::string path = scene(kPlate);
  const std::string title = "the first principal stress of the plate, where the hole concentrates it (Pa)";
  const std::unique_ptr<PreparedScene> p =
      prepare_scene(load_scene(path, {"render.height=200", "output.colorbar_title=\"" + title + "\""}), color);
  ASSERT_TRUE(p->output.legend);
  const LegendLayout& l = *p->output.legend;
  const double length = l.bar_y1 - l.bar_y0;
  ASSERT_GT(l.title_wrap, 0.0);
  EXPECT_LE(l.title_wrap, length + 1e-9);
  const CairoOwned<cairo_t> cr = measuring_context();
  const double font = l.style.font_size * l.pixels_per_point;
  double w = 0.0, h = 0.0, one_w = 0.0, one_h = 0.0;
  text_size(cr.get(), title, font, w, h, false, l.title_wrap);
  text_size(cr.get(), title, font, one_w, one_h);
  EXPECT_LE(w, length + 1.0);  // along the bar, within it
  EXPECT_GE(h, 2.0 * one_h);   // in two lines or more
  EXPECT_LE(l.left + (l.bar_x1 - l.bar_x0) + h, p->render.width);  // and the column holds them
  const std::unique_ptr<PreparedScene> fits =
      prepare_scene(load_scene(path, {"render.height=600", "output.colorbar_title=\"λ₁ (Pa)\""}), color);
  ASSERT_TRUE(fits->output.legend);
  EXPECT_EQ(fits->output.legend->title_wrap, 0.0);
}

// One side given: the other follows the body's shape, as with neither,
// so "--set render.width=320" on a wide plate gives a wide picture, not a
// tall one with the plate small in its middle.
TEST_F(FigureOutput, OneSideGivenTheOtherFollowsTheBody) {
  const ColorManagement color("", "");
  const std::string path = scene("[data]\nfile = \"plate.vtu\"\n");
  // The free part's shape (the legend's strip on the right left out).
  const auto free_aspect = [](const PreparedScene& p) {
    return p.render.width * (1.0 - p.output.legend->reserved) / p.render.height;
  };
  const std::unique_ptr<PreparedScene> automatic = prepare_scene(load_scene(path), color);
  ASSERT_TRUE(automatic->output.legend);
  const double body = free_aspect(*automatic);
  ASSERT_GT(body, 1.5);  // the plate is wide
  const std::unique_ptr<PreparedScene> wide = prepare_scene(load_scene(path, {"render.width=320"}), color);
  EXPECT_EQ(wide->render.width, 320);
  EXPECT_NEAR(free_aspect(*wide) / body, 1.0, 0.03);
  const std::unique_ptr<PreparedScene> tall = prepare_scene(load_scene(path, {"render.height=300"}), color);
  EXPECT_EQ(tall->render.height, 300);
  EXPECT_NEAR(free_aspect(*tall) / body, 1.0, 0.03);
  // Beside a print size, the other side keeps the print's shape.
  for (const char* side : {"render.width=600", "render.height=300"}) {
    const std::unique_ptr<PreparedScene> proof =
        prepare_scene(load_scene(path, {"output.print_size=[85, 60]", side}), color);
    EXPECT_NEAR(double(proof->render.width) / proof->render.height, 85.0 / 60.0, 0.005) << side;
  }
}

TEST_F(FigureOutput, PngCarriesDpiSceneDataAndResolvedSettings) {
  const std::string path = scene(kPlate);
  const RenderSummary summary = render(path, {"output.dpi=600"});
  auto in = open_image(summary.image_path);
  ASSERT_TRUE(in);
  const OIIO::ImageSpec& spec = in->spec();
  EXPECT_NEAR(spec.get_float_attribute("XResolution"), 600.0f, 0.01f);  // PNG stores pixels per metre
  EXPECT_EQ(spec.get_string_attribute("ResolutionUnit"), "inch");
  EXPECT_EQ(std::string(spec.get_string_attribute("Software")).rfind("Hyperstreamball ", 0), 0u);
  EXPECT_NE(spec.get_string_attribute("hsb:scene_text").find("file = \"plate.vtu\""), std::string::npos);
  EXPECT_NE(spec.get_string_attribute("hsb:scene_text").find("--set output.dpi=600"), std::string::npos);
  EXPECT_EQ(spec.get_string_attribute("hsb:data_sha1").size(), 40u);
  EXPECT_NE(spec.get_string_attribute("hsb:data_file").find("plate.vtu"), std::string::npos);
  EXPECT_NE(spec.get_string_attribute("hsb:resolved").find("scale = "), std::string::npos);
  // The scene hash covers the data: another data file under the same name
  // gives another hash.
  const std::string first = spec.get_string_attribute("hsb:scene_sha1");
  in.reset();
  fs::copy_file(fs::path(HSB_SOURCE_DIR) / "scenes/data/generated/beam_bending.vtu", dir_ / "plate.vtu",
                fs::copy_options::overwrite_existing);
  const RenderSummary again = run_render_job({path, {"output.dpi=600"}, (dir_ / "out").string()});
  auto second = open_image(again.image_path);
  ASSERT_TRUE(second);
  EXPECT_NE(second->spec().get_string_attribute("hsb:scene_sha1"), first);
}

// A huge scene is named by its size and hash, not copied into each image.
TEST_F(FigureOutput, AHugeSceneIsNotCopiedIntoTheImage) {
  const std::string path = scene(std::string(kPlate) + "# " + std::string(200000, 'x') + "\n");
  const RenderSummary summary = render(path, {"render.width=64", "render.height=48"});
  auto in = open_image(summary.image_path);
  ASSERT_TRUE(in);
  const std::string text = in->spec().get_string_attribute("hsb:scene_text");
  EXPECT_LT(text.size(), 200u) << text.substr(0, 200);
  EXPECT_EQ(text.rfind("(200", 0), 0u) << text.substr(0, 200);
  EXPECT_NE(text.find("more than an image keeps; SHA-1 "), std::string::npos);
  EXPECT_LT(fs::file_size(summary.image_path), 100000u);
}

TEST_F(FigureOutput, ExrHasTheLayersAFigureIsComposedFrom) {
  const std::string path = scene(std::string(kPlate) + "[output]\nfile = \"x.exr\"\n");
  const RenderSummary summary = render(path);
  auto in = open_image(summary.image_path);
  ASSERT_TRUE(in);
  const OIIO::ImageSpec& spec = in->spec();
  const std::vector<std::string> names{"R", "G", "B", "A", "Z", "N.X", "N.Y", "N.Z", "scalar", "id"};
  for (const std::string& name : names)
    EXPECT_GE(spec.channelindex(name), 0) << name << " missing";
  ASSERT_EQ(spec.nchannels, int(names.size()));
  EXPECT_EQ(spec.channelformat(spec.channelindex("id")), OIIO::TypeDesc::UINT);
  EXPECT_EQ(spec.channelformat(spec.channelindex("R")), OIIO::TypeDesc::FLOAT);
  EXPECT_FALSE(spec.get_string_attribute("hsb:scene_sha1").empty());

  std::vector<float> px(std::size_t(spec.width) * std::size_t(spec.height) * names.size());
  ASSERT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, px.data()));
  const int a = spec.channelindex("A"), id = spec.channelindex("id"), nx = spec.channelindex("N.X");
  const int scalar = spec.channelindex("scalar"), z = spec.channelindex("Z");
  int on_glyph = 0;
  for (std::size_t i = 0; i < px.size(); i += names.size()) {
    if (px[i + std::size_t(a)] < 1.0f || px[i + std::size_t(id)] == 0.0f) continue;  // edges, the shell, background
    ++on_glyph;
    const double n = std::hypot(px[i + std::size_t(nx)], px[i + std::size_t(nx) + 1], px[i + std::size_t(nx) + 2]);
    EXPECT_GT(n, 0.5);  // unit normals, averaged over a pixel
    EXPECT_LE(n, 1.0 + 1e-5);
    EXPECT_TRUE(std::isfinite(px[i + std::size_t(scalar)]));
    EXPECT_GT(px[i + std::size_t(z)], 0.0f);
  }
  EXPECT_GT(on_glyph, 100);

  const std::string half = scene(std::string(kPlate) + "[output]\nfile = \"h.exr\"\nbit_depth = 16\n");
  auto h = open_image(render(half).image_path);
  ASSERT_TRUE(h);
  EXPECT_EQ(h->spec().channelformat(0), OIIO::TypeDesc::HALF);
}


TEST_F(FigureOutput, PdfPrintsAtItsDpiWithTheLegendAsText) {
  const std::string path = scene(std::string(kPlate) + "[output]\nfile = \"x.pdf\"\ncolorbar_title = \"λ₃ (Pa)\"\n");
  const RenderSummary summary = render(path);
  // 400 × 300 pixels at 300 DPI: 96 × 72 points.
  const std::string info = output_of("pdfinfo '" + summary.image_path + "'");
  EXPECT_NE(info.find(" 96 x 72 pts"), std::string::npos) << info;
  EXPECT_NE(info.find("Creator:         Hyperstreamball"), std::string::npos) << info;
  EXPECT_NE(info.find("hsb:scene_sha1="), std::string::npos) << info;
  const std::string text = output_of("pdftotext '" + summary.image_path + "' -");
  EXPECT_NE(text.find("λ₃ (Pa)"), std::string::npos) << text;
  EXPECT_NE(text.find("×10⁶"), std::string::npos) << text;  // stresses in pascals share a factor

  const std::string svg_scene = scene(std::string(kPlate) + "[output]\nfile = \"x.svg\"\n");
  std::ifstream svg(render(svg_scene).image_path);
  std::ostringstream svg_text;
  svg_text << svg.rdbuf();
  EXPECT_NE(svg_text.str().find("key=\"hsb:scene_sha1\""), std::string::npos);
  EXPECT_NE(svg_text.str().find("<image"), std::string::npos);
}

// What a user's scene and files name goes into the SVG's metadata: a
// control character or bytes that are not UTF-8 there (a file name may be
// any bytes) still make well-formed XML, each such character U+FFFD.
TEST_F(FigureOutput, SvgMetadataIsWellFormedWhateverTheNamesHold) {
  scene("");
  const std::string odd = (dir_ / "odd\x01name\xff\xc3.toml").string();
  std::ofstream(odd) << kPlate << "[output]\nfile = \"odd.svg\"\ncolorbar_title = \"bell\\u0007 & <tag> \\u00e9\"\n";
  const std::string svg = render(odd).image_path;
  const std::string parsed = output_of("/usr/bin/python3 -c \"import sys, xml.dom.minidom as m; "
                                       "d = m.parse(sys.argv[1]); print(len(d.getElementsByTagName('metadata')))\" '" +
                                       svg + "' 2>&1");
  EXPECT_EQ(parsed, "1\n") << parsed;
  std::ifstream in(svg, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find("odd\xEF\xBF\xBDname\xEF\xBF\xBD\xEF\xBF\xBD.toml"), std::string::npos);
  EXPECT_NE(text.str().find("&amp; &lt;tag&gt; \xC3\xA9"), std::string::npos);  // é kept, as UTF-8
}

}  // namespace
}  // namespace hsb
