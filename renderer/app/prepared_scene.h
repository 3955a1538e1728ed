#pragma once
// A scene file turned into what the renderer (or an exporter) needs: the
// field side run, colours mapped and colour-managed, the camera framed.

#include <string>
#include <vector>

#include "field/glyph_pipeline.h"
#include "renderer/image/color_management.h"
#include "renderer/image/colormap.h"
#include "renderer/scene/scene_spec.h"
#include "renderer/surface/blob_field.h"

namespace hsb {

struct PreparedScene {
  SceneSpec spec;
  GlyphScene glyphs;
  ColorScale scale;
  BlobField field;
  ShadingSpec shading;  // colours converted to scene-linear
  CameraSpec camera;    // framed on the data when the scene does not say
  TraceSettings trace;
};

// `color` is the colour management for spec.output's display and view.
PreparedScene prepare_scene(SceneSpec spec, const ColorManagement& color);

}  // namespace hsb
