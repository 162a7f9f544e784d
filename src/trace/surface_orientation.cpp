#include "trace/surface_orientation.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <utility>

#include "math/frame.h"
#include "math/sampling.h"
#include "trace/ray_tracer.h"

namespace relight {
namespace {

// Paths walked from each seed, and the surfaces each meets at most; rays from each lattice point.
constexpr int kPathsPerSeed = 256;
constexpr int kBounces = 12;
constexpr int kRaysPerSeed = 64;
// A side is enclosed when at most this fraction of its rays escapes to infinity (a room keeps
// its windows as glass and its doors as openings: a doorway lets out a few).
constexpr double kEnclosedEscapeFraction = 0.25;
// Seeds used at most, spread evenly over those given (a storey's sensors number tens of
// thousands; a thousand seeds reach every room of it); lattice seeds at most.
constexpr std::size_t kMaxSeeds = 1024;
constexpr std::size_t kMaxLatticeSeeds = 64;
// The lattice that seeds a scene without seeds: at most this many points along an axis, and a
// point is room-sized when rays along the axes find this much space around it.
constexpr int kLatticePoints = 16;
constexpr double kRoomWidth = 1.5, kRoomHeight = 2.0;
// Sides are numbered 2t (front of triangle t) and 2t + 1 (back).
constexpr std::uint32_t kEscaped = kNoHit - 1;

struct Flood {
  const TriangleSoup& soup;
  const std::vector<bool>& glass;
  std::vector<Vec3> normals;  // unit geometric normals; zero for a degenerate triangle
  RayTracer tracer;
  double epsilon = 0;
  std::vector<std::uint8_t> reached;   // per side
  std::vector<std::uint32_t> cast;     // per side: paths sent on from it
  std::vector<std::uint32_t> escaped;  // per side: of those, paths out to infinity

