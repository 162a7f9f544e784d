#include "light/compact_sources.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "math/equirect.h"

namespace relight {

namespace {

struct Region {
  std::vector<std::size_t> texels;
  Rgb integral;  // Σ L Ω
  double y = 0;  // Σ Y Ω
};

}  // namespace

CompactSources find_compact_sources(const Environment& env) {
  CompactSources out;
  if (env.kind == EnvironmentKind::kSky) {
    if (const std::optional<SunDisc>& sun = env.sun()) {
      const double e = sun->normal_illuminance;
      out.sources.push_back({*sun, Rgb{e, e, e}, disc_directions(*sun)});
      out.sky_sun = true;
    }
    return out;
  }
  if (env.kind != EnvironmentKind::kMap) return out;
  const EquirectMap& map = *env.map;
  const int w = map.width, h = map.height;
  const std::size_t count = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  std::vector<double> omega(static_cast<std::size_t>(h));
  double total = 0;
  for (int j = 0; j < h; ++j) {
    omega[static_cast<std::size_t>(j)] = equirect_row_solid_angle(w, h, j);
    for (int i = 0; i < w; ++i) {
      total += luminance(map.texels[static_cast<std::size_t>(j) * w + i]) *
               omega[static_cast<std::size_t>(j)];
    }
  }
  out.map_texels.assign(count, 0);
  if (!(total > 0)) return out;
  const double threshold = kCompactContrast * total / (4 * kPi);
  // Regions of bright texels, grown from each unvisited one (8-connected, wrapping in u).
  std::vector<std::uint8_t> seen(count, 0);
  std::vector<Region> regions;
  std::vector<std::size_t> stack;
  for (std::size_t start = 0; start < count; ++start) {
    if (seen[start] || luminance(map.texels[start]) < threshold) continue;
    Region region;
    seen[start] = 1;
    stack.push_back(start);
    while (!stack.empty()) {
      const std::size_t t = stack.back();
      stack.pop_back();
      region.texels.push_back(t);
      const int i = static_cast<int>(t % static_cast<std::size_t>(w));
      const int j = static_cast<int>(t / static_cast<std::size_t>(w));
      const double o = omega[static_cast<std::size_t>(j)];
      region.integral += map.texels[t] * o;
      region.y += luminance(map.texels[t]) * o;
      for (int dj = -1; dj <= 1; ++dj) {
        const int jj = j + dj;
        if (jj < 0 || jj >= h) continue;
        for (int di = -1; di <= 1; ++di) {
          const int ii = (i + di + w) % w;
          const std::size_t u = static_cast<std::size_t>(jj) * w + ii;
          if (seen[u] || luminance(map.texels[u]) < threshold) continue;
          seen[u] = 1;
          stack.push_back(u);
        }
      }
    }
    if (region.y >= kCompactMinShare * total) regions.push_back(std::move(region));
  }
  std::sort(regions.begin(), regions.end(),
            [](const Region& a, const Region& b) { return a.y > b.y; });
  const MapRotation rotation(env.rotate_deg);
  const double max_radius = kCompactMaxRadiusDeg * kPi / 180;
  for (const Region& region : regions) {
    if (static_cast<int>(out.sources.size()) == kMaxCompactSources) break;
    // The luminance centroid and the region's solid angle, in the map's frame.
    Vec3 centroid;
    double solid_angle = 0;
    for (const std::size_t t : region.texels) {
      const int i = static_cast<int>(t % static_cast<std::size_t>(w));
      const int j = static_cast<int>(t / static_cast<std::size_t>(w));
      const double o = omega[static_cast<std::size_t>(j)];
      centroid += equirect_texel_direction(w, h, i, j) * (luminance(map.texels[t]) * o);
      solid_angle += o;
    }
    centroid = normalize(centroid);
    // Every texel's cell within the limit: its centre's angle plus half its diagonal.
    bool compact = true;
    for (const std::size_t t : region.texels) {
      const int i = static_cast<int>(t % static_cast<std::size_t>(w));
      const int j = static_cast<int>(t / static_cast<std::size_t>(w));
      const Vec3 d = equirect_texel_direction(w, h, i, j);
      const double sin_polar = std::sqrt(std::max(0.0, 1 - d.y * d.y));
      const double half_diagonal = 0.5 * std::hypot(2 * kPi / w * sin_polar, kPi / h);
      if (std::acos(std::clamp(dot(d, centroid), -1.0, 1.0)) + half_diagonal > max_radius) {
        compact = false;
        break;
      }
    }
    if (!compact) continue;
    // A uniform disc of the region's solid angle: 2π(1 − cos r) = Ω; E_n = ∫L dω · π sin²r / Ω.
    const double radius = std::acos(1 - solid_angle / (2 * kPi));
    const double to_normal = kPi * std::sin(radius) * std::sin(radius) / solid_angle;
    const Rgb e = region.integral * (env.scale * to_normal);
    const SunDisc disc = make_source_disc(rotation.to_world(centroid), radius, luminance(e));
    out.sources.push_back({disc, e, disc_directions(disc)});
    for (const std::size_t t : region.texels) out.map_texels[t] = 1;
  }
  return out;
}

}  // namespace relight
