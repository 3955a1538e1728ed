#pragma once
// Colour management through OpenColorIO: the renderer's scene-linear working
// space, colours authored in display sRGB (colormaps, background), and the
// display/view transform applied to every displayable image.

#include <OpenColorIO/OpenColorIO.h>

#include <optional>
#include <string>
#include <vector>

#include "renderer/image/channel_tables.h"
#include "renderer/render/shading.h"

namespace hsb {

class ColorManagement {
 public:
  // Uses the config file `config` when given, else $OCIO when it is set,
  // else the config compiled into the program
  // (renderer/image/hyperstreamball.ocio). Empty display/view select the
  // config's defaults. Throws with OCIO's message on a bad config or name.
  ColorManagement(const std::string& display, const std::string& view, const std::string& config = "");

  // A colour picked in display terms (role color_picking) in scene-linear.
  Rgb to_scene_linear(const Rgb& picked) const;
  // The inverse: scene-linear to the picking space (for overlays drawn in
  // display terms on a display-referred image).
  Rgb to_picking(const Rgb& linear) const;

  // Scene-linear RGBA pixels to display-referred, in place.
  void apply_display(std::vector<float>& rgba, int width, int height) const;

  const std::string& display() const { return display_; }
  const std::string& view() const { return view_; }
  // The config in use: its file, or "built-in hyperstreamball".
  const std::string& config_name() const { return config_name_; }

 private:
  std::string config_name_;  // before config_: the constructor fills it while loading
  OCIO_NAMESPACE::ConstConfigRcPtr config_;
  std::string display_, view_;
  OCIO_NAMESPACE::ConstCPUProcessorRcPtr to_linear_, to_picking_, to_display_;
  std::optional<ChannelTables> display_tables_;  // to_display_ where it treats each channel alone
};

// The LUT files the colour configuration in `config_file` reads (its
// FileTransforms, found in its search path), for the picture's hash: a
// changed LUT changes the picture. None where OCIO cannot read it;
// throws, naming it, for a LUT that is a FIFO, socket or device.
std::vector<std::string> color_config_luts(const std::string& config_file);

// The built-in config's text (for tests and for `hsb --print-ocio-config`).
const char* builtin_ocio_config();

}  // namespace hsb
