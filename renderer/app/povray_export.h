#pragma once
// The same blended field as a POV-Ray 3.7 scene, for side-by-side
// comparison with POV-Ray's exact blob renderer (hsb export --format pov).

#include <string>

#include "renderer/render/camera.h"
#include "renderer/render/render_image.h"
#include "renderer/render/shading.h"
#include "renderer/surface/blob_field.h"

namespace hsb {

// Writes `pov_path` (camera, key light with shadows, ambient light,
// background, one `blob` whose components are this field's sources with
// their colours) and, beside it, an .ini with the image size, no
// anti-aliasing and sRGB PNG output, so `povray FILE.ini` renders it.
// POV-Ray's blob density is the `quartic` kernel; other kernels are refused
// (std::invalid_argument), as is blend = "max".
void write_povray_scene(const BlobField& field, const CameraSpec& camera, const ShadingSpec& shading,
                        const RenderSettings& render, const std::string& pov_path,
                        const std::string& ini_path, const std::string& image_path);

}  // namespace hsb
