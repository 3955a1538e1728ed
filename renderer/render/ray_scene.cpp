#include "renderer/render/ray_scene.h"

#include <stdexcept>
#include <string>

namespace hsb {
namespace {

void report_embree_error(void*, RTCError code, const char* message) {
  // Errors are also collected with rtcGetDeviceError where they matter;
  // printing here gives the message text that the code alone lacks.
  std::fprintf(stderr, "hsb: Embree error %d: %s\n", int(code), message ? message : "");
}

// The twelve edges of a box as round linear curves of constant radius.
RTCGeometry make_box_edges(RTCDevice device, const Box3& box, double radius) {
  RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_ROUND_LINEAR_CURVE);
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), 24));
  auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT, sizeof(unsigned), 12));
  auto corner = [&](int i) {
    return Vec3(i & 1 ? box.hi.x() : box.lo.x(), i & 2 ? box.hi.y() : box.lo.y(),
                i & 4 ? box.hi.z() : box.lo.z());
  };
  int edge = 0;
  for (int a = 0; a < 8; ++a) {
    for (int bit = 1; bit < 8; bit <<= 1) {
      if (a & bit) continue;  // each edge once, from its lower corner
      const Vec3 ends[2] = {corner(a), corner(a | bit)};
      for (int e = 0; e < 2; ++e) {
        float* v = vertices + 4 * (2 * edge + e);
        v[0] = float(ends[e].x());
        v[1] = float(ends[e].y());
        v[2] = float(ends[e].z());
        v[3] = float(radius);
      }
      indices[edge] = unsigned(2 * edge);
      ++edge;
    }
  }
  rtcSetGeometryMask(geometry, RayScene::kContextMask);
  rtcCommitGeometry(geometry);
  return geometry;
}

RTCScene make_shell(RTCDevice device, const TriangleMesh& mesh) {
  RTCScene scene = rtcNewScene(device);
  RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), mesh.vertices.size()));
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
    for (int k = 0; k < 3; ++k) vertices[3 * i + std::size_t(k)] = float(mesh.vertices[i][k]);
  auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), mesh.triangles.size()));
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i)
    for (int k = 0; k < 3; ++k) indices[3 * i + std::size_t(k)] = mesh.triangles[i][std::size_t(k)];
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(scene, geometry);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(scene);
  return scene;
}

}  // namespace

EmbreeDevice::EmbreeDevice() : device_(rtcNewDevice(nullptr)) {
  if (!device_) throw std::runtime_error("cannot create an Embree device");
  rtcSetDeviceErrorFunction(device_, report_embree_error, nullptr);
}

EmbreeDevice::~EmbreeDevice() { rtcReleaseDevice(device_); }

RayScene::RayScene(const EmbreeDevice& device, const BlobField& field, const TraceSettings& settings,
                   const DrawnContext& context) {
  scene_ = rtcNewScene(device.get());
  blobs_ = std::make_unique<BlobGeometry>(device.get(), field, settings);
  if (!field.sources.empty()) field_id_ = blobs_->attach_to(scene_, kFieldMask);
  if (context.box) {
    RTCGeometry edges = make_box_edges(device.get(), *context.box, context.box_radius);
    box_id_ = rtcAttachGeometry(scene_, edges);
    rtcReleaseGeometry(edges);
  }
  rtcCommitScene(scene_);
  if (context.shell && !context.shell->triangles.empty()) shell_ = make_shell(device.get(), *context.shell);
  if (rtcGetDeviceError(device.get()) != RTC_ERROR_NONE)
    throw std::runtime_error("Embree failed to build the scene");
}

RayScene::~RayScene() {
  if (scene_) rtcReleaseScene(scene_);
  if (shell_) rtcReleaseScene(shell_);
}

}  // namespace hsb
