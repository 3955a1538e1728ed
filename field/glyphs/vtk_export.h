#pragma once
// Trajectories and sources as VTK PolyData (.vtp), so the same sources can
// be inspected in ParaView (its Tensor Glyph filter draws them).

#include <string>
#include <vector>

#include "field/glyph_pipeline.h"

namespace hsb {

// One more point-data array for the sources file, a tuple per source in
// the scene's order: what the renderer adds to a source (its glyph shape),
// which the field library does not know.
struct SourceArray {
  std::string name;
  int components = 1;
  std::vector<double> values;  // components × the number of sources
};

// Writes two XML PolyData files (each complete or not at all):
//  - `trajectories_path`: one polyline per trajectory of two points or
//    more, with point data "arc_length" and cell data "trajectory" (its
//    index among all trajectories, single-point ones included);
//  - `sources_path`: one vertex per source with point data "tensor" (the
//    tensor, V diag(λ) Vᵀ, 9 components), "eigenvalues", "radii" (r_k of the
//    mapping), "scalar" (the colour scalar) and the active tensors "glyph" =
//    V diag(glyph_scale · r_k) Vᵀ. ParaView's Tensor Glyph (sphere source of
//    radius ½, eigenvalue extraction on, no colouring by eigenvalues) then
//    draws ellipsoids with semi-axes glyph_scale·r_k/2; and `more`.
// Throws DataError when a file cannot be written, std::invalid_argument
// when an array of `more` has not one tuple per source.
void write_glyph_scene_vtp(const GlyphScene& scene, double glyph_scale, const std::string& trajectories_path,
                           const std::string& sources_path, const std::vector<SourceArray>& more = {});

}  // namespace hsb
