#include "field/glyphs/glyph_mapping.h"

#include <cmath>

#include "field/tensor/tensor_measures.h"

namespace hsb {

namespace {

Vec3 unclamped_radii(const Vec3& magnitude, const GlyphMapping& mapping) {
  const double s = mapping.scale;
  switch (mapping.mapping) {
    case RadiusMapping::linear:
      return s * magnitude;
    case RadiusMapping::sqrt:
      return s * magnitude.cwiseSqrt();
    case RadiusMapping::normalized: {
      const double largest = magnitude.maxCoeff();
      // A zero tensor has no shape to keep: draw it as a sphere of the
      // normalised size rather than dividing by zero.
      if (largest == 0.0) return Vec3::Constant(s);
      return (s / largest) * magnitude;
    }
    case RadiusMapping::constant:
      break;
  }
  return Vec3::Constant(s);
}

}  // namespace

Vec3 map_radii(const Vec3& eigenvalues, const GlyphMapping& mapping) {
  Vec3 radii = unclamped_radii(eigenvalues.cwiseAbs(), mapping);
  // Uniform scaling keeps the ratios of the radii, which carry the tensor's
  // shape; clamping each radius alone would turn large glyphs into spheres.
  const double largest = radii.maxCoeff();
  if (largest > mapping.ceiling) radii *= mapping.ceiling / largest;
  return radii.cwiseMax(mapping.floor);
}

const char* color_scalar_name(ColorScalar c) {
  switch (c) {
    case ColorScalar::lambda1: return "lambda1";
    case ColorScalar::lambda2: return "lambda2";
    case ColorScalar::lambda3: return "lambda3";
    case ColorScalar::mean: return "mean";
    case ColorScalar::von_mises: return "von_mises";
    case ColorScalar::family_eigenvalue: return "family_eigenvalue";
    case ColorScalar::fa: return "fa";
    case ColorScalar::trace: return "trace";
    case ColorScalar::westin_linear: return "cl";
    case ColorScalar::westin_planar: return "cp";
    case ColorScalar::westin_spherical: return "cs";
    case ColorScalar::mode: return "mode";
    case ColorScalar::direction: return "direction";
    case ColorScalar::speed: return "speed";
    case ColorScalar::array: return "array";
    case ColorScalar::arc_length: return "arc_length";
    case ColorScalar::none: return "none";
  }
  return "?";
}

const std::vector<ColorScalar>& named_color_scalars() {
  static const std::vector<ColorScalar> named{ColorScalar::lambda1,   ColorScalar::lambda2,
                                              ColorScalar::lambda3,   ColorScalar::mean,
                                              ColorScalar::von_mises, ColorScalar::family_eigenvalue,
                                              ColorScalar::fa,        ColorScalar::trace,
                                              ColorScalar::westin_linear, ColorScalar::westin_planar,
                                              ColorScalar::westin_spherical, ColorScalar::mode,
                                              ColorScalar::direction,
                                              ColorScalar::speed,     ColorScalar::arc_length,
                                              ColorScalar::none};
  return named;
}

bool needs_tensors(ColorScalar which) {
  switch (which) {
    case ColorScalar::speed:
    case ColorScalar::array:
    case ColorScalar::arc_length:
    case ColorScalar::none:
      return false;
    default:
      return true;
  }
}

std::optional<std::array<double, 2>> natural_range(ColorScalar which) {
  switch (which) {
    case ColorScalar::fa:
    case ColorScalar::direction:
    case ColorScalar::westin_linear:
    case ColorScalar::westin_planar:
    case ColorScalar::westin_spherical:
      return std::array<double, 2>{0.0, 1.0};
    case ColorScalar::mode:
      return std::array<double, 2>{-1.0, 1.0};
    default:
      return std::nullopt;
  }
}

double color_scalar(const Vec3& eigenvalues, ColorScalar which) {
  const double l1 = eigenvalues(0), l2 = eigenvalues(1), l3 = eigenvalues(2);
  switch (which) {
    case ColorScalar::lambda1:
      return l1;
    case ColorScalar::lambda2:
      return l2;
    case ColorScalar::lambda3:
      return l3;
    case ColorScalar::mean:
      return (l1 + l2 + l3) / 3.0;
    case ColorScalar::von_mises:
      // Invariant under rotation, so principal stresses suffice.
      return std::sqrt(0.5 * ((l1 - l2) * (l1 - l2) + (l2 - l3) * (l2 - l3) +
                              (l3 - l1) * (l3 - l1)));
    case ColorScalar::fa:
    case ColorScalar::direction:  // the weight of its colour
      return fractional_anisotropy(eigenvalues);
    case ColorScalar::trace:
      return l1 + l2 + l3;
    case ColorScalar::westin_linear:
      return westin_measures(eigenvalues).linear;
    case ColorScalar::westin_planar:
      return westin_measures(eigenvalues).planar;
    case ColorScalar::westin_spherical:
      return westin_measures(eigenvalues).spherical;
    case ColorScalar::mode:
      return tensor_mode(eigenvalues);
    case ColorScalar::speed:
    case ColorScalar::family_eigenvalue:  // resolved per line by the pipeline; λ1 for a lone source
      return l1;
    case ColorScalar::array:
    case ColorScalar::arc_length:
    case ColorScalar::none:
      return 0.0;
  }
  return l3;  // unreachable for valid enum values
}

}  // namespace hsb
