// `relight precompute`: everything a static scene needs so that every later change of a source's
// state is a weighted sum (light transport is linear). The engine prepares the mesh, the receivers
// and the gather operator; each source module (sources/luminaires, sources/portals,
// sources/emitters) computes its direct transfer and registers the columns it bounces; all bounce
// together through one gather operator (rays traced once for every basis and bounce).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <Eigen/SparseCore>

#include "engine/ranks.h"
#include "engine/receivers.h"
#include "engine/source_precompute.h"
#include "scene/mesh_preparation.h"
#include "scene/scene.h"
#include "sources/emitters/nearfield_precompute.h"
#include "sources/environment/cuts_precompute.h"
#include "sources/luminaires/luminaire_precompute.h"
#include "sources/objects/object_mesh.h"
#include "sources/portals/portal_precompute.h"
#include "sources/precompute_memory.h"

namespace relight {

struct PrecomputeOptions {
  bool progress = true;
  std::uint64_t seed = 1;
  int opening_samples = kOpeningSamples;  // points on a luminous opening (luminaire_direct.h)
  // The ranks of an MPI run (engine/ranks.h), each calling precompute_transfer with the same
  // scene and options: each traces its share of the receivers, and every rank returns the same
  // Precomputed (its phases' times are its own). nullptr: this process alone.
  RankExchange* ranks = nullptr;
  // Memory this process (rank) may use, bytes: a scene whose predicted peak
  // (sources/precompute_memory.h) is more is refused before the gather operator is traced, on
  // every rank (AgreedInputError). nullopt: no check. `memory_source` says where the figure comes
  // from, for the refusal.
  std::optional<std::uint64_t> memory_bytes;
  std::string memory_source;
};

inline constexpr std::uint32_t kGlassOutsidePortals = 0xFFFFFFFFu;

// The precompute's peak memory predicted on `ranks` ranks (sources/precompute_memory.h) by a
// process holding what precompute_transfer holds before it traces: the prepared mesh, its
// receivers and their ray points, the movable objects and the Embree scenes. What it samples, the
// precompute reuses to size its stores. `relight info` and precompute_transfer both call it.
struct PrecomputePrediction {
  GatherEntries gather;
  CutsPrediction cuts;  // empty without a top-level environment
  PrecomputeMemory memory;
};
PrecomputePrediction predict_precompute(const Scene& scene, const PreparedMesh& mesh,
                                        const Receivers& receivers,
                                        std::span<const Vec3> ray_points,
                                        std::span<const ObjectMesh> objects,
                                        const TracedScene& traced, std::uint64_t seed,
                                        int ranks = 1);

struct Precomputed {
  PreparedMesh mesh;
  // Per mesh triangle: 0 opaque, p + 1 for glass of portal p, kGlassOutsidePortals for glass
  // of a "portal": true material that no portal lists (an opening to darkness).
  std::vector<std::uint32_t> triangle_portal;
  Receivers receivers;
  int sh_order = 8;
  std::string direct_mode = "exact";
  int bounces = 0;
  std::vector<LuminaireTransfer> luminaires;  // in scene order
  int portal_sh_order = 6;
  std::vector<PortalTransfer> portals;  // in scene order
  NearfieldTransfer nearfield;          // sh_order 0 when the scene has no emitters
  // The gather operator (receivers × vertices), kept for what the run time bounces itself
  // (engine/runtime_scene.h): the exact sun through portals, and near-field emitters with
  // "nearfield_interreflection", and movable objects. Empty for a scene with none of these.
  Eigen::SparseMatrix<float, Eigen::RowMajor> gather;
  // The movable objects' prepared meshes (scene order) and the seconds each took; all the rest
  // of an object's light is traced at run time (sources/objects/object_lighting.h).
  std::vector<ObjectMesh> objects;
  std::vector<double> object_seconds;
  // The top-level environment's visibility cuts (sources/environment/cuts_precompute.h); empty
  // without one.
  CutsTransfer cuts;
  std::vector<PhaseTiming> phases;
  PrecomputeMemory memory;            // the peak predicted before the gather operator was traced
  std::vector<std::string> warnings;  // e.g. portals too large for their shells (§6)
};

Precomputed precompute_transfer(const Scene& scene, const PrecomputeOptions& options);

}  // namespace relight
