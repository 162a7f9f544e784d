#include "sources/precompute_memory.h"

#include <algorithm>
#include <cstdio>

#include "engine/transfer_blocks.h"
#include "math/sh.h"

namespace relight {

namespace {

// A portal's direct cubemaps as encoded, a receiver's share: the encodings measured on rooms
// with windows store 115–360 bytes a receiver (the summary of `relight precompute` prints them),
// their working buffers come on top while a block is encoded.
constexpr std::uint64_t kPortalCubemapBytes = 384;

// The exact-direct geometry of a luminaire: a direction and a factor a receiver, as floats.
constexpr std::uint64_t kDirectGeometryBytes = 4 * sizeof(float);

std::string megabytes(std::uint64_t bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.0f MB", static_cast<double>(bytes) * 1e-6);
  return text;
}

}  // namespace

PrecomputeMemory predict_precompute_memory(const Scene& scene, const Receivers& receivers,
                                           const GatherEntries& entries, std::uint64_t cuts,
                                           std::uint64_t resident, int ranks) {
  PrecomputeMemory m;
  m.resident = resident;
  m.receivers = receivers.size();
  m.ranks = static_cast<std::uint64_t>(std::max(ranks, 1));
  // A rank's share, rounded up to whole blocks of the transfer; the blocks are dealt in turn
  // (engine/ranks.h), so a share holds vertex and sensor rows in the proportion of all rows.
  m.share = std::min<std::uint64_t>(m.receivers,
                                    (block_count(m.receivers) + m.ranks - 1) / m.ranks * kBlock);
  const std::uint64_t vertices = receivers.vertex_count;
  const std::uint64_t share_sensors =
      m.receivers == 0 ? 0 : (m.share * receivers.sensor_count + m.receivers - 1) / m.receivers;
  const std::uint64_t share_vertices = std::min(vertices, m.share - share_sensors);
  const auto luminaire_columns = static_cast<std::uint64_t>(sh_count(scene.precompute.sh_order));
  m.columns =
      scene.luminaires.size() * luminaire_columns +
      scene.portals.size() * static_cast<std::uint64_t>(sh_count(scene.precompute.portal_sh_order));

  // The gather operator: a float and a column index an entry, a row offset a row.
  const double gather_entries = entries.per_vertex_row * static_cast<double>(share_vertices) +
                                entries.per_sensor_row * static_cast<double>(share_sensors);
  m.gather = static_cast<std::uint64_t>(gather_entries * 8) + 4 * (m.receivers + 1);
  const std::uint64_t window = gather_build_scratch_bytes(entries, vertices);

  const std::uint64_t column_bytes = m.columns * sizeof(float);
  const std::uint64_t dense = m.share * column_bytes;                  // M
  const std::uint64_t dense_vertices = share_vertices * column_bytes;  // Mv
  const std::uint64_t reflected = (m.ranks > 1 ? vertices : share_vertices) * column_bytes;
  const std::uint64_t bounce = 5 * dense + dense_vertices + reflected;
  const bool half = scene.precompute.storage == "fp16";
  const std::uint64_t packed = half ? 3 * dense / 2 : 3 * dense;
  // Packing one source's three channels (read in place) into a float copy, converted to binary16
  // beside it: the largest source's copy is held beside the direct columns, the three channels and
  // every source's packed transfer.
  const std::uint64_t largest_source =
      m.share * sizeof(float) *
      std::max(scene.luminaires.empty() ? 0 : luminaire_columns,
               scene.portals.empty()
                   ? 0
                   : static_cast<std::uint64_t>(sh_count(scene.precompute.portal_sh_order)));
  const std::uint64_t pack = 4 * dense + packed + (half ? 3 * largest_source : 0);
  m.sources = m.share * (scene.portals.size() * kPortalCubemapBytes +
                         scene.luminaires.size() * kDirectGeometryBytes);
  if (!scene.emitters.empty()) {
    const auto k = static_cast<std::uint64_t>(sh_count(scene.precompute.nearfield_sh_order));
    m.sources += m.receivers * k * sizeof(float);  // every rank holds every receiver's
  }
  if (scene.precompute.direct == "sh") {
    m.sources += m.share * scene.luminaires.size() * luminaire_columns * sizeof(float);
  }

  m.cuts = cuts;  // every rank computes every cut

  m.dense = std::max(bounce, pack);
  m.peak_phase = pack >= bounce ? "pack" : "bounces";
  std::uint64_t after_gather = m.dense + m.sources;
  if (packed + m.sources + m.cuts > after_gather) {
    after_gather = packed + m.sources + m.cuts;
    m.dense = packed;
    m.peak_phase = "visibility cuts";
  }
  if (window > after_gather) m.peak_phase = "gather operator";
  m.bytes = m.resident + m.gather + std::max(window, after_gather);
  return m;
}

std::string memory_summary(const PrecomputeMemory& need) {
  std::string parts = "resident before tracing " + megabytes(need.resident) + ", gather operator " +
                      megabytes(need.gather) + ", " + std::to_string(need.columns) +
                      " basis columns × " + std::to_string(need.share) + " receivers " +
                      megabytes(need.dense);
  if (need.sources > 0) parts += ", direct light kept " + megabytes(need.sources);
  if (need.cuts > 0) parts += ", visibility cuts " + megabytes(need.cuts);
  return megabytes(need.bytes) + " (" + parts + "; peak in the " + need.peak_phase + " phase)";
}

std::string memory_refusal(const Scene& scene, const PrecomputeMemory& need,
                           std::uint64_t available, const std::string& limit_source) {
  if (need.bytes <= available) return {};
  const std::string receivers = need.ranks > 1 ? "a rank's " + std::to_string(need.share) + " of " +
                                                     std::to_string(need.receivers) + " receivers"
                                               : std::to_string(need.receivers) + " receivers";
  return scene.file.string() + ": too large to precompute here: " + receivers +
         " need an estimated " + memory_summary(need) + ", and " + megabytes(available) +
         " is available (" + limit_source + ")";
}

}  // namespace relight
