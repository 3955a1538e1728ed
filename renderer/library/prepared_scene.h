#pragma once
// A scene file turned into what the renderer (or an exporter) needs: the
// field side run, and every value the scene left automatic resolved, in
// one place and in one pass, before any Embree scene is built.

#include <string>
#include <vector>

#include "field/glyph_pipeline.h"
#include "renderer/image/color_management.h"
#include "renderer/image/colormap.h"
#include "renderer/image/legend.h"
#include "renderer/render/ray_scene.h"
#include "renderer/scene/scene_spec.h"
#include "renderer/scene/toml_text.h"
#include "renderer/surface/blob_field.h"

namespace hsb {

// The output side, resolved.
struct OutputSettings {
  std::string file;  // relative to the output folder
  int bit_depth = 8;  // PNG/TIFF: 8 or 16; EXR: 16 (half) or 32 (float)
  double dpi = 300.0;
  std::optional<LegendLayout> legend;  // none: no colour bar and no shape key

  // Whether the picture is written as it is rendered, a band of rows at a
  // time (raster_stream.h), and never held whole: a PNG or TIFF with
  // nothing drawn over it.
  bool streams() const;
};

struct PreparedScene {
  SceneSpec spec;        // as the scene file says, automatic values unresolved
  GlyphScene glyphs;     // with the field side's resolved values (glyphs.values)
  ColorScale scale;
  BlobField field;
  ShadingSpec shading;   // colours converted to scene-linear
  DrawnContext context;  // points into glyphs.boundary
  CameraSpec camera;
  RenderSettings render;
  TraceSettings trace;
  OutputSettings output;
  // What prepare_scene() chose for each automatic key that applies, by
  // key path (the keys the scene gives are here too, as given): `hsb info`
  // pins those the scene left out.
  toml::table resolved;
  // About the data and the picture: the image is still made.
  std::vector<std::string> warnings;
  // The peak resident memory the render will take, checked against the
  // machine's limits before the render allocates it.
  double memory_estimate = 0.0;

  // Records `value` as what automatic `key` resolved to; returns it.
  template <class V>
  V resolve(std::string_view key, V value) {
    assign_at_path(resolved, key, value);
    return value;
  }

  PreparedScene() = default;
  PreparedScene(const PreparedScene&) = delete;  // context points into glyphs
  PreparedScene& operator=(const PreparedScene&) = delete;
  PreparedScene(PreparedScene&&) = delete;
};

// The image's file name, relative to the output folder: output.file, else
// the scene's (or data file's) name with .png.
std::string output_file_name(const SceneSpec& spec);

// The picture's pixels: render.width and height, else output.print_size
// at output.dpi, else 800 × 800.
std::array<int, 2> picture_size(const SceneSpec& spec);

// The colour bar of `p`'s scale in a width × height picture, as its
// [output] asks (placement, length, font size, title).
LegendLayout legend_for(const PreparedScene& p, int width, int height);

// Whether the legend shows the shape key: output.shape_key, automatic for
// signed glyphs.
bool wants_shape_key(const SceneSpec& spec);

// Colours `p`'s glyphs by `scale` instead (panels that share a colour bar).
void set_color_scale(PreparedScene& p, const ColorScale& scale, const ColorManagement& color);

// The colour management the scene's [output] asks for: its OCIO config
// (else $OCIO, else the built-in one), display and view. Throws SceneError
// naming the scene when the config cannot be read or has no such display
// or view.
ColorManagement scene_color_management(const SceneSpec& spec);

// `color` is the colour management for spec.output's display and view.
// Throws DataError for unusable data and SceneError for a scene that cannot
// be rendered (a camera that cannot be built).
std::unique_ptr<PreparedScene> prepare_scene(SceneSpec spec, const ColorManagement& color);

// An isolated glyph's largest semi-axis for a largest radius of 1: the
// influence radius R times the kernel's level radius at the isovalue.
double glyph_extent(const SurfaceSpec& surface);

}  // namespace hsb
