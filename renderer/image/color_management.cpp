#include "renderer/image/color_management.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

#include "base/input_file.h"
#include "renderer/image/pixel_rows.h"

namespace OCIO = OCIO_NAMESPACE;

namespace hsb {
namespace {

// `file` if given, else $OCIO if set, else the built-in config; `name`
// says which. A file is asked first whether it is one to read: OCIO
// would open a FIFO and wait for a writer for ever.
OCIO::ConstConfigRcPtr load_config(const std::string& file, std::string& name) {
  if (!file.empty()) {
    if (const std::string why = unreadable_input(file); !why.empty())
      throw std::runtime_error("output.ocio_config names " + file + ": " + why);
    name = file;
    return OCIO::Config::CreateFromFile(file.c_str());
  }
  const char* env = std::getenv("OCIO");
  if (env && *env) {
    if (const std::string why = unreadable_input(env); !why.empty())
      throw std::runtime_error(std::string("$OCIO names ") + env + ": " + why);
    name = env;
    return OCIO::Config::CreateFromEnv();
  }
  name = "built-in hyperstreamball";
  std::istringstream text(builtin_ocio_config());
  return OCIO::Config::CreateFromStream(text);
}

// The files `transform` reads (a FileTransform's LUT, within groups),
// found in the configuration's search path, into `files`. A file OCIO
// cannot find is left to OCIO, which names it when the transform is used.
void add_lut_files(const OCIO::Config& config, const OCIO::ConstTransformRcPtr& transform,
                   std::vector<std::string>& files) {
  if (!transform) return;
  if (const auto group = OCIO::DynamicPtrCast<const OCIO::GroupTransform>(transform)) {
    for (int i = 0; i < group->getNumTransforms(); ++i) add_lut_files(config, group->getTransform(i), files);
  } else if (const auto file = OCIO::DynamicPtrCast<const OCIO::FileTransform>(transform)) {
    try {
      files.push_back(config.getCurrentContext()->resolveFileLocation(file->getSrc()));
    } catch (const OCIO::Exception&) {
    }
  }
}

// Every LUT file the configuration's colour spaces, view transforms and
// looks read, in order, each once.
std::vector<std::string> lut_files(const OCIO::Config& config) {
  std::vector<std::string> files;
  for (int i = 0; i < config.getNumColorSpaces(OCIO::SEARCH_REFERENCE_SPACE_ALL, OCIO::COLORSPACE_ALL); ++i) {
    const char* name = config.getColorSpaceNameByIndex(OCIO::SEARCH_REFERENCE_SPACE_ALL, OCIO::COLORSPACE_ALL, i);
    if (const OCIO::ConstColorSpaceRcPtr space = config.getColorSpace(name))
      for (const auto direction : {OCIO::COLORSPACE_DIR_TO_REFERENCE, OCIO::COLORSPACE_DIR_FROM_REFERENCE})
        add_lut_files(config, space->getTransform(direction), files);
  }
  for (int i = 0; i < config.getNumViewTransforms(); ++i)
    if (const OCIO::ConstViewTransformRcPtr view = config.getViewTransform(config.getViewTransformNameByIndex(i)))
      for (const auto direction : {OCIO::VIEWTRANSFORM_DIR_TO_REFERENCE, OCIO::VIEWTRANSFORM_DIR_FROM_REFERENCE})
        add_lut_files(config, view->getTransform(direction), files);
  for (int i = 0; i < config.getNumLooks(); ++i)
    if (const OCIO::ConstLookRcPtr look = config.getLook(config.getLookNameByIndex(i))) {
      add_lut_files(config, look->getTransform(), files);
      add_lut_files(config, look->getInverseTransform(), files);
    }
  std::vector<std::string> once;
  for (const std::string& f : files)
    if (std::find(once.begin(), once.end(), f) == once.end()) once.push_back(f);
  return once;
}

// Each LUT asked as the configuration's own file is: OCIO opens a LUT
// that is a FIFO and waits for a writer for ever.
void check_lut_files(const OCIO::Config& config, const std::string& config_name) {
  for (const std::string& path : lut_files(config))
    if (const std::string why = unreadable_input(path); !why.empty() && why != "no such file")
      throw std::runtime_error("the colour configuration " + config_name + " names the LUT " + path + ": " + why);
}

}  // namespace

ColorManagement::ColorManagement(const std::string& display, const std::string& view, const std::string& config)
    : config_(load_config(config, config_name_)) {
  check_lut_files(*config_, config_name_);
  display_ = display.empty() ? config_->getDefaultDisplay() : display;
  view_ = view.empty() ? config_->getDefaultView(display_.c_str()) : view;

  to_linear_ = config_->getProcessor(OCIO::ROLE_COLOR_PICKING, OCIO::ROLE_SCENE_LINEAR)
                   ->getDefaultCPUProcessor();
  to_picking_ = config_->getProcessor(OCIO::ROLE_SCENE_LINEAR, OCIO::ROLE_COLOR_PICKING)
                    ->getDefaultCPUProcessor();
  OCIO::DisplayViewTransformRcPtr transform = OCIO::DisplayViewTransform::Create();
  transform->setSrc(OCIO::ROLE_SCENE_LINEAR);
  transform->setDisplay(display_.c_str());
  transform->setView(view_.c_str());
  to_display_ = config_->getProcessor(transform)->getDefaultCPUProcessor();
  display_tables_ = ChannelTables::of(to_display_);
}

std::vector<std::string> color_config_luts(const std::string& config_file) {
  OCIO::ConstConfigRcPtr config;
  try {
    config = OCIO::Config::CreateFromFile(config_file.c_str());
  } catch (const OCIO::Exception&) {
    return {};  // OCIO says what is wrong with it when the picture is made
  }
  check_lut_files(*config, config_file);
  return lut_files(*config);
}

Rgb ColorManagement::to_scene_linear(const Rgb& picked) const {
  Rgb out = picked;
  to_linear_->applyRGB(out.data());
  return out;
}

Rgb ColorManagement::to_picking(const Rgb& linear) const {
  Rgb out = linear;
  to_picking_->applyRGB(out.data());
  return out;
}

void ColorManagement::apply_display(std::vector<float>& rgba, int width, int height) const {
  // The processor works pixel by pixel and keeps no state: bands of rows
  // on every core give the same values as the whole image on one.
  tbb::parallel_for(tbb::blocked_range<int>(0, height, rows_per_task(width)), [&](const tbb::blocked_range<int>& rows) {
    float* band = rgba.data() + std::size_t(rows.begin()) * std::size_t(width) * 4;
    if (!display_tables_) {
      OCIO::PackedImageDesc image(band, width, long(rows.size()), 4);
      to_display_->apply(image);
      return;
    }
    // The tables where they reach, OCIO for the rest (highlights beyond 1).
    const std::size_t pixels = std::size_t(width) * std::size_t(rows.size());
    for (std::size_t i = 0; i < pixels; ++i)
      if (!display_tables_->apply(band + 4 * i)) to_display_->applyRGBA(band + 4 * i);
  });
}

}  // namespace hsb
