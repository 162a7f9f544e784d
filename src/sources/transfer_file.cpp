#include "sources/transfer_file.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "common/input_error.h"
#include "common/read_file.h"
#include "engine/transfer_blocks.h"
#include "engine/transfer_sections.h"
#include "light/photometric_web.h"
#include "math/sh.h"
#include "scene/scene_loader.h"
#include "sources/emitters/nearfield_sections.h"
#include "sources/environment/cuts_sections.h"
#include "sources/luminaires/luminaire_sections.h"
#include "sources/objects/object_sections.h"
#include "sources/portals/portal_sections.h"
#include "store/rlt_writer.h"
#include "store/xxh64.h"

namespace relight {

namespace fs = std::filesystem;

namespace {

constexpr std::uint32_t kMetadata = rlt_fourcc("META");
constexpr std::uint32_t kMeshPositions = rlt_fourcc("MPOS");
constexpr std::uint32_t kMeshNormals = rlt_fourcc("MNRM");
constexpr std::uint32_t kVertexAlbedo = rlt_fourcc("MALB");
constexpr std::uint32_t kVertexTexture = rlt_fourcc("MTEX");
constexpr std::uint32_t kTriangles = rlt_fourcc("MTRI");
constexpr std::uint32_t kPortalTriangles = rlt_fourcc("MPRT");
constexpr std::uint32_t kTriangleMaterials = rlt_fourcc("MMAT");
constexpr std::uint32_t kGatherRows = rlt_fourcc("GROW");
constexpr std::uint32_t kGatherColumns = rlt_fourcc("GCOL");
constexpr std::uint32_t kGatherValues = rlt_fourcc("GVAL");

std::span<const std::uint32_t> indices(const int* p, Eigen::Index n) {
  return {reinterpret_cast<const std::uint32_t*>(p), static_cast<std::size_t>(n)};
}

using GatherMatrix = Eigen::SparseMatrix<float, Eigen::RowMajor>;

// The gather operator's sections, in file order.
enum class GatherSection { rows, columns, values };

// Several ranks (collective): one of the gather operator's sections from every rank's
// rows (engine/gather_operator.h: each rank holds its own), gathered block by block of
// receivers as rank 0 writes it: per block, its rows' entry counts, columns or values. `sink`
// (rank 0) receives the blocks in file order; the other ranks pass none.
void gather_operator_section(const GatherMatrix& g, const RankShares& ranks, GatherSection section,
                             const RecordSink* sink) {
  const std::vector<std::size_t> mine = ranks.my_blocks();
  // A few MB a round: 64 rows of up to 4,096 entries (a sensor's) are 1 MB.
  constexpr std::size_t kBlocksPerRound = 32;
  const int* outer = g.outerIndexPtr();
  std::vector<std::uint32_t> counts;
  gather_block_records(
      ranks,
      [&](std::size_t i) -> std::span<const std::uint8_t> {
        const std::size_t first = ranks.first(mine[i]), last = ranks.last(mine[i]);
        const auto begin = static_cast<std::size_t>(outer[first]);
        const auto entries = static_cast<std::size_t>(outer[last]) - begin;
        switch (section) {
          case GatherSection::rows:
            counts.clear();
            for (std::size_t r = first; r < last; ++r) {
              counts.push_back(static_cast<std::uint32_t>(outer[r + 1] - outer[r]));
            }
            return {reinterpret_cast<const std::uint8_t*>(counts.data()),
                    counts.size() * sizeof(std::uint32_t)};
          case GatherSection::columns:
            return {reinterpret_cast<const std::uint8_t*>(g.innerIndexPtr() + begin),
                    entries * sizeof(std::uint32_t)};
          case GatherSection::values:
            return {reinterpret_cast<const std::uint8_t*>(g.valuePtr() + begin),
                    entries * sizeof(float)};
        }
        return {};
      },
      kBlocksPerRound, sink);
}

// The gather operator kept for the run-time bounce (engine/runtime_scene.h), in compressed rows,
// also when it has no entry (an open floor under a top-level environment: nothing to bounce, but
// the run time's objects and edits need to know so); none only without rows. On several ranks,
// each section gathered from every rank (gather_operator_section) through `sink`.
void write_gather_sections(SectionSink& sink, const GatherMatrix& g) {
  if (g.rows() == 0) return;
  if (!g.isCompressed()) throw std::invalid_argument("gather operator not compressed");
  if (sink.alone()) {
    RltWriter& w = *sink.writer();
    w.add_u32(kGatherRows, "gather rows", indices(g.outerIndexPtr(), g.rows() + 1));
    w.add_u32(kGatherColumns, "gather columns", indices(g.innerIndexPtr(), g.nonZeros()));
    w.add_f32(kGatherValues, "gather values",
              std::span(g.valuePtr(), static_cast<std::size_t>(g.nonZeros())));
    return;
  }
  const RankShares ranks = sink.ranks();
  // The rows' offsets from their counts, running over the blocks in file order.
  sink.gathered(kGatherRows, "gather rows", RltElement::u32,
                [&g, ranks](const RltWriter::Sink* to) {
                  if (to == nullptr) {
                    gather_operator_section(g, ranks, GatherSection::rows, nullptr);
                    return;
                  }
                  write_running_offsets<std::uint32_t>(*to, [&](const RecordSink& counts) {
                    gather_operator_section(g, ranks, GatherSection::rows, &counts);
                  });
                });
  for (const GatherSection section : {GatherSection::columns, GatherSection::values}) {
    const bool columns = section == GatherSection::columns;
    sink.gathered(columns ? kGatherColumns : kGatherValues,
                  columns ? "gather columns" : "gather values",
                  columns ? RltElement::u32 : RltElement::f32,
                  [&g, ranks, section](const RltWriter::Sink* to) {
                    gather_into(to, [&](const RecordSink* records) {
                      gather_operator_section(g, ranks, section, records);
                    });
                  });
  }
}

void read_gather_sections(const RltFile& file, std::size_t receivers, std::size_t vertices,
                          RuntimeSceneView& view, const std::string& where) {
  if (!file.find_info(kGatherRows)) return;
  view.gather_rows = file.view<std::uint32_t>(kGatherRows);
  view.gather_columns = file.view<std::uint32_t>(kGatherColumns);
  view.gather_values = file.view<float>(kGatherValues);
  if (view.gather_rows.size() != receivers + 1 || view.gather_rows.front() != 0 ||
      view.gather_rows.back() != view.gather_columns.size() ||
      view.gather_values.size() != view.gather_columns.size() ||
      !std::is_sorted(view.gather_rows.begin(), view.gather_rows.end()) ||
      std::any_of(view.gather_columns.begin(), view.gather_columns.end(),
                  [&](std::uint32_t c) { return c >= vertices; })) {
    fail_input(where, "gather operator has inconsistent sizes");
  }
}

// The receivers (vertices, then every sensor set's points) with their normals.
void add_sensor_receivers(const Scene& scene, RuntimeSceneView& view) {
  for (const SensorSet& s : scene.sensors) {
    view.receiver_positions.insert(view.receiver_positions.end(), s.points.begin(), s.points.end());
    view.receiver_normals.insert(view.receiver_normals.end(), s.points.size(), s.normal);
  }
}

// The scene's materials in order (scene_from_json's `materials`).
nlohmann::json materials_json(const std::vector<Material>& materials) {
  nlohmann::json out = nlohmann::json::array();
  for (const Material& m : materials) {
    out.push_back({{"name", m.name},
                   {"albedo", {m.albedo.r, m.albedo.g, m.albedo.b}},
                   {"portal", m.portal},
                   {"glossy", m.glossy},
                   {"metallic", m.metallic},
                   {"roughness", m.roughness}});
    if (m.glazing) {
      out.back()["glazing"] = {{"visible_transmittance", m.glazing->visible_transmittance},
                               {"panes", m.glazing->panes},
                               {"diffusing", m.glazing->diffusing}};
    }
  }
  return out;
}

std::vector<Material> materials_from_json(const nlohmann::json& array, const std::string& where) {
  std::vector<Material> out;
  try {
    for (const nlohmann::json& j : array) {
      const auto albedo = j.at("albedo").get<std::vector<double>>();
      if (albedo.size() != 3) fail_input(where, "scene_materials: an albedo needs 3 numbers");
      out.push_back({j.at("name").get<std::string>(), Rgb{albedo[0], albedo[1], albedo[2]},
                     j.at("portal").get<bool>(), j.at("glossy").get<bool>(),
                     j.at("metallic").get<double>(), j.at("roughness").get<double>()});
      if (const auto g = j.find("glazing"); g != j.end()) {
        out.back().glazing =
            make_glazing(g->at("visible_transmittance").get<double>(), g->at("panes").get<int>(),
                         g->at("diffusing").get<bool>());
      }
    }
  } catch (const nlohmann::json::exception& e) {
    fail_input(where, std::string("scene_materials: ") + e.what());
  } catch (const std::invalid_argument& e) {  // a glazing no glass can have
    fail_input(where, std::string("scene_materials: ") + e.what());
  }
  return out;
}

}  // namespace

std::string scene_digest(const nlohmann::json& scene_document) {
  const std::string text = scene_document.dump();
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx",
                static_cast<unsigned long long>(xxh64(std::as_bytes(std::span(text)))));
  return hex;
}

