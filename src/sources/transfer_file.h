// The precomputed scene as a .rlt file (docs/rlt-format.md, "Sections of a transfer
// file"): metadata JSON (the scene without its geometry, settings, statistics), the
// prepared mesh for rendering, and per-luminaire transfer, each quantity one section
// holding all luminaires back to back. Opening maps the file and exposes the transfer as
// spans for the Relighter: no copy, no parse of the large arrays.
#pragma once

#include <filesystem>
#include <span>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/scene.h"
#include "sources/precompute.h"
#include "sources/transfer_view.h"
#include "store/rlt_file.h"

namespace relight {

// A digest of a scene document (XXH64 of its canonical dump), stored in the metadata
// as "scene_digest" so that a cached .rlt can be matched to the scene it came from.
std::string scene_digest(const nlohmann::json& scene_document);

// `scene_document` is the scene JSON as loaded from `scene_file`.
// The IES/LDT files of the scene's luminaires are stored in the file too, so a .rlt
// keeps the photometry it was computed with, wherever the scene's folder goes.
// With several `ranks` (collective), `precomputed` holds each rank's share of the
// blocked transfer (sources/precompute.h); rank 0 writes, gathering those sections from every
// rank while it writes them, and the other ranks call send_transfer_file_sections.
void write_transfer_file(const std::filesystem::path& file, const Precomputed& precomputed,
                         const Scene& scene, const nlohmann::json& scene_document,
                         const std::filesystem::path& scene_file, RankExchange* ranks = nullptr);
void send_transfer_file_sections(const Precomputed& precomputed, const Scene& scene,
                                 RankExchange& ranks);

struct TransferFile {
  explicit TransferFile(RltFile f) : file(std::move(f)) {}
  RltFile file;
  nlohmann::json metadata;
  Scene scene;  // materials, luminaires, sensors, cameras (geometry lives in the mesh below)
  std::vector<Vec3> positions;
  std::vector<Triangle> triangles;
  std::vector<std::uint32_t> opaque_triangles;    // indices of non-portal triangles
  std::vector<std::uint32_t> portal_triangles;    // indices of the portals' triangles
  std::vector<std::uint32_t> portal_of_triangle;  // for each of those: its portal
  std::vector<std::uint32_t> triangle_material;   // per triangle (empty for files before MMAT)
  std::span<const float> vertex_albedo;           // 3 per vertex
  std::size_t vertex_count = 0, sensor_count = 0;
  TransferView view;

  Bounds bounds() const;
};

TransferFile open_transfer_file(const std::filesystem::path& file);

// Views of a precompute still in memory (tests, the demo): same layout as the file.
TransferView in_memory_view(const Precomputed& precomputed);

}  // namespace relight
