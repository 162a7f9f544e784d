// The precompute of the visibility cuts (Iwasaki et al., Cyberworlds, §V.A.1: the capture paper,
// papers/003), made when the scene has a top-level environment: the direction tree of
// `CutsSettings::directions` directions and a self-visibility cut
// (sources/environment/self_visibility.h) at every receiver — the static scene's vertices, then its
// sensors — traced against the static scene's opaque surfaces and its portals' glass (a window
// shows its own exterior, not the top-level environment: reference/reference_tracer.h does the
// same), height encoded (math/cut_encoding.h). Movable objects are not in these cuts: they shadow
// through their visibility cut fields (sources/environment/visibility_field.h), and each object
// vertex has its own cut of the object's self-occlusion, in the object's frame. Every rank of an
// MPI run computes every cut (they are not dealt out). Pinned by
// tests/cli/environment_cuts_test.cpp.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "engine/receivers.h"
#include "math/cut_encoding.h"
#include "math/direction_tree.h"
#include "scene/scene.h"
#include "sources/environment/visibility_field.h"
#include "sources/objects/object_mesh.h"
#include "trace/traced_scene.h"

namespace relight {

struct CutsTransfer {
  std::vector<Vec3> directions;  // the tree's leaves in leaf order; empty: no cuts
  HeightCuts self_visibility;    // one cut per receiver
  // Per movable object (scene order): its visibility cut field's layout, and the fields' cuts
  // back to back (object o's samples from field_first[o]; field_first has one more entry).
  std::vector<VisibilityFieldLayout> fields;
  std::vector<std::uint64_t> field_first;
  HeightCuts field_cuts;
  // One cut per object vertex (objects back to back, scene order): its object's occlusion
  // alone, in the object's frame as the scene places it.
  HeightCuts object_self_visibility;
  double threshold = 0;
  std::uint64_t rays = 0;
  double seconds = 0;

  bool empty() const { return directions.empty(); }
};

// The nodes precompute_cuts will store, from a sample of each store's cuts traced as it traces
// them (a few hundred receivers' and object vertices' cuts, and of each field's samples): what the
// precompute's memory prediction counts (sources/precompute_memory.h) and the stores reserve.
struct CutsPrediction {
  DirectionTree tree;  // the settings' direction tree, sampled with and then traced over
  std::uint64_t receiver_nodes = 0;                // the self-visibility cuts'
  std::vector<std::uint64_t> field_nodes;          // per object: its field's
  std::vector<std::uint64_t> object_vertex_nodes;  // per object: its vertices' own cuts'
  std::uint64_t bytes = 0;                         // all of them height encoded
  std::uint64_t window = 0;  // the most a window of cuts holds before it is encoded

  // What the cuts hold at their peak: the stores and a window being encoded.
  std::uint64_t held() const { return bytes + window; }
};

CutsPrediction predict_cuts(const CutsSettings& settings, const Receivers& receivers,
                            std::span<const Vec3> ray_points, const TracedScene& traced,
                            std::span<const ObjectMesh> objects);

// `ray_points` per receiver (engine/receivers.h receiver_ray_points), pushed off the surface
// here; `objects` the scene's movable objects as prepared. `predicted`, when given (predict_cuts
// of the same inputs), gives the direction tree and sizes the stores before they fill.
CutsTransfer precompute_cuts(const CutsSettings& settings, const Receivers& receivers,
                             std::span<const Vec3> ray_points, const TracedScene& traced,
                             std::span<const ObjectMesh> objects, bool progress,
                             const CutsPrediction* predicted = nullptr);

}  // namespace relight
