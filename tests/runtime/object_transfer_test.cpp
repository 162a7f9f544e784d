// The movable objects' traced transfer (sources/objects/object_transfer.h) against a closed
// form, and a drag (retraced in part) against the same placement traced from scratch, through
// the Relighter that owns them.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <tuple>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "runtime/lighting_state.h"
#include "runtime/relighter.h"
#include "scene/scene_loader.h"
#include "sources/precompute.h"
#include "sources/transfer_file.h"
#include "support/scene_json.h"

namespace relight {
namespace {

using nlohmann::json;
using testing::box;

Precomputed precompute(const Scene& scene) {
  PrecomputeOptions options;
  options.progress = false;
  return precompute_transfer(scene, options);
}

LightingState state_of(const Scene& scene, const json& document) {
  LightingState s = default_lighting_state(scene);
  apply_lighting_state(s, scene, document, "state.json", ".");
  return s;
}

// Configuration factor from a point to a centred a × a square in a parallel plane at height h
// (Howell's catalogue: four corner rectangles of a/2 × a/2).
double centred_square_factor(double a, double h) {
  const double x = a / 2 / h, sx = std::sqrt(1 + x * x);
  return 4 * (2 * x / sx * std::atan(x / sx)) / (2 * kPi);
}

// A floor sensor under a 1 m square plate 1 m up, in a closed box: the plate's cone rows give
// the plate what the sensor sees of it (its configuration factor) and take as much from the
// ceiling behind it.
TEST(ObjectTransfer, ASensorUnderAPlateSeesItsConfigurationFactorWithinTwoPercent) {
  const json document = {
      {"materials", {{"grey", {{"albedo", {0.5, 0.5, 0.5}}}}}},
      {"geometry",
       {{{"type", "box"},
         {"min", {-3, 0, -3}},
         {"max", {3, 3, 3}},
         {"normals", "inward"},
         {"material", "grey"}}}},
      {"objects",
       {{{"name", "plate"}, {"geometry", {box({-0.5, 1, -0.5}, {0.5, 1.01, 0.5}, "grey")}}}}},
      {"sensors", {{{"name", "s"}, {"points", {{0, 0, 0}}}}}},
      {"precompute", {{"max_edge", 1.0}, {"gather_rays", 16}}}};
  const Scene scene = scene_from_json(document, "plate.json");
  const Precomputed p = precompute(scene);
  Relighter relighter(in_memory_view(p), scene);
  std::vector<float> e(3 * relighter.receivers());
  relighter.relight(e);
  const ObjectTransfer& t = relighter.objects()->transfer();
  const std::size_t row = p.receivers.vertex_count;  // the sensor
  double gained = 0, lost = 0;
  const ObjectRows& c = t.cones[0];
  for (std::size_t i = c.begin[row]; i < c.end[row]; ++i) {
    (c.columns[i] >= p.receivers.vertex_count ? gained : lost) += c.values[i];
  }
  const double f = centred_square_factor(1, 1);
  std::printf("configuration factor %.4f; plate gained %.4f, room lost %.4f\n", f, gained, -lost);
  EXPECT_NEAR(gained, f, 0.02 * f);
  EXPECT_NEAR(-lost, f, 0.02 * f);
}

// Dragging (two moves, each retracing only what it can change) ends where tracing the final
// placement from scratch does.
// A 4 × 2.5 × 4 m grey room with a tall red box and a low grey one, a downlight, floor sensors.
json two_object_room() {
  return {{"materials",
           {{"grey", {{"albedo", {0.6, 0.6, 0.6}}}}, {"red", {{"albedo", {0.7, 0.1, 0.1}}}}}},
          {"geometry",
           {{{"type", "box"},
             {"min", {0, 0, 0}},
             {"max", {4, 2.5, 4}},
             {"normals", "inward"},
             {"material", "grey"}}}},
          {"objects",
           {{{"name", "a"}, {"geometry", {box({0.5, 0, 0.5}, {1.0, 1.5, 1.5}, "red")}}},
            {{"name", "b"}, {"geometry", {box({2.5, 0, 2.5}, {3.2, 0.8, 3.0}, "grey")}}}}},
          {"luminaires",
           {{{"name", "l"},
             {"position", {2, 2.4, 2}},
             {"distribution", {{"type", "cosine_power"}, {"candela", 500}, {"exponent", 1}}}}}},
          {"sensors",
           {{{"name", "floor"},
             {"grid",
              {{"corner", {0.1, 0.01, 0.1}},
               {"u", {3.8, 0, 0}},
               {"v", {0, 0, 3.8}},
               {"nu", 8},
               {"nv", 8}}},
             {"normal", {0, 1, 0}}}}},
          {"precompute", {{"max_edge", 0.4}, {"gather_rays", 64}, {"sensor_gather_rays", 256}}}};
}

// The worst relative difference in luminance between two lights, where the second is over 1 lx.
double worst_difference(const std::vector<float>& a, const std::vector<float>& b) {
  double worst = 0;
  for (std::size_t i = 0; i < b.size(); i += 3) {
    const double x = luminance(Rgb{a[i], a[i + 1], a[i + 2]});
    const double y = luminance(Rgb{b[i], b[i + 1], b[i + 2]});
    if (y > 1) worst = std::max(worst, std::abs(x / y - 1));
  }
  return worst;
}

TEST(ObjectTransfer, ADragEndsWhereTracingTheFinalPlacementFromScratchDoes) {
  const Scene scene = scene_from_json(two_object_room(), "drag.json");
  const Precomputed p = precompute(scene);
  const json first = {{"objects", {{"a", {{"translate", {0.8, 0, 0.4}}}}}}};
  const json last = {{"objects", {{"a", {{"translate", {1.0, 0, 0.6}}, {"rotate_deg", 20}}}}}};
  std::vector<float> dragged(3 * p.receivers.size()), fresh(dragged.size());
  {
    Relighter r(in_memory_view(p), scene);
    r.relight(dragged);
    r.set_state(state_of(scene, first));
    r.relight(dragged);
    r.set_state(state_of(scene, last));
    r.relight(dragged);
    EXPECT_LT(
        r.objects()->transfer().retraced_rows,
        (scene.objects.size() + 1) * (p.receivers.size() + r.objects()->placed().vertex_count()));
  }
  {
    Relighter r(in_memory_view(p), scene);
    r.set_state(state_of(scene, last));
    r.relight(fresh);
  }
  const double worst = worst_difference(dragged, fresh);
  std::printf("dragged vs traced from scratch: worst relative difference %.5f\n", worst);
  EXPECT_LT(worst, 0.005);  // the warm-started bounce stops at 1e-3 relative change
}

// The largest difference between two sets of the objects' rows, entry by entry (rows as dense
// maps from column to weight).
double worst_row_difference(const ObjectRows& a, const ObjectRows& b) {
  double worst = 0;
  std::vector<double> dense;
  for (std::size_t row = 0; row < std::min(a.rows(), b.rows()); ++row) {
    std::vector<std::pair<std::uint32_t, double>> entries;
    for (std::size_t i = a.begin[row]; i < a.end[row]; ++i) {
      entries.emplace_back(a.columns[i], a.values[i]);
    }
    for (std::size_t i = b.begin[row]; i < b.end[row]; ++i) {
      entries.emplace_back(b.columns[i], -double{b.values[i]});
    }
    std::sort(entries.begin(), entries.end());
    for (std::size_t i = 0; i < entries.size();) {
      double sum = 0;
      const std::uint32_t column = entries[i].first;
      for (; i < entries.size() && entries[i].first == column; ++i) sum += entries[i].second;
      worst = std::max(worst, std::abs(sum));
    }
  }
  return a.rows() == b.rows() ? worst : 1.0;
}

// Drags `a` toward `b` in four steps, turning it, then lights the same state from scratch, and
// returns the worst entry difference of the two transfers' rows (every object's cones and the
// base rows) and of their glass hits; `entries`, `glass`: the fresh transfer's.
double drag_against_fresh(const Scene& scene, std::size_t& entries, std::size_t& glass) {
  const Precomputed p = precompute(scene);
  std::vector<float> e(3 * p.receivers.size());
  Relighter dragged(in_memory_view(p), scene);
  dragged.relight(e);
  for (int step = 1; step <= 4; ++step) {
    const json state = {
        {"objects",
         {{"a", {{"translate", {0.3 * step, 0, 0.25 * step}}, {"rotate_deg", 10 * step}}}}}};
    dragged.set_state(state_of(scene, state));
    dragged.relight(e);
  }
  Relighter fresh(in_memory_view(p), scene);
  fresh.set_state(dragged.state());
  fresh.relight(e);
  const ObjectTransfer& a = dragged.objects()->transfer();
  const ObjectTransfer& b = fresh.objects()->transfer();
  if (a.cones.size() != b.cones.size()) return 1;
  double worst = worst_row_difference(a.base, b.base);
  entries = b.base.used;
  glass = b.base.glass.size();
  // Glass hits as sparse rows too: per row, the weights by portal and direction.
  const auto glass_rows = [](const ObjectRows& rows) {
    ObjectRows out;
    std::map<std::tuple<std::uint32_t, std::uint32_t, double, double, double>, double> sums;
    for (const GlassHit& g : rows.glass) {
      sums[{g.row, g.portal, g.direction.x, g.direction.y, g.direction.z}] += g.weight;
    }
    std::map<std::tuple<std::uint32_t, std::uint32_t, double, double, double>, std::uint32_t> ids;
    out.begin.assign(rows.rows(), 0);
    out.end.assign(rows.rows(), 0);
    for (const auto& [key, weight] : sums) {
      const std::uint32_t row = std::get<0>(key);
      auto [id, added] = ids.emplace(key, static_cast<std::uint32_t>(ids.size()));
      if (out.begin[row] == out.end[row]) out.begin[row] = out.end[row] = out.columns.size();
      out.columns.push_back(id->second);
      out.values.push_back(static_cast<float>(weight));
      ++out.end[row];
    }
    return std::make_pair(out, ids);
  };
  for (std::size_t k = 0; k < a.cones.size(); ++k) {
    worst = std::max(worst, worst_row_difference(a.cones[k], b.cones[k]));
    entries += b.cones[k].used;
    glass += b.cones[k].glass.size();
    // The same hit keys in both (direction and portal) with equal summed weights.
    auto [ga, ida] = glass_rows(a.cones[k]);
    auto [gb, idb] = glass_rows(b.cones[k]);
    std::map<std::tuple<std::uint32_t, std::uint32_t, double, double, double>, double> diff;
    for (const auto& [key, id] : ida) diff[key] += ga.values[id];
    for (const auto& [key, id] : idb) diff[key] -= gb.values[id];
    for (const auto& [key, d] : diff) worst = std::max(worst, std::abs(d));
  }
  return worst;
}

// The rows a drag updates in place — another object's rays that may meet the dragged one, only
// those traced, the change in their count added — equal the rows traced from scratch for the
// final placement, entry by entry (the same rays: only float rounding differs).
TEST(ObjectTransfer, ADraggedObjectsRowsEqualTheRowsTracedFromScratchEntryByEntry) {
  std::size_t entries = 0, glass = 0;
  const double worst =
      drag_against_fresh(scene_from_json(two_object_room(), "rows.json"), entries, glass);
  std::printf("%zu entries; worst difference %.2e\n", entries, worst);
  EXPECT_GT(entries, 1000u);
  EXPECT_LT(worst, 1e-5);
}

// Likewise under a skylight over most of the ceiling, where rays that now meet an object no
// longer see the sky through the glass (the glass hits the rows carry).
TEST(ObjectTransfer, ADraggedObjectsGlassHitsEqualThoseTracedFromScratch) {
  json document = two_object_room();
  document["materials"]["glass"] = {{"portal", true}};
  document["geometry"].push_back(
      testing::quad({0.2, 2.49, 0.2}, {3.6, 0, 0}, {0, 0, 3.6}, "glass"));  // facing down
  document["portals"] = {{{"name", "sky"},
                          {"material", "glass"},
                          {"environment", {{"type", "uniform"}, {"luminance", 3000}}}}};
  std::size_t entries = 0, glass = 0;
  const double worst =
      drag_against_fresh(scene_from_json(document, "skylight.json"), entries, glass);
  std::printf("%zu entries, %zu glass hits; worst difference %.2e\n", entries, glass, worst);
  EXPECT_GT(glass, 1000u);
  EXPECT_LT(worst, 1e-5);
}

// Dimming, recolouring and re-aiming a luminaire with the objects moved re-evaluates the
// objects' stored shadow factors (no ray): the light then equals that of the same state lit
// from scratch.
TEST(ObjectTransfer, ADimmerColourAndAimChangeWithMovedObjectsMatchesLightingTheStateFromScratch) {
  const Scene scene = scene_from_json(two_object_room(), "dim.json");
  const Precomputed p = precompute(scene);
  const json moved = {{"objects", {{"a", {{"translate", {0.8, 0, 0.4}}}}}}};
  json dimmed = moved;
  dimmed["luminaires"] = {
      {"l", {{"dimmer", 0.4}, {"color", {1, 0.8, 0.6}}, {"target", {1.5, 0, 2.5}}}}};
  std::vector<float> changed(3 * p.receivers.size()), fresh(changed.size());
  {
    Relighter r(in_memory_view(p), scene);
    r.set_state(state_of(scene, moved));
    r.relight(changed);
    r.set_state(state_of(scene, dimmed));
    r.relight(changed);
    EXPECT_EQ(r.objects()->transfer().retraced_rows, 0u);  // the light changed, no object moved
  }
  {
    Relighter r(in_memory_view(p), scene);
    r.set_state(state_of(scene, dimmed));
    r.relight(fresh);
  }
  const double worst = worst_difference(changed, fresh);
  std::printf("dimmed and re-aimed vs lit from scratch: worst relative difference %.5f\n", worst);
  EXPECT_LT(worst, 0.005);
}

}  // namespace
}  // namespace relight
