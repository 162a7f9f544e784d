#include "store/transfer_file.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "common/input_error.h"
#include "common/read_file.h"
#include "engine/transfer_blocks.h"
#include "light/photometric_web.h"
#include "math/sh.h"
#include "scene/scene_loader.h"
#include "store/rlt_writer.h"
#include "store/xxh64.h"

namespace relight {

namespace fs = std::filesystem;

namespace {

constexpr std::uint32_t kMetadata = rlt_fourcc("META");
constexpr std::uint32_t kMeshPositions = rlt_fourcc("MPOS");
constexpr std::uint32_t kMeshNormals = rlt_fourcc("MNRM");
constexpr std::uint32_t kVertexAlbedo = rlt_fourcc("MALB");
constexpr std::uint32_t kTriangles = rlt_fourcc("MTRI");
constexpr std::uint32_t kPortalTriangles = rlt_fourcc("MPRT");
constexpr std::uint32_t kTriangleMaterials = rlt_fourcc("MMAT");
// Near-field emitters (only when the scene has some): shadowed SH transfer per receiver, and
// with "nearfield_interreflection" the gather operator (compressed rows) that the run time
// bounces their light through (format version 2; version 1 had NFTI, the SH transfer bounced
// in the precompute, instead).
constexpr std::uint32_t kNearfieldTransfer = rlt_fourcc("NFTR");
constexpr std::uint32_t kGatherRows = rlt_fourcc("NGRO");
constexpr std::uint32_t kGatherColumns = rlt_fourcc("NGCO");
constexpr std::uint32_t kGatherValues = rlt_fourcc("NGVA");

// Per-luminaire sections: two type characters, then the luminaire index in the upper
// 16 bits ("DX" + j: direction x, "DY", "DZ", "DF": direct factor, "TI": indirect SH
// transfer, "TD": SH-basis direct in "sh" mode).
constexpr std::uint32_t luminaire_section(char a, char b, std::size_t j) {
  return static_cast<std::uint32_t>(static_cast<unsigned char>(a)) |
         static_cast<std::uint32_t>(static_cast<unsigned char>(b)) << 8 |
         static_cast<std::uint32_t>(j) << 16;
}

// Per-portal sections, the same way: "CR" + p: the direct cubemap records (bytes), "CO":
// their offsets (u64, receivers + 1), "PI": the indirect SH transfer (blocked RGB).
constexpr std::uint32_t portal_section(char a, char b, std::size_t p) {
  return luminaire_section(a, b, p);
}

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

std::string section_name(const char* what, std::size_t j) {
  return std::string(what) + " " + std::to_string(j);
}

}  // namespace

std::string scene_digest(const nlohmann::json& scene_document) {
  const std::string text = scene_document.dump();
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx",
                static_cast<unsigned long long>(xxh64(std::as_bytes(std::span(text)))));
  return hex;
}

