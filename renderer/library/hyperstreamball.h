#pragma once
// Hyperstreamball as a library: the four calls a front end makes (the
// command line, the Python module, a viewer), on plain structs.
//
//   hsb::SceneSpec spec = hsb::load("scenes/fig09_point_load_hyperstreamsurface.toml", {"glyphs.spacing=0.02"});
//   const std::unique_ptr<hsb::Prepared> prepared = hsb::prepare(std::move(spec));
//   const hsb::Picture picture = hsb::render(*prepared);
//   hsb::write(picture, *prepared, "out/fig09.png");
//
// Data a program already holds goes in as arrays: set
// spec.pipeline.data.file.arrays (field/reading/data_arrays.h) before
// prepare(). A render is cancelled through RenderControl::cancel, from
// any thread; it then throws RenderCancelled, and `prepared` can render
// again.

#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "renderer/library/prepared_scene.h"
#include "renderer/render/render_image.h"
#include "renderer/scene/scene_spec.h"

namespace hsb {

// A scene file, or a data file as the scene that names only it, with
// --set style overrides ("key.path=value"). Throws SceneError naming
// file:line:column and the key.
SceneSpec load(const std::string& path, const std::vector<std::string>& overrides = {});

// Scene text not in a file: `name` names it in errors and output files;
// relative paths in it are relative to `base_dir`.
SceneSpec load_text(const std::string& text, const std::string& name, const std::string& base_dir = ".",
                    const std::vector<std::string>& overrides = {});

// A scene with its data read, traced and resolved, and the colour
// management its [output] asks for, which the picture goes through.
struct Prepared {
  ColorManagement color;
  std::unique_ptr<PreparedScene> scene;
};

// Throws DataError for unusable data and SceneError for a scene that
// cannot be rendered.
std::unique_ptr<Prepared> prepare(SceneSpec spec);

struct RenderControl {
  // Polled per 4×4 tile: set, render() throws RenderCancelled within
  // milliseconds (tests/bench/cancel_bench).
  const std::atomic<bool>* cancel = nullptr;
  // The fraction of the picture made, after each band of rows.
  std::function<void(double)> progress;
  // Set: the picture is handed here a band of rows at a time as it is
  // made, and never held whole (a large PNG or TIFF written as it renders:
  // renderer/image/raster_stream.h); the Picture's film keeps the last band.
  std::function<void(const Film& film, int first, int last)> rows_done;
};

// A rendered picture: the film, scene-linear, and what was traced.
struct Picture {
  RenderOutput rendered;
  std::vector<std::string> warnings;  // the scene's, and the picture's own (no glyph in view, rays not traced)
};

Picture render(const Prepared& prepared, const RenderControl& control = {});
// The same for a prepared scene whose colour management is held apart
// (the panels of a figure share one): the render needs none.
Picture render(const PreparedScene& prepared, const RenderControl& control = {});

// The picture display-referred, premultiplied RGBA, as its file shows it
// before the colour bar is drawn: what a viewer puts on screen.
std::vector<float> display_rgba(const Picture& picture, const Prepared& prepared);

// Writes `picture` to `path` in the format its extension names (PNG,
// TIFF, PDF, SVG display-referred with the colour bar drawn, EXR
// scene-linear), with the scene and its resolved values in its metadata.
// Written under a temporary name and renamed when complete.
// The picture's film is spent on it (its display copy takes its place).
void write(Picture picture, const Prepared& prepared, const std::string& path);

}  // namespace hsb
