#pragma once
// Everything a scene file says, validated, with every default filled in.
// scenes/README.md documents each key; keep the two in step.

#include <array>
#include <optional>
#include <string>

#include "field/glyph_pipeline.h"
#include "renderer/scene/scene_error.h"
#include "renderer/render/camera.h"
#include "renderer/render/render_image.h"
#include "renderer/render/shading.h"
#include "renderer/surface/blob_field.h"
#include "renderer/surface/field_ray.h"

namespace hsb {

struct SurfaceSpec {
  KernelKind kernel = KernelKind::wyvill;
  Blend blend = Blend::sum;
  double influence_radius = 1.0;  // R of eq. 10/11, fixed for all sources
  double isovalue = 0.5;          // C
};

struct ColorSpec {
  std::string map = "viridis";
  std::optional<std::array<double, 2>> range;  // nullopt: from the sources
};

struct OutputSpec {
  std::string file;       // relative to the output folder; default <scene stem>.png
  int bit_depth = 8;      // PNG/TIFF
  std::string display;    // OCIO display; "" = the config's default
  std::string view;       // OCIO view; "" = the display's default
  bool colorbar = true;
  std::string colorbar_title;  // "" = named after glyphs.color_by
};

struct SceneSpec {
  std::string path;  // the scene file, as given
  GlyphPipelineSpec pipeline;
  SurfaceSpec surface;
  ColorSpec color;
  CameraSpec camera;  // position and look_at are filled in by resolve_camera()
  std::optional<Vec3> camera_position, camera_look_at;  // nullopt: framed on the data
  ShadingSpec shading;  // background and box colours still in display terms
  RenderSettings render;
  Intersector intersector = Intersector::sphere;
  double min_step = 1e-6;  // sphere tracer's smallest step, × domain diagonal
  int max_steps = 200000;
  OutputSpec output;
};

// Reads and validates a scene file. `overrides` are "key.path=value" strings
// (hsb --set); each value is parsed as a TOML value, or taken as a string
// when it is not one. Throws SceneError naming file:line:column and the key.
SceneSpec load_scene(const std::string& path, const std::vector<std::string>& overrides = {});

// The camera, with position and look_at defaulting to a view of `domain`
// from the front-right, above (the domain is known only once data is read).
CameraSpec resolve_camera(const SceneSpec& spec, const Box3& domain);

// The scene's text plus overrides, for the hash written into images.
std::string scene_fingerprint_text(const std::string& path, const std::vector<std::string>& overrides);

}  // namespace hsb