void write_transfer_file(const fs::path& file, const Precomputed& p, const Scene& source,
                         const nlohmann::json& scene_document, const fs::path& scene_file) {
  if (p.luminaires.size() > 0xFFFF || p.portals.size() > 0xFFFF) {
    throw std::invalid_argument("too many luminaires or portals");
  }
  nlohmann::json scene = scene_document;
  scene.erase("geometry");
  nlohmann::json phases = nlohmann::json::array();
  for (const PhaseTiming& t : p.phases) {
    phases.push_back({{"name", t.name}, {"seconds", t.seconds}, {"rays", t.rays}});
  }
  // Photometry files, one text section per luminaire that has one ("PH" + index).
  std::vector<std::string> photometry(source.luminaires.size());
  nlohmann::json photometry_files = nlohmann::json::array();
  for (std::size_t j = 0; j < source.luminaires.size(); ++j) {
    const DistributionSpec& d = source.luminaires[j].distribution;
    if (d.type != DistributionType::kIes && d.type != DistributionType::kLdt) continue;
    photometry[j] = d.contents ? *d.contents : read_file(d.file, kMaxPhotometryFileBytes);
    photometry_files.push_back({{"luminaire", j}, {"file", d.file.string()}});
  }
  nlohmann::json portals = nlohmann::json::array();
  for (const PortalTransfer& t : p.portals) {
    portals.push_back({{"name", t.geometry.name},
                       {"face_size", t.direct.face_size},
                       {"centre", vec3_json(t.geometry.centre)},
                       {"outward", vec3_json(t.direct.outward)},
                       {"area", t.geometry.area},
                       {"diameter", t.geometry.diameter},
                       {"triangles", t.geometry.triangles.size()},
                       {"samples", t.direct.samples},
                       {"rays", t.direct.rays},
                       {"direct_encoding", encoding_stats_json(t.direct.stats)},
                       {"indirect_bytes", t.indirect_blocks.size() * sizeof(float)}});
  }
  const nlohmann::json metadata = {
      {"photometry", photometry_files},
      {"portal_sh_order", p.portal_sh_order},
      {"nearfield_sh_order", p.nearfield.sh_order},
      {"portals", portals},
      {"format", "relight transfer"},
      {"scene_file", fs::absolute(scene_file).lexically_normal().string()},
      {"scene_digest", scene_digest(scene_document)},
      {"scene", scene},
      {"sh_order", p.sh_order},
      {"direct", p.direct_mode},
      {"bounces", p.bounces},
      {"vertices", p.receivers.vertex_count},
      {"sensors", p.receivers.sensor_count},
      {"triangles", p.mesh.triangles.size()},
      {"luminaires", p.luminaires.size()},
      {"phases", phases}};

  std::vector<float> positions, normals, albedo;
  for (std::size_t v = 0; v < p.receivers.vertex_count; ++v) {
    for (int c = 0; c < 3; ++c) {
      positions.push_back(static_cast<float>(p.mesh.positions[v][c]));
      normals.push_back(static_cast<float>(p.mesh.normals[v][c]));
    }
    const Rgb a = p.receivers.albedo[v];
    albedo.insert(albedo.end(),
                  {static_cast<float>(a.r), static_cast<float>(a.g), static_cast<float>(a.b)});
  }
  std::vector<std::uint32_t> triangles;
  triangles.reserve(3 * p.mesh.triangles.size());
  for (const Triangle& t : p.mesh.triangles) triangles.insert(triangles.end(), t.begin(), t.end());

  RltWriter w;
  w.add_text(kMetadata, "metadata", metadata.dump());
  w.add_f32(kMeshPositions, "mesh positions", positions);
  w.add_f32(kMeshNormals, "mesh normals", normals);
  w.add_f32(kVertexAlbedo, "vertex albedo", albedo);
  w.add_u32(kTriangles, "triangles", triangles);
  w.add_u32(kPortalTriangles, "portal triangles", p.triangle_portal);
  w.add_u32(kTriangleMaterials, "triangle materials", p.mesh.triangle_material);
  if (!p.nearfield.transfer.empty()) {
    w.add_f32(kNearfieldTransfer, "near-field transfer", p.nearfield.transfer);
  }
  if (p.nearfield.gather.nonZeros() > 0) {
    // The writer keeps spans into `p` until it writes: the matrix is stored as it is.
    const Eigen::SparseMatrix<float, Eigen::RowMajor>& g = p.nearfield.gather;
    if (!g.isCompressed())
      throw std::invalid_argument("write_transfer_file: gather not compressed");
    const auto index_span = [](const int* p, Eigen::Index n) {
      return std::span(reinterpret_cast<const std::uint32_t*>(p), static_cast<std::size_t>(n));
    };
    w.add_u32(kGatherRows, "near-field gather rows", index_span(g.outerIndexPtr(), g.rows() + 1));
    w.add_u32(kGatherColumns, "near-field gather columns",
              index_span(g.innerIndexPtr(), g.nonZeros()));
    w.add_f32(kGatherValues, "near-field gather values",
              std::span(g.valuePtr(), static_cast<std::size_t>(g.nonZeros())));
  }
  for (std::size_t j = 0; j < p.luminaires.size(); ++j) {
    const LuminaireTransfer& l = p.luminaires[j];
    w.add_f32(luminaire_section('D', 'X', j), section_name("direct dir x", j), l.direct.dir_x);
    w.add_f32(luminaire_section('D', 'Y', j), section_name("direct dir y", j), l.direct.dir_y);
    w.add_f32(luminaire_section('D', 'Z', j), section_name("direct dir z", j), l.direct.dir_z);
    w.add_f32(luminaire_section('D', 'F', j), section_name("direct factor", j), l.direct.factor);
    w.add_f32(luminaire_section('T', 'I', j), section_name("indirect sh", j), l.indirect_blocks);
    if (!photometry[j].empty()) {
      w.add_text(luminaire_section('P', 'H', j), section_name("photometry", j), photometry[j]);
    }
    if (!l.direct_sh_blocks.empty()) {
      w.add_f32(luminaire_section('T', 'D', j), section_name("direct sh", j), l.direct_sh_blocks);
    }
  }
  for (std::size_t q = 0; q < p.portals.size(); ++q) {
    const PortalTransfer& t = p.portals[q];
    w.add_section(portal_section('C', 'R', q), section_name("portal direct cubemaps", q),
                  std::as_bytes(std::span(t.direct.records)));
    w.add_u64(portal_section('C', 'O', q), section_name("portal direct offsets", q),
              t.direct.offsets);
    w.add_f32(portal_section('P', 'I', q), section_name("portal indirect sh", q),
              t.indirect_blocks);
  }
  try {
    w.write(file);
  } catch (const std::runtime_error& e) {
    fail_input(file.string(), e.what());
  }
}

