// Figures of panels (layout, labels, a shared colour bar and range) and
// scenes on vector data (colour by a named array, errors for colours the
// data cannot give).

#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "field/reading/data_error.h"
#include "renderer/app/panel_figure.h"
#include "renderer/app/render_job.h"
#include "renderer/library/prepared_scene.h"
#include "tests/renderer/command_output.h"
#include "tests/temp_dir.h"

namespace hsb {
namespace {

namespace fs = std::filesystem;

const fs::path source_dir(HSB_SOURCE_DIR);

fs::path temp_dir(const std::string& name) {
  return test_temp_dir("panels_" + name, true);
}


TEST(Panels, ColumnsNearestSquarePanelsUnlessGiven) {
  EXPECT_EQ(panel_columns(4, 1600, 400, std::nullopt), 4);  // a wide strip: one row
  EXPECT_EQ(panel_columns(4, 800, 800, std::nullopt), 2);   // a square: 2 × 2
  EXPECT_EQ(panel_columns(3, 300, 900, std::nullopt), 1);   // a tall strip: one column
  EXPECT_EQ(panel_columns(6, 900, 600, std::nullopt), 3);
  EXPECT_EQ(panel_columns(5, 900, 600, 2), 2);
  EXPECT_EQ(panel_columns(2, 900, 600, 7), 2);  // never more columns than panels
}

const char* const kFigure =
    "[glyphs]\nplacement = \"curve\"\n[glyphs.curve]\nkind = \"circle\"\nsemi_axes = [0.4, 0.15, 0.15]\n"
    "[figure]\ncolumns = 2\ncaption = \"Four panels of sources along a circle.\"\n"
    "[[panel]]\nlabel = \"few\"\n\"glyphs.curve.count\" = 4\n"
    "[[panel]]\n\"glyphs.curve.count\" = 8\n[[panel]]\n[panel.glyphs.curve]\ncount = 12\n"
    "[[panel]]\n\"glyphs.curve.count\" = 24\n"
    "[render]\nwidth = 400\nheight = 360\nsamples = 1\n";

TEST(Panels, AGridOfLabelledPanelsWithOneSharedBar) {
  const fs::path dir = temp_dir("grid");
  std::ofstream(dir / "figure.toml") << kFigure;
  const RenderSummary summary = run_render_job({(dir / "figure.toml").string(), {}, (dir / "out").string()});
  EXPECT_EQ(summary.sources, 4u + 8u + 12u + 24u);
  auto in = OIIO::ImageInput::open(summary.image_path);
  ASSERT_TRUE(in);
  EXPECT_EQ(in->spec().width, 400);
  EXPECT_EQ(in->spec().height, 360);
  std::vector<float> px(std::size_t(400 * 360 * 4));
  ASSERT_TRUE(in->read_image(0, 0, 0, 4, OIIO::TypeDesc::FLOAT, px.data()));
  // Something drawn in each quarter of the panel area (left of the bar).
  for (int q = 0; q < 4; ++q) {
    int coloured = 0;
    const int x0 = (q % 2) * 160, y0 = (q / 2) * 150;
    for (int y = y0 + 20; y < y0 + 140; ++y)
      for (int x = x0 + 10; x < x0 + 150; ++x) {
        const float* p = &px[(std::size_t(y) * 400 + std::size_t(x)) * 4];
        coloured += std::fabs(p[0] - p[2]) > 0.1f;  // not white or grey: a glyph
      }
    EXPECT_GT(coloured, 50) << "panel " << q;
  }
  // The same figure as a PDF: the labels, the caption and one colour bar's title are text.
  const RenderSummary pdf =
      run_render_job({(dir / "figure.toml").string(), {"output.file=figure.pdf"}, (dir / "out").string()});
  const std::string text = output_of("pdftotext '" + pdf.image_path + "' -");
  for (const char* expected : {"(a) few", "(b)", "(c)", "(d)", "Four panels of sources along a circle.",
                               "position along the curve"})
    EXPECT_NE(text.find(expected), std::string::npos) << expected << " not in:\n" << text;
  std::size_t titles = 0;
  for (std::size_t at = text.find("position along the curve"); at != std::string::npos;
       at = text.find("position along the curve", at + 1))
    ++titles;
  EXPECT_EQ(titles, 1u);  // shared
}

TEST(Panels, DifferentScalarsKeepTheirOwnBars) {
  const fs::path dir = temp_dir("own");
  std::ofstream(dir / "figure.toml")
      << "[data]\nfile = \"" << (source_dir / "scenes/data/generated/beam_bending.vtu").string() << "\"\n"
      << "[figure]\ncolumns = 2\nlabels = false\n[[panel]]\n\"glyphs.color_by\" = \"lambda1\"\n"
         "[[panel]]\n\"glyphs.color_by\" = \"lambda3\"\n[render]\nwidth = 480\nheight = 200\nsamples = 1\n"
         "[output]\nfile = \"f.pdf\"\n";
  const RenderSummary pdf = run_render_job({(dir / "figure.toml").string(), {}, (dir / "out").string()});
  const std::string text = output_of("pdftotext '" + pdf.image_path + "' -");
  EXPECT_NE(text.find("major eigenvalue"), std::string::npos) << text;
  EXPECT_NE(text.find("minor eigenvalue"), std::string::npos) << text;
  EXPECT_EQ(text.find("(a)"), std::string::npos) << "labels = false";
}

TEST(Panels, ABadPanelKeyNamesThePanel) {
  const fs::path dir = temp_dir("bad");
  std::ofstream(dir / "figure.toml") << "[[panel]]\n\"glyphs.spacing\" = 0.1\n\n[[panel]]\n\"glyphs.spacing\" = -1\n";
  try {
    run_render_job({(dir / "figure.toml").string(), {}, (dir / "out").string()});
    FAIL() << "no error";
  } catch (const SceneError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind((dir / "figure.toml").string() + ":4: panel (b): ", 0), 0u) << m;
    EXPECT_NE(m.find("glyphs.spacing must be > 0"), std::string::npos) << m;
  }
  EXPECT_FALSE(fs::exists(dir / "out" / "figure.png"));
}

// A caption taller than the picture once left panels of 0 pixels, blamed
// on "--set render.width=0".
TEST(Panels, PanelsTooSmallForTheFigureAreTheFiguresError) {
  const fs::path dir = temp_dir("small");
  std::ofstream(dir / "figure.toml") << "[render]\nwidth = 120\nheight = 60\n[figure]\ncaption = \""
                                     << std::string(3000, 'w') << "\"\n[[panel]]\n[[panel]]\n";
  try {
    run_render_job({(dir / "figure.toml").string(), {}, (dir / "out").string()});
    FAIL() << "no error";
  } catch (const SceneError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind((dir / "figure.toml").string() + ": 2 panels of a 120×60 picture with its caption get ", 0), 0u)
        << m;
    EXPECT_NE(m.find("less than 4: enlarge render.width and render.height"), std::string::npos) << m;
    EXPECT_EQ(m.find("--set"), std::string::npos) << m;
  }
  EXPECT_FALSE(fs::exists(dir / "out" / "figure.png"));
}

