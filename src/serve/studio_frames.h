// The studio's binary messages (docs/studio-protocol.md): the geometry `RLGE` once per
// connection, the movable objects' meshes `RLOB` after it (scenes with objects only), and a
// radiance frame `RLFR` per state change, and the windows' views out `RLWV` when they change. A
// frame carries per vertex what a camera sees of the
// diffuse surface, L = ρ·E/π per channel (cd/m²), and the illuminance Y(E) (lx) for the
// false-colour view, as half floats, then the sensors' own readings as floats, then the same
// two values per object vertex. Little-endian, as the protocol page lays out.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "math/rgb.h"
#include "runtime/relit_scene.h"
#include "runtime/window_view.h"

namespace relight {

inline constexpr std::uint32_t kStudioProtocolVersion = 1;
inline constexpr std::uint32_t kNoSeq = 0xFFFFFFFFu;

std::string encode_geometry(const TransferFile& transfer);

// `RLOB`: every movable object's mesh as the scene places it (scene order; indices local to
// the object). Clients place each one as the lighting state says (math/placement.h).
std::string encode_objects(std::span<const ObjectMesh> objects);

// Per vertex: the portal whose glass it belongs to, or −1 (a vertex any opaque triangle uses
// is opaque).
std::vector<int> vertex_portals(const TransferFile& transfer);

// What one frame shows, before encoding.
struct FrameValues {
  std::vector<float> radiance;     // 3 per vertex, cd/m²
  std::vector<float> illuminance;  // 1 per vertex, lx
  std::vector<float> sensors;      // 1 per sensor point, lx
  // The movable objects' vertices, all objects back to back in scene order (PlacedObjects
  // order); zero for hidden objects. Empty when the scene has no objects.
  std::vector<float> object_radiance;     // 3 per object vertex, cd/m²
  std::vector<float> object_illuminance;  // 1 per object vertex, lx
};

// `irradiance`: 3 per receiver (vertices, then sensors) as RelitScene::irradiance gives it;
// `glass_radiance`: per portal, what its glass vertices show (the shell's mean radiance);
// `vertex_albedo`: 3 per vertex, what the vertices reflect under the state's materials
// (RelitScene::vertex_albedo).
void compute_frame_values(const TransferFile& transfer, std::span<const int> vertex_portal,
                          std::span<const float> irradiance, std::span<const Rgb> glass_radiance,
                          std::span<const float> vertex_albedo, FrameValues& out);

// The objects' vertices' values from their albedo and irradiance (3 floats per object vertex
// each: RelitScene::object_albedo, object_irradiance). Throws
// std::invalid_argument when the two disagree in size.
void compute_object_values(std::span<const float> albedo, std::span<const float> irradiance,
                           FrameValues& out);

std::string encode_frame(std::uint32_t frame_number, std::optional<std::uint32_t> seq,
                         float milliseconds, const FrameValues& values);

// `RLGV` (docs/studio-protocol.md): the glossy vertices' luminance toward one client's eye
// for frame `frame_number`; `luminance` is 3 per vertex, NaN at vertices that are not glossy
// (render/relit_scene_image.h glossy_vertex_luminance).
std::string encode_glossy_view(std::uint32_t frame_number, Vec3 eye, float milliseconds,
                               std::span<const float> luminance);

// `RLWV` (docs/studio-protocol.md): what each window shows looking out, for frame
// `frame_number`, for a client that draws the outside through the glass per pixel: per portal
// its centre, the sun traced apart from its shell, and the shell's cubemap (math/cubemap.h
// layout) as half floats. Throws std::invalid_argument when the shells' face sizes differ.
std::string encode_window_views(std::uint32_t frame_number, std::span<const WindowView> views);

}  // namespace relight