TransferView in_memory_view(const Precomputed& p) {
  TransferView v;
  v.receivers = p.receivers.size();
  v.sh_order = p.sh_order;
  v.direct_sh_mode = p.direct_mode == "sh";
  for (const LuminaireTransfer& l : p.luminaires) {
    v.luminaires.push_back({l.direct.dir_x, l.direct.dir_y, l.direct.dir_z, l.direct.factor,
                            l.indirect_blocks, l.direct_sh_blocks});
  }
  v.portal_sh_order = p.portal_sh_order;
  for (const PortalTransfer& t : p.portals) {
    v.portals.push_back({t.geometry.name, t.direct.face_size, t.geometry.centre, t.direct.outward,
                         t.geometry.diameter, t.direct.records, t.direct.offsets,
                         t.indirect_blocks});
  }
  if (p.nearfield.sh_order > 0) {
    NearfieldTransferView& nf = v.nearfield;
    nf.sh_order = p.nearfield.sh_order;
    nf.transfer = p.nearfield.transfer;
    const auto& g = p.nearfield.gather;
    if (g.nonZeros() > 0) {
      if (!g.isCompressed()) throw std::invalid_argument("in_memory_view: gather not compressed");
      nf.gather_rows = {reinterpret_cast<const std::uint32_t*>(g.outerIndexPtr()),
                        static_cast<std::size_t>(g.rows() + 1)};
      nf.gather_columns = {reinterpret_cast<const std::uint32_t*>(g.innerIndexPtr()),
                           static_cast<std::size_t>(g.nonZeros())};
      nf.gather_values = {g.valuePtr(), static_cast<std::size_t>(g.nonZeros())};
    }
    nf.vertex_albedo.reserve(3 * p.receivers.vertex_count);
    for (std::size_t v = 0; v < p.receivers.vertex_count; ++v) {
      const Rgb a = p.receivers.albedo[v];
      nf.vertex_albedo.insert(
          nf.vertex_albedo.end(),
          {static_cast<float>(a.r), static_cast<float>(a.g), static_cast<float>(a.b)});
    }
    nf.vertex_count = p.receivers.vertex_count;
    nf.receiver_positions = p.receivers.positions;
    nf.receiver_normals = p.receivers.normals;
    nf.mesh_positions = p.mesh.positions;
    for (std::size_t i = 0; i < p.mesh.triangles.size(); ++i) {
      if (p.triangle_portal[i] == 0) nf.opaque_triangles.push_back(p.mesh.triangles[i]);
    }
  }
  return v;
}

Bounds TransferFile::bounds() const {
  if (positions.empty()) return {};
  Bounds b{positions.front(), positions.front()};
  for (const Vec3& p : positions) {
    b.min = min(b.min, p);
    b.max = max(b.max, p);
  }
  return b;
}

