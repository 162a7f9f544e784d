#include "sources/portals/portal_sections.h"

#include <algorithm>

#include "common/input_error.h"
#include "engine/transfer_blocks.h"
#include "engine/transfer_sections.h"
#include "math/sh.h"
#include "store/rlt_format.h"

namespace relight {

namespace {

nlohmann::json encoding_stats_json(const CubemapEncodingStats& s) {
  return {{"receivers", s.receivers},
          {"empty", s.empty},
          {"pulse", s.pulse},
          {"haar", s.haar},
          {"runs", s.runs},
          {"rectangles", s.rectangles},
          {"bytes", s.bytes},
          {"pulse_bytes", s.pulse_bytes},
          {"haar_bytes", s.haar_bytes},
          {"runs_bytes", s.runs_bytes},
          {"rectangles_bytes", s.rectangles_bytes},
          {"all_pulse_bytes", s.all_pulse_bytes},
          {"all_haar_bytes", s.all_haar_bytes},
          {"all_runs_bytes", s.all_runs_bytes},
          {"all_rectangles_bytes", s.all_rectangles_bytes}};
}

nlohmann::json vec3_json(Vec3 v) {
  return nlohmann::json::array({v.x, v.y, v.z});
}

Vec3 vec3_from_json(const nlohmann::json& j) {
  return {j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>()};
}

}  // namespace

namespace {

enum class RecordPart { records, sizes };

// Several ranks (collective): each rank's blocks of cubemap records, or their records' sizes, to
// rank 0's `sink` in file order (each rank holds its own, engine/ranks.h).
void gather_cubemap_records(const PortalDirect& direct, const RankShares& ranks, RecordPart part,
                            const RecordSink* sink) {
  // Records of ~300 bytes: 64 receivers a block, a few MB a round.
  constexpr std::size_t kBlocksPerRound = 256;
  const std::size_t local = direct.offsets.size() - 1;
  std::vector<std::uint32_t> sizes;
  gather_block_records(
      ranks,
      [&](std::size_t i) -> std::span<const std::uint8_t> {
        const std::size_t first = i * ranks.block, last = std::min(local, first + ranks.block);
        if (part == RecordPart::records) {
          return std::span(direct.records)
              .subspan(direct.offsets[first], direct.offsets[last] - direct.offsets[first]);
        }
        sizes.clear();
        for (std::size_t r = first; r < last; ++r) {
          sizes.push_back(static_cast<std::uint32_t>(direct.offsets[r + 1] - direct.offsets[r]));
        }
        return {reinterpret_cast<const std::uint8_t*>(sizes.data()),
                sizes.size() * sizeof(std::uint32_t)};
      },
      kBlocksPerRound, sink);
}

}  // namespace

void write_portal_sections(SectionSink& sink, std::span<const PortalTransfer> portals,
                           std::size_t indirect_block_bytes) {
  for (std::size_t q = 0; q < portals.size(); ++q) {
    const PortalTransfer& t = portals[q];
    const std::uint32_t records = rlt_indexed('C', 'R', q), offsets = rlt_indexed('C', 'O', q);
    const std::string records_name = rlt_indexed_name("portal direct cubemaps", q);
    const std::string offsets_name = rlt_indexed_name("portal direct offsets", q);
    if (sink.alone()) {
      sink.writer()->add_section(records, records_name, std::as_bytes(std::span(t.direct.records)));
      sink.writer()->add_u64(offsets, offsets_name, t.direct.offsets);
    } else {
      const PortalDirect& direct = t.direct;
      const RankShares ranks = sink.ranks();
      sink.gathered(records, records_name, RltElement::bytes,
                    [&direct, ranks](const RltWriter::Sink* to) {
                      gather_into(to, [&](const RecordSink* records) {
                        gather_cubemap_records(direct, ranks, RecordPart::records, records);
                      });
                    });
      // The offsets from the records' sizes, running over the blocks in file order.
      sink.gathered(offsets, offsets_name, RltElement::u64,
                    [&direct, ranks](const RltWriter::Sink* to) {
                      if (to == nullptr) {
                        gather_cubemap_records(direct, ranks, RecordPart::sizes, nullptr);
                        return;
                      }
                      write_running_offsets<std::uint64_t>(*to, [&](const RecordSink& sizes) {
                        gather_cubemap_records(direct, ranks, RecordPart::sizes, &sizes);
                      });
                    });
    }
    sink.transfer(rlt_indexed('P', 'I', q), rlt_indexed_name("portal indirect sh", q),
                  t.indirect.view(), indirect_block_bytes);
  }
}

nlohmann::json portal_metadata(std::span<const PortalTransfer> portals,
                               std::size_t indirect_bytes) {
  nlohmann::json out = nlohmann::json::array();
  for (const PortalTransfer& t : portals) {
    out.push_back({{"name", t.geometry.name},
                   {"face_size", t.direct.face_size},
                   {"centre", vec3_json(t.geometry.centre)},
                   {"outward", vec3_json(t.direct.outward)},
                   {"area", t.geometry.area},
                   {"diameter", t.geometry.diameter},
                   {"triangles", t.geometry.triangles.size()},
                   {"samples", t.direct.samples},
                   {"rays", t.direct.rays},
                   {"direct_encoding", encoding_stats_json(t.direct.stats)},
                   {"indirect_bytes", indirect_bytes}});
  }
  return out;
}

std::vector<PortalTransferView> read_portal_sections(const RltFile& file,
                                                     const nlohmann::json& metadata,
                                                     std::span<const Portal> portals,
                                                     std::size_t receivers, int sh_order,
                                                     const std::string& where) {
  if (metadata.size() != portals.size()) {
    fail_input(where, "metadata disagrees with its scene description (portals)");
  }
  const auto k = static_cast<std::size_t>(sh_count(sh_order));
  std::vector<PortalTransferView> out;
  for (std::size_t q = 0; q < portals.size(); ++q) {
    const nlohmann::json& j = metadata[q];
    PortalTransferView v;
    v.name = j.at("name").get<std::string>();
    v.face_size = j.at("face_size").get<int>();
    v.centre = vec3_from_json(j.at("centre"));
    v.outward = vec3_from_json(j.at("outward"));
    v.diameter = j.at("diameter").get<double>();
    const std::span<const std::byte> records = file.section(rlt_indexed('C', 'R', q));
    v.records = {reinterpret_cast<const std::uint8_t*>(records.data()), records.size()};
    v.offsets = file.view<std::uint64_t>(rlt_indexed('C', 'O', q));
    v.indirect = transfer_section(file, rlt_indexed('P', 'I', q));
    const int n = v.face_size;
    bool valid = v.name == portals[q].name && n >= 1 && n <= 256 && (n & (n - 1)) == 0 &&
                 v.offsets.size() == receivers + 1 && v.offsets.front() == 0 &&
                 v.offsets.back() == v.records.size() &&
                 v.indirect.size() == blocked_floats(receivers, k, 3);
    for (std::size_t r = 0; valid && r < receivers; ++r) valid = v.offsets[r] < v.offsets[r + 1];
    if (!valid) fail_input(where, "transfer of portal \"" + v.name + "\" has inconsistent sizes");
    out.push_back(v);
  }
  return out;
}

}  // namespace relight
