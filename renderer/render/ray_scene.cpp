#include "renderer/render/ray_scene.h"

#include <stdexcept>
#include <string>

#include "base/point_extremes.h"
#include "renderer/surface/ray_packets.h"

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

}  // namespace

EmbreeDevice::EmbreeDevice()
    : isa_(active_isa()), device_(rtcNewDevice((std::string("isa=") + isa_name(isa_)).c_str())) {
  if (!device_) throw std::runtime_error("cannot create an Embree device");
  rtcSetDeviceErrorFunction(device_, report_embree_error, nullptr);
  packet_width_ = native_packet_width(device_);
}

std::string EmbreeDevice::describe() const {
  const auto version = [&](RTCDeviceProperty p) { return std::to_string(rtcGetDeviceProperty(device_, p)); };
  return "Embree " + version(RTC_DEVICE_PROPERTY_VERSION_MAJOR) + "." + version(RTC_DEVICE_PROPERTY_VERSION_MINOR) +
         "." + version(RTC_DEVICE_PROPERTY_VERSION_PATCH) + ", " + isa_name(isa_) + " kernels, " +
         std::to_string(packet_width_) + "-ray packets";
}

EmbreeDevice::~EmbreeDevice() { rtcReleaseDevice(device_); }

RayScene::RayScene(const EmbreeDevice& device, const BlobField& field, const TraceSettings& settings,
                   const DrawnContext& context)
    : packet_width_(device.packet_width()) {
  scene_ = rtcNewScene(device.get());
  blobs_ = std::make_unique<BlobGeometry>(device.get(), field, settings);
  if (context.glyphs && !field.sources.empty()) field_id_ = blobs_->attach_to(scene_, kFieldMask);
  if (context.box) {
    const std::vector<std::vector<Vec3>> lines = box_edges(*context.box);
    std::vector<const std::vector<Vec3>*> pointers;
    for (const std::vector<Vec3>& line : lines) pointers.push_back(&line);
    box_ = std::make_unique<ContextLines>(pointers, context.box_radius);
    box_id_ = box_->attach_to(device.get(), scene_, kContextMask);
  }
  if (!context.trajectories.empty()) {
    tubes_ = std::make_unique<ContextLines>(context.trajectories, context.trajectory_radius);
    tubes_id_ = tubes_->attach_to(device.get(), scene_, kContextMask);
  }
  rtcCommitScene(scene_);
  if (context.shell && !context.shell->triangles.empty())
    shell_ = std::make_unique<ShellGeometry>(device.get(), *context.shell);
  RTCBounds bounds;
  rtcGetSceneBounds(scene_, &bounds);
  reach_ = {Vec3(bounds.lower_x, bounds.lower_y, bounds.lower_z), Vec3(bounds.upper_x, bounds.upper_y, bounds.upper_z)};
  if (shell_) reach_.extend(bounding_box(context.shell->vertices));
  if (rtcGetDeviceError(device.get()) != RTC_ERROR_NONE)
    throw std::runtime_error("Embree failed to build the scene");
}

RayScene::~RayScene() {
  if (scene_) rtcReleaseScene(scene_);
}

}  // namespace hsb
