#include "engine/albedo_edit.h"

#include <algorithm>
#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace relight {

AlbedoEdit::AlbedoEdit(const GatherOperator& gather, std::span<const float> original,
                       BounceSettings settings)
    : gather_(gather),
      original_(original.begin(), original.end()),
      edited_(original_),
      change_(original_.size(), 0.0f),
      settings_(settings) {
  const auto rows = static_cast<std::size_t>(gather.matrix.rows());
  const auto vertices = static_cast<std::size_t>(gather.matrix.cols());
  if (original_.size() != 3 * vertices || rows < vertices) {
    throw std::invalid_argument("AlbedoEdit: the albedo is not one per vertex of the operator");
  }
  reflected_.assign(3 * vertices, 0.0f);
  once_.assign(3 * rows, 0.0f);
  bounced_.assign(3 * rows, 0.0f);
}

bool AlbedoEdit::set_albedo(std::span<const float> edited) {
  if (edited.size() != original_.size()) {
    throw std::invalid_argument("AlbedoEdit: the edited albedo is not one per vertex");
  }
  if (std::equal(edited.begin(), edited.end(), edited_.begin())) return false;
  edited_.assign(edited.begin(), edited.end());
  active_ = false;
  for (std::size_t i = 0; i < edited_.size(); ++i) {
    change_[i] = edited_[i] - original_[i];
    active_ = active_ || change_[i] != 0;
  }
  return true;
}

int AlbedoEdit::solve(std::span<const float> total, std::span<float> delta, int max_bounces,
                      bool warm) {
  const std::size_t rows = once_.size() / 3, vertices = original_.size() / 3;
  if (total.size() != 3 * rows || delta.size() != 3 * rows) {
    throw std::invalid_argument("AlbedoEdit: the light is not one per receiver");
  }
  if (!active_ || settings_.max_bounces == 0) {
    std::fill(delta.begin(), delta.end(), 0.0f);
    return 0;
  }
  // s = G (Δρ ⊙ E) at every receiver.
  for (std::size_t i = 0; i < 3 * vertices; ++i) reflected_[i] = change_[i] * total[i];
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rows, 256), [&](const auto& range) {
    for (std::size_t r = range.begin(); r != range.end(); ++r) {
      float sum[3];
      gather_rgb_row(gather_.matrix, static_cast<Eigen::Index>(r), reflected_, sum);
      std::copy_n(sum, 3, once_.begin() + static_cast<std::ptrdiff_t>(3 * r));
    }
  });
  // X = G ρ' (s + X): the bounce solver with s as its direct light and the edited albedo.
  int bounces = 0;
  if (max_bounces != 0) {
    BounceSettings settings = settings_;
    if (max_bounces > 0) settings.max_bounces = std::min(settings.max_bounces, max_bounces);
    const RgbGather op = stored_rgb_gather(gather_, edited_);
    bounces = solve_bounces_rgb(op, once_, bounced_, warm, settings);
  } else {
    std::fill(bounced_.begin(), bounced_.end(), 0.0f);
  }
  for (std::size_t i = 0; i < 3 * rows; ++i) delta[i] = once_[i] + bounced_[i];
  return bounces;
}

}  // namespace relight
