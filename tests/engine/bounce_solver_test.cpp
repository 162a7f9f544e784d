// The bounce solver against closed forms: inside a closed sphere of albedo ρ under uniform direct
// irradiance E_d the total is E_d / (1 − ρ) at every vertex and sensor, per colour channel; the
// iteration stops after the predicted number of bounces; basis columns are independent and
// superpose; a closed room conserves flux.
#include "engine/bounce_solver.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "engine/gather_operator.h"
#include "scene/primitives.h"

namespace relight {
namespace {

struct Rig {
  Scene scene;
  PreparedMesh mesh;
  TracedScene traced;
  Receivers receivers;
  GatherOperator gather;
};

Rig make_rig(Scene scene, double max_edge, int rays) {
  PreparationSettings settings;
  settings.max_edge = max_edge;
  PreparedMesh mesh = prepare_mesh(scene.geometry, settings);
  TracedScene traced = build_traced_scene(mesh, scene.materials);
  Receivers receivers = make_receivers(scene, mesh);
  GatherOperator gather = build_gather_operator(receivers, mesh, traced, rays, rays, 2024, false);
  return {std::move(scene), std::move(mesh), std::move(traced), std::move(receivers),
          std::move(gather)};
}

// A closed inward sphere (2562 vertices) of one albedo with sensors inside facing about.
Rig closed_sphere(Rgb albedo) {
  Scene scene;
  scene.materials = {{"wall", albedo}};
  scene.geometry = make_sphere({0, 0, 0}, 2, Facing::kInward, 4, 0);
  const Vec3 sensors[][2] = {{{0, 0, 0}, {0, 1, 0}},
                             {{1.5, 0.2, -0.3}, {1, 0, 0}},
                             {{-0.4, -1.8, 0.1}, {0, -1, 0}},
                             {{0.3, 0.9, 1.2}, {-1, 2, 0.5}}};
  for (const auto& s : sensors) {
    scene.sensors.push_back({"s" + std::to_string(scene.sensors.size()), {s[0]}, normalize(s[1])});
  }
  return make_rig(std::move(scene), 0, 64);
}

// The first n with ρ^n (1 − ρ) / (1 − ρ^{n+1}) < tol: the relative change of the n-th
// bounce when every row of G sums to one and E_d is uniform.
int predicted_bounces(double rho, double tolerance) {
  int n = 1;
  while (std::pow(rho, n) * (1 - rho) / (1 - std::pow(rho, n + 1)) >= tolerance) ++n;
  return n;
}

double worst_relative_error(const Eigen::MatrixXf& indirect, const Eigen::MatrixXf& direct,
                            double rho) {
  double worst = 0;
  for (Eigen::Index k = 0; k < direct.cols(); ++k) {
    for (Eigen::Index r = 0; r < direct.rows(); ++r) {
      const double expected = direct(r, k) / (1 - rho);
      const double total = double{direct(r, k)} + indirect(r, k);
      worst = std::max(worst, std::abs(total - expected) / expected);
    }
  }
  return worst;
}

Eigen::MatrixXf uniform_columns(std::size_t receivers) {
  Eigen::MatrixXf direct(static_cast<Eigen::Index>(receivers), 2);
  direct.col(0).setConstant(1);
  direct.col(1).setConstant(2);
  return direct;
}

class BounceSolverClosedSphere : public ::testing::TestWithParam<double> {};

TEST_P(BounceSolverClosedSphere, TotalIsDirectOverOneMinusRhoAtEveryVertexAndSensor) {
  const double rho = GetParam();
  const Rig rig = closed_sphere({rho, rho, rho});
  const Eigen::MatrixXf direct = uniform_columns(rig.receivers.size());
  const BounceSettings settings;
  const BounceResult result = solve_bounces(rig.gather, rig.receivers, direct, settings, false);
  for (int c = 0; c < 3; ++c) {
    ASSERT_EQ(result.indirect[c].rows(), direct.rows());
    ASSERT_EQ(result.indirect[c].cols(), direct.cols());
    EXPECT_LT(worst_relative_error(result.indirect[c], direct, rho), 0.01) << "channel " << c;
  }
  // Only the sensor rows: they gather but do not reflect.
  const auto vertices = static_cast<Eigen::Index>(rig.receivers.vertex_count);
  const Eigen::Index sensors = direct.rows() - vertices;
  EXPECT_LT(
      worst_relative_error(result.indirect[1].bottomRows(sensors), direct.bottomRows(sensors), rho),
      0.01);
  const int expected = predicted_bounces(rho, settings.tolerance);
  EXPECT_NEAR(result.bounces, expected, 1);
  const double per_bounce = result.seconds / result.bounces;  // one channel solved, two copied
  ::testing::Test::RecordProperty("vertices", static_cast<int>(vertices));
  ::testing::Test::RecordProperty("nonzeros", static_cast<int>(rig.gather.matrix.nonZeros()));
  ::testing::Test::RecordProperty("bounces", result.bounces);
  ::testing::Test::RecordProperty("predicted_bounces", expected);
  ::testing::Test::RecordProperty("seconds", std::to_string(result.seconds));
  ::testing::Test::RecordProperty("seconds_per_bounce", std::to_string(per_bounce));
  ::testing::Test::RecordProperty("worst_relative_error", std::to_string(worst_relative_error(
                                                              result.indirect[0], direct, rho)));
}

INSTANTIATE_TEST_SUITE_P(Albedo, BounceSolverClosedSphere, ::testing::Values(0.5, 0.8));

// The run-time RGB solve (solve_bounces_rgb): channel c of one source bounces with albedo
// channel c, to E_d / (1 − ρ_c) in the closed sphere at vertices and sensors; started warm from
// the solution for a direct light 1 % weaker it reaches the same total, to its own looser
// tolerance, in fewer bounces.
TEST(BounceSolver, RgbSolveMatchesTheClosedFormAndAWarmStartConvergesFaster) {
  const Rgb albedo{0.8, 0.5, 0.2};
  const Rig rig = closed_sphere(albedo);
  const std::size_t n = rig.receivers.size();
  std::vector<float> direct(3 * n), indirect(3 * n);
  for (std::size_t r = 0; r < n; ++r) {
    direct[3 * r] = 1;
    direct[3 * r + 1] = 2;
    direct[3 * r + 2] = 3;
  }
  const BounceSettings settings;
  const int cold = solve_bounces_rgb(rig.gather, rig.receivers, direct, indirect, false, settings);
  const double rho[3] = {albedo.r, albedo.g, albedo.b};
  double worst = 0;
  for (std::size_t r = 0; r < n; ++r) {
    for (std::size_t c = 0; c < 3; ++c) {
      const double expected = direct[3 * r + c] / (1 - rho[c]);
      worst =
          std::max(worst, std::abs(direct[3 * r + c] + indirect[3 * r + c] - expected) / expected);
    }
  }
  EXPECT_LT(worst, 0.01);
  EXPECT_NEAR(cold, predicted_bounces(0.8, settings.tolerance), 1);
  // Warm: the solution of 0.99 × the light as the start.
  std::vector<float> weaker(direct), warm_indirect(3 * n);
  for (float& e : weaker) e *= 0.99f;
  solve_bounces_rgb(rig.gather, rig.receivers, weaker, warm_indirect, false, settings);
  const int warm =
      solve_bounces_rgb(rig.gather, rig.receivers, direct, warm_indirect, true, settings);
  double apart = 0;
  for (std::size_t i = 0; i < 3 * n; ++i) {
    apart = std::max(apart,
                     std::abs(double{warm_indirect[i]} - indirect[i]) / (direct[i] + indirect[i]));
  }
  std::printf("RGB solve: %d bounces cold, %d warm; worst error %.2e, warm vs cold %.2e\n", cold,
              warm, worst, apart);
  EXPECT_LT(warm, cold / 2);
  // The warm start stops at kWarmBounceTolerance: within kWarmBounceTolerance / (1 − ρ_max).
  EXPECT_LT(apart, kWarmBounceTolerance / (1 - 0.8));
}

TEST(BounceSolver, ColourChannelsBounceWithTheirOwnAlbedo) {
  const Rgb albedo{0.8, 0.5, 0.2};
  const Rig rig = closed_sphere(albedo);
  const Eigen::MatrixXf direct = uniform_columns(rig.receivers.size());
  const BounceResult result = solve_bounces(rig.gather, rig.receivers, direct, {}, false);
  const double rho[3] = {albedo.r, albedo.g, albedo.b};
  for (int c = 0; c < 3; ++c) {
    EXPECT_LT(worst_relative_error(result.indirect[c], direct, rho[c]), 0.01) << "channel " << c;
  }
  // The slowest channel sets the count.
  EXPECT_NEAR(result.bounces, predicted_bounces(0.8, 1e-4), 1);
  // Equal channels are solved once and are identical.
  const Rig grey = closed_sphere({0.5, 0.5, 0.5});
  const BounceResult same = solve_bounces(grey.gather, grey.receivers, direct, {}, false);
  EXPECT_EQ((same.indirect[0] - same.indirect[2]).cwiseAbs().maxCoeff(), 0.0f);
  EXPECT_NEAR((result.indirect[1] - same.indirect[1]).cwiseAbs().maxCoeff(), 0.0f, 1e-4);
}

// A 4 × 3 × 5 m room, walls of different albedo, lit by columns of assorted shapes
// (including negative values, as SH basis columns are).
struct Room {
  Rig rig;
  Eigen::MatrixXf direct;
};

Room lit_room(double rho_walls, double rho_floor, int columns) {
  Scene scene;
  scene.materials = {{"walls", {rho_walls, rho_walls, rho_walls}},
                     {"floor", {rho_floor, 0.9 * rho_floor, 0.5 * rho_floor}}};
  scene.geometry = make_box({0, 0, 0}, {4, 3, 5}, Facing::kInward, 0);
  for (std::size_t t = 0; t < scene.geometry.triangles.size(); ++t) {
    bool floor = true;
    for (std::uint32_t v : scene.geometry.triangles[t]) {
      floor = floor && scene.geometry.positions[v].y == 0;
    }
    if (floor) scene.geometry.triangle_material[t] = 1;
  }
  scene.sensors.push_back({"desk", {{1, 0.8, 1}, {2, 0.8, 2.5}, {3, 0.8, 4}}, {0, 1, 0}});
  Rig rig = make_rig(std::move(scene), 0.5, 128);
  Eigen::MatrixXf direct(static_cast<Eigen::Index>(rig.receivers.size()), columns);
  for (Eigen::Index r = 0; r < direct.rows(); ++r) {
    const Vec3 p = rig.receivers.positions[r];
    for (Eigen::Index k = 0; k < columns; ++k) {
      direct(r, k) = static_cast<float>(std::cos(0.7 * k * p.x + 0.3 * p.y) + 0.2 * k * p.z);
    }
    const bool lit = p.x == 0 && rig.receivers.normals[r].x > 0.5;  // the x = 0 wall
    direct(r, 0) = lit ? 100.0f : 0.0f;
  }
  return {std::move(rig), std::move(direct)};
}

double relative_difference(const Eigen::MatrixXf& a, const Eigen::MatrixXf& b) {
  return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
}

TEST(BounceSolver, ColumnsSolvedTogetherEqualColumnsSolvedApart) {
  const Room room = lit_room(0.7, 0.4, 4);
  BounceSettings fixed;  // a fixed bounce count: convergence is per column otherwise
  fixed.tolerance = 0;
  fixed.max_bounces = 15;
  const BounceResult together =
      solve_bounces(room.rig.gather, room.rig.receivers, room.direct, fixed, false);
  EXPECT_EQ(together.bounces, 15);
  for (Eigen::Index k = 0; k < room.direct.cols(); ++k) {
    const Eigen::MatrixXf column = room.direct.col(k);
    const BounceResult apart =
        solve_bounces(room.rig.gather, room.rig.receivers, column, fixed, false);
    for (int c = 0; c < 3; ++c) {
      EXPECT_LT(relative_difference(together.indirect[c].col(k), apart.indirect[c]), 1e-5)
          << "column " << k << " channel " << c;
    }
  }
  // Superposition: solve(a·A + b·B) = a·solve(A) + b·solve(B).
  const Eigen::MatrixXf mixed = 0.25 * room.direct.col(0) - 3.0 * room.direct.col(2);
  const BounceResult combined =
      solve_bounces(room.rig.gather, room.rig.receivers, mixed, fixed, false);
  for (int c = 0; c < 3; ++c) {
    const Eigen::MatrixXf expected =
        0.25 * together.indirect[c].col(0) - 3.0 * together.indirect[c].col(2);
    EXPECT_LT(relative_difference(combined.indirect[c], expected), 1e-5) << "channel " << c;
  }
}

TEST(BounceSolver, ClosedWhiteRoomLitOnOneWallConservesFlux) {
  // Every reflected lumen lands somewhere in a closed room: total flux on the surfaces is
  // Φ_direct / (1 − ρ) whatever the distribution. Vertex areas are a third of the areas
  // of their triangles (the lumped hat functions of per-vertex transfer).
  const double rho = 0.6;
  const Room room = lit_room(rho, rho, 1);
  const Rig& rig = room.rig;
  std::vector<double> area(rig.receivers.vertex_count, 0.0);
  for (const Triangle& t : rig.mesh.triangles) {
    const Vec3 a = rig.mesh.positions[t[0]], b = rig.mesh.positions[t[1]],
               c = rig.mesh.positions[t[2]];
    const double third = length(cross(b - a, c - a)) / 6;
    for (std::uint32_t v : t) area[v] += third;
  }
  const BounceResult result = solve_bounces(rig.gather, rig.receivers, room.direct, {}, false);
  double direct_flux = 0, total_flux = 0;
  for (std::size_t v = 0; v < area.size(); ++v) {
    const auto r = static_cast<Eigen::Index>(v);
    direct_flux += area[v] * room.direct(r, 0);
    total_flux += area[v] * (room.direct(r, 0) + result.indirect[0](r, 0));  // red: ρ everywhere
  }
  const double expected = direct_flux / (1 - rho);
  EXPECT_NEAR(total_flux, expected, 0.01 * expected);  // measured: 0.04 %
  // The lit wall is 3 × 5 m at 100 lx.
  EXPECT_NEAR(direct_flux, 1500, 1e-6);
  ::testing::Test::RecordProperty("flux_ratio", std::to_string(total_flux / expected));
  ::testing::Test::RecordProperty("bounces", result.bounces);
}

TEST(BounceSolver, NoAlbedoOrNoBouncesMeansNoInterreflection) {
  const Rig rig = closed_sphere({0, 0, 0});
  const Eigen::MatrixXf direct = uniform_columns(rig.receivers.size());
  const BounceResult black = solve_bounces(rig.gather, rig.receivers, direct, {}, false);
  BounceSettings none;
  none.max_bounces = 0;
  const Rig grey = closed_sphere({0.5, 0.5, 0.5});
  const BounceResult unbounced = solve_bounces(grey.gather, grey.receivers, direct, none, false);
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(black.indirect[c].cwiseAbs().maxCoeff(), 0.0f);
    EXPECT_EQ(unbounced.indirect[c].cwiseAbs().maxCoeff(), 0.0f);
    EXPECT_EQ(unbounced.indirect[c].rows(), direct.rows());
  }
  EXPECT_EQ(unbounced.bounces, 0);
  // One bounce: each vertex gathers ρ · E_d from a closed sphere.
  BounceSettings one;
  one.max_bounces = 1;
  const BounceResult first = solve_bounces(grey.gather, grey.receivers, direct, one, false);
  EXPECT_EQ(first.bounces, 1);
  EXPECT_NEAR(first.indirect[0].col(1).minCoeff(), 1.0, 1e-5);
  EXPECT_NEAR(first.indirect[0].col(1).maxCoeff(), 1.0, 1e-5);
}

TEST(BounceSolver, RejectsMismatchedSizes) {
  const Rig rig = closed_sphere({0.5, 0.5, 0.5});
  const Eigen::MatrixXf vertices_only =
      Eigen::MatrixXf::Ones(static_cast<Eigen::Index>(rig.receivers.vertex_count), 1);
  EXPECT_THROW(solve_bounces(rig.gather, rig.receivers, vertices_only, {}, false),
               std::invalid_argument);
  Receivers other = rig.receivers;
  other.positions.pop_back();
  other.normals.pop_back();
  other.albedo.pop_back();
  other.sensor_count -= 1;
  const Eigen::MatrixXf direct = uniform_columns(other.size());
  EXPECT_THROW(solve_bounces(rig.gather, other, direct, {}, false), std::invalid_argument);
}

}  // namespace
}  // namespace relight
