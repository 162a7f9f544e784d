#include "engine/glossy_first_bounce.h"

#include <algorithm>
#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "math/rgb.h"

namespace relight {

GlossyFirstBounce::GlossyFirstBounce(const GatherOperator& gather, std::span<const Vec3> positions,
                                     std::span<const Vec3> normals,
                                     std::vector<std::int32_t> glossy_of,
                                     std::vector<MetallicRoughness> glossy,
                                     std::span<const float> albedo, BounceSettings settings)
    : gather_(gather),
      positions_(positions.begin(), positions.end()),
      normals_(normals.begin(), normals.end()),
      glossy_of_(std::move(glossy_of)),
      glossy_(std::move(glossy)),
      albedo_(albedo.begin(), albedo.end()),
      settings_(settings) {
  const auto rows = static_cast<std::size_t>(gather.matrix.rows());
  const auto vertices = static_cast<std::size_t>(gather.matrix.cols());
  if (positions_.size() != rows || normals_.size() != rows || glossy_of_.size() != vertices ||
      albedo_.size() != 3 * vertices) {
    throw std::invalid_argument("GlossyFirstBounce: operator, receivers and albedo disagree");
  }
  for (const std::int32_t g : glossy_of_) {
    if (g >= static_cast<std::int32_t>(glossy_.size())) {
      throw std::invalid_argument("GlossyFirstBounce: a vertex refers to a missing material");
    }
  }
  row_first_.reserve(rows + 1);
  for (std::size_t r = 0; r < rows; ++r) {
    row_first_.push_back(entries_.size());
    for (Eigen::SparseMatrix<float, Eigen::RowMajor>::InnerIterator it(
             gather.matrix, static_cast<Eigen::Index>(r));
         it; ++it) {
      if (glossy_of_[static_cast<std::size_t>(it.index())] < 0) continue;
      entries_.push_back(
          {static_cast<std::uint32_t>(r), static_cast<std::uint32_t>(it.index()), it.value()});
    }
  }
  row_first_.push_back(entries_.size());
}

void GlossyFirstBounce::respond(std::span<const float> dir_x, std::span<const float> dir_y,
                                std::span<const float> dir_z, std::span<const float> direct,
                                std::span<float> response) const {
  const std::size_t rows = positions_.size();
  const std::size_t stride = direct.size() == 3 * rows ? 3 : 1;
  if (dir_x.size() != rows || dir_y.size() != rows || dir_z.size() != rows ||
      (direct.size() != rows && stride == 1) || response.size() != 3 * rows) {
    throw std::invalid_argument("GlossyFirstBounce: one light direction per receiver expected");
  }
  // c_r = Σ_{j glossy} G_rj (π f_j(l_j, ω_jr) − ρh_j) D_j.
  std::vector<float> once(3 * rows, 0.0f);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rows, 64), [&](const auto& range) {
    for (std::size_t r = range.begin(); r != range.end(); ++r) {
      Rgb c;
      for (std::size_t k = row_first_[r]; k < row_first_[r + 1]; ++k) {
        const Entry& entry = entries_[k];
        const std::size_t j = entry.vertex;
        const Rgb light = stride == 1 ? Rgb{direct[j], direct[j], direct[j]}
                                      : Rgb{direct[3 * j], direct[3 * j + 1], direct[3 * j + 2]};
        if (max_component(light) <= 0) continue;
        const Vec3 to_r = positions_[r] - positions_[j];
        const double d = length(to_r);
        if (d <= 0) continue;
        const MetallicRoughness& m = glossy_[static_cast<std::size_t>(glossy_of_[j])];
        const Vec3 l{-dir_x[j], -dir_y[j], -dir_z[j]};
        const Rgb f = metallic_roughness_brdf(m, normals_[j], l, to_r / d);
        const Rgb rho{albedo_[3 * j], albedo_[3 * j + 1], albedo_[3 * j + 2]};
        c += (f * kPi - rho) * light * entry.weight;
      }
      once[3 * r] = static_cast<float>(c.r);
      once[3 * r + 1] = static_cast<float>(c.g);
      once[3 * r + 2] = static_cast<float>(c.b);
    }
  });
  // Γ = c + X, X = G ρ (c + X).
  std::vector<float> bounced(3 * rows, 0.0f);
  const RgbGather op = stored_rgb_gather(gather_, albedo_);
  solve_bounces_rgb(op, once, bounced, false, settings_);
  for (std::size_t i = 0; i < 3 * rows; ++i) response[i] = once[i] + bounced[i];
}

}  // namespace relight
