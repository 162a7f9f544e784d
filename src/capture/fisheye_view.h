// A fisheye view's geometry (capture/capture.h): the lens mapping across the image circle and the
// view's orientation in the world.
//
// Lens mappings (r: distance from the circle's centre, θ: angle from the optical axis, f the
// focal length): equidistant r = f θ, equisolid angle r = 2 f sin(θ/2), stereographic
// r = 2 f tan(θ/2) (Kannala & Brandt, "A Generic Camera Model and Calibration Method for
// Conventional, Wide-Angle, and Fish-Eye Lenses", PAMI 2006, Eqs. 1–4). f follows from the
// field of view across the circle's diameter: r(fov/2) = radius.
//
// Orientation (the capture contract of docs/capture.md): the front photo looks north (−z) with
// the image's up along +y, so its right is +x; the back photo looks south (+z), up +y, right −x.
// Pinned by tests/capture/fisheye_view_test.cpp.
#pragma once

#include <optional>

#include "capture/image_circle.h"
#include "math/vec3.h"

namespace relight {

enum class FisheyeProjection { kEquidistant, kEquisolid, kStereographic };

struct FisheyeLens {
  FisheyeProjection projection = FisheyeProjection::kEquidistant;
  double fov_rad = 190.0 * kPi / 180.0;  // across the circle's diameter
};

// r(θ) / r(fov/2): 0 at the centre, 1 on the circle.
double lens_radius(const FisheyeLens& lens, double theta);
// The inverse: θ of a normalised radius in [0, 1].
double lens_angle(const FisheyeLens& lens, double radius);

struct FisheyeView {
  ImageCircle circle;
  FisheyeLens lens;
  Vec3 axis, right, up;  // the optical axis and the image's right and up, in the world
};

FisheyeView front_view(const ImageCircle& circle, const FisheyeLens& lens);
FisheyeView back_view(const ImageCircle& circle, const FisheyeLens& lens);

// Where a world direction falls in the photo (pixel coordinates, pixel (x, y) covering
// [x, x + 1) × [y, y + 1), y down), or nullopt beyond the lens's field of view.
struct PhotoPoint {
  double x = 0, y = 0;
};
std::optional<PhotoPoint> photo_point(const FisheyeView& view, Vec3 dir);

// The world direction a photo point sees, or nullopt outside the image circle.
std::optional<Vec3> view_direction(const FisheyeView& view, PhotoPoint point);

}  // namespace relight