namespace {

void read_portal_views(TransferFile& t, const std::string& where) {
  const nlohmann::json& m = t.metadata;
  const nlohmann::json portals = m.value("portals", nlohmann::json::array());
  if (portals.size() != t.scene.portals.size()) {
    fail_input(where, "metadata disagrees with its scene description (portals)");
  }
  t.view.portal_sh_order = m.value("portal_sh_order", 6);
  if (t.view.portal_sh_order < 1 || t.view.portal_sh_order > 16) {
    fail_input(where, "portal_sh_order out of range");
  }
  const std::size_t k = static_cast<std::size_t>(sh_count(t.view.portal_sh_order));
  const std::size_t receivers = t.view.receivers;
  for (std::size_t q = 0; q < portals.size(); ++q) {
    const nlohmann::json& j = portals[q];
    PortalTransferView v;
    v.name = j.at("name").get<std::string>();
    v.face_size = j.at("face_size").get<int>();
    v.centre = vec3_from_json(j.at("centre"));
    v.outward = vec3_from_json(j.at("outward"));
    v.diameter = j.at("diameter").get<double>();
    const std::span<const std::byte> records = t.file.section(portal_section('C', 'R', q));
    v.records = {reinterpret_cast<const std::uint8_t*>(records.data()), records.size()};
    v.offsets = t.file.view<std::uint64_t>(portal_section('C', 'O', q));
    v.indirect = t.file.view<float>(portal_section('P', 'I', q));
    const int n = v.face_size;
    bool valid = v.name == t.scene.portals[q].name && n >= 1 && n <= 256 && (n & (n - 1)) == 0 &&
                 v.offsets.size() == receivers + 1 && v.offsets.front() == 0 &&
                 v.offsets.back() == v.records.size() &&
                 v.indirect.size() == blocked_floats(receivers, k, 3);
    for (std::size_t r = 0; valid && r < receivers; ++r) {
      valid = v.offsets[r] < v.offsets[r + 1];
    }
    if (!valid) fail_input(where, "transfer of portal \"" + v.name + "\" has inconsistent sizes");
    t.view.portals.push_back(v);
  }
}

}  // namespace

