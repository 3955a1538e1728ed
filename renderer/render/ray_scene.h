#pragma once
// The top-level Embree scene: the blob field plus context geometry.

#include <embree3/rtcore.h>

#include <memory>
#include <optional>

#include "field/box3.h"
#include "field/triangle_mesh.h"
#include "renderer/render/shading.h"
#include "renderer/surface/blob_geometry.h"

namespace hsb {

// Owns an Embree device; one per process is enough, scenes share it.
class EmbreeDevice {
 public:
  EmbreeDevice();
  ~EmbreeDevice();
  EmbreeDevice(const EmbreeDevice&) = delete;
  EmbreeDevice& operator=(const EmbreeDevice&) = delete;
  RTCDevice get() const { return device_; }

 private:
  RTCDevice device_;
};

// What is drawn besides (or instead of) the glyphs, each part when present.
struct DrawnContext {
  bool glyphs = true;       // false: the field is not drawn (trajectories alone)
  std::optional<Box3> box;  // its twelve edges
  double box_radius = 0.0;
  const TriangleMesh* shell = nullptr;  // a data set's boundary surface
  // Trajectories as thin tubes (each polyline of two points or more).
  std::vector<const std::vector<Vec3>*> trajectories;
  double trajectory_radius = 0.0;
};

class RayScene {
 public:
  // Embree geometry masks. The field casts shadows; the domain's edges are
  // context like the shell: drawn, but a shadow ray passes them, because a
  // thin dark line across a glyph reads as a feature of the data.
  static constexpr unsigned kFieldMask = 1u;
  static constexpr unsigned kContextMask = 2u;
  static constexpr unsigned kShadowRayMask = kFieldMask;

  // `field` (and what `context` points to) must outlive the scene. The
  // box's edges and the trajectory tubes are round curves that cast no
  // shadow (shadow rays carry kShadowRayMask). The shell becomes a
  // separate scene of triangles, shaded with its vertex normals: it is
  // composited over what the rays hit, casts no shadow and hides nothing.
  RayScene(const EmbreeDevice& device, const BlobField& field, const TraceSettings& settings,
           const DrawnContext& context = {});
  ~RayScene();
  RayScene(const RayScene&) = delete;
  RayScene& operator=(const RayScene&) = delete;

  RTCScene get() const { return scene_; }
  unsigned field_id() const { return field_id_; }
  unsigned box_id() const { return box_id_; }
  unsigned tubes_id() const { return tubes_id_; }
  const BlobGeometry& blobs() const { return *blobs_; }
  RTCScene shell() const { return shell_; }  // nullptr when there is none
  // The shell's normal at a hit: interpolated from its vertices when it has
  // vertex normals, else the triangle's own.
  Vec3 shell_normal(unsigned primitive, float u, float v, const Vec3& geometric) const;

 private:
  RTCScene scene_ = nullptr;
  RTCScene shell_ = nullptr;
  std::unique_ptr<BlobGeometry> blobs_;
  unsigned field_id_ = RTC_INVALID_GEOMETRY_ID;
  unsigned box_id_ = RTC_INVALID_GEOMETRY_ID;
  unsigned tubes_id_ = RTC_INVALID_GEOMETRY_ID;
  RTCGeometry shell_geometry_ = nullptr;  // owned by shell_
  bool shell_has_normals_ = false;
};

}  // namespace hsb
