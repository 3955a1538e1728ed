#pragma once
// A figure as a PDF or SVG page, the way journals ask for figures: the
// rendered picture embedded as an image at its DPI (the page is as large
// as the picture prints), and its annotations (colour bars, labels) over it
// as vector shapes and text that stay sharp and searchable.

#include <map>
#include <string>
#include <vector>

#include "renderer/image/annotations.h"

namespace hsb {

struct VectorFigure {
  const std::vector<float>* rgba = nullptr;  // display-referred, premultiplied
  int width = 0, height = 0;
  double dpi = 300.0;
  const Annotations* annotations = nullptr;  // legends and text, as vector shapes and text
  std::map<std::string, std::string> metadata;  // "Software", "ImageDescription", … (PDF only)
};

// Writes the page to `path` (.pdf or .svg), complete or not at all.
// Throws std::runtime_error when it cannot.
void write_vector_figure(const VectorFigure& figure, const ColorManagement& color, const std::string& path);

}  // namespace hsb