TransferFile open_transfer_file(const fs::path& file) {
  TransferFile t(RltFile::open(file));
  const std::string where = file.string();
  try {
    t.metadata = nlohmann::json::parse(t.file.text(kMetadata));
  } catch (const nlohmann::json::exception& e) {
    fail_input(where, std::string("metadata is not valid JSON: ") + e.what());
  }
  const nlohmann::json& m = t.metadata;
  if (m.value("format", "") != "relight transfer") fail_input(where, "not a relight transfer file");
  const fs::path scene_file = m.at("scene_file").get<std::string>();
  EmbeddedFiles embedded;
  for (const nlohmann::json& f : m.value("photometry", nlohmann::json::array())) {
    const std::size_t j = f.at("luminaire").get<std::size_t>();
    embedded[f.at("file").get<std::string>()] =
        std::make_shared<const std::string>(t.file.text(luminaire_section('P', 'H', j)));
  }
  t.scene = scene_from_json(m.at("scene"), scene_file, &embedded);
  t.vertex_count = m.at("vertices").get<std::size_t>();
  t.sensor_count = m.at("sensors").get<std::size_t>();
  const std::size_t receivers = t.vertex_count + t.sensor_count;
  if (t.sensor_count != t.scene.sensor_count() ||
      m.at("luminaires").get<std::size_t>() != t.scene.luminaires.size()) {
    fail_input(where, "metadata disagrees with its scene description");
  }

  const auto positions = t.file.view<float>(kMeshPositions);
  const auto triangles = t.file.view<std::uint32_t>(kTriangles);
  const auto portal = t.file.view<std::uint32_t>(kPortalTriangles);
  t.vertex_albedo = t.file.view<float>(kVertexAlbedo);
  if (positions.size() != 3 * t.vertex_count || t.vertex_albedo.size() != 3 * t.vertex_count ||
      triangles.size() % 3 != 0 || portal.size() != triangles.size() / 3) {
    fail_input(where, "mesh sections have inconsistent sizes");
  }
  t.positions.reserve(t.vertex_count);
  for (std::size_t v = 0; v < t.vertex_count; ++v) {
    t.positions.push_back({positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]});
  }
  t.triangles.reserve(triangles.size() / 3);
  for (std::size_t i = 0; i < triangles.size(); i += 3) {
    const Triangle tri{triangles[i], triangles[i + 1], triangles[i + 2]};
    for (std::uint32_t v : tri) {
      if (v >= t.vertex_count) fail_input(where, "a triangle refers to a missing vertex");
    }
    const std::uint32_t glass = portal[i / 3];
    if (glass == 0) {
      t.opaque_triangles.push_back(static_cast<std::uint32_t>(i / 3));
    } else if (glass != kGlassOutsidePortals) {
      if (glass > t.scene.portals.size())
        fail_input(where, "a triangle refers to a missing portal");
      t.portal_triangles.push_back(static_cast<std::uint32_t>(i / 3));
      t.portal_of_triangle.push_back(glass - 1);
    }
    t.triangles.push_back(tri);
  }
  if (t.file.find_info(kTriangleMaterials)) {
    const auto materials = t.file.view<std::uint32_t>(kTriangleMaterials);
    if (materials.size() != t.triangles.size())
      fail_input(where, "triangle materials: wrong count");
    for (const std::uint32_t m : materials) {
      if (m >= t.scene.materials.size())
        fail_input(where, "a triangle refers to a missing material");
    }
    t.triangle_material.assign(materials.begin(), materials.end());
  }

  t.view.receivers = receivers;
  t.view.sh_order = m.at("sh_order").get<int>();
  t.view.direct_sh_mode = m.at("direct").get<std::string>() == "sh";
  if (t.view.sh_order < 1 || t.view.sh_order > 32) fail_input(where, "sh_order out of range");
  const std::size_t k = static_cast<std::size_t>(sh_count(t.view.sh_order));
  for (std::size_t j = 0; j < t.scene.luminaires.size(); ++j) {
    LuminaireTransferView v;
    v.dir_x = t.file.view<float>(luminaire_section('D', 'X', j));
    v.dir_y = t.file.view<float>(luminaire_section('D', 'Y', j));
    v.dir_z = t.file.view<float>(luminaire_section('D', 'Z', j));
    v.factor = t.file.view<float>(luminaire_section('D', 'F', j));
    v.indirect = t.file.view<float>(luminaire_section('T', 'I', j));
    if (t.view.direct_sh_mode) v.direct_sh = t.file.view<float>(luminaire_section('T', 'D', j));
    if (v.dir_x.size() != receivers || v.dir_y.size() != receivers || v.dir_z.size() != receivers ||
        v.factor.size() != receivers || v.indirect.size() != blocked_floats(receivers, k, 3) ||
        (t.view.direct_sh_mode && v.direct_sh.size() != blocked_floats(receivers, k, 1))) {
      fail_input(where, "transfer of luminaire \"" + t.scene.luminaires[j].name +
                            "\" has inconsistent sizes");
    }
    t.view.luminaires.push_back(v);
  }
  read_portal_views(t, where);
  NearfieldTransferView& nf = t.view.nearfield;
  if (!t.scene.emitters.empty()) {
    nf.sh_order = m.value("nearfield_sh_order", 0);
    if (nf.sh_order < 1 || nf.sh_order > 16 || !t.file.find_info(kNearfieldTransfer)) {
      fail_input(where, "the scene has emitters but the file holds no near-field transfer");
    }
    const std::size_t kn = static_cast<std::size_t>(sh_count(nf.sh_order));
    nf.transfer = t.file.view<float>(kNearfieldTransfer);
    if (nf.transfer.size() != receivers * kn) {
      fail_input(where, "near-field transfer has an inconsistent size");
    }
    if (t.file.find_info(kGatherRows)) {
      nf.gather_rows = t.file.view<std::uint32_t>(kGatherRows);
      nf.gather_columns = t.file.view<std::uint32_t>(kGatherColumns);
      nf.gather_values = t.file.view<float>(kGatherValues);
      if (nf.gather_rows.size() != receivers + 1 || nf.gather_rows.front() != 0 ||
          nf.gather_rows.back() != nf.gather_columns.size() ||
          nf.gather_values.size() != nf.gather_columns.size() ||
          !std::is_sorted(nf.gather_rows.begin(), nf.gather_rows.end()) ||
          std::any_of(nf.gather_columns.begin(), nf.gather_columns.end(),
                      [&](std::uint32_t c) { return c >= t.vertex_count; })) {
        fail_input(where, "near-field gather operator has inconsistent sizes");
      }
    }
    nf.vertex_albedo.assign(t.vertex_albedo.begin(), t.vertex_albedo.end());
    nf.vertex_count = t.vertex_count;
    nf.receiver_positions = t.positions;
    const auto normals = t.file.view<float>(kMeshNormals);
    if (normals.size() != 3 * t.vertex_count) fail_input(where, "mesh normals: inconsistent size");
    for (std::size_t v = 0; v < t.vertex_count; ++v) {
      nf.receiver_normals.push_back({normals[3 * v], normals[3 * v + 1], normals[3 * v + 2]});
    }
    for (const SensorSet& s : t.scene.sensors) {
      nf.receiver_positions.insert(nf.receiver_positions.end(), s.points.begin(), s.points.end());
      nf.receiver_normals.insert(nf.receiver_normals.end(), s.points.size(), s.normal);
    }
    nf.mesh_positions = t.positions;
    for (const std::uint32_t i : t.opaque_triangles) nf.opaque_triangles.push_back(t.triangles[i]);
  }
  return t;
}

}  // namespace relight
