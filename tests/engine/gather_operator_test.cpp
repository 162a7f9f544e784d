// The gather operator against closed forms: a row sums to the point-to-surface form factor
// (1 inside a closed room, 0 facing nothing), its barycentric split reproduces the cosine-weighted
// mean hit position, back sides and portals gather nothing, and the matrix is a deterministic
// function of the seed.
#include "engine/gather_operator.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "scene/primitives.h"

namespace relight {
namespace {

struct Rig {
  Scene scene;
  PreparedMesh mesh;
  TracedScene traced;
  Receivers receivers;
};

Rig make_rig(Scene scene, double max_edge) {
  PreparationSettings settings;
  settings.max_edge = max_edge;
  PreparedMesh mesh = prepare_mesh(scene.geometry, settings);
  TracedScene traced = build_traced_scene(mesh, scene.materials);
  Receivers receivers = make_receivers(scene, mesh);
  return {std::move(scene), std::move(mesh), std::move(traced), std::move(receivers)};
}

Scene scene_of(TriangleSoup geometry, std::vector<Material> materials) {
  Scene scene;
  scene.materials = std::move(materials);
  scene.geometry = std::move(geometry);
  return scene;
}

void add_sensor(Scene& scene, Vec3 point, Vec3 normal) {
  scene.sensors.push_back({"s" + std::to_string(scene.sensors.size()), {point}, normalize(normal)});
}

double row_sum(const GatherOperator& g, Eigen::Index row) {
  double sum = 0;
  for (Eigen::SparseMatrix<float, Eigen::RowMajor>::InnerIterator it(g.matrix, row); it; ++it) {
    sum += it.value();
  }
  return sum;
}

// Σ_k G[row, k] · position_k: the mean position of the rays' hits (barycentrics are linear).
Vec3 row_centroid(const GatherOperator& g, const PreparedMesh& mesh, Eigen::Index row) {
  Vec3 sum;
  for (Eigen::SparseMatrix<float, Eigen::RowMajor>::InnerIterator it(g.matrix, row); it; ++it) {
    sum += mesh.positions[it.index()] * double{it.value()};
  }
  return sum;
}

// (1/π) ∫ f(x, z) cosθ dω over the rectangle [x0,x1]×[z0,z1] at height h above a point at
// the origin facing +y: cosθ dω = h² dA / d⁴. Midpoint rule, error far below the tests'.
double cosine_integral(double x0, double x1, double z0, double z1, double h,
                       const std::function<double(double, double)>& f) {
  constexpr int kSteps = 1000;
  const double dx = (x1 - x0) / kSteps, dz = (z1 - z0) / kSteps;
  double sum = 0;
  for (int i = 0; i < kSteps; ++i) {
    const double x = x0 + (i + 0.5) * dx;
    for (int j = 0; j < kSteps; ++j) {
      const double z = z0 + (j + 0.5) * dz;
      const double d2 = x * x + z * z + h * h;
      sum += f(x, z) * h * h / (d2 * d2);
    }
  }
  return sum * dx * dz / kPi;
}

// Rows of a closed room sum to one: every ray reaches a front face. Embree's default
// (non-watertight) triangle test lets a ray through a shared edge about once in 10^5–10^6
// rays; such a row loses exactly 1/M. With RTC_SCENE_FLAG_ROBUST in the tracer no ray is
// lost (measured on these scenes), and the check then holds with zero lost rays.
struct ClosedRows {
  double worst_row_error = 0;  // |sum − 1| over rows, rays lost to cracks set aside
  int lost_rays = 0;
};

ClosedRows check_closed_rows(const GatherOperator& g, int rays) {
  ClosedRows result;
  for (Eigen::Index r = 0; r < g.matrix.rows(); ++r) {
    const double lost = (1 - row_sum(g, r)) * rays;
    const double whole = std::round(lost);
    result.lost_rays += static_cast<int>(whole);
    result.worst_row_error = std::max(result.worst_row_error, std::abs(lost - whole) / rays);
    EXPECT_LE(whole, 1) << "row " << r;
    EXPECT_GE(whole, 0) << "row " << r;
  }
  return result;
}

TEST(GatherOperator, RowsInsideAClosedBoxSumToOne) {
  Scene scene = scene_of(make_box({0, 0, 0}, {4, 3, 5}, Facing::kInward, 0), {{"wall"}});
  add_sensor(scene, {2, 1.5, 2.5}, {0, 1, 0});
  add_sensor(scene, {0.1, 0.2, 4.9}, {1, -1, 0.3});
  add_sensor(scene, {3.5, 2.9, 0.5}, {-0.2, 0.5, 1});
  add_sensor(scene, {2, 0, 2.5}, {0, 1, 0});  // on the floor, as a work-plane sensor would be
  const Rig rig = make_rig(std::move(scene), 0.5);
  const GatherOperator g =
      build_gather_operator(rig.receivers, rig.mesh, rig.traced, 256, 256, 1, false);
  ASSERT_EQ(g.matrix.rows(), static_cast<Eigen::Index>(rig.receivers.size()));
  ASSERT_EQ(g.matrix.cols(), static_cast<Eigen::Index>(rig.mesh.positions.size()));
  EXPECT_EQ(g.rays, 256u * rig.receivers.size());
  const ClosedRows rows = check_closed_rows(g, 256);
  EXPECT_LT(rows.worst_row_error, 1e-6);
  EXPECT_LE(rows.lost_rays, std::max<double>(1, 1e-5 * static_cast<double>(g.rays)));
  // The sensors, in the open middle of the room, lose nothing.
  const auto first_sensor = static_cast<Eigen::Index>(rig.receivers.vertex_count);
  for (Eigen::Index s = first_sensor; s < g.matrix.rows(); ++s) {
    EXPECT_NEAR(row_sum(g, s), 1, 1e-6) << "sensor " << s - first_sensor;
  }
  ::testing::Test::RecordProperty("receivers", static_cast<int>(rig.receivers.size()));
  ::testing::Test::RecordProperty("worst_row_sum_error", std::to_string(rows.worst_row_error));
  ::testing::Test::RecordProperty("rays_lost_to_cracks", rows.lost_rays);
}

TEST(GatherOperator, EveryRowOfAClosedInwardSphereSumsToOne) {
  Scene scene = scene_of(make_sphere({0, 0, 0}, 2, Facing::kInward, 4, 0), {{"wall"}});
  add_sensor(scene, {0, 0, 0}, {0, 1, 0});
  add_sensor(scene, {1.5, 0.5, -0.5}, {1, 0, 0});
  const Rig rig = make_rig(std::move(scene), 0);
  const int rays = 256;
  const GatherOperator g =
      build_gather_operator(rig.receivers, rig.mesh, rig.traced, rays, rays, 11, false);
  const ClosedRows rows = check_closed_rows(g, rays);
  EXPECT_LT(rows.worst_row_error, 1e-6);
  EXPECT_LE(rows.lost_rays, std::max<double>(1, 1e-5 * static_cast<double>(g.rays)));
  const double rays_per_second = static_cast<double>(g.rays) / g.seconds;
  ::testing::Test::RecordProperty("vertices", static_cast<int>(rig.receivers.vertex_count));
  ::testing::Test::RecordProperty("nonzeros", static_cast<int>(g.matrix.nonZeros()));
  ::testing::Test::RecordProperty("seconds", std::to_string(g.seconds));
  ::testing::Test::RecordProperty("rays_lost_to_cracks", rows.lost_rays);
  ::testing::Test::RecordProperty("rays_per_second", std::to_string(rays_per_second));
}

TEST(GatherOperator, FacingAwayFromAllGeometryOrAtBackSidesGathersNothing) {
  // A floor facing up, a box facing outward: nothing is visible from above the floor
  // looking up, and from inside the outward box every hit is a back side.
  TriangleSoup soup = make_quad({-5, 0, -5}, {0, 0, 10}, {10, 0, 0}, 0);
  soup.append(make_box({20, 0, 0}, {22, 2, 2}, Facing::kOutward, 0));
  Scene scene = scene_of(std::move(soup), {{"grey"}});
  add_sensor(scene, {0, 1, 0}, {0, 1, 0});     // above the floor, looking up at the sky
  add_sensor(scene, {0, -1, 0}, {0, 1, 0});    // under the floor, sees its back
  add_sensor(scene, {21, 1, 1}, {0.3, 1, 0});  // inside the outward box
  const Rig rig = make_rig(std::move(scene), 0);
  ASSERT_NEAR(geometric_normal(rig.mesh, 0).y, 1, 1e-12);
  const GatherOperator g =
      build_gather_operator(rig.receivers, rig.mesh, rig.traced, 128, 128, 3, false);
  const auto first_sensor = static_cast<Eigen::Index>(rig.receivers.vertex_count);
  for (Eigen::Index s = 0; s < 3; ++s) {
    EXPECT_EQ(row_sum(g, first_sensor + s), 0.0) << "sensor " << s;
  }
  // A floor vertex sees only sky: its row is empty too.
  EXPECT_EQ(row_sum(g, 0), 0.0);
}

TEST(GatherOperator, RowIsThePointToRectangleFormFactorWithItsBarycentricCentroid) {
  // A sensor at the origin facing up under a ceiling rectangle [0,2]×[-1,1] at h = 1,
  // facing down: row sum = form factor, Σ G·x = (1/π)∫ x cosθ dω (barycentric split).
  const double h = 1;
  Scene scene = scene_of(make_quad({0, h, -1}, {2, 0, 0}, {0, 0, 2}, 0), {{"ceiling"}});
  add_sensor(scene, {0, 0, 0}, {0, 1, 0});
  const Rig rig = make_rig(std::move(scene), 0.5);
  ASSERT_NEAR(geometric_normal(rig.mesh, 0).y, -1, 1e-12);
  const auto sensor = static_cast<Eigen::Index>(rig.receivers.vertex_count);
  const double form_factor = cosine_integral(0, 2, -1, 1, h, [](double, double) { return 1.0; });
  const double mean_x = cosine_integral(0, 2, -1, 1, h, [](double x, double) { return x; });
  const double mean_z = cosine_integral(0, 2, -1, 1, h, [](double, double z) { return z; });
  // Several seeds: the scrambled (0,2)-sequence converges much faster than 1/√M.
  double worst_sum = 0, worst_x = 0, worst_z = 0;
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    const GatherOperator g =
        build_gather_operator(rig.receivers, rig.mesh, rig.traced, 16384, 16384, seed, false);
    const Vec3 centroid = row_centroid(g, rig.mesh, sensor);
    worst_sum = std::max(worst_sum, std::abs(row_sum(g, sensor) - form_factor));
    worst_x = std::max(worst_x, std::abs(centroid.x - mean_x));
    worst_z = std::max(worst_z, std::abs(centroid.z - mean_z));
    EXPECT_NEAR(centroid.y, h * row_sum(g, sensor), 1e-6);
  }
  EXPECT_NEAR(form_factor, 0.334750, 1e-5);  // the corner formula, two 2×1 rectangles
  // Measured: 2e-4 (sum) and 4e-4 (centroid) at 16384 rays.
  EXPECT_LT(worst_sum, 1e-3) << "form factor " << form_factor;
  EXPECT_LT(worst_x, 1.5e-3) << "mean x " << mean_x;
  EXPECT_LT(worst_z, 1.5e-3);
  ::testing::Test::RecordProperty("form_factor", std::to_string(form_factor));
  ::testing::Test::RecordProperty("worst_form_factor_error", std::to_string(worst_sum));
  ::testing::Test::RecordProperty("worst_centroid_error",
                                  std::to_string(std::max(worst_x, worst_z)));
}

TEST(GatherOperator, RaysThroughAPortalGatherNothingBeyondIt) {
  // A closed room whose ceiling is a window, under an exterior canopy facing down: the
  // floor centre gathers the walls and floor only, 1 − F(floor centre → ceiling).
  TriangleSoup soup = make_box({0, 0, 0}, {4, 3, 4}, Facing::kInward, 0);
  for (std::size_t t = 0; t < soup.triangles.size(); ++t) {
    bool ceiling = true;
    for (std::uint32_t v : soup.triangles[t]) ceiling = ceiling && soup.positions[v].y == 3;
    if (ceiling) soup.triangle_material[t] = 1;
  }
  soup.append(make_quad({-2, 4, -2}, {8, 0, 0}, {0, 0, 8}, 0));
  Scene scene = scene_of(std::move(soup), {{"wall"}, {"glass", {0, 0, 0}, true}});
  add_sensor(scene, {2, 0, 2}, {0, 1, 0});
  const Rig rig = make_rig(std::move(scene), 1.0);
  const GatherOperator g =
      build_gather_operator(rig.receivers, rig.mesh, rig.traced, 4096, 4096, 5, false);
  const auto sensor = static_cast<Eigen::Index>(rig.receivers.vertex_count);
  const double ceiling = cosine_integral(-2, 2, -2, 2, 3, [](double, double) { return 1.0; });
  // Measured: 1e-3 at 4096 rays.
  EXPECT_NEAR(row_sum(g, sensor), 1 - ceiling, 3e-3) << "ceiling form factor " << ceiling;
  ::testing::Test::RecordProperty("walls_and_floor_error",
                                  std::to_string(row_sum(g, sensor) - (1 - ceiling)));
  // No ray lands on the window, and none on the canopy beyond it but for the rare ray
  // that slips through an edge of the window's triangles (see ClosedRows).
  double canopy = 0;
  for (int k = 0; k < g.matrix.outerSize(); ++k) {
    for (Eigen::SparseMatrix<float, Eigen::RowMajor>::InnerIterator it(g.matrix, k); it; ++it) {
      ASSERT_EQ(rig.mesh.vertex_material[it.index()], 0u) << "row " << k;  // not the glass
      if (rig.mesh.positions[it.index()].y > 3.5) canopy += it.value();
    }
  }
  const double canopy_rays = canopy * 4096;
  EXPECT_LE(canopy_rays, std::max<double>(1, 1e-5 * static_cast<double>(g.rays)));
  ::testing::Test::RecordProperty("canopy_rays", std::to_string(canopy_rays));
}

TEST(GatherOperator, IsADeterministicFunctionOfTheSeed) {
  Scene scene = scene_of(make_box({0, 0, 0}, {2, 2, 3}, Facing::kInward, 0), {{"wall"}});
  add_sensor(scene, {1, 1, 1}, {0, 0, 1});
  const Rig rig = make_rig(std::move(scene), 0.5);
  const GatherOperator a =
      build_gather_operator(rig.receivers, rig.mesh, rig.traced, 64, 64, 9, false);
  const GatherOperator b =
      build_gather_operator(rig.receivers, rig.mesh, rig.traced, 64, 64, 9, false);
  const GatherOperator c =
      build_gather_operator(rig.receivers, rig.mesh, rig.traced, 64, 64, 10, false);
  ASSERT_EQ(a.matrix.nonZeros(), b.matrix.nonZeros());
  EXPECT_EQ((a.matrix - b.matrix).norm(), 0.0f);
  EXPECT_GT((a.matrix - c.matrix).norm(), 0.0f);
}

// The build reserves its storage from a sample of rows and grows it when the sample was short:
// the matrix is the same whatever it reserved, and the sample's mean is the matrix's within 10 %.
TEST(GatherOperator, TheMatrixDoesNotDependOnTheStorageReservedForItAndTheSampleMatchesIt) {
  Scene scene = scene_of(make_box({0, 0, 0}, {4, 3, 5}, Facing::kInward, 0), {{"wall"}});
  add_sensor(scene, {2, 1.5, 2.5}, {0, 1, 0});
  add_sensor(scene, {0.5, 0.2, 4.5}, {0, 1, 0});
  const Rig rig = make_rig(std::move(scene), 0.25);
  const GatherOperator sampled =
      build_gather_operator(rig.receivers, rig.mesh, rig.traced, 64, 512, 4, false);
  const GatherEntries none{0, 0}, plenty{1e4, 1e4};
  const GatherOperator short_of_it =
      build_gather_operator(rig.receivers, rig.mesh, rig.traced, 64, 512, 4, false, nullptr, &none);
  const GatherOperator beyond_it = build_gather_operator(rig.receivers, rig.mesh, rig.traced, 64,
                                                         512, 4, false, nullptr, &plenty);
  // More entries than the least the build reserves (a chunk of the longest rows), so that it grows.
  ASSERT_GT(sampled.matrix.nonZeros(), 2 * 64 * 3 * 512);
  for (const GatherOperator* other : {&short_of_it, &beyond_it}) {
    ASSERT_EQ(other->matrix.nonZeros(), sampled.matrix.nonZeros());
    EXPECT_EQ((other->matrix - sampled.matrix).norm(), 0.0f);
  }
  const GatherEntries e = sample_gather_entries(rig.receivers, rig.mesh, rig.traced, 64, 512, 4);
  double vertex_entries = 0;
  for (std::size_t r = 0; r < rig.receivers.vertex_count; ++r) {
    vertex_entries += sampled.matrix.row(static_cast<Eigen::Index>(r)).nonZeros();
  }
  const double mean = vertex_entries / static_cast<double>(rig.receivers.vertex_count);
  EXPECT_NEAR(e.per_vertex_row / mean, 1, 0.1) << e.per_vertex_row << " against " << mean;
  EXPECT_GT(e.per_sensor_row, e.per_vertex_row);  // 512 rays against 64
}

TEST(GatherOperator, RejectsBadArguments) {
  Scene scene = scene_of(make_box({0, 0, 0}, {1, 1, 1}, Facing::kInward, 0), {{"wall"}});
  const Rig rig = make_rig(std::move(scene), 0);
  EXPECT_THROW(build_gather_operator(rig.receivers, rig.mesh, rig.traced, 0, 0, 1, false),
               std::invalid_argument);
  Receivers fewer = rig.receivers;
  fewer.vertex_count -= 1;
  EXPECT_THROW(build_gather_operator(fewer, rig.mesh, rig.traced, 8, 8, 1, false),
               std::invalid_argument);
}

}  // namespace
}  // namespace relight
