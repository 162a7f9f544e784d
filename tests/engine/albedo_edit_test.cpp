// AlbedoEdit (engine/albedo_edit.h): the light an albedo change adds, from the light bounced
// with the old albedo and the gather operator alone, equals the difference of two full solves
// (old and new albedo, from the same direct light) — to 1e-4 of the light with the solver
// converged to 1e-7 — on a random operator whose rows reflect 0.2–0.9 of what they gather;
// and with no bounce it is s = G (ρ' − ρ) E exactly.
#include <random>

#include <gtest/gtest.h>

#include "engine/albedo_edit.h"

namespace relight {
namespace {

struct Room {
  GatherOperator gather;
  Receivers receivers;
  std::vector<float> direct;  // 3 per receiver
};

// `vertices` reflecting rows and `sensors` more; each row gathers from 6 random vertices.
Room random_room(std::size_t vertices, std::size_t sensors, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0, 1);
  std::uniform_int_distribution<std::size_t> pick(0, vertices - 1);
  const std::size_t rows = vertices + sensors;
  std::vector<Eigen::Triplet<float>> entries;
  for (std::size_t r = 0; r < rows; ++r) {
    const double total = 0.2 + 0.7 * unit(rng);
    for (int k = 0; k < 6; ++k) {
      entries.emplace_back(static_cast<int>(r), static_cast<int>(pick(rng)),
                           static_cast<float>(total / 6));
    }
  }
  Room room;
  room.gather.matrix.resize(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(vertices));
  room.gather.matrix.setFromTriplets(entries.begin(), entries.end());
  room.gather.matrix.makeCompressed();
  room.receivers.vertex_count = vertices;
  room.receivers.sensor_count = sensors;
  room.receivers.positions.assign(rows, Vec3{});
  room.receivers.normals.assign(rows, Vec3{0, 0, 1});
  room.receivers.albedo.assign(rows, Rgb{});
  for (std::size_t v = 0; v < vertices; ++v) {
    room.receivers.albedo[v] = {0.2 + 0.6 * unit(rng), 0.2 + 0.6 * unit(rng),
                                0.2 + 0.6 * unit(rng)};
  }
  for (std::size_t i = 0; i < 3 * rows; ++i)
    room.direct.push_back(static_cast<float>(100 * unit(rng)));
  return room;
}

std::vector<float> albedo_of(const Receivers& r) {
  std::vector<float> a;
  for (std::size_t v = 0; v < r.vertex_count; ++v) {
    a.insert(a.end(), {static_cast<float>(r.albedo[v].r), static_cast<float>(r.albedo[v].g),
                       static_cast<float>(r.albedo[v].b)});
  }
  return a;
}

// Direct + interreflected light (3 per receiver) of a full solve.
std::vector<float> total_light(const Room& room, const Receivers& receivers,
                               const BounceSettings& settings) {
  std::vector<float> indirect(room.direct.size());
  solve_bounces_rgb(room.gather, receivers, room.direct, indirect, false, settings);
  std::vector<float> total(room.direct.size());
  for (std::size_t i = 0; i < total.size(); ++i) total[i] = room.direct[i] + indirect[i];
  // Sensors reflect nothing, and their direct light is theirs alone.
  return total;
}

TEST(AlbedoEdit, EditedLightMatchesAFullSolveOfTheEditedRoomTo1e4) {
  const Room room = random_room(400, 50, 7);
  BounceSettings settings;
  settings.tolerance = 1e-7;
  settings.max_bounces = 400;
  const std::vector<float> before = total_light(room, room.receivers, settings);

  Receivers edited = room.receivers;
  for (std::size_t v = 0; v < 150; ++v) edited.albedo[v] = {0.9, 0.1, 0.5};  // a repainted wall
  const std::vector<float> after = total_light(room, edited, settings);

  AlbedoEdit edit(room.gather, albedo_of(room.receivers), settings);
  EXPECT_TRUE(edit.set_albedo(albedo_of(edited)));
  EXPECT_FALSE(edit.set_albedo(albedo_of(edited)));
  EXPECT_TRUE(edit.active());
  std::vector<float> delta(before.size());
  const int bounces = edit.solve(before, delta, -1, false);
  EXPECT_GT(bounces, 3);
  double worst = 0, peak = 0, change = 0;
  for (std::size_t i = 0; i < after.size(); ++i) {
    worst = std::max(worst, double(std::abs(before[i] + delta[i] - after[i])));
    peak = std::max(peak, double(std::abs(after[i])));
    change = std::max(change, double(std::abs(after[i] - before[i])));
  }
  EXPECT_LT(worst, 1e-4 * peak);
  EXPECT_GT(change, 0.05 * peak);  // the edit is not negligible

  // No bounce: s = G (ρ' − ρ) E, row by row.
  edit.solve(before, delta, 0, false);
  const std::vector<float> original = albedo_of(room.receivers), now = albedo_of(edited);
  for (Eigen::Index r = 0; r < room.gather.matrix.rows(); r += 37) {
    double s[3] = {0, 0, 0};
    for (Eigen::SparseMatrix<float, Eigen::RowMajor>::InnerIterator it(room.gather.matrix, r); it;
         ++it) {
      for (int c = 0; c < 3; ++c) {
        const std::size_t k = 3 * static_cast<std::size_t>(it.index()) + c;
        s[c] += it.value() * (now[k] - original[k]) * before[k];
      }
    }
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(delta[3 * static_cast<std::size_t>(r) + c], s[c], 1e-4 * peak) << r;
    }
  }

  // Back to the original albedo: no light added.
  EXPECT_TRUE(edit.set_albedo(original));
  EXPECT_FALSE(edit.active());
  edit.solve(before, delta, -1, true);
  for (const float d : delta) EXPECT_EQ(d, 0.0f);
}

}  // namespace
}  // namespace relight
