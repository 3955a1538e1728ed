#pragma once
// Everything a scene file says, validated. A key the file leaves out that
// has a fixed default gets the schema's (scene_keys.h; the initializers
// below are the defaults of the C++ structs alone); a key whose value
// depends on the data (a length, a colour range, the camera) is
// std::nullopt, "automatic", and is resolved with every other automatic
// value in prepare_scene(), once the data is read.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "field/glyph_pipeline.h"
#include "renderer/image/legend.h"
#include "renderer/render/camera_framing.h"
#include "renderer/render/render_image.h"
#include "renderer/render/shading.h"
#include "renderer/scene/scene_error.h"
#include "renderer/surface/blob_field.h"
#include "renderer/surface/field_ray.h"

namespace hsb {

struct SurfaceSpec {
  KernelKind kernel = KernelKind::wyvill;
  Blend blend = Blend::sum;
  double influence_radius = 1.0;  // R of eq. 10/11, fixed for all sources
  double isovalue = 0.5;          // C
  // Read from [glyphs]: each glyph's form, and a superquadric's sharpness γ.
  // Automatic (shape_given false): the ellipsoid, or the superquadric for
  // a diffusion volume's glyphs at its points.
  GlyphShape shape = GlyphShape::ellipsoid;
  bool shape_given = false;
  double sharpness = 3.0;
};

struct ColorSpec {
  // Automatic: "coolwarm" for values of both signs (tension and
  // compression), centred on zero; "viridis" for one-signed values.
  std::optional<std::string> map;
  std::optional<std::array<double, 2>> range;  // automatic: from the sources, or a bounded measure's own
  std::optional<bool> symmetric;               // automatic: for a diverging map
  bool log = false;                            // by the logarithm of the scalar
};

// What is drawn around the glyphs. Automatic: a box frames an analytic
// domain, a shell shows a mesh's boundary, the box's edges are D/500 thick,
// trajectory tubes a fifth of the median glyph, the ground just below the
// lowest thing drawn.
struct ContextSpec {
  bool glyphs = true;
  std::optional<bool> box, shell;
  std::optional<double> box_radius;
  bool trajectories = false;
  std::optional<double> trajectory_radius;
  bool ground = false;
  std::optional<double> ground_height;
};

// The lights' lengths in the data's units. Automatic: ambient occlusion
// reaches four median glyphs.
struct LightLengths {
  std::optional<double> ao_distance;
};

// The [render] table's image and tracing keys.
struct RenderSpec {
  // Automatic: output.print_size at output.dpi, or 800 × 800.
  std::optional<int> width, height;
  int samples = 2;
  std::optional<double> shadow_offset;     // in the data's units; automatic: D·1e-5
  std::optional<Intersector> intersector;  // automatic: exact where it applies
  std::optional<double> min_step;          // the sphere tracer's, in the data's units; automatic: D·1e-6
  int max_steps = 200000;
};

struct OutputSpec {
  std::optional<std::string> file;  // relative to the output folder; automatic: <scene stem>.png
  std::optional<int> bit_depth;     // automatic: 8 for PNG and TIFF, 32 (float) for EXR
  std::vector<Plane> layers{Plane::depth, Plane::normal, Plane::scalar, Plane::id};  // an EXR's, besides RGBA
  double dpi = 300.0;
  std::optional<std::array<double, 2>> print_size;  // millimetres
  std::string ocio_config;                    // an OCIO config file; empty: $OCIO, else the built-in one
  std::optional<std::string> display, view;  // OCIO; automatic: the config's defaults
  bool colorbar = true;
  LegendPlacement colorbar_position = LegendPlacement::right;
  double colorbar_length = 0.6;
  double font_size = 7.0;  // points
  std::optional<std::string> colorbar_title;  // automatic: named after glyphs.color_by
  std::optional<bool> shape_key;              // automatic: for glyphs.shape = "signed"
};

// A figure of several panels: the scene once per [[panel]], each with the
// panel's keys over the scene's, laid out in a grid and labelled.
struct PanelSpec {
  std::string label;                   // after its letter: "(a) 4 sources"
  std::vector<std::string> overrides;  // "key.path=value", as --set
  int line = 0;                        // of its [[panel]] header, for errors
};

struct FigureSpec {
  std::optional<int> columns;  // automatic: as near a square as the picture allows
  bool labels = true;          // (a), (b), … at each panel's top left
  std::string caption;         // under the panels; "" for none
};

struct SceneSpec {
  std::string path;  // the scene file, as given (or the data file a scene was made for)
  std::string base_dir;  // relative paths in it are relative to this
  std::string text;  // the scene's TOML text
  std::vector<std::string> overrides;  // --set key=value
  GlyphPipelineSpec pipeline;
  SurfaceSpec surface;
  ColorSpec color;
  CameraRequest camera;
  ShadingSpec shading;  // light and colours, display-referred; its lengths are in `light`
  LightLengths light;
  ContextSpec context;
  RenderSpec render;
  OutputSpec output;
  FigureSpec figure;
  std::vector<PanelSpec> panels;  // none: a single picture
};

// Reads and validates a scene file. `overrides` are "key.path=value" strings
// (hsb --set); each value is parsed as a TOML value, or taken as a string
// when it is not one. Throws SceneError naming file:line:column and the key.
SceneSpec load_scene(const std::string& path, const std::vector<std::string>& overrides = {});

// The same for scene text that is not in a file: `path` names it in errors
// and output files, relative paths in it are relative to `base_dir`.
SceneSpec load_scene_text(const std::string& text, const std::string& path, const std::string& base_dir,
                          const std::vector<std::string>& overrides = {});

// The scene's TOML as read, with its overrides applied (for printing it
// back with automatic values filled in).
toml::table scene_table(const SceneSpec& spec);

// Refuses a length in the data's units (a key whose schema unit is "data
// length") that the scene gives outside kSmallestLengthPerDiagonal to
// kLargestLengthPerDiagonal times the data's diagonal: a SceneError at the
// key's line, the allowed range in the data's own units.
void check_data_lengths(const SceneSpec& spec, double diagonal);

// True for a path that names data of a format hsb knows (by extension, else
// by content; field/reading/data_formats.h), read or not: `hsb` makes it a scene
// naming only that file, which says so when hsb does not read the format.
bool is_data_file(const std::string& path);
// That scene: its one key is data.file.
SceneSpec scene_for_data_file(const std::string& path, const std::vector<std::string>& overrides = {});
// A scene file, or a data file as that scene.
SceneSpec load_scene_or_data_file(const std::string& path, const std::vector<std::string>& overrides = {});

}  // namespace hsb
