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

// The twelve edges of a box, as two-point lines.
std::vector<std::vector<Vec3>> box_edges(const Box3& box) {
  auto corner = [&](int i) {
    return Vec3(i & 1 ? box.hi.x() : box.lo.x(), i & 2 ? box.hi.y() : box.lo.y(), i & 4 ? box.hi.z() : box.lo.z());
  };
  std::vector<std::vector<Vec3>> edges;
  for (int a = 0; a < 8; ++a)
    for (int bit = 1; bit < 8; bit <<= 1)
      if (!(a & bit)) edges.push_back({corner(a), corner(a | bit)});  // each edge once, from its lower corner
  return edges;
}

// Polylines as round linear curves of one radius, with `mask`.
RTCGeometry make_tubes(RTCDevice device, const std::vector<const std::vector<Vec3>*>& lines, double radius,
                       unsigned mask) {
  std::size_t points = 0, segments = 0;
  for (const std::vector<Vec3>* line : lines) {
    if (line->size() < 2) continue;
    points += line->size();
    segments += line->size() - 1;
  }
  RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_ROUND_LINEAR_CURVE);
  auto* vertices = static_cast<float*>(
      rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), points));
  auto* indices = static_cast<unsigned*>(
      rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT, sizeof(unsigned), segments));
  std::size_t v = 0, i = 0;
  for (const std::vector<Vec3>* line : lines) {
    if (line->size() < 2) continue;
    for (std::size_t k = 0; k < line->size(); ++k, ++v) {
      if (k + 1 < line->size()) indices[i++] = unsigned(v);
      for (int c = 0; c < 3; ++c) vertices[4 * v + std::size_t(c)] = float((*line)[k][c]);
      vertices[4 * v + 3] = float(radius);
    }
  }
  rtcSetGeometryMask(geometry, mask);
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
  if (mesh.normals.size() == mesh.vertices.size()) {
    rtcSetGeometryVertexAttributeCount(geometry, 1);
    auto* normals = static_cast<float*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_VERTEX_ATTRIBUTE, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), mesh.normals.size()));
    for (std::size_t i = 0; i < mesh.normals.size(); ++i)
      for (int k = 0; k < 3; ++k) normals[3 * i + std::size_t(k)] = float(mesh.normals[i][k]);
  }
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
  if (context.glyphs && !field.sources.empty()) field_id_ = blobs_->attach_to(scene_, kFieldMask);
  if (context.box) {
    const std::vector<std::vector<Vec3>> lines = box_edges(*context.box);
    std::vector<const std::vector<Vec3>*> pointers;
    for (const std::vector<Vec3>& line : lines) pointers.push_back(&line);
    RTCGeometry edges = make_tubes(device.get(), pointers, context.box_radius, kContextMask);
    box_id_ = rtcAttachGeometry(scene_, edges);
    rtcReleaseGeometry(edges);
  }
  if (!context.trajectories.empty()) {
    RTCGeometry tubes = make_tubes(device.get(), context.trajectories, context.trajectory_radius, kContextMask);
    tubes_id_ = rtcAttachGeometry(scene_, tubes);
    rtcReleaseGeometry(tubes);
  }
  rtcCommitScene(scene_);
  if (context.shell && !context.shell->triangles.empty()) {
    shell_ = make_shell(device.get(), *context.shell);
    shell_geometry_ = rtcGetGeometry(shell_, 0);
    shell_has_normals_ = context.shell->normals.size() == context.shell->vertices.size();
  }
  if (rtcGetDeviceError(device.get()) != RTC_ERROR_NONE)
    throw std::runtime_error("Embree failed to build the scene");
}

Vec3 RayScene::shell_normal(unsigned primitive, float u, float v, const Vec3& geometric) const {
  if (!shell_has_normals_) return geometric.normalized();
  float n[3];
  rtcInterpolate0(shell_geometry_, primitive, u, v, RTC_BUFFER_TYPE_VERTEX_ATTRIBUTE, 0, n, 3);
  const Vec3 normal(n[0], n[1], n[2]);
  return normal.norm() > 0.0 ? normal.normalized() : geometric.normalized();
}

RayScene::~RayScene() {
  if (scene_) rtcReleaseScene(scene_);
  if (shell_) rtcReleaseScene(shell_);
}

}  // namespace hsb
