// Movable objects under the top-level environment (Iwasaki et al., Cyberworlds, §V, Eq. 3–4: the
// capture paper, papers/003): the visibility at a receiver x is its own cut times the occlusion of
// every object near it,
//     V(x, ω) = SVC(x, ω) · Π_o VCF_o(x, ω),
// each VCF_o interpolated from the eight samples of object o's field around x
// (sources/environment/visibility_field.h) and the product taken by the merge with counters
// (math/cut_merge.h); E = Σ_{nodes} V · n · M over the product's nodes with the environment's
// moments (light/environment_clusters.h). Objects whose bounding sphere lies below x's
// horizon or beyond their field's outer sphere are culled (§V.B).
//
// At the room's receivers this gives what the objects take from the empty room's direct light
// (room_delta: E with the objects less E without). At an object vertex it gives all of its
// direct light, in the object's own frame (its cut of itself is stored there): the other
// objects' fields and the environment's moments turned into that frame, and the static scene —
// which no stored cut holds for a vertex that moves — traced once per placement at 1,024
// coarse directions (the tree's nodes of that depth, one ray along each), a floor below a
// chair's seat blocking the ground half of a sky. Both go to the objects' bounce as direct
// light (sources/objects/object_lighting.h ObjectLightInputs::extra_room and extra_objects).
//
// Within a field's inner sphere (a floor beside or under the object), where the paper's field has
// no samples, the object itself is traced from the receiver in its bounding cone, leaf by leaf
// above the receiver's horizon — along the leaves whose ray meets the object's box; the rest
// are open without a ray.
// An object turned about the vertical relative to the frame of the receiver's cut has its
// interpolated field re-expressed in that frame leaf by leaf within its bounding cone (each
// leaf at the nearest leaf of the turned direction): exact to a leaf, slower than the merge
// alone.
//
// The environment's compact sources (light/compact_sources.h) are traced instead, against the
// static scene and the objects as placed (sources/environment/compact_light.h): at room receivers
// the difference the objects make to what the static scene lets through (where some source's cone
// from the receiver meets an object's bounding sphere), at object vertices all of it. Kept apart
// from the cuts' parts (room_compact, object_compact) since renderers that trace direct light
// per pixel trace these. Pinned by tests/cli/environment_cuts_test.cpp (moved and turned objects
// against the reference).
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <span>
#include <vector>

#include "engine/runtime_scene.h"
#include "light/compact_sources.h"
#include "light/environment.h"
#include "light/environment_clusters.h"
#include "math/cut_merge.h"
#include "math/direction_tree.h"
#include "math/placement.h"
#include "math/point_grid.h"
#include "sources/environment/cuts_sections.h"
#include "sources/objects/object_mesh.h"

namespace relight {

// The environment's compact sources as the room's receivers see them past the static scene.
struct RoomCompact {
  const CompactSources& sources;
  std::span<const float> fraction;  // per receiver, per source: f_s
  std::span<const float> direct;    // 3 per receiver: Σ_s E_s (part of the room's direct light)
};

class EnvironmentObjects {
 public:
  // All must outlive this.
  EnvironmentObjects(const CutsTransferView& cuts, const DirectionTree& tree,
                     const PointGrid& leaves, const RuntimeScene& room,
                     std::span<const ObjectMesh> meshes);

  // Lights the objects as `placed` by `placements` under `env` (null: dark), whose world
  // moments are `moments` (its compact sources left out), against the empty room's direct light
  // `room_direct` (3 per room receiver, the compact sources' `compact.direct` included).
  // `env_changed`: the environment changed since the last call. Returns whether anything was
  // made again (false: the same environment and placements as the last call).
  bool update(const Environment* env, std::span<const RgbMoment> moments,
              std::span<const Vec3> directions, std::span<const float> room_direct,
              const RoomCompact& compact, const PlacedObjects& placed,
              std::span<const MovablePlacement> placements, bool env_changed);

  // Object vertex q's visibility (PlacedObjects order) in its object's frame, as the last update
  // placed it: its cut of itself times the static scene's coarse view and the other objects'
  // fields; null when the object is hidden or there is no environment. For renderers.
  const ValueCut* object_visibility(std::size_t q, const PlacedObjects& placed) const;
  // Room receiver r's visibility with the objects as last placed, in the world: its cut times
  // the fields of the objects that reach it; null where none reaches it (its own cut alone) or
  // there is no environment. For renderers.
  const ValueCut* room_visibility(std::size_t r) const;
  // The environment's moments in object a's frame (its turn as last placed).
  std::span<const RgbMoment> object_moments(std::size_t a) const;
  // Their nodes' light directions in the same frame.
  std::span<const Vec3> object_light_directions(std::size_t a) const;
  std::span<const ObjectMesh> meshes() const { return meshes_; }
  // Object a's turn as last placed, degrees.
  double object_turn(std::size_t a) const { return placements_.at(a).rotate_deg; }

  // The cuts' parts: what the objects take from the room's receivers (3 per receiver), the
  // objects' vertices' direct light (3 per vertex); then the compact sources' likewise.
  std::span<const float> room_delta() const { return room_delta_; }
  std::span<const float> object_direct() const { return object_direct_; }
  std::span<const float> room_compact() const { return room_compact_; }
  std::span<const float> object_compact() const { return object_compact_; }
  double seconds() const { return seconds_; }
  // The turned frames' light and leaf tables kept for the placements as they stand (bounded
  // however many turns a drag went through).
  std::size_t kept_turns() const { return turned_.size() + turns_.size(); }

