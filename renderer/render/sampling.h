#pragma once
// Deterministic sample patterns. Every random number is a hash of what it
// is for (the pixel, the camera sample, the purpose, the index), so a
// render gives the same bytes whatever the thread count and however often
// it is repeated.

#include <cmath>
#include <cstdint>

#include "base/vec3.h"

namespace hsb {

// A stateless integer hash (the finaliser of MurmurHash3) as a number in [0, 1).
inline double hash_unit(std::uint64_t key) {
  key ^= key >> 33;
  key *= 0xff51afd7ed558ccdULL;
  key ^= key >> 33;
  key *= 0xc4ceb9fe1a85ec53ULL;
  key ^= key >> 33;
  return double(key >> 11) * (1.0 / 9007199254740992.0);
}

// What a random number is for: keys that differ in purpose never repeat.
enum class SamplePurpose : std::uint64_t { pixel = 0, light = 1, ambient = 2 };

// The key for number `index` of camera sample `sample` of pixel `pixel`.
inline std::uint64_t sample_key(std::uint64_t pixel, std::uint64_t sample, SamplePurpose purpose,
                                std::uint64_t index) {
  return ((pixel * 4096u + sample) * 4u + std::uint64_t(purpose)) * 1024u + index;
}

// Point k of n stratified over [0, 1)²: the n cells of a near-square grid,
// one jittered point in each, so a few samples already cover the square.
inline void stratified(int k, int n, std::uint64_t key, double& u, double& v) {
  int columns = int(std::ceil(std::sqrt(double(n))));
  const int rows = (n + columns - 1) / columns;
  const int i = k % columns, j = k / columns;
  u = (i + hash_unit(key)) / columns;
  v = (j + hash_unit(key + 0x9e3779b97f4a7c15ULL)) / rows;
}

// A unit vector whose angle to `axis` is uniform over a cone of half-angle
// `half_angle` (radians) in solid angle, from (u, v) ∈ [0, 1)².
inline Vec3 in_cone(const Vec3& axis, double half_angle, double u, double v) {
  const double cos_max = std::cos(half_angle);
  const double cos_t = 1.0 - u * (1.0 - cos_max), sin_t = std::sqrt(std::max(0.0, 1.0 - cos_t * cos_t));
  const double phi = 2.0 * M_PI * v;
  const Vec3 a = axis.normalized();
  const Vec3 t = (std::fabs(a.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).cross(a).normalized();
  const Vec3 b = a.cross(t);
  return (cos_t * a + sin_t * (std::cos(phi) * t + std::sin(phi) * b)).normalized();
}

// A cosine-weighted direction on the hemisphere around `normal`.
inline Vec3 cosine_hemisphere(const Vec3& normal, double u, double v) {
  const double r = std::sqrt(u), phi = 2.0 * M_PI * v;
  const Vec3 t = (std::fabs(normal.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).cross(normal).normalized();
  const Vec3 b = normal.cross(t);
  return (r * std::cos(phi) * t + r * std::sin(phi) * b + std::sqrt(std::max(0.0, 1.0 - u)) * normal).normalized();
}

}  // namespace hsb
