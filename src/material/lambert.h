// The Lambertian surface, the model of every material without `metallic` or `roughness`: under
// illuminance E (lx) a diffuse surface of albedo ρ has luminance L = ρE/π (cd/m²), per
// colour channel. Every place that turns irradiance into radiance — vertex and pixel
// shading, the studio's frames, the reference tracer's next-event estimate, the near-field
// images — calls this. Pinned by tests/reference/reference_closed_form_test.cpp (a diffuse
// patch under a point source against I·cosθ/d² · ρ/π).
#pragma once

#include "math/rgb.h"
#include "math/vec3.h"

namespace relight {

constexpr Rgb lambertian_radiance(Rgb albedo, Rgb irradiance) {
  return albedo * irradiance * (1 / kPi);
}

constexpr double lambertian_radiance(double albedo, double irradiance) {
  return albedo * irradiance / kPi;
}

}  // namespace relight
