#include "transfer/portal_direct.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "common/progress.h"
#include "math/cubemap.h"
#include "math/sampling.h"
#include "math/sh.h"

namespace relight {

namespace {

constexpr std::size_t kChunk = 64;  // receivers per unit of parallel work

// Solid angle of the triangle (a, b, c) seen from the origin (Van Oosterom & Strackee 1983).
double triangle_solid_angle(Vec3 a, Vec3 b, Vec3 c) {
  const double la = length(a), lb = length(b), lc = length(c);
  const double numerator = std::abs(dot(a, cross(b, c)));
  const double denominator = la * lb * lc + dot(a, b) * lc + dot(a, c) * lb + dot(b, c) * la;
  return 2 * std::atan2(numerator, denominator);
}

struct Scratch {
  Scratch(int n, std::size_t triangles, int bases)
      : cells(cubemap_texel_count(n), 0.0),
        omega(triangles),
        cdf(triangles),
        sh(static_cast<std::size_t>(bases)),
        basis(static_cast<std::size_t>(bases)) {}
  std::vector<double> cells;
  std::vector<std::uint32_t> touched;
  std::vector<double> omega, cdf, sh, basis;
  CubemapEncodeScratch encode;
};

struct ChunkOutput {
  std::vector<std::uint8_t> bytes;
  std::vector<std::uint32_t> sizes;
  std::vector<EncodedReceiver> encoded;
  Vec3 flow{0, 0, 0};  // Σ weight · direction: where the light comes from
  std::uint64_t rays = 0, samples = 0;
};

struct PortalTriangles {
  std::vector<Vec3> a, b, c, unit_normal;
};

PortalTriangles portal_triangles(const PreparedMesh& mesh, const PortalGeometry& portal) {
  PortalTriangles t;
  for (std::uint32_t id : portal.triangles) {
    const Triangle& tri = mesh.triangles[id];
    t.a.push_back(mesh.positions[tri[0]]);
    t.b.push_back(mesh.positions[tri[1]]);
    t.c.push_back(mesh.positions[tri[2]]);
    t.unit_normal.push_back(normalize(cross(t.b.back() - t.a.back(), t.c.back() - t.a.back())));
  }
  return t;
}

std::uint32_t next_power_of_two(std::uint64_t v) {
  std::uint32_t p = 1;
  while (p < v && p < (1u << 30)) p <<= 1;
  return p;
}

// Fills scratch.cells (touched cells listed) and scratch.sh for one receiver.
void sample_receiver(Vec3 point, Vec3 normal, std::size_t receiver, const PortalTriangles& tris,
                     const PortalGeometry& portal, const TracedScene& traced,
                     const PortalDirectSettings& s, Scratch& scratch, ChunkOutput& out) {
  const int n = s.face_size;
  std::fill(scratch.sh.begin(), scratch.sh.end(), 0.0);
  const Vec3 origin = offset_from_surface(point, normal);
  double total = 0;
  for (std::size_t i = 0; i < tris.a.size(); ++i) {
    const Vec3 a = tris.a[i] - origin, b = tris.b[i] - origin, c = tris.c[i] - origin;
    const bool in_front = dot(a, normal) > 0 || dot(b, normal) > 0 || dot(c, normal) > 0;
    scratch.omega[i] = in_front ? triangle_solid_angle(a, b, c) : 0.0;
    total += scratch.omega[i];
    scratch.cdf[i] = total;
  }
  if (!(total > 0)) return;
  const double mean_cell = 4 * kPi / static_cast<double>(cubemap_texel_count(n));
  const double wanted = std::ceil(s.samples_per_cell * total / mean_cell);
  const std::uint32_t count = std::min<std::uint32_t>(
      static_cast<std::uint32_t>(s.max_samples),
      next_power_of_two(static_cast<std::uint64_t>(std::max<double>(s.min_samples, wanted))));
  Pcg32 rng(s.seed, receiver);
  const std::uint32_t scramble_1 = rng.next_u32(), scramble_2 = rng.next_u32();
  const double per_sample = 1.0 / count;
  for (std::uint32_t i = 0; i < count; ++i) {
    const double u1 = unit_interval(van_der_corput(i, scramble_1)) * total;
    const double u2 = unit_interval(sobol2(i, scramble_2));
    const auto it = std::upper_bound(scratch.cdf.begin(), scratch.cdf.end(), u1);
    const std::size_t k = std::min<std::size_t>(static_cast<std::size_t>(it - scratch.cdf.begin()),
                                                tris.a.size() - 1);
    if (!(scratch.omega[k] > 0)) continue;
    const double below = k == 0 ? 0.0 : scratch.cdf[k - 1];
    const double v1 = std::clamp((u1 - below) / scratch.omega[k], 0.0, 1.0);
    const double root = std::sqrt(v1);
    const double b0 = 1 - root, b1 = u2 * root;
    const Vec3 y = tris.a[k] * b0 + tris.b[k] * b1 + tris.c[k] * (1 - b0 - b1);
    const Vec3 d = y - origin;
    const double d2 = dot(d, d);
    if (!(d2 > 0)) continue;
    const Vec3 dir = d * (1.0 / std::sqrt(d2));
    const double cos_r = dot(normal, dir);
    const double cos_y = std::abs(dot(tris.unit_normal[k], dir));
    if (cos_r <= 0 || cos_y <= 0) continue;
    ++out.samples;
    ++out.rays;
    if (traced.opaque.occluded({origin, dir})) continue;  // before or past the portal
    const double pdf = (scratch.omega[k] / total) * d2 / (portal.areas[k] * cos_y);
    const double weight = cos_r / pdf * per_sample;
    const std::size_t cell = cubemap_texel_index(n, cubemap_texel(n, dir));
    if (scratch.cells[cell] == 0) scratch.touched.push_back(static_cast<std::uint32_t>(cell));
    scratch.cells[cell] += weight;
    sh_eval(s.sh_order, dir, scratch.basis);
    for (std::size_t b = 0; b < scratch.sh.size(); ++b) scratch.sh[b] += weight * scratch.basis[b];
    out.flow = out.flow + dir * weight;
  }
}

}  // namespace

PortalDirect compute_portal_direct(const Receivers& receivers, const std::vector<Vec3>& ray_points,
                                   const std::vector<std::uint8_t>& skip, const PreparedMesh& mesh,
                                   const TracedScene& traced, const PortalGeometry& portal,
                                   const PortalDirectSettings& settings, bool progress) {
  const int n = settings.face_size;
  if (n < 1 || (n & (n - 1)) != 0 || settings.sh_order < 1 || settings.samples_per_cell < 1 ||
      settings.min_samples < 1 || settings.max_samples < settings.min_samples) {
    throw std::invalid_argument("portal direct: bad settings");
  }
  if (ray_points.size() != receivers.size() || skip.size() != receivers.size() ||
      portal.triangles.empty()) {
    throw std::invalid_argument("portal direct: inputs do not match");
  }
  const PortalTriangles tris = portal_triangles(mesh, portal);
  const int bases = sh_count(settings.sh_order);
  const std::size_t rows = receivers.size();
  const std::size_t chunk_count = (rows + kChunk - 1) / kChunk;
  PortalDirect result;
  result.face_size = n;
  result.sh_columns = Eigen::MatrixXf::Zero(static_cast<Eigen::Index>(rows), bases);
  std::vector<ChunkOutput> chunks(chunk_count);
  tbb::enumerable_thread_specific<Scratch> scratches(n, tris.a.size(), bases);
  Progress bar("portal \"" + portal.name + "\" direct", rows, progress);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, chunk_count), [&](const auto& range) {
    Scratch& scratch = scratches.local();
    for (std::size_t c = range.begin(); c != range.end(); ++c) {
      ChunkOutput& out = chunks[c];
      const std::size_t first = c * kChunk, last = std::min(rows, first + kChunk);
      for (std::size_t r = first; r < last; ++r) {
        scratch.touched.clear();
        if (!skip[r]) {
          sample_receiver(ray_points[r], receivers.normals[r], r, tris, portal, traced, settings,
                          scratch, out);
        }
        const std::size_t before = out.bytes.size();
        if (scratch.touched.empty()) {
          out.bytes.push_back(static_cast<std::uint8_t>(CubemapCodeKind::kEmpty));
          out.encoded.push_back({CubemapCodeKind::kEmpty, 1, 1, 1, 0, 0});
        } else {
          out.encoded.push_back(
              encode_receiver_cubemap(n, scratch.cells, {}, out.bytes, scratch.encode));
          for (int b = 0; b < bases; ++b) {
            result.sh_columns(static_cast<Eigen::Index>(r), b) =
                static_cast<float>(scratch.sh[static_cast<std::size_t>(b)]);
          }
          for (std::uint32_t cell : scratch.touched) scratch.cells[cell] = 0;
        }
        out.sizes.push_back(static_cast<std::uint32_t>(out.bytes.size() - before));
      }
      bar.advance(last - first);
    }
  });
  bar.finish();

  result.offsets.reserve(rows + 1);
  result.offsets.push_back(0);
  Vec3 flow{0, 0, 0};
  for (const ChunkOutput& chunk : chunks) {
    result.records.insert(result.records.end(), chunk.bytes.begin(), chunk.bytes.end());
    for (std::uint32_t size : chunk.sizes) result.offsets.push_back(result.offsets.back() + size);
    for (const EncodedReceiver& e : chunk.encoded) add_receiver(result.stats, e);
    flow = flow + chunk.flow;
    result.rays += chunk.rays;
    result.samples += chunk.samples;
  }
  // The light travels −flow; the portal's outward side is the side the flow points to.
  if (length(portal.normal) > 0) {
    result.outward = dot(flow, portal.normal) >= 0 ? portal.normal : portal.normal * -1.0;
  } else {
    result.outward = length(flow) > 0 ? normalize(flow) : Vec3{0, 1, 0};
  }
  return result;
}

}  // namespace relight