std::unique_ptr<PreparedScene> prepared(const std::string& text) {
  const ColorManagement color("", "");
  return prepare_scene(load_scene_text(text, "flow.toml", ""), color);
}

const std::string kGlazing = (source_dir / "scenes/data/generated/double_glazing.vtu").string();

TEST(Flows, ColourByANamedArrayOfTheFile) {
  const auto p = prepared("[data]\nfile = \"" + kGlazing + "\"\n[glyphs]\ncolor_by = \"array:temperature\"\n");
  EXPECT_TRUE(p->glyphs.flow);
  ASSERT_GT(p->glyphs.sources.size(), 10u);
  double lo = 1e9, hi = -1e9;
  for (const GlyphSource& s : p->glyphs.sources) lo = std::min(lo, s.scalar), hi = std::max(hi, s.scalar);
  EXPECT_GE(lo, 288.15 - 1e-6);  // kelvin, between the panes' temperatures
  EXPECT_LE(hi, 303.15 + 1e-6);
  EXPECT_GT(hi - lo, 5.0);
  EXPECT_EQ(legend_for(*p, 800, 800).title, "temperature");
  // Speed by default; spheres along the flow.
  const auto speed = prepared("[data]\nfile = \"" + kGlazing + "\"\n");
  EXPECT_EQ(speed->glyphs.color, ColorScalar::speed);
  for (const GlyphSource& s : speed->glyphs.sources) EXPECT_DOUBLE_EQ(s.radii.x(), s.radii.z());
}

TEST(Flows, TensorGlyphsColouredByAnotherArray) {
  // The cantilever's stress glyphs coloured by its displacement (a
  // 3-component array: by its magnitude), largest at the free tip x = 1.
  const auto p = prepared("[data]\nfile = \"" + (source_dir / "scenes/data/generated/beam_bending.vtu").string() +
                          "\"\n[glyphs]\ncolor_by = \"array:displacement\"\n");
  EXPECT_FALSE(p->glyphs.flow);
  const GlyphSource* tip = nullptr;
  const GlyphSource* root = nullptr;
  for (const GlyphSource& s : p->glyphs.sources) {
    if (!tip || s.centre.x() > tip->centre.x()) tip = &s;
    if (!root || s.centre.x() < root->centre.x()) root = &s;
  }
  ASSERT_TRUE(tip && root);
  EXPECT_GT(tip->scalar, 3e-3);   // the tip moves 4 mm
  EXPECT_LT(root->scalar, 5e-4);  // the clamped end hardly at all
}

TEST(Flows, ColoursTheDataCannotGiveAreErrors) {
  const std::string data = "[data]\nfile = \"" + kGlazing + "\"\n";
  EXPECT_THROW(prepared(data + "[glyphs]\ncolor_by = \"lambda3\"\n"), DataError);
  try {
    prepared(data + "[glyphs]\ncolor_by = \"array:pressure\"\n");
    FAIL() << "no error";
  } catch (const DataError& e) {
    EXPECT_NE(std::string(e.what()).find("no array named \"pressure\" to colour by; the file has point data: "
                                         "velocity (3 components), temperature (1 components)"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(prepared("[glyphs]\ncolor_by = \"speed\"\n"), DataError);  // the point load holds tensors
  EXPECT_THROW(load_scene_text("[glyphs]\ncolor_by = \"array:t\"\n", "x.toml", ""), SceneError);
}

}  // namespace
}  // namespace hsb
