// Colour: the built-in OCIO config, the transforms, colormaps and ranges.

#include <gtest/gtest.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <optional>
#include <filesystem>
#include <fstream>
#include <future>
#include <sstream>

#include "renderer/image/channel_tables.h"
#include "renderer/image/color_management.h"
#include "renderer/image/colormap.h"
#include "renderer/image/direction_key.h"
#include "tests/temp_dir.h"
#include "tests/without_waiting.h"

namespace hsb {
namespace {

double srgb_to_linear(double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); }

class Color : public ::testing::Test {
 protected:
  void SetUp() override { unsetenv("OCIO"); }
};

TEST_F(Color, BuiltinConfigValidates) {
  std::istringstream text(builtin_ocio_config());
  const auto config = OCIO_NAMESPACE::Config::CreateFromStream(text);
  EXPECT_NO_THROW(config->validate());
  EXPECT_STREQ(config->getDefaultDisplay(), "sRGB");
}

TEST_F(Color, PickedSrgbBecomesLinearByTheSrgbCurve) {
  const ColorManagement color("", "");
  for (float v : {0.0f, 0.02f, 0.2f, 0.5f, 0.8f, 1.0f}) {
    const Rgb lin = color.to_scene_linear({v, v, v});
    EXPECT_NEAR(lin[0], srgb_to_linear(v), 2e-4) << v;
    const Rgb back = color.to_picking(lin);
    EXPECT_NEAR(back[1], v, 2e-4);
  }
}

TEST_F(Color, DisplayTransformEncodesSceneLinearAsSrgb) {
  const ColorManagement color("", "");
  EXPECT_EQ(color.display(), "sRGB");
  EXPECT_EQ(color.view(), "Standard");
  std::vector<float> px{0.214f, 0.5f, 1.0f, 0.7f};
  color.apply_display(px, 1, 1);
  EXPECT_NEAR(px[0], 0.5, 2e-3);
  EXPECT_NEAR(px[1], 0.7354, 2e-3);
  EXPECT_NEAR(px[2], 1.0, 2e-4);
  EXPECT_FLOAT_EQ(px[3], 0.7f);  // alpha untouched
}

// The default view's sRGB encoding goes through tables; the picture is
// OCIO's own to a tenth of a 16-bit level, highlights beyond 1 included
// (those are OCIO's).
TEST_F(Color, SrgbDisplayThroughTablesIsOciosOwn) {
  std::istringstream text(builtin_ocio_config());
  const auto config = OCIO_NAMESPACE::Config::CreateFromStream(text);
  const auto processor = config->getProcessor(OCIO_NAMESPACE::ROLE_SCENE_LINEAR, "srgb")->getDefaultCPUProcessor();
  const std::optional<ChannelTables> tables = ChannelTables::of(processor);
  ASSERT_TRUE(tables);
  const ColorManagement color("", "");
  std::vector<float> pixels, reference;
  std::uint32_t state = 12345;
  const auto next = [&] { return float((state = state * 1664525u + 1013904223u) >> 8) / float(1 << 24); };
  for (int i = 0; i < 20000; ++i) {
    const float scale = i % 10 == 0 ? 1.5f : (i % 3 == 0 ? 0.01f : 1.0f);  // dark values, highlights
    pixels.insert(pixels.end(), {scale * next(), scale * next(), scale * next(), next()});
  }
  reference = pixels;
  color.apply_display(pixels, 100, 200);
  OCIO_NAMESPACE::PackedImageDesc image(reference.data(), 100, 200, 4);
  processor->apply(image);
  float worst = 0.0f;
  for (std::size_t i = 0; i < pixels.size(); ++i) worst = std::max(worst, std::abs(pixels[i] - reference[i]));
  EXPECT_LE(worst, ChannelTables::kTolerance);
  float rgb[3] = {1.2f, 0.5f, 0.5f};
  EXPECT_FALSE(tables->apply(rgb));
  EXPECT_EQ(rgb[0], 1.2f);  // left for OCIO
}

// Tables only where they are the transform: not for a view that mixes
// channels (Filmic's ACES output), nor for an encoding whose foot is too
// steep for them (a logarithm).
TEST_F(Color, NoTablesForCrosstalkOrASteepFoot) {
  std::istringstream text(builtin_ocio_config());
  const auto config = OCIO_NAMESPACE::Config::CreateFromStream(text);
  auto filmic = OCIO_NAMESPACE::DisplayViewTransform::Create();
  filmic->setSrc(OCIO_NAMESPACE::ROLE_SCENE_LINEAR);
  filmic->setDisplay("sRGB");
  filmic->setView("Filmic");
  EXPECT_FALSE(ChannelTables::of(config->getProcessor(filmic)->getDefaultCPUProcessor()));
  auto log = OCIO_NAMESPACE::LogAffineTransform::Create();
  log->setBase(2.0);
  log->setLinSideOffsetValue({1e-4, 1e-4, 1e-4});
  log->setLogSideSlopeValue({0.07, 0.07, 0.07});
  log->setLogSideOffsetValue({0.95, 0.95, 0.95});
  EXPECT_FALSE(ChannelTables::of(config->getProcessor(log)->getDefaultCPUProcessor()));
}

// The built-in config with Raw as the sRGB display's first (default) view,
// written to a file.
std::string raw_first_config() {
  std::string text = builtin_ocio_config();
  const std::string raw = "    - !<View> {name: Raw, colorspace: raw}\n";
  const std::string standard = "    - !<View> {name: Standard, colorspace: srgb}\n";
  text.erase(text.find(raw), raw.size());
  text.insert(text.find(standard), raw);
  const std::string views = "active_views: [Standard, Filmic, Raw]";
  text.replace(text.find(views), views.size(), "active_views: [Raw, Standard, Filmic]");
  const std::string path = (test_temp_dir("color_test") / "raw_first.ocio").string();
  std::ofstream(path) << text;
  return path;
}

TEST_F(Color, OcioEnvironmentVariableSelectsAnotherConfig) {
  const std::string path = raw_first_config();
  setenv("OCIO", path.c_str(), 1);
  const ColorManagement color("", "");
  unsetenv("OCIO");
  EXPECT_EQ(color.view(), "Raw");
  EXPECT_EQ(color.config_name(), path);
  std::vector<float> px{0.214f, 0.5f, 1.0f, 1.0f};
  color.apply_display(px, 1, 1);
  EXPECT_FLOAT_EQ(px[0], 0.214f);  // Raw passes scene-linear values through
}

TEST_F(Color, AConfigFileWinsOverOcio) {
  setenv("OCIO", "/nonexistent/config.ocio", 1);
  const ColorManagement color("", "", raw_first_config());
  unsetenv("OCIO");
  EXPECT_EQ(color.view(), "Raw");
}

// $OCIO naming a FIFO: OCIO would open it and wait for a writer for ever,
// and every render of a batch with it. Refused at once, named. (Should
// it wait, a writer comes after a few seconds to release it, and the test
// fails.)
TEST_F(Color, AnOcioThatIsAFifoIsRefusedAtOnce) {
  const std::filesystem::path fifo = test_temp_dir("color_test") / "fifo.ocio";
  std::filesystem::remove(fifo);
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  setenv("OCIO", fifo.c_str(), 1);
  const std::string error = without_waiting(fifo, [] {
    try {
      const ColorManagement color("", "");
    } catch (const std::exception& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  });
  unsetenv("OCIO");
  EXPECT_EQ(error, "$OCIO names " + fifo.string() + ": not a regular file (a FIFO, socket or device)");
}

TEST_F(Color, AFlatColourMakesTheRoundTripExactly) {
  // A colormap colour picked in display sRGB, lit by light of 1, reaches
  // the display as it was defined: what the colour bar promises.
  const ColorManagement color("", "");
  for (const Rgb& picked : {Rgb{0.267f, 0.005f, 0.329f}, Rgb{0.5f, 0.5f, 0.5f}, Rgb{0.993f, 0.906f, 0.144f}}) {
    const Rgb linear = color.to_scene_linear(picked);
    std::vector<float> px{linear[0], linear[1], linear[2], 1.0f};
    color.apply_display(px, 1, 1);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(px[std::size_t(c)], picked[std::size_t(c)], 1e-4);
  }
}

TEST_F(Color, FilmicViewRollsHighlightsOffInsteadOfClipping) {
  const ColorManagement filmic("sRGB", "Filmic");
  std::vector<float> px;
  for (float v : {0.0f, 0.02f, 0.18f, 1.0f, 4.0f, 16.0f}) px.insert(px.end(), {v, v, v, 1.0f});
  filmic.apply_display(px, 6, 1);
  for (std::size_t i = 1; i < 6; ++i) EXPECT_GT(px[4 * i], px[4 * (i - 1)]) << "monotonic";
  EXPECT_NEAR(px[0], 0.0f, 0.01f);
  EXPECT_GT(px[4 * 2], 0.3f);   // middle grey stays a middle grey
  EXPECT_LT(px[4 * 2], 0.6f);
  EXPECT_LT(px[4 * 3], 0.95f);  // white light is not yet clipped ...
  EXPECT_LT(px[4 * 5], 1.0f);   // ... and four stops above it still is not
  EXPECT_NEAR(px[4 * 3 + 1], px[4 * 3], 1e-3);  // grey stays grey
}

TEST_F(Color, UnknownViewIsAnError) { EXPECT_ANY_THROW(ColorManagement("sRGB", "NoSuchView")); }

// Direction colour: x red, y green, z blue whatever the eigenvector's
// sign, a diagonal their mix, faded to the uncoloured grey as the weight
// (FA) falls.
TEST_F(Color, DirectionColourIsTheAxisFadedToGrey) {
  const Rgb x = direction_srgb(Vec3::UnitX(), 1.0), minus_y = direction_srgb(-Vec3::UnitY(), 1.0);
  EXPECT_EQ(x, (Rgb{1.0f, 0.0f, 0.0f}));
  EXPECT_EQ(minus_y, (Rgb{0.0f, 1.0f, 0.0f}));
  const Rgb diagonal = direction_srgb(Vec3(1, 0, -1).normalized(), 1.0);
  EXPECT_FLOAT_EQ(diagonal[0], diagonal[2]);
  EXPECT_EQ(diagonal[1], 0.0f);
  const Rgb none = direction_srgb(Vec3::UnitZ(), 0.0), half = direction_srgb(Vec3::UnitZ(), 0.5);
  EXPECT_FLOAT_EQ(none[0], none[2]);  // grey: no hue
  EXPECT_GT(half[2], half[0]);
  EXPECT_LT(half[2], 1.0f);
  EXPECT_EQ(direction_srgb(Vec3::UnitZ(), 7.0), direction_srgb(Vec3::UnitZ(), 1.0));  // the weight is clamped
}

TEST_F(Color, ColormapEndsAndInterpolation) {
  const Colormap& v = colormap_named("viridis");
  // The ends are #440154 and #fde725 to the byte.
  EXPECT_NEAR(v.at(0.0)[0], 68 / 255.0, 0.5 / 255.0);
  EXPECT_NEAR(v.at(1.0)[1], 231 / 255.0, 0.5 / 255.0);
  EXPECT_EQ(v.at(-3.0), v.at(0.0));
  EXPECT_EQ(v.at(7.0), v.at(1.0));
  EXPECT_EQ(v.at(std::nan("")), v.at(0.0));
  const Colormap& c = colormap_named("coolwarm");
  const Rgb mid = c.at(0.5);
  EXPECT_NEAR(mid[0], mid[2], 1e-6);  // neutral at zero
  EXPECT_THROW(colormap_named("jet"), std::invalid_argument);
}

TEST_F(Color, EveryMapHasAReversedTwin) {
  for (const char* name : {"viridis", "cividis", "magma", "coolwarm", "RdBu"}) {
    const Colormap& map = colormap_named(name);
    const Colormap& reversed = colormap_named(std::string(name) + "_r");
    EXPECT_EQ(reversed.diverging, map.diverging) << name;
    for (double u : {0.0, 0.13, 0.5, 0.77, 1.0})
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(reversed.at(u)[std::size_t(c)], map.at(1.0 - u)[std::size_t(c)], 1e-6) << name << " at " << u;
  }
}

TEST_F(Color, AutoRangeIgnoresSingularOutliersAndCentresDivergingMaps) {
  std::vector<double> values;
  for (int i = 0; i < 1000; ++i) values.push_back(-1.0 + i / 1000.0);  // [−1, 0)
  values.push_back(-1e6);  // a singular point's value
  const ColorScale seq = auto_scale(colormap_named("viridis"), values, false, false);
  EXPECT_GT(seq.lo, -5.0);  // the fence: q2 − 3 × the bulk's reach
  EXPECT_LT(seq.lo, -1.0);
  EXPECT_LT(seq.hi, 0.0);
  EXPECT_TRUE(seq.clipped_low());
  EXPECT_FALSE(seq.clipped_high());
  EXPECT_DOUBLE_EQ(seq.data_lo, -1e6);
  const ColorScale div = auto_scale(colormap_named("coolwarm"), values, true, false);
  EXPECT_DOUBLE_EQ(div.lo, -div.hi);
  EXPECT_NEAR(div.normalized(0.0), 0.5, 1e-12);
  const ColorScale flat = auto_scale(colormap_named("viridis"), {2.0, 2.0}, false, false);
  EXPECT_LT(flat.lo, flat.hi);
}

// A hole's stress concentration (3σ, a few glyphs among many near σ) is
// what the picture is for: it keeps its own colour, unclipped.
TEST_F(Color, AutoRangeKeepsAStressConcentration) {
  std::vector<double> values;
  for (int i = 0; i < 1000; ++i) values.push_back(9.0 + 2.0 * i / 1000.0);  // σ ≈ 10
  for (double peak : {30.0, 27.0, 24.0}) values.push_back(peak);
  const ColorScale scale = auto_scale(colormap_named("viridis"), values, false, false);
  EXPECT_DOUBLE_EQ(scale.hi, 30.0);
  EXPECT_FALSE(scale.clipped_high());
  EXPECT_DOUBLE_EQ(scale.lo, 9.0);
}

// A disc split by +25 of tension under −970 of compression: one fence
// for both sides painted the tension white. Sides more than kSidesApart
// times apart keep their own fences, and a diverging map centred on zero
// spreads each over its half; sides alike stay one symmetric range.
TEST_F(Color, SidesFarApartKeepTheirOwnRangesCentredOnZero) {
  std::vector<double> values;
  for (int i = 0; i < 500; ++i) values.push_back(25.0 * (i + 1) / 500.0);   // (0, 25]
  for (int i = 0; i < 500; ++i) values.push_back(-970.0 * (i + 1) / 500.0);  // [−970, 0)
  const Colormap& coolwarm = colormap_named("coolwarm");
  const ColorScale apart = auto_scale(coolwarm, values, true, false);
  EXPECT_DOUBLE_EQ(apart.lo, -970.0);
  EXPECT_DOUBLE_EQ(apart.hi, 25.0);
  ASSERT_TRUE(apart.centred_on_zero());
  EXPECT_DOUBLE_EQ(apart.normalized(0.0), 0.5);
  EXPECT_DOUBLE_EQ(apart.normalized(25.0), 1.0);
  EXPECT_DOUBLE_EQ(apart.normalized(12.5), 0.75);  // the tension's own half of the map
  EXPECT_DOUBLE_EQ(apart.normalized(-970.0), 0.0);
  EXPECT_DOUBLE_EQ(apart.normalized(-485.0), 0.25);
  // Within kSidesApart: one symmetric range, as before (normalized to the
  // bit of the linear formula).
  for (double& v : values)
    if (v > 0.0) v *= 20.0;  // (0, 500]
  const ColorScale alike = auto_scale(coolwarm, values, true, false);
  EXPECT_DOUBLE_EQ(alike.lo, -970.0);
  EXPECT_DOUBLE_EQ(alike.hi, 970.0);
  EXPECT_EQ(alike.normalized(123.0), (123.0 - alike.lo) / (alike.hi - alike.lo));
  // A sequential map is never centred; nor a range that does not cross zero.
  EXPECT_FALSE((ColorScale{&colormap_named("viridis"), -970.0, 25.0}).centred_on_zero());
  EXPECT_FALSE((ColorScale{&coolwarm, 1.0, 25.0}).centred_on_zero());
}

TEST_F(Color, SignedValuesAreBothSignsOnlyBeyondAHundredthOfTheLargest) {
  EXPECT_TRUE(both_signs({-5.0, 3.0, 1.0}));
  EXPECT_FALSE(both_signs({-5.0, 0.0, 0.01}));  // round-off above zero: one-signed
  EXPECT_FALSE(both_signs({1.0, 2.0}));
  EXPECT_FALSE(both_signs({}));
}

}  // namespace
}  // namespace hsb
