// hsb's superquadric against Teem's own (tests/renderer/teem/make_masks.sh:
// `tend glyph -rt -g sqd -sh 3` on diag(1, 0.5, 0.2), 256 × 256): one
// isolated glyph traced through the same pixel centres, along the same
// parallel rays, must cover the same pixels within one pixel of the edge.
// Teem's echo decides a hit by the exact implicit function, so a pixel may
// differ only where the silhouette passes within round-off of its centre.

#include <gtest/gtest.h>

#include <OpenImageIO/imagebuf.h>

#include <cstdio>
#include <string>
#include <vector>

#include "renderer/render/ray_scene.h"
#include "renderer/surface/blob_geometry.h"
#include "renderer/surface/field_ray.h"

namespace hsb {
namespace {

constexpr int kSize = 256;
constexpr double kHalfWindow = 1.2;

// The mask as hits (true where Teem's alpha is over one half), row j down.
std::vector<bool> teem_mask(const std::string& name) {
  OIIO::ImageBuf image(std::string(HSB_SOURCE_DIR) + "/tests/renderer/teem/" + name + ".png");
  EXPECT_TRUE(image.read()) << name;
  EXPECT_EQ(image.spec().width, kSize);
  EXPECT_EQ(image.spec().height, kSize);
  std::vector<bool> hits(kSize * kSize);
  for (int j = 0; j < kSize; ++j)
    for (int i = 0; i < kSize; ++i) hits[j * kSize + i] = image.getchannel(i, j, 0, 0) > 0.5f;
  return hits;
}

// The glyph Teem draws: half-axes (1, 0.5, 0.2) along x, y, z; the source's
// radii are those over the kernel's level radius, so that the isolated
// glyph's level surface has exactly those half-axes.
BlobField teem_glyph() {
  GlyphSource g;
  g.radii = Vec3(1.0, 0.5, 0.2) / kernel_level_radius(KernelKind::wyvill, 0.5);
  g.eigenvalues = g.radii;
  return make_blob_field({g}, {{1.0f, 1.0f, 1.0f}}, 1.0, KernelKind::wyvill, Blend::sum, 0.5,
                         GlyphShape::superquadric, 3.0);
}

// hsb's hits at Teem's pixel centres: pixel (i, j) is the point
// (a, b) = (u_i, -v_j) of the plane the view looks down onto, the ray
// parallel to `down`.
std::vector<bool> hsb_mask(const BlobField& field, int a_axis, int b_axis, int down_axis) {
  const EmbreeDevice device;
  TraceSettings settings;
  settings.min_step = 1e-9;
  const BlobGeometry blobs(device.get(), field, settings);
  std::vector<bool> hits(kSize * kSize);
  for (int j = 0; j < kSize; ++j)
    for (int i = 0; i < kSize; ++i) {
      const double u = -kHalfWindow + (i + 0.5) * 2 * kHalfWindow / kSize;
      const double v = -kHalfWindow + (j + 0.5) * 2 * kHalfWindow / kSize;
      Vec3 origin = Vec3::Zero(), direction = Vec3::Zero();
      origin[a_axis] = u, origin[b_axis] = -v, origin[down_axis] = 10.0;
      direction[down_axis] = -1.0;
      FieldRay ray;
      TraceStats stats;
      const RayInterval whole{origin, direction, 0.0, 20.0};
      blobs.collect_spans(&whole, 1, &ray);
      hits[j * kSize + i] =
          !ray.spans.empty() && ray.first_crossing(field, origin, direction, 0.0, 20.0, settings, stats) >= 0.0;
    }
  return hits;
}

// Pixels where the masks differ, and how many of them lie off Teem's edge
// (no pixel of the other kind among the eight around it).
void compare(const std::vector<bool>& teem, const std::vector<bool>& hsb, int& differ, int& off_edge, int& covered) {
  differ = off_edge = covered = 0;
  for (int j = 0; j < kSize; ++j)
    for (int i = 0; i < kSize; ++i) {
      covered += teem[j * kSize + i];
      if (teem[j * kSize + i] == hsb[j * kSize + i]) continue;
      ++differ;
      bool edge = false;
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di) {
          const int x = i + di, y = j + dj;
          if (x >= 0 && y >= 0 && x < kSize && y < kSize && teem[y * kSize + x] != teem[j * kSize + i]) edge = true;
        }
      off_edge += !edge;
    }
}

TEST(TeemSilhouette, SuperquadricCoversTeemsPixels) {
  const BlobField field = teem_glyph();
  struct View {
    const char* mask;
    int a, b, down;
  };
  for (const View& view : {View{"sqd_down_z", 0, 1, 2}, View{"sqd_down_x", 1, 2, 0}}) {
    SCOPED_TRACE(view.mask);
    int differ, off_edge, covered;
    compare(teem_mask(view.mask), hsb_mask(field, view.a, view.b, view.down), differ, off_edge, covered);
    std::printf("%s: %d of Teem's %d glyph pixels differ, %d of them off its edge\n", view.mask, differ, covered, off_edge);
    EXPECT_GT(covered, 4000);  // the mask is the glyph, not an empty picture
    EXPECT_EQ(off_edge, 0);
    EXPECT_LE(differ, covered / 1000) << "of " << covered << " glyph pixels";
  }
}

}  // namespace
}  // namespace hsb
