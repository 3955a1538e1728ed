#pragma once
// A data set's boundary surface, drawn as a translucent shell: every layer
// a camera ray crosses is composited, so what the ray needs is all its
// crossings in order, not the first.
//
// The triangles are the primitives of an Embree user geometry in a scene of
// their own, intersected in double precision here with a watertight test
// (Woop, Benthin and Wald, "Watertight Ray/Triangle Intersection", JCGT
// 2013): a ray through an edge or a vertex crosses the surface once, never
// zero times, and the triangles that share the crossing report it at the
// same t, where it is counted once. Stepping from one hit to the next with
// Embree's float triangles instead counted such crossings twice or not at
// all (dark and light specks over the shell), and rounded differently on
// each instruction set.

#include <embree3/rtcore.h>

#include <cstdint>
#include <vector>

#include "field/glyphs/triangle_mesh.h"

namespace hsb {

// The crossing of the ray o + t d with triangle (a, b, c) for t in
// (tmin, tmax), or a negative value; `weights` are then the barycentric
// weights of a, b and c there.
double ray_triangle(const Vec3& o, const Vec3& d, const Vec3& a, const Vec3& b, const Vec3& c, double tmin,
                    double tmax, Vec3& weights);

struct ShellCrossing {
  double t;
  Vec3 normal;  // unit; smooth where the mesh has vertex normals
};

class ShellGeometry {
 public:
  // `mesh` must outlive this object.
  ShellGeometry(RTCDevice device, const TriangleMesh& mesh);
  ~ShellGeometry();
  ShellGeometry(const ShellGeometry&) = delete;
  ShellGeometry& operator=(const ShellGeometry&) = delete;

  bool empty() const { return mesh_.triangles.empty(); }

  // The ray's crossings of the surface in (0, tmax), nearest first, at
  // most `max_layers` of them, into `out` (cleared first).
  void crossings(const Vec3& o, const Vec3& d, double tmax, std::size_t max_layers,
                 std::vector<ShellCrossing>& out) const;

 private:
  static void bounds(const RTCBoundsFunctionArguments* args);
  static void intersect(const RTCIntersectFunctionNArguments* args);

  const TriangleMesh& mesh_;
  double merge_distance_;  // crossings closer than this along a ray are one
  double margin_;          // how far the boxes Embree sees are widened
  RTCScene scene_ = nullptr;
};

}  // namespace hsb