  bool is_glass(std::uint32_t t) const { return glass.at(soup.triangle_material[t]); }
};

std::vector<std::uint32_t> identity_ids(std::size_t n) {
  std::vector<std::uint32_t> ids(n);
  std::iota(ids.begin(), ids.end(), 0U);
  return ids;
}

Vec3 unit_normal(const TriangleSoup& soup, std::uint32_t t) {
  const Triangle& tri = soup.triangles[t];
  const Vec3 n = cross(soup.positions[tri[1]] - soup.positions[tri[0]],
                       soup.positions[tri[2]] - soup.positions[tri[0]]);
  const double len = length(n);
  return len > 0 ? n / len : Vec3{0, 0, 0};
}

// The side of the triangle a hit ray arrives at, or kEscaped / kNoHit (glass, degenerate).
std::uint32_t side_hit(const Flood& flood, const Ray& ray, const RayHit& hit) {
  if (!hit.hit()) return kEscaped;
  if (flood.is_glass(hit.triangle)) return kNoHit;
  const Vec3 n = flood.normals[hit.triangle];
  const double facing = dot(ray.direction, n);
  if (facing == 0) return kNoHit;
  return 2 * hit.triangle + (facing < 0 ? 0U : 1U);
}

// The hit point moved off the triangle's edges into its inside: a path that meets a room's
// corner turns from a point of the room, not from one a rounding error put just outside it.
Vec3 inside_point(const Flood& flood, std::uint32_t t, const RayHit& hit) {
  constexpr double kInset = 1e-4;
  const double u = std::clamp(hit.u, kInset, 1 - 2 * kInset);
  const double v = std::clamp(hit.v, kInset, 1 - kInset - u);
  const Triangle& tri = flood.soup.triangles[t];
  return flood.soup.positions[tri[0]] * (1 - u - v) + flood.soup.positions[tri[1]] * u +
         flood.soup.positions[tri[2]] * v;
}

// Walks paths from the seeds through the air: each path leaves its seed, and each surface it
// meets sends it on from the point it met, off the side it arrived at. Paths start and turn only
// at points reached through the air, so none starts inside a solid where a piece of furniture
// stands on the floor or a wall on its slab.
void walk(Flood& flood, std::span<const AirSeed> seeds) {
  struct Path {
    Ray ray;
    std::uint32_t from = kNoHit;  // the side it left, or kNoHit when it left a seed
    Pcg32 rng;
  };
  std::vector<Path> paths;
  paths.reserve(seeds.size() * kPathsPerSeed);
  for (std::size_t s = 0; s < seeds.size(); ++s) {
    const AirSeed& seed = seeds[s];
    const bool hemisphere = length(seed.facing) > 0;
    const Frame frame = frame_from_normal(hemisphere ? normalize(seed.facing) : Vec3{0, 1, 0});
    for (int i = 0; i < kPathsPerSeed; ++i) {
      Pcg32 rng(0x5eed, s * kPathsPerSeed + i);
      const double u1 = rng.next_double(), u2 = rng.next_double();
      const Vec3 d = hemisphere ? frame.to_world(sample_cosine_hemisphere(u1, u2))
                                : sample_uniform_sphere(u1, u2);
      paths.push_back({{seed.point, d, flood.epsilon}, kNoHit, rng});
    }
  }
  std::vector<Ray> rays;
  std::vector<RayHit> hits;
  for (int bounce = 0; bounce <= kBounces && !paths.empty(); ++bounce) {
    rays.resize(paths.size());
    hits.assign(paths.size(), RayHit{});
    for (std::size_t i = 0; i < paths.size(); ++i) rays[i] = paths[i].ray;
    flood.tracer.intersect(rays, hits);
    std::size_t alive = 0;
    for (std::size_t i = 0; i < paths.size(); ++i) {
      Path& path = paths[i];
      const std::uint32_t side = side_hit(flood, path.ray, hits[i]);
      if (path.from != kNoHit) {
        ++flood.cast[path.from];
        if (side == kEscaped) ++flood.escaped[path.from];
      }
      if (side >= kEscaped) continue;  // out to infinity, into glass or a degenerate triangle
      flood.reached[side] = 1;
      const std::uint32_t t = side / 2;
      const Vec3 n = (side % 2 == 0 ? 1.0 : -1.0) * flood.normals[t];
      const Vec3 d = frame_from_normal(n).to_world(
          sample_cosine_hemisphere(path.rng.next_double(), path.rng.next_double()));
      path.ray = {inside_point(flood, t, hits[i]) + n * flood.epsilon, d, 0};
      path.from = side;
      paths[alive++] = path;
    }
    paths.erase(paths.begin() + static_cast<std::ptrdiff_t>(alive), paths.end());
  }
}

// At most `most` of the seeds, evenly spread over their order.
std::vector<AirSeed> every_nth(const std::vector<AirSeed>& seeds, std::size_t most) {
  const std::size_t stride = std::max<std::size_t>(1, (seeds.size() + most - 1) / most);
  std::vector<AirSeed> kept;
  for (std::size_t i = 0; i < seeds.size(); i += stride) kept.push_back(seeds[i]);
  return kept;
}

struct Box {
  Vec3 lo{0, 0, 0}, hi{0, 0, 0};
};

Box soup_bounds(const TriangleSoup& soup) {
  Box box{soup.positions.front(), soup.positions.front()};
  for (const Vec3& p : soup.positions) {
    box.lo = {std::min(box.lo.x, p.x), std::min(box.lo.y, p.y), std::min(box.lo.z, p.z)};
    box.hi = {std::max(box.hi.x, p.x), std::max(box.hi.y, p.y), std::max(box.hi.z, p.z)};
  }
  return box;
}

// Distance to the first surface along ±axis from p, summed over both directions (infinite when
// either escapes).
double span_along(const RayTracer& tracer, Vec3 p, Vec3 axis, double epsilon) {
  double total = 0;
  for (const double sign : {1.0, -1.0}) {
    const RayHit hit = tracer.intersect({p, axis * sign, epsilon});
    if (!hit.hit()) return std::numeric_limits<double>::infinity();
    total += hit.t;
  }
  return total;
}

// Lattice points over the bounds from which every ray meets a surface and around which the axes
// find room for a person.
std::vector<AirSeed> lattice_seeds(const Flood& flood, const Box& box) {
  const Vec3 extent = box.hi - box.lo;
  const double step = std::max({extent.x, extent.y, extent.z}) / kLatticePoints;
  if (!(step > 0)) return {};
  const auto count = [&](double e) { return std::max(1, static_cast<int>(std::floor(e / step))); };
  const int nx = count(extent.x), ny = count(extent.y), nz = count(extent.z);
  std::vector<Vec3> points;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      for (int k = 0; k < nz; ++k)
        points.push_back(box.lo + Vec3{(i + 0.5) * extent.x / nx, (j + 0.5) * extent.y / ny,
                                       (k + 0.5) * extent.z / nz});
  std::vector<std::uint8_t> keep(points.size(), 0);
  tbb::parallel_for(std::size_t{0}, points.size(), [&](std::size_t i) {
    const Vec3 p = points[i];
    if (span_along(flood.tracer, p, {1, 0, 0}, flood.epsilon) < kRoomWidth ||
        span_along(flood.tracer, p, {0, 0, 1}, flood.epsilon) < kRoomWidth ||
        span_along(flood.tracer, p, {0, 1, 0}, flood.epsilon) < kRoomHeight)
      return;
    Pcg32 rng(0x1a77, i);
    for (int r = 0; r < kRaysPerSeed; ++r) {
      const Vec3 d = sample_uniform_sphere(rng.next_double(), rng.next_double());
      if (!flood.tracer.intersect({p, d, flood.epsilon}).hit()) return;
    }
    keep[i] = 1;
  });
  std::vector<AirSeed> seeds;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (keep[i] != 0) seeds.push_back({points[i]});
  return every_nth(seeds, kMaxLatticeSeeds);
}

}  // namespace

SurfaceOrientation find_turned_surfaces(const TriangleSoup& soup, const std::vector<bool>& glass,
                                        std::span<const AirSeed> seeds) {
  SurfaceOrientation result;
  const std::size_t n = soup.triangles.size();
  if (n == 0) return result;
  Flood flood{soup, glass, {}, RayTracer(soup.positions, soup.triangles, identity_ids(n)),
              0,    {},    {}, {}};
  flood.normals.resize(n);
  for (std::uint32_t t = 0; t < n; ++t) flood.normals[t] = unit_normal(soup, t);
  const Box box = soup_bounds(soup);
  flood.epsilon = 1e-6 * std::max(1.0, length(box.hi - box.lo));
  flood.reached.assign(2 * n, 0);
  flood.cast.assign(2 * n, 0);
  flood.escaped.assign(2 * n, 0);

  std::vector<AirSeed> own_seeds;
  if (seeds.empty()) {
    own_seeds = lattice_seeds(flood, box);
    result.lattice_seeds = true;
  } else {
    own_seeds = every_nth({seeds.begin(), seeds.end()}, kMaxSeeds);
  }
  seeds = own_seeds;
  walk(flood, seeds);

  for (std::uint32_t t = 0; t < n; ++t) {
    if (flood.is_glass(t) || length(flood.normals[t]) == 0) continue;
    ++result.checked;
    const std::size_t side = 2 * std::size_t{t};
    const bool front = flood.reached[side] != 0, back = flood.reached[side + 1] != 0;
    if (front) continue;
    if (!back) {
      ++result.unreached;
    } else if (flood.escaped[side + 1] <= kEnclosedEscapeFraction * flood.cast[side + 1]) {
      result.turned.push_back(t);
    } else {
      ++result.open_back_facing;
    }
  }
  return result;
}

void turn_triangles(TriangleSoup& soup, std::span<const std::uint32_t> triangles) {
  const bool textured = !soup.textures.empty();
  for (const std::uint32_t t : triangles) {
    std::swap(soup.triangles[t][1], soup.triangles[t][2]);
    if (textured) std::swap(soup.textures.corner_uv[3 * t + 1], soup.textures.corner_uv[3 * t + 2]);
  }
}

std::vector<AirSeed> air_seeds(const Scene& scene) {
  std::vector<AirSeed> seeds;
  for (const Luminaire& l : scene.luminaires) seeds.push_back({l.position});
  for (const SensorSet& set : scene.sensors)
    for (const Vec3& p : set.points) seeds.push_back({p, set.normal});
  return seeds;
}

SurfaceOrientation orient_scene_surfaces(Scene& scene) {
  std::vector<bool> glass(scene.materials.size());
  for (std::size_t m = 0; m < glass.size(); ++m) glass[m] = scene.materials[m].portal;
  const std::vector<AirSeed> seeds = air_seeds(scene);
  SurfaceOrientation orientation = find_turned_surfaces(scene.geometry, glass, seeds);
  turn_triangles(scene.geometry, orientation.turned);
  return orientation;
}

std::string orientation_warning(const SurfaceOrientation& o) {
  std::string line;
  char buffer[256];
  if (!o.turned.empty()) {
    std::snprintf(buffer, sizeof buffer,
                  "turned %zu of %zu triangles whose front faced out of the closed space they "
                  "bound (surfaces are one-sided: they would have reflected nothing into it)",
                  o.turned.size(), o.checked);
    line = buffer;
  }
  if (o.open_back_facing > 0) {
    std::snprintf(buffer, sizeof buffer,
                  "%s%zu triangles are seen only from behind, in the open, and were left as they "
                  "are: their back sides absorb",
                  line.empty() ? "" : "; ", o.open_back_facing);
    line += buffer;
  }
  return line;
}

}  // namespace relight