 private:
  struct Scratch;
  // Object o's occlusion at world point x (normal n) in a frame turned by `frame_deg`: its
  // field interpolated, or within the field's inner sphere the object traced; false when o
  // casts nothing there.
  bool field_factor(std::size_t o, Vec3 x, Vec3 n, double frame_deg, const PlacedObjects& placed,
                    Scratch& s, ValueCut& out) const;
  // Top down over the tree's nodes in leaf order: on_node(first leaf, height) for each node
  // disjoint from the cone (unit axis, half-angle) or wholly below the horizon of `up`,
  // on_leaves(first leaf, count) for the other leaves — a node wholly within the cone and above
  // the horizon at once, without a test a leaf.
  template <typename OnNode, typename OnLeaves>
  void walk_cone(Vec3 axis, double half, Vec3 up, const OnNode& on_node,
                 const OnLeaves& on_leaves) const;
  // The cut that is 1 outside the cone (unit axis, half-angle) and below the horizon of `up`,
  // leaf_value(leaf) at the other leaves.
  template <typename LeafValue>
  void cone_cut(Vec3 axis, double half, Vec3 up, const LeafValue& leaf_value, ValueCut& out) const;
  // For a turn of `relative_deg` from a receiver's frame to an object's: per leaf of the
  // receiver's frame, the object frame's nearest leaf (made once per turn).
  const std::vector<std::uint32_t>& leaf_turn(double relative_deg) const;
  // The moments of the environment in a frame turned by `frame_deg`.
  std::span<const RgbMoment> frame_moments(double frame_deg);
  struct FrameLight {                // the environment in a turned frame
    std::vector<RgbMoment> moments;  // empty: to be made for the current environment
    std::vector<Vec3> directions;    // moment_direction of each node
    EnvironmentGridParts parts;      // the environment's grid placed in the frame
  };
  // Object a's turned frame as last placed; null for the world frame's.
  const FrameLight* object_frame(std::size_t a) const;
  // Into s.factors[first …]: the fields at x (normal n, frame turned by `frame` degrees) of the
  // objects other than `skip` that are moving (moving_) or, with `moving` false, that are not;
  // returns how many.
  std::size_t factors_at(Vec3 x, Vec3 n, double frame, std::size_t skip, bool moving,
                         const PlacedObjects& placed, Scratch& s, std::size_t first) const;
  // room_products_[i] = room receiver i's cut times the fields of the objects that reach it
  // (cleared when none does): its rest (made again with `rebuild`) times the moving objects'.
  void room_product(std::size_t i, const PlacedObjects& placed, bool rebuild, Scratch& s);
  // object_products_[q] = object vertex q's (of object a) visibility, as object_visibility: its
  // rest (made again with `rebuild`) times the moving objects' fields.
  void object_cut(std::size_t q, std::size_t a, const PlacedObjects& placed, bool rebuild,
                  Scratch& s);
  // The compact sources at the room's receivers near the objects and at the objects' vertices.
  void trace_compact(const RoomCompact& compact, const PlacedObjects& placed,
                     std::span<const MovablePlacement> placements);
  // Object vertex q's view of the static scene (1,024 coarse directions), traced again.
  void trace_static(std::size_t q, const PlacedObjects& placed, double frame_deg);

  CutsTransferView cuts_;
  const DirectionTree& tree_;
  const PointGrid& leaves_;
  const RuntimeScene& room_;
  std::span<const ObjectMesh> meshes_;
  const Environment* env_ = nullptr;
  std::span<const RgbMoment> world_moments_;
  std::span<const Vec3> world_directions_;
  // Kept for the turns the objects stand at (others dropped after each update, so that an
  // object turned frame after frame leaves nothing behind).
  std::map<std::int64_t, FrameLight> turned_;  // by turn, µ°
  mutable std::mutex turn_mutex_;
  struct LeafTurn {
    std::vector<std::uint32_t> table;
    bool used = false;  // since the last update that placed anything
  };
  mutable std::map<std::int64_t, std::unique_ptr<LeafTurn>> turns_;  // by relative turn, µ°
  std::vector<MovablePlacement> placements_;  // as the static views were traced
  int coarse_depth_ = 10;                     // depth of the static views' nodes
  std::vector<std::uint64_t> static_bits_;    // per object vertex: one bit per coarse node
  std::size_t static_words_ = 0;
  struct NodeCone {  // a tree node's cone, together for the walks
    Vec3 axis;
    double cos_spread = 1, spread = 0, sin_spread = 0;  // its half-angle's cosine, it, its sine
  };
  std::vector<NodeCone> cones_;  // per node (0 unused)
  bool valid_ = false;           // updated at least once
  // The visibilities as last placed (products made again only when a placement changes; a new
  // environment only sums them again).
  std::vector<ValueCut> room_products_, object_products_;
  // A drag: the objects the last update moved (1), and every receiver's product of everything
  // else — its own cut, the static scene, the objects left where they were — so that while the
  // same objects move again only their fields are interpolated and multiplied in. Made again
  // when another set of objects moves.
  std::vector<std::uint8_t> moving_;
  bool rests_valid_ = false;
  std::vector<ValueCut> room_rests_, object_rests_;  // room: empty when no object stays in reach
  std::vector<std::uint8_t> room_reached_;           // a moving object reached the receiver
  std::vector<float> room_delta_, object_direct_;
  const CompactSources* compact_ = nullptr;  // the last update's
  std::vector<float> room_compact_, object_compact_;
  double seconds_ = 0;
};

}  // namespace relight
