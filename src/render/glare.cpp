// Glare at an observer's eye: UGR and DGP; formulas and choices in glare.h.
#include "render/glare.h"

#include <cmath>
#include <stdexcept>

#include "math/rgb.h"
#include "render/relit_scene_image.h"
#include "runtime/direct_light.h"
#include "trace/ray_tracer.h"

namespace relight {

namespace {

constexpr double kGlareFactor = 5;  // sources: brighter than 5 × the view's mean luminance

}  // namespace

double guth_position_index(Vec3 view, Vec3 up, Vec3 source) {
  const double forward = dot(source, view);
  const double sigma = degrees(std::acos(std::clamp(forward, -1.0, 1.0)));
  const Vec3 side = source - view * forward;  // the source's offset from the line of sight
  const double right = std::abs(dot(side, cross(view, up)));
  const double above = std::abs(dot(side, up));  // below: mirrored (glare.h)
  const double tau = degrees(std::atan2(right, above));
  const double ln_p = (35.2 - 0.31889 * tau - 1.22 * std::exp(-2 * tau / 9)) * 1e-3 * sigma +
                      (21 + 0.26667 * tau - 0.002963 * tau * tau) * 1e-5 * sigma * sigma;
  return std::exp(ln_p);
}

GlareResult evaluate_glare(RelitScene& scene, Vec3 eye, Vec3 view_direction, int n) {
  if (!(length(view_direction) > 0)) throw std::invalid_argument("glare: a zero view direction");
  const Vec3 view = normalize(view_direction);
  const Vec3 world_up = std::abs(view.y) > 0.999 ? Vec3{0, 0, -1} : Vec3{0, 1, 0};
  const Vec3 up = normalize(world_up - view * dot(world_up, view));
  const Vec3 right = cross(view, up);
  GlareResult out;

  // The view hemisphere, 2n² directions of equal solid angle.
  const int rows = n, columns = 2 * n;
  const double omega = 2 * kPi / (rows * columns);
  std::vector<Ray> rays;
  rays.reserve(static_cast<std::size_t>(rows) * columns);
  for (int i = 0; i < rows; ++i) {
    const double c = (i + 0.5) / rows, sn = std::sqrt(1 - c * c);
    for (int j = 0; j < columns; ++j) {
      const double phi = 2 * kPi * (j + 0.5) / columns;
      rays.push_back({eye, view * c + up * (sn * std::cos(phi)) + right * (sn * std::sin(phi))});
    }
  }
  const std::vector<Rgb> seen = relit_scene_luminance(scene, rays, false);
  double e_view = 0;
  for (std::size_t k = 0; k < rays.size(); ++k) {
    e_view += luminance(seen[k]) * dot(rays[k].direction, view) * omega;
  }

  // Every light's direct light at the eye, exactly (runtime/direct_light.h), and each light
  // in view a source of its own luminance and solid angle.
  const DirectLight direct(scene);
  double direct_ev = 0;
  std::vector<GlareSource> lights;
  double ugr_sum = 0;
  bool any_luminaire = false;
  direct.for_each_at(
      eye, view, true, [&](LightKind kind, std::string_view name, const SeenLight& light) {
        const double e = luminance(light.irradiance);
        direct_ev += e;
        if (kind == LightKind::kLuminaire) out.luminaire_direct_ev += e;
        if (!light.in_view) return;
        if (!(light.luminance > 0 && light.solid_angle > 0)) {  // a point source in view
          if (kind == LightKind::kLuminaire) out.unrated.emplace_back(name);
          return;
        }
        GlareSource src{std::string(light_kind_name(kind)),
                        std::string(name),
                        light.direction,
                        light.luminance,
                        light.solid_angle,
                        guth_position_index(view, up, light.direction)};
        if (kind == LightKind::kLuminaire && dot(light.direction, up) > 0) {  // UGR: above the
          ugr_sum += src.luminance * src.luminance * src.solid_angle /        // line of sight
                     (src.position_index * src.position_index);
          any_luminaire = true;
        }
        lights.push_back(std::move(src));
      });
  out.ev = e_view + direct_ev;
  out.background_luminance = (out.ev - out.luminaire_direct_ev) / kPi;
  if (any_luminaire && out.background_luminance > 0) {
    out.ugr = 8 * std::log10(0.25 / out.background_luminance * ugr_sum);
  }

  // DGP: every source brighter than 5 × E_v/π.
  const double threshold = kGlareFactor * out.ev / kPi;
  double dgp_sum = 0;
  const auto add = [&](const GlareSource& src) {
    if (src.luminance <= threshold || out.ev <= 0) return;
    dgp_sum += src.luminance * src.luminance * src.solid_angle /
               (std::pow(out.ev, 1.87) * src.position_index * src.position_index);
    out.sources.push_back(src);
  };
  // The view's bright directions add to the sum one by one, and are reported as one source:
  // their solid angle, mean luminance and mean direction.
  GlareSource bright{"view", "", {}, 0, 0, 1};
  for (std::size_t k = 0; k < rays.size(); ++k) {
    const double l = luminance(seen[k]);
    if (l <= threshold || out.ev <= 0) continue;
    const double p = guth_position_index(view, up, rays[k].direction);
    dgp_sum += l * l * omega / (std::pow(out.ev, 1.87) * p * p);
    bright.solid_angle += omega;
    bright.luminance += l * omega;
    bright.direction += rays[k].direction * (l * omega);
  }
  if (bright.solid_angle > 0) {
    bright.luminance /= bright.solid_angle;
    bright.direction = normalize(bright.direction);
    bright.position_index = guth_position_index(view, up, bright.direction);
    out.sources.push_back(bright);
  }
  for (const GlareSource& src : lights) add(src);
  out.dgp = 5.87e-5 * out.ev + 9.18e-2 * std::log10(1 + dgp_sum) + 0.16;
  return out;
}

}  // namespace relight
