#include "light/environment_clusters.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <tbb/parallel_for.h>

#include "math/equirect.h"

namespace relight {

namespace {

// The mean spacing of N uniform directions.
double leaf_spacing(const DirectionTree& tree) {
  return std::sqrt(4 * kPi / static_cast<double>(tree.leaf_count()));
}

// M += L · w · ω.
void add_moment(RgbMoment& m, Rgb l, double w, Vec3 d) {
  const double c[3] = {d.x, d.y, d.z};
  for (int i = 0; i < 3; ++i) {
    m.r[i] += static_cast<float>(l.r * w * c[i]);
    m.g[i] += static_cast<float>(l.g * w * c[i]);
    m.b[i] += static_cast<float>(l.b * w * c[i]);
  }
}

// Gives L·Ω·ω of every part of an equirectangular grid of W × H texels, each split into k × k
// parts, to the nearest leaf; `radiance(i, j, ω_map)` the radiance of texel (i, j) in map
// direction ω_map (called from many threads) and `to_world` a map direction in the frame.
// The radiance and the nearest leaf of a band of rows are found in parallel, then deposited in the
// grid's order, so the moments are those of one thread. With `kept` (parts no more than
// kMaxKeptParts) every part's directions and nearest leaf are found once for the grid and frame and
// kept there; only the radiance is found again, as the nearest leaf is most of the cost of a sun
// moving frame to frame (measured: docs/decisions.md).
constexpr std::size_t kMaxKeptParts = std::size_t{1} << 18;

template <typename Radiance, typename ToWorld>
void deposit_grid(int width, int height, int k, const Radiance& radiance, const ToWorld& to_world,
                  const PointGrid& leaves, std::vector<RgbMoment>& node, std::size_t n,
                  const EnvironmentGridKey& key, EnvironmentGridParts* kept) {
  const int w = width * k, h = height * k;
  const std::size_t parts = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  const auto map_direction = [&](int i, int j) {
    return equirect_direction((i + 0.5) / w, (j + 0.5) / h);
  };
  if (kept != nullptr && parts <= kMaxKeptParts) {
    EnvironmentGridParts& g = *kept;
    if (!(g.key == key) || g.leaves != &leaves || g.leaf.size() != parts) {
      g.key = key;
      g.leaves = &leaves;
      g.map_direction.resize(parts);
      g.direction.resize(parts);
      g.leaf.resize(parts);
      tbb::parallel_for(0, h, [&](int j) {
        for (int i = 0; i < w; ++i) {
          const std::size_t t = static_cast<std::size_t>(j) * w + i;
          g.map_direction[t] = map_direction(i, j);
          g.direction[t] = to_world(g.map_direction[t]);
          g.leaf[t] = static_cast<std::uint32_t>(leaves.nearest(g.direction[t]));
        }
      });
    }
    std::vector<Rgb> l(parts);
    tbb::parallel_for(0, h, [&](int j) {
      for (int i = 0; i < w; ++i) {
        const std::size_t t = static_cast<std::size_t>(j) * w + i;
        l[t] = radiance(i / k, j / k, g.map_direction[t]);
      }
    });
    for (int j = 0; j < h; ++j) {
      const double omega = equirect_row_solid_angle(w, h, j);
      for (int i = 0; i < w; ++i) {
        const std::size_t t = static_cast<std::size_t>(j) * w + i;
        if (l[t].r == 0 && l[t].g == 0 && l[t].b == 0) continue;
        add_moment(node[n + g.leaf[t]], l[t], omega, g.direction[t]);
      }
    }
    return;
  }
  struct Part {
    std::uint32_t leaf = 0;
    Rgb l;
    Vec3 d;
  };
  constexpr int kBand = 16;
  std::vector<std::vector<Part>> rows(kBand);
  for (int band = 0; band < h; band += kBand) {
    const int last = std::min(h, band + kBand);
    tbb::parallel_for(band, last, [&](int j) {
      std::vector<Part>& row = rows[static_cast<std::size_t>(j - band)];
      row.clear();
      for (int i = 0; i < w; ++i) {
        const Vec3 m = map_direction(i, j);
        const Rgb l = radiance(i / k, j / k, m);
        if (l.r == 0 && l.g == 0 && l.b == 0) continue;
        const Vec3 d = to_world(m);
        row.push_back({static_cast<std::uint32_t>(leaves.nearest(d)), l, d});
      }
    });
    for (int j = band; j < last; ++j) {
      const double omega = equirect_row_solid_angle(w, h, j);
      for (const Part& p : rows[static_cast<std::size_t>(j - band)]) {
        add_moment(node[n + p.leaf], p.l, omega, p.d);
      }
    }
  }
}

}  // namespace

Vec3 moment_direction(const RgbMoment& m, Vec3 fallback) {
  const Vec3 d{luminance({m.r[0], m.g[0], m.b[0]}), luminance({m.r[1], m.g[1], m.b[1]}),
               luminance({m.r[2], m.g[2], m.b[2]})};
  return length(d) > 0 ? normalize(d) : fallback;
}

std::vector<Vec3> moment_directions(std::span<const RgbMoment> moments, const DirectionTree& tree) {
  std::vector<Vec3> out(moments.size());
  for (std::size_t k = 1; k < moments.size(); ++k)
    out[k] = moment_direction(moments[k], tree.axis[k]);
  return out;
}

PointGrid leaf_grid(const DirectionTree& tree) {
  return PointGrid(tree.leaves, 2 * leaf_spacing(tree));
}

std::vector<RgbMoment> environment_moments(const Environment& env, const DirectionTree& tree,
                                           const PointGrid& leaves, double frame_rotate_deg,
                                           const CompactSources* traced,
                                           EnvironmentGridParts* kept) {
  const bool mask = traced != nullptr && !traced->map_texels.empty();
  // World → the object's frame: the turn undone.
  const Placement back{{0, 0, 0}, -frame_rotate_deg};
  const auto to_frame = [&](Vec3 d) { return placed_direction(d, back); };
  const std::size_t n = tree.leaf_count();
  const double spacing = leaf_spacing(tree);
  std::vector<RgbMoment> node(2 * n);
  switch (env.kind) {
    case EnvironmentKind::kUniform:
      for (std::size_t i = 0; i < n; ++i) {
        add_moment(node[n + i], env.uniform_radiance, 4 * kPi / static_cast<double>(n),
                   tree.leaves[i]);
      }
      break;
    case EnvironmentKind::kMap: {
      const EquirectMap& map = *env.map;
      // The parts at most half the spacing across, in azimuth at the equator and in elevation.
      const double texel = std::max(2 * kPi / map.width, kPi / map.height);
      const int k = std::max(1, static_cast<int>(std::ceil(texel / (0.5 * spacing))));
      const MapRotation rotation(env.rotate_deg);
      deposit_grid(
          map.width, map.height, k,
          [&](int i, int j, Vec3) {
            const std::size_t t = static_cast<std::size_t>(j) * map.width + i;
            return mask && traced->map_texels[t] ? Rgb{} : map.texels[t] * env.scale;
          },
          [&](Vec3 d) { return to_frame(rotation.to_world(d)); }, leaves, node, n,
          {true, map.width, map.height, k, frame_rotate_deg, env.rotate_deg}, kept);
      break;
    }
    case EnvironmentKind::kSky: {
      const int height = static_cast<int>(std::ceil(kPi / (1.0 * spacing)));
      deposit_grid(
          2 * height, height, 1, [&](int, int, Vec3 d) { return env.diffuse_radiance(d); },
          to_frame, leaves, node, n, {false, 2 * height, height, 1, frame_rotate_deg, 0}, kept);
      if (const std::optional<SunDisc>& sun = env.sun(); sun && !(traced && traced->sky_sun)) {
        constexpr int kSpiral = 64;
        const double share = sun->integrated_luminance() / kSpiral;
        for (const Vec3& world : sun_disc_spiral(*sun, kSpiral)) {
          const Vec3 d = to_frame(world);
          add_moment(node[n + leaves.nearest(d)], Rgb{1, 1, 1}, share, d);
        }
      }
      break;
    }
  }
  for (std::size_t k = n - 1; k >= 1; --k) {
    node[k] = node[2 * k];
    node[k] += node[2 * k + 1];
  }
  return node;
}

}  // namespace relight
