#pragma once
// The end of the output path, shared by single pictures and panel figures:
// what a file says about how it was made, and the display-referred picture
// with its annotations written as PNG, TIFF, PDF or SVG (or the film as a
// scene-linear EXR).

#include <map>
#include <string>
#include <vector>

#include "renderer/image/annotations.h"
#include "renderer/image/raster_stream.h"
#include "renderer/library/prepared_scene.h"
#include "renderer/render/film.h"

namespace hsb {

// The hash an image stores as hsb:scene_sha1: of the scene's text, its
// overrides and the data file's bytes.
std::string scene_sha1(const SceneSpec& spec);

// Every file's metadata: software, `description`, the scene text, its
// hash, the data file and its hash, `resolved` (the scene with its
// automatic values written out), the colour management.
std::map<std::string, std::string> picture_metadata(const SceneSpec& spec, const std::string& description,
                                                    const std::string& resolved, const ColorManagement& color);

// A one-line description of a prepared scene's picture.
std::string picture_description(const PreparedScene& prepared);

// A PNG's or TIFF's shape: RGBA where the background is `transparent`,
// else RGB (an opaque picture's alpha says nothing, and a quarter fewer
// bytes make a quarter less to deflate); the output's bit depth and dpi.
RasterStream::Format display_raster_format(int width, int height, const OutputSettings& output, bool transparent);

// Writes display-referred, premultiplied `rgba` with `annotations` drawn
// over it to `path`, in the format its extension names (not EXR).
void write_display_picture(const std::string& path, std::vector<float> rgba, int width, int height, bool transparent,
                           const Annotations& annotations, const OutputSettings& output,
                           std::map<std::string, std::string> metadata, const ColorManagement& color);

// Writes the film scene-linear to an EXR: RGBA, then its other planes.
void write_scene_linear_picture(const std::string& path, const Film& film, const OutputSettings& output,
                                std::map<std::string, std::string> metadata);

// The grey text takes over `rgba` near a legend's bar.
float legend_ink(const std::vector<float>& rgba, int width, int height, const LegendLayout& legend);

}  // namespace hsb
