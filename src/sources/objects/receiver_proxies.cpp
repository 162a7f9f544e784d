#include "sources/objects/receiver_proxies.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <unordered_map>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace relight {

namespace {

constexpr double kSameSurfaceCos = 0.9063;  // cos 25°
constexpr double kPlaneTolerance = 0.25;    // of a spacing
constexpr double kReach = 1.5;              // of a spacing
constexpr std::size_t kStencil = 4;

using Cell = std::array<std::int64_t, 3>;

Cell cell_of(Vec3 p, double spacing) {
  return {static_cast<std::int64_t>(std::floor(p.x / spacing)),
          static_cast<std::int64_t>(std::floor(p.y / spacing)),
          static_cast<std::int64_t>(std::floor(p.z / spacing))};
}

struct CellHash {
  std::size_t operator()(const Cell& c) const {
    std::uint64_t h = 1469598103934665603ULL;
    for (const std::int64_t v : c) h = (h ^ static_cast<std::uint64_t>(v)) * 1099511628211ULL;
    return static_cast<std::size_t>(h);
  }
};

struct Surfaces {
  std::span<const Vec3> points, normals;
  std::span<const std::uint32_t> group;
  double spacing;
  // Whether vertex b lies on vertex a's surface.
  bool same(std::size_t a, std::size_t b) const {
    return group[a] == group[b] && dot(normals[a], normals[b]) >= kSameSurfaceCos &&
           std::abs(dot(points[b] - points[a], normals[a])) <= kPlaneTolerance * spacing;
  }
};

}  // namespace

double default_proxy_spacing(std::span<const Vec3> points) {
  if (points.empty()) return 1;
  Vec3 lo = points[0], hi = points[0];
  for (const Vec3& p : points) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  const double diagonal = length(hi - lo);
  return diagonal > 0 ? diagonal / 64 : 1;
}

ReceiverProxies build_receiver_proxies(std::span<const Vec3> points, std::span<const Vec3> normals,
                                       std::span<const std::uint32_t> group, double spacing) {
  if (points.size() != normals.size() || points.size() != group.size() || !(spacing > 0)) {
    throw std::invalid_argument(
        "receiver proxies: one normal and group per point and a positive spacing");
  }
  const std::size_t n = points.size();
  const Surfaces surfaces{points, normals, group, spacing};
  // Clusters per cell: the first member's point and normal define the surface.
  std::unordered_map<Cell, std::vector<std::uint32_t>, CellHash> cells;  // cell → its clusters
  std::vector<std::uint32_t> cluster_seed, cluster_of(n);
  std::vector<std::vector<std::uint32_t>> members;
  for (std::size_t v = 0; v < n; ++v) {
    std::vector<std::uint32_t>& here = cells[cell_of(points[v], spacing)];
    std::uint32_t found = std::numeric_limits<std::uint32_t>::max();
    for (const std::uint32_t c : here) {
      if (surfaces.same(cluster_seed[c], v)) {
        found = c;
        break;
      }
    }
    if (found == std::numeric_limits<std::uint32_t>::max()) {
      found = static_cast<std::uint32_t>(cluster_seed.size());
      cluster_seed.push_back(static_cast<std::uint32_t>(v));
      members.emplace_back();
      here.push_back(found);
    }
    cluster_of[v] = found;
    members[found].push_back(static_cast<std::uint32_t>(v));
  }
  // Each cluster's proxy: the member nearest the members' mean.
  ReceiverProxies out;
  out.spacing = spacing;
  out.proxy_of.assign(n, -1);
  std::vector<std::uint32_t> cluster_proxy(members.size());
  for (std::size_t c = 0; c < members.size(); ++c) {
    Vec3 mean{};
    for (const std::uint32_t v : members[c]) mean += points[v];
    mean = mean / static_cast<double>(members[c].size());
    std::uint32_t best = members[c][0];
    for (const std::uint32_t v : members[c]) {
      if (length(points[v] - mean) < length(points[best] - mean)) best = v;
    }
    cluster_proxy[c] = best;
  }
  std::vector<std::uint32_t> sorted = cluster_proxy;
  std::sort(sorted.begin(), sorted.end());
  out.proxies = sorted;
  for (std::size_t j = 0; j < sorted.size(); ++j) {
    out.proxy_of[sorted[j]] = static_cast<std::int32_t>(j);
  }
  // Stencils: the nearest proxies on the vertex's surface within reach.
  std::vector<std::array<std::pair<float, std::uint32_t>, kStencil>> best(n);
  std::vector<std::uint8_t> count(n, 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1024), [&](const auto& range) {
    for (std::size_t v = range.begin(); v != range.end(); ++v) {
      auto& slots = best[v];
      std::uint8_t& used = count[v];
      const auto offer = [&](float w, std::uint32_t j) {
        for (std::size_t i = 0; i < used; ++i) {
          if (slots[i].second == j) return;
        }
        if (used < kStencil) {
          slots[used++] = {w, j};
        } else {
          auto weakest = std::min_element(slots.begin(), slots.end());
          if (weakest->first < w) *weakest = {w, j};
        }
      };
      const std::uint32_t own =
          static_cast<std::uint32_t>(out.proxy_of[cluster_proxy[cluster_of[v]]]);
      if (out.proxy_of[v] >= 0) {
        offer(1, static_cast<std::uint32_t>(out.proxy_of[v]));
        continue;
      }
      const Cell c = cell_of(points[v], spacing);
      for (std::int64_t dx = -1; dx <= 1; ++dx) {
        for (std::int64_t dy = -1; dy <= 1; ++dy) {
          for (std::int64_t dz = -1; dz <= 1; ++dz) {
            const auto it = cells.find({c[0] + dx, c[1] + dy, c[2] + dz});
            if (it == cells.end()) continue;
            for (const std::uint32_t cluster : it->second) {
              const std::uint32_t p = cluster_proxy[cluster];
              const double d = length(points[p] - points[v]) / (kReach * spacing);
              if (d >= 1 || !surfaces.same(v, p)) {
                continue;
              }
              offer(static_cast<float>((1 - d) * (1 - d)),
                    static_cast<std::uint32_t>(out.proxy_of[p]));
            }
          }
        }
      }
      // Its own cluster's proxy always counts, however far within the cell.
      bool has_own = false;
      for (std::size_t i = 0; i < used; ++i) has_own = has_own || slots[i].second == own;
      if (!has_own) {
        if (used < kStencil) {
          slots[used++] = {1e-3f, own};
        } else {
          *std::min_element(slots.begin(), slots.end()) = {1e-3f, own};
        }
      }
    }
  });
  for (std::size_t v = 0; v < n; ++v) {
    float total = 0;
    for (std::size_t i = 0; i < count[v]; ++i) total += best[v][i].first;
    for (std::size_t i = 0; i < count[v]; ++i) {
      out.stencil.push_back(best[v][i].second);
      out.weights.push_back(best[v][i].first / total);
    }
    out.first.push_back(static_cast<std::uint32_t>(out.stencil.size()));
  }
  return out;
}

