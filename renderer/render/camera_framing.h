#pragma once
// Where the camera stands when a scene does not say: looking from a named
// view at what is drawn, far enough that all of it fits the picture with a
// margin, so nothing is cut off and the camera is outside everything.

#include <optional>
#include <string>
#include <vector>

#include "base/box3.h"
#include "renderer/render/camera.h"

namespace hsb {

// What to fit in the picture.
enum class FrameTarget {
  drawn,   // the glyphs and the context drawn around them (box, boundary shell)
  glyphs,  // the glyphs alone
  data,    // the data set's bounds
};

// The scene's [camera]: what it leaves out is automatic.
struct CameraRequest {
  std::optional<Vec3> position, look_at, up;
  // From the framed box's centre towards the camera (unit): a named view's
  // direction or the scene's own. Automatic: automatic_view().
  std::optional<Vec3> view;
  Projection projection = Projection::perspective;
  double fov_degrees = 30.0;
  std::optional<double> height;  // orthographic view height
  FrameTarget frame = FrameTarget::drawn;
  double margin = 0.05;  // of the picture's height and width, on each side
};

// The direction of a named view ("front" looks along +y, "top" down −z,
// "iso" from front-right-above, …); nullopt for an unknown name.
std::optional<Vec3> named_view(const std::string& name);
// The names, for error messages and the reference.
const char* const* view_names();

// `up`: +z, or +y when looking along z or within 25° of it (a flat
// body seen from above keeps its edges square to the picture).
Vec3 automatic_up(const Vec3& view);

// For a compact body, from the front-right and 23° above (lower than
// "iso"); for one at least twice as long as it is wide, from the side and
// above, its length across the picture, the near end a little closer. A
// flat body (thinnest side under a fifth of the middle one) from the side
// its faces look to, 15° off square. A 2-D result (its plane's normal
// along `plane_axis`) straight from above its plane.
Vec3 automatic_view(const Box3& data, std::optional<int> plane_axis = std::nullopt);

// The parts of the picture a legend takes, as fractions of its width (at
// the right) and of its height (at the bottom); at most 0.4 each.
struct PictureReserve {
  double right = 0.0, bottom = 0.0;
};

// The camera for `request`, framing `box` in a width×height picture less
// `reserve`. The camera describes the free part (CameraSpec::frame_width,
// frame_height), so a view framed by hand, or pinned by `hsb info`, stays
// clear of the legend. Given position and look_at win; whatever is missing is found
// so that the box's corners project inside the margin of the free part
// (perspective: the distance along the view; orthographic: the view
// height), centred in it.
CameraSpec frame_camera(const CameraRequest& request, const Box3& box, int width, int height,
                        const PictureReserve& reserve = {});
// The same framing `points` (all of them seen, the picture fitted to
// their extent), for shapes a box would frame loosely.
CameraSpec frame_camera(const CameraRequest& request, const std::vector<Vec3>& points, int width, int height,
                        const PictureReserve& reserve = {});

}  // namespace hsb
