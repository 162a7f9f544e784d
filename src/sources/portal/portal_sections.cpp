#include "sources/portal/portal_sections.h"

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
          {"bytes", s.bytes},
          {"pulse_bytes", s.pulse_bytes},
          {"haar_bytes", s.haar_bytes},
          {"all_pulse_bytes", s.all_pulse_bytes},
          {"all_haar_bytes", s.all_haar_bytes}};
}

nlohmann::json vec3_json(Vec3 v) {
  return nlohmann::json::array({v.x, v.y, v.z});
}

Vec3 vec3_from_json(const nlohmann::json& j) {
  return {j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>()};
}

}  // namespace

void write_portal_sections(RltWriter& w, std::span<const PortalTransfer> portals,
                           const RankShares& ranks, std::size_t indirect_block_bytes) {
  for (std::size_t q = 0; q < portals.size(); ++q) {
    const PortalTransfer& t = portals[q];
    w.add_section(rlt_indexed('C', 'R', q), rlt_indexed_name("portal direct cubemaps", q),
                  std::as_bytes(std::span(t.direct.records)));
    w.add_u64(rlt_indexed('C', 'O', q), rlt_indexed_name("portal direct offsets", q),
              t.direct.offsets);
    add_transfer_section(w, rlt_indexed('P', 'I', q), rlt_indexed_name("portal indirect sh", q),
                         t.indirect.view(), ranks, indirect_block_bytes);
  }
}

void send_portal_sections(std::span<const PortalTransfer> portals, const RankShares& ranks,
                          std::size_t indirect_block_bytes) {
  for (const PortalTransfer& t : portals) {
    send_transfer_section(t.indirect.view(), ranks, indirect_block_bytes);
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