bool takes_proxy_row(const ReceiverProxies& proxies, std::size_t vertex, Vec3 point,
                     const BoundingSphere& sphere, double distance) {
  return proxies.proxy_of[vertex] < 0 && sphere.radius > 0 &&
         length(point - sphere.centre) - sphere.radius >= distance * proxies.spacing;
}

void spread_from_proxies(const ReceiverProxies& proxies,
                         std::span<const std::span<const std::uint8_t>> use,
                         std::span<const float> values, std::span<float> out) {
  const std::size_t count = proxies.proxies.size(), vertices = proxies.first.size() - 1;
  bool sizes = values.size() == 3 * count * use.size() && out.size() >= 3 * vertices;
  for (const auto& u : use) sizes = sizes && u.size() == vertices;
  if (!sizes) throw std::invalid_argument("receiver proxies: sizes disagree");
  // A vertex far from most objects takes most layers: it sums the proxies' totals over all
  // layers less the few it does not take.
  std::vector<float> total(3 * count, 0.0f);
  for (std::size_t l = 0; l < use.size(); ++l) {
    for (std::size_t i = 0; i < 3 * count; ++i) total[i] += values[3 * l * count + i];
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, vertices, 2048), [&](const auto& range) {
    for (std::size_t v = range.begin(); v != range.end(); ++v) {
      std::size_t used = 0;
      for (const auto& u : use) used += u[v] != 0 ? 1 : 0;
      if (used == 0) continue;
      const bool by_total = 2 * used > use.size();
      float sum[3] = {0, 0, 0};
      for (std::uint32_t i = proxies.first[v]; i < proxies.first[v + 1]; ++i) {
        const std::size_t j = proxies.stencil[i];
        float x[3] = {0, 0, 0};
        if (by_total) std::copy_n(&total[3 * j], 3, x);
        for (std::size_t l = 0; l < use.size(); ++l) {
          if ((use[l][v] != 0) == by_total) continue;  // counted by the total, or not taken
          const float sign = by_total ? -1.0f : 1.0f;
          for (std::size_t k = 0; k < 3; ++k) x[k] += sign * values[3 * (l * count + j) + k];
        }
        for (std::size_t k = 0; k < 3; ++k) sum[k] += proxies.weights[i] * x[k];
      }
      for (std::size_t k = 0; k < 3; ++k) out[3 * v + k] += sum[k];
    }
  });
}

}  // namespace relight