namespace {

// The ranks' shares of the receivers (engine/ranks.h), and the bytes of one block of each kind
// of blocked section.
struct BlockedSections {
  RankShares ranks;
  LuminaireBlockBytes luminaire;
  std::size_t portal_indirect = 0;
};

BlockedSections blocked_sections(const Precomputed& p, const Scene& scene, RankExchange* ranks) {
  const std::size_t receivers = p.receivers.size();
  const std::size_t element =
      transfer_storage_named(scene.precompute.storage) == TransferStorage::fp16 ? 2 : 4;
  const auto k = static_cast<std::size_t>(sh_count(p.sh_order));
  BlockedSections out{ranks != nullptr ? dealt_blocks(*ranks, receivers, kBlock)
                                       : single_process_shares(receivers, kBlock),
                      {k * 3 * kBlock * element, p.direct_mode == "sh" ? k * kBlock * 4 : 0},
                      static_cast<std::size_t>(sh_count(p.portal_sh_order)) * 3 * kBlock * element};
  return out;
}

// The sections that every rank holds a share of, each kind's through `sink`: the one path of the
// writing rank and of the others.
void write_shared_sections(SectionSink& sink, const Precomputed& p,
                           std::span<const std::string> photometry,
                           const BlockedSections& blocked) {
  write_luminaire_sections(sink, p.luminaires, photometry, blocked.luminaire);
  write_portal_sections(sink, p.portals, blocked.portal_indirect);
  write_nearfield_sections(sink, p.nearfield);
  write_gather_sections(sink, p.gather);
}

}  // namespace

