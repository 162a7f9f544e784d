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
                                     std::span<const float> albedo, BounceSettings settings,
                                     const MirrorReflection* mirrors)
    : gather_(gather),
      positions_(positions.begin(), positions.end()),
      normals_(normals.begin(), normals.end()),
      glossy_of_(std::move(glossy_of)),
      glossy_(std::move(glossy)),
      albedo_(albedo.begin(), albedo.end()),
      settings_(settings),
      mirrors_(mirrors != nullptr && !mirrors->empty() ? mirrors : nullptr) {
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
                                std::span<float> response, const MirrorLight* mirror,
                                std::span<const float> reflected) const {
  const std::size_t rows = positions_.size();
  const std::size_t stride = direct.size() == 3 * rows ? 3 : 1;
  if (dir_x.size() != rows || dir_y.size() != rows || dir_z.size() != rows ||
      (direct.size() != rows && stride == 1) || response.size() != 3 * rows) {
    throw std::invalid_argument("GlossyFirstBounce: one light direction per receiver expected");
  }
  if (reflected.empty()) reflected = direct;
  if (reflected.size() != direct.size()) {
    throw std::invalid_argument("GlossyFirstBounce: reflected light and direct light disagree");
  }
  const MirrorReflection* mirrors = mirror != nullptr ? mirrors_ : nullptr;
  if (mirror != nullptr && ((mirror->channels != 1 && mirror->channels != 3) ||
                            mirror->paths.size() * mirror->channels != mirror->intensity.size())) {
    throw std::invalid_argument("GlossyFirstBounce: one intensity per mirror path expected");
  }
  // c_r = Σ_{j glossy} G_rj (π f_j(l_j, ω_jr) D_j − ρh_j D'_j).
  std::vector<float> once(3 * rows, 0.0f);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rows, 64), [&](const auto& range) {
    for (std::size_t r = range.begin(); r != range.end(); ++r) {
      Rgb c;
      for (std::size_t k = row_first_[r]; k < row_first_[r + 1]; ++k) {
        const Entry& entry = entries_[k];
        const std::size_t j = entry.vertex;
        const auto at = [&](std::span<const float> e) {
          return stride == 1 ? Rgb{e[j], e[j], e[j]} : Rgb{e[3 * j], e[3 * j + 1], e[3 * j + 2]};
        };
        const Rgb light = at(direct), bounced = at(reflected);
        if (max_component(light) <= 0 && bounced == Rgb{}) continue;
        const Vec3 to_r = positions_[r] - positions_[j];
        const double d = length(to_r);
        if (d <= 0) continue;
        const MetallicRoughness& m = glossy_[static_cast<std::size_t>(glossy_of_[j])];
        const Vec3 l{-dir_x[j], -dir_y[j], -dir_z[j]};
        // A near-mirror's specular lobe comes as the light's image (below).
        const Rgb f = mirrors != nullptr && mirrors->reflects(j)
                          ? metallic_roughness_diffuse(m, normals_[j], l, to_r / d)
                          : metallic_roughness_brdf(m, normals_[j], l, to_r / d);
        const Rgb rho{albedo_[3 * j], albedo_[3 * j + 1], albedo_[3 * j + 2]};
        c += (f * kPi * light - rho * bounced) * entry.weight;
      }
      once[3 * r] = static_cast<float>(c.r);
      once[3 * r + 1] = static_cast<float>(c.g);
      once[3 * r + 2] = static_cast<float>(c.b);
    }
  });
  if (mirrors != nullptr) {
    // c_r += I_k · factor_k · E_s(cos θ_y) over receiver r's paths.
    for (std::size_t k = 0; k < mirror->paths.size(); ++k) {
      const MirrorPath& path = mirror->paths[k];
      const std::int32_t g = glossy_of_.at(path.vertex);
      const float* i = &mirror->intensity[k * mirror->channels];
      const Rgb intensity = mirror->channels == 1 ? Rgb{i[0], i[0], i[0]} : Rgb{i[0], i[1], i[2]};
      if (path.receiver >= rows || g < 0 || max_component(intensity) <= 0) continue;
      const Rgb e = specular_directional_albedo(glossy_[static_cast<std::size_t>(g)], path.cos_in) *
                    intensity * path.factor;
      float* c = &once[3 * std::size_t{path.receiver}];
      c[0] += static_cast<float>(e.r);
      c[1] += static_cast<float>(e.g);
      c[2] += static_cast<float>(e.b);
    }
  }
  // Γ = c + X, X = G ρ (c + X).
  std::vector<float> bounced(3 * rows, 0.0f);
  const RgbGather op = stored_rgb_gather(gather_, albedo_);
  solve_bounces_rgb(op, once, bounced, false, settings_);
  for (std::size_t i = 0; i < 3 * rows; ++i) response[i] = once[i] + bounced[i];
}

}  // namespace relight
