// The image circle of a fisheye photo (capture/capture.h): a phone's clip-on fisheye is rarely
// centred on the sensor, so its centre and radius are measured, not assumed.
//
// Method: outside the circle the sensor sees nothing (black, up to noise). From a rough centre
// (the centroid of the lit pixels) 720 rays are walked from the photo's edge inward to the
// first run of three lit pixels ("lit": above 5 % of full scale in the brightest channel); a
// dark band just inside the rim (the lens frame's reflection) does not stop the walk because
// it is reached from outside. Rays whose first lit pixel is the photo's own edge (a circle
// cropped by the frame) are dropped. An algebraic least-squares circle (Kåsa 1976) is fitted
// to the edge points, points further than 2 px from it are dropped and the fit repeated.
// Coordinates are in pixels with pixel (x, y) covering [x, x + 1) × [y, y + 1), y down.
// Pinned by tests/capture/image_circle_test.cpp (synthetic circles: centre within 0.5 px).
#pragma once

#include <string>

#include "image/photo.h"

namespace relight {

struct ImageCircle {
  double cx = 0, cy = 0, radius = 0;
};

// The circle of the photo (its longest exposure, where most of the circle is lit). Throws
// InputError "WHERE: reason" when fewer than 24 edge points are found (no fisheye circle).
ImageCircle find_image_circle(const Photo& photo, const std::string& where);

}  // namespace relight