void send_transfer_file_sections(const Precomputed& p, const Scene& scene, RankExchange& ranks) {
  const BlockedSections blocked = blocked_sections(p, scene, &ranks);
  SectionSink sink(blocked.ranks);
  write_shared_sections(sink, p, {}, blocked);
}

void write_transfer_file(const fs::path& file, const Precomputed& p, const Scene& source,
                         const nlohmann::json& scene_document, const fs::path& scene_file,
                         RankExchange* ranks) {
  if (p.luminaires.size() > 0xFFFF || p.portals.size() > 0xFFFF) {
    throw std::invalid_argument("too many luminaires or portals");
  }
  const BlockedSections blocked = blocked_sections(p, source, ranks);
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
  nlohmann::json metadata = {
      {"photometry", photometry_files},
      {"portal_sh_order", p.portal_sh_order},
      {"nearfield_sh_order", p.nearfield.sh_order},
      {"portals",
       portal_metadata(p.portals, block_count(p.receivers.size()) * blocked.portal_indirect)},
      {"format", "relight transfer"},
      {"scene_file", fs::absolute(scene_file).lexically_normal().string()},
      {"scene_digest", scene_digest(scene_document)},
      {"scene", scene},
      {"scene_materials", materials_json(source.materials)},
      {"sh_order", p.sh_order},
      {"direct", p.direct_mode},
      {"bounces", p.bounces},
      {"vertices", p.receivers.vertex_count},
      {"sensors", p.receivers.sensor_count},
      {"triangles", p.mesh.triangles.size()},
      {"luminaires", p.luminaires.size()},
      {"phases", phases}};
  if (!p.cuts.empty()) {
    const HeightCutsView svc = p.cuts.self_visibility.view();
    metadata["cuts"] = {{"directions", p.cuts.directions.size()},
                        {"threshold", p.cuts.threshold},
                        {"self_visibility_nodes", svc.node_count()},
                        {"self_visibility_bytes", svc.bytes()},
                        {"index_encoded_bytes", index_encoded_bytes(svc)}};
  }

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
  std::vector<float> texture;
  for (const Rgb& t : p.mesh.vertex_texture) {
    texture.insert(texture.end(),
                   {static_cast<float>(t.r), static_cast<float>(t.g), static_cast<float>(t.b)});
  }
  if (!texture.empty()) w.add_f32(kVertexTexture, "vertex texture", texture);
  w.add_u32(kTriangles, "triangles", triangles);
  w.add_u32(kPortalTriangles, "portal triangles", p.triangle_portal);
  w.add_u32(kTriangleMaterials, "triangle materials", p.mesh.triangle_material);
  SectionSink sink(w, blocked.ranks);
  write_shared_sections(sink, p, photometry, blocked);
  ObjectSectionData objects;
  write_object_sections(w, p.objects, objects);
  CutsSectionData cuts;
  write_cuts_sections(w, p.cuts, cuts);
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
                            l.indirect.view(), l.direct_sh_blocks});
  }
  v.portal_sh_order = p.portal_sh_order;
  for (const PortalTransfer& t : p.portals) {
    v.portals.push_back({t.geometry.name, t.direct.face_size, t.geometry.centre, t.direct.outward,
                         t.geometry.diameter, t.direct.records, t.direct.offsets,
                         t.indirect.view()});
  }
  v.objects = p.objects;
  v.cuts = cuts_view(p.cuts);
  v.nearfield.sh_order = p.nearfield.sh_order;
  v.nearfield.transfer = p.nearfield.transfer;
  RuntimeSceneView& s = v.scene;
  const auto& g = p.gather;
  if (g.rows() > 0) {
    if (!g.isCompressed()) throw std::invalid_argument("in_memory_view: gather not compressed");
    s.gather_rows = indices(g.outerIndexPtr(), g.rows() + 1);
    s.gather_columns = indices(g.innerIndexPtr(), g.nonZeros());
    s.gather_values = {g.valuePtr(), static_cast<std::size_t>(g.nonZeros())};
  }
  s.vertex_albedo.reserve(3 * p.receivers.vertex_count);
  for (std::size_t i = 0; i < p.receivers.vertex_count; ++i) {
    const Rgb a = p.receivers.albedo[i];
    s.vertex_albedo.insert(s.vertex_albedo.end(), {static_cast<float>(a.r), static_cast<float>(a.g),
                                                   static_cast<float>(a.b)});
  }
  s.vertex_count = p.receivers.vertex_count;
  s.vertex_material = p.mesh.vertex_material;
  for (const Rgb& t : p.mesh.vertex_texture) {
    s.vertex_texture.insert(
        s.vertex_texture.end(),
        {static_cast<float>(t.r), static_cast<float>(t.g), static_cast<float>(t.b)});
  }
  s.receiver_positions = p.receivers.positions;
  s.receiver_normals = p.receivers.normals;
  s.mesh_positions = p.mesh.positions;
  for (std::size_t i = 0; i < p.mesh.triangles.size(); ++i) {
    const std::uint32_t glass = p.triangle_portal[i];
    if (glass == 0) {
      s.opaque_triangles.push_back(p.mesh.triangles[i]);
      s.opaque_ids.push_back(static_cast<std::uint32_t>(i));
    } else if (glass != kGlassOutsidePortals) {
      s.glass_triangles.push_back(p.mesh.triangles[i]);
      s.glass_portal.push_back(glass - 1);
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
        std::make_shared<const std::string>(luminaire_photometry(t.file, j));
  }
  if (m.contains("scene_materials")) {
    const std::vector<Material> materials = materials_from_json(m.at("scene_materials"), where);
    t.scene = scene_from_json(m.at("scene"), scene_file, &embedded, &materials);
  } else {  // files from before scene_materials: scenes without mesh files' own materials
    t.scene = scene_from_json(m.at("scene"), scene_file, &embedded);
  }
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
  t.scene.mesh_bounds = t.bounds();
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
  t.view.luminaires = read_luminaire_sections(t.file, t.scene.luminaires, receivers,
                                              t.view.sh_order, t.view.direct_sh_mode, where);
  t.view.portal_sh_order = m.value("portal_sh_order", 6);
  if (t.view.portal_sh_order < 1 || t.view.portal_sh_order > 16) {
    fail_input(where, "portal_sh_order out of range");
  }
  t.view.portals = read_portal_sections(t.file, m.value("portals", nlohmann::json::array()),
                                        t.scene.portals, receivers, t.view.portal_sh_order, where);
  NearfieldTransferView& nf = t.view.nearfield;
  if (!t.scene.emitters.empty()) {
    nf.sh_order = m.value("nearfield_sh_order", 0);
    read_nearfield_sections(t.file, receivers, nf, where);
  }
  t.view.objects = read_object_sections(t.file, t.scene, where);
  std::size_t object_vertices = 0;
  for (const ObjectMesh& o : t.view.objects) object_vertices += o.positions.size();
  t.view.cuts =
      read_cuts_sections(t.file, receivers, t.view.objects.size(), object_vertices, where);
  if (t.scene.environment && t.view.cuts.directions.empty()) {
    fail_input(where,
               "the scene has a top-level environment but the file no visibility cuts "
               "(run relight precompute again)");
  }
  RuntimeSceneView& s = t.view.scene;
  read_gather_sections(t.file, receivers, t.vertex_count, s, where);
  s.vertex_albedo.assign(t.vertex_albedo.begin(), t.vertex_albedo.end());
  s.vertex_count = t.vertex_count;
  if (t.file.find_info(kVertexTexture)) {
    const auto texture = t.file.view<float>(kVertexTexture);
    if (texture.size() != 3 * t.vertex_count) fail_input(where, "vertex texture: wrong count");
    s.vertex_texture.assign(texture.begin(), texture.end());
  }
  if (!t.triangle_material.empty()) {
    // Every triangle's material is its vertices' (scene/mesh_preparation.h).
    s.vertex_material.assign(t.vertex_count, kNoMaterial);
    for (std::size_t i = 0; i < t.triangles.size(); ++i) {
      for (const std::uint32_t v : t.triangles[i]) s.vertex_material[v] = t.triangle_material[i];
    }
  }
  s.receiver_positions = t.positions;
  const auto normals = t.file.view<float>(kMeshNormals);
  if (normals.size() != 3 * t.vertex_count) fail_input(where, "mesh normals: inconsistent size");
  for (std::size_t v = 0; v < t.vertex_count; ++v) {
    s.receiver_normals.push_back({normals[3 * v], normals[3 * v + 1], normals[3 * v + 2]});
  }
  add_sensor_receivers(t.scene, s);
  s.mesh_positions = t.positions;
  for (const std::uint32_t i : t.opaque_triangles) s.opaque_triangles.push_back(t.triangles[i]);
  s.opaque_ids = t.opaque_triangles;
  for (std::size_t i = 0; i < t.portal_triangles.size(); ++i) {
    s.glass_triangles.push_back(t.triangles[t.portal_triangles[i]]);
    s.glass_portal.push_back(t.portal_of_triangle[i]);
  }
  return t;
}

}  // namespace relight
