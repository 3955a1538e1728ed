#pragma once
// The top-level Embree scene: the blob field plus context geometry.

#include <embree3/rtcore.h>

#include <memory>
#include <optional>
#include <string>

#include "base/box3.h"
#include "field/glyphs/triangle_mesh.h"
#include "renderer/render/context_lines.h"
#include "renderer/render/shading.h"
#include "renderer/render/shell_geometry.h"
#include "renderer/surface/blob_geometry.h"
#include "renderer/surface/instruction_set.h"

namespace hsb {

// Owns an Embree device; one per process is enough, scenes share it. Its
// kernels are those of active_isa() (instruction_set.h), like the
// renderer's own.
class EmbreeDevice {
 public:
  EmbreeDevice();
  ~EmbreeDevice();
  EmbreeDevice(const EmbreeDevice&) = delete;
  EmbreeDevice& operator=(const EmbreeDevice&) = delete;
  RTCDevice get() const { return device_; }
  InstructionSet isa() const { return isa_; }
  int packet_width() const { return packet_width_; }  // native_packet_width()
  // "Embree 3.13.5, avx2 kernels, 8-ray packets"
  std::string describe() const;

 private:
  InstructionSet isa_;
  RTCDevice device_;
  int packet_width_;
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
  // box's edges and the trajectory tubes are round tubes (context_lines.h)
  // that cast no shadow (shadow rays carry kShadowRayMask). The shell is
  // a separate geometry (shell_geometry.h), shaded with its vertex normals:
  // it is composited over what the rays hit, casts no shadow and hides
  // nothing.
  RayScene(const EmbreeDevice& device, const BlobField& field, const TraceSettings& settings,
           const DrawnContext& context = {});
  ~RayScene();
  RayScene(const RayScene&) = delete;
  RayScene& operator=(const RayScene&) = delete;

  RTCScene get() const { return scene_; }
  // How many rays to trace in one packet (ray_packets.h).
  int packet_width() const { return packet_width_; }
  unsigned field_id() const { return field_id_; }
  unsigned box_id() const { return box_id_; }
  unsigned tubes_id() const { return tubes_id_; }
  const BlobGeometry& blobs() const { return *blobs_; }
  const ShellGeometry* shell() const { return shell_.get(); }  // nullptr when there is none
  // The box holding all a camera ray can meet: the geometry and the
  // shell (empty, lo > hi, when there is nothing).
  const Box3& reach() const { return reach_; }

 private:
  RTCScene scene_ = nullptr;
  int packet_width_ = 1;
  std::unique_ptr<BlobGeometry> blobs_;
  std::unique_ptr<ContextLines> box_, tubes_;
  std::unique_ptr<ShellGeometry> shell_;
  unsigned field_id_ = RTC_INVALID_GEOMETRY_ID;
  unsigned box_id_ = RTC_INVALID_GEOMETRY_ID;
  unsigned tubes_id_ = RTC_INVALID_GEOMETRY_ID;
  Box3 reach_;
};

}  // namespace hsb
