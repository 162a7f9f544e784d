// Welding: positions closer than epsilon become one vertex, so triangles that touch share
// vertices and transfer is continuous across them. Positions are hashed on a grid of cells
// 4 epsilon wide; a position looks into a neighbouring cell only when it lies within epsilon
// of that cell's border, so a near neighbour across a border is found while most lookups
// touch a single cell. The first position of a cluster is its representative (no averaging,
// so welded geometry stays where the file put it).
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "scene/mesh_preparation_steps.h"

namespace relight {
namespace {

struct CellKey {
  std::int64_t x = 0, y = 0, z = 0;
  bool operator==(const CellKey&) const = default;
};

std::uint64_t mix(std::uint64_t h) {
  h ^= h >> 33;
  h *= 0xff51afd7ed558ccdULL;
  h ^= h >> 33;
  h *= 0xc4ceb9fe1a85ec53ULL;
  h ^= h >> 33;
  return h;
}

struct CellHash {
  std::size_t operator()(const CellKey& k) const {
    return mix(static_cast<std::uint64_t>(k.x) * 0x9e3779b97f4a7c15ULL ^
               mix(static_cast<std::uint64_t>(k.y) + 0x632be59bd9b4e019ULL) ^
               (static_cast<std::uint64_t>(k.z) << 21 | static_cast<std::uint64_t>(k.z) >> 43));
  }
};

constexpr std::uint32_t kNone = 0xffffffffu;

WeldResult weld_exact(std::span<const Vec3> positions) {
  WeldResult result;
  result.remap.resize(positions.size());
  std::unordered_map<CellKey, std::uint32_t, CellHash> seen;
  seen.reserve(positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const Vec3 p = positions[i];
    // + 0.0 turns -0.0 into +0.0, so both hash alike.
    const CellKey key{std::bit_cast<std::int64_t>(p.x + 0.0),
                      std::bit_cast<std::int64_t>(p.y + 0.0),
                      std::bit_cast<std::int64_t>(p.z + 0.0)};
    const auto [it, inserted] =
        seen.try_emplace(key, static_cast<std::uint32_t>(result.positions.size()));
    if (inserted) result.positions.push_back(p);
    result.remap[i] = it->second;
  }
  return result;
}

}  // namespace

WeldResult weld_positions(std::span<const Vec3> positions, double epsilon) {
  if (!(epsilon > 0)) return weld_exact(positions);

  double largest = 0;
  for (const Vec3& p : positions) {
    largest = std::max({largest, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  }
  // Cells at least 2 epsilon wide (so at most one neighbour per axis is needed), and wide
  // enough that cell coordinates stay far inside int64.
  const double cell = std::max(4 * epsilon, largest * 0x1p-50);
  const double reach = epsilon / cell;  // epsilon in cell units, <= 1/4
  const double epsilon2 = epsilon * epsilon;

  WeldResult result;
  result.remap.resize(positions.size());
  std::unordered_map<CellKey, std::uint32_t, CellHash> first_in_cell;
  first_in_cell.reserve(positions.size());
  std::vector<std::uint32_t> next_in_cell;  // per representative: chain within its cell

  for (std::size_t i = 0; i < positions.size(); ++i) {
    const Vec3 p = positions[i];
    const Vec3 scaled = p / cell;
    const CellKey home{static_cast<std::int64_t>(std::floor(scaled.x)),
                       static_cast<std::int64_t>(std::floor(scaled.y)),
                       static_cast<std::int64_t>(std::floor(scaled.z))};
    int lo[3], hi[3];
    const double fraction[3] = {scaled.x - std::floor(scaled.x), scaled.y - std::floor(scaled.y),
                                scaled.z - std::floor(scaled.z)};
    for (int a = 0; a < 3; ++a) {
      lo[a] = fraction[a] < reach ? -1 : 0;
      hi[a] = fraction[a] > 1 - reach ? 1 : 0;
    }
    std::uint32_t match = kNone;
    for (int dx = lo[0]; dx <= hi[0] && match == kNone; ++dx) {
      for (int dy = lo[1]; dy <= hi[1] && match == kNone; ++dy) {
        for (int dz = lo[2]; dz <= hi[2] && match == kNone; ++dz) {
          const auto it = first_in_cell.find({home.x + dx, home.y + dy, home.z + dz});
          if (it == first_in_cell.end()) continue;
          for (std::uint32_t r = it->second; r != kNone; r = next_in_cell[r]) {
            const Vec3 d = result.positions[r] - p;
            if (dot(d, d) <= epsilon2) {
              match = r;
              break;
            }
          }
        }
      }
    }
    if (match == kNone) {
      match = static_cast<std::uint32_t>(result.positions.size());
      result.positions.push_back(p);
      const auto [it, inserted] = first_in_cell.try_emplace(home, match);
      next_in_cell.push_back(inserted ? kNone : it->second);
      it->second = match;
    }
    result.remap[i] = match;
  }
  return result;
}

}  // namespace relight
