// Editing a curve distribution at run time: moving one control point updates the SH
// weights incrementally (Dobashi et al. 1995's Eq. 21) and gives the same light as
// projecting the edited curve anew.
#include <gtest/gtest.h>

#include "runtime/relighter.h"
#include "scene/scene_loader.h"
#include "sources/precompute.h"
#include "sources/transfer_file.h"

namespace relight {
namespace {

nlohmann::json room(const std::vector<double>& candela) {
  return {{"materials", {{"grey", {{"albedo", {0.6, 0.5, 0.4}}}}}},
          {"geometry",
           {{{"type", "box"},
             {"min", {0, 0, 0}},
             {"max", {3, 2.5, 3}},
             {"normals", "inward"},
             {"material", "grey"}}}},
          {"luminaires",
           {{{"name", "spot"},
             {"position", {1.5, 2.4, 1.5}},
             {"aim", {0.3, -1, 0.2}},
             {"distribution",
              {{"type", "curve"}, {"gamma_deg", {0, 15, 30, 50, 90}}, {"candela", candela}}}}}},
          {"sensors",
           {{{"name", "floor"},
             {"grid",
              {{"corner", {0.2, 0, 0.2}},
               {"u", {2.6, 0, 0}},
               {"v", {0, 0, 2.6}},
               {"nu", 4},
               {"nv", 4}}}}}},
          {"precompute",
           {{"max_edge", 0.6}, {"gather_rays", 32}, {"sensor_gather_rays", 64}, {"sh_order", 6}}}};
}

std::vector<float> relight_all(Relighter& relighter) {
  std::vector<float> e(3 * relighter.receivers());
  relighter.relight(e);
  return e;
}

TEST(RelighterCurveEdit, OneMovedControlPointUpdatesIncrementallyAndMatchesAFreshProjection) {
  const std::vector<double> before = {900, 800, 400, 60, 0}, after = {900, 800, 650, 60, 0};
  const Scene scene = scene_from_json(room(before), "room.json");
  PrecomputeOptions options;
  options.progress = false;
  const Precomputed p = precompute_transfer(scene, options);

  Relighter edited(in_memory_view(p), scene);
  LightingState state = edited.state();
  state.luminaires[0].distribution.curve_candela = after;
  edited.set_state(state);
  EXPECT_EQ(edited.incremental_curve_updates(), 1u);
  // Re-aiming keeps the projector; replacing two points projects anew.
  state.luminaires[0].aim = normalize(Vec3{-0.2, -1, 0.1});
  edited.set_state(state);
  state.luminaires[0].aim = normalize(Vec3{0.3, -1, 0.2});
  edited.set_state(state);
  EXPECT_EQ(edited.incremental_curve_updates(), 1u);

  // The same transfer, relit with the edited curve projected from scratch.
  const Scene edited_scene = scene_from_json(room(after), "room.json");
  Relighter fresh(in_memory_view(p), edited_scene);
  const std::vector<float> a = relight_all(edited), b = relight_all(fresh);
  double worst = 0, peak = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    worst = std::max(worst, double(std::abs(a[i] - b[i])));
    peak = std::max(peak, double(std::abs(b[i])));
  }
  EXPECT_LT(worst, 1e-5 * peak) << "worst difference " << worst << " of peak " << peak;

  // And the edit changed the light (the test is not comparing two unchanged states).
  Relighter original(in_memory_view(p), scene);
  const std::vector<float> c = relight_all(original);
  double change = 0;
  for (std::size_t i = 0; i < c.size(); ++i)
    change = std::max(change, double(std::abs(c[i] - b[i])));
  EXPECT_GT(change, 0.01 * peak);
}

}  // namespace
}  // namespace relight
