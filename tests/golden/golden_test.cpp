// Golden-image tests: small renders of canonical scenes against reviewed
// images (see tests/golden/README.md for tolerances and regeneration).

#include <gtest/gtest.h>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <cstdlib>
#include <filesystem>

#include "renderer/app/render_job.h"

namespace hsb {
namespace {

namespace fs = std::filesystem;

const fs::path golden_dir = fs::path(HSB_SOURCE_DIR) / "tests" / "golden";
const fs::path output_dir = fs::path(HSB_BINARY_DIR) / "tests" / "golden";

constexpr float pixel_threshold = 0.01f;  // any channel, display-referred [0, 1]
constexpr double max_failing_fraction = 0.001;
constexpr double max_mean_error = 0.001;

class Golden : public ::testing::TestWithParam<std::string> {};

TEST_P(Golden, MatchesReviewedImage) {
  const std::string name = GetParam();
  const RenderSummary summary =
      run_render_job({(golden_dir / "scenes" / (name + ".toml")).string(), {}, output_dir.string()});
  const fs::path reference = golden_dir / (name + ".png");

  if (std::getenv("HSB_UPDATE_GOLDEN")) {
    fs::copy_file(summary.image_path, reference, fs::copy_options::overwrite_existing);
    GTEST_SKIP() << "updated " << reference;
  }
  ASSERT_TRUE(fs::exists(reference)) << reference << " is missing; run scripts/update-golden.sh";

  OIIO::ImageBuf rendered(summary.image_path), golden(reference.string());
  ASSERT_TRUE(rendered.read() && golden.read()) << rendered.geterror() << golden.geterror();
  ASSERT_EQ(rendered.spec().width, golden.spec().width);
  ASSERT_EQ(rendered.spec().height, golden.spec().height);
  const auto result = OIIO::ImageBufAlgo::compare(rendered, golden, pixel_threshold, pixel_threshold / 4);
  const double pixels = double(golden.spec().width) * golden.spec().height;
  const double failing = double(result.nfail) / pixels;

  if (failing > max_failing_fraction || result.meanerror > max_mean_error) {
    OIIO::ImageBuf diff = OIIO::ImageBufAlgo::absdiff(rendered, golden);
    diff = OIIO::ImageBufAlgo::mul(diff, 10.0f);
    const fs::path diff_path = output_dir / (name + ".diff.png");
    diff.write(diff_path.string());
    ADD_FAILURE() << name << ": " << result.nfail << " pixels (" << failing * 100
                  << "%) differ by more than " << pixel_threshold << ", mean error " << result.meanerror
                  << ", max " << result.maxerror << "; new render " << summary.image_path
                  << ", difference " << diff_path;
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, Golden,
                         ::testing::Values("ellipsoids_at_seeds", "hyperstreamlines_quartic",
                                           "union_of_ellipsoids", "cylinder_hyperstreamlines",
                                           "streamballs_double_glazing", "panels_along_a_curve",
                                           "signed_hyperstreamlines", "signed_beads", "diffusion_glyph_field"),
                         [](const ::testing::TestParamInfo<std::string>& param) { return param.param; });

}  // namespace
}  // namespace hsb
