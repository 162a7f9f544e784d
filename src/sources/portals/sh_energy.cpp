#include "sources/portals/sh_energy.h"

#include <algorithm>
#include <span>
#include <stdexcept>
#include <vector>

#include <Eigen/Dense>

#include "engine/transfer_blocks.h"

namespace relight {

namespace {

constexpr std::size_t kChannels = 3;

using BlockColumns =
    Eigen::Map<const Eigen::MatrixXf, Eigen::Unaligned, Eigen::OuterStride<Eigen::Dynamic>>;

// (1/N_v) T_lᵀ T_l of one order and channel, accumulated block by block: in a block the
// 2l+1 bases of order l are columns of 64 vertices, kChannels · 64 floats apart.
Eigen::MatrixXd order_gram(const BlockedTransfer& blocks, std::size_t vertex_count,
                           std::size_t k_count, int l, std::size_t channel) {
  const std::size_t first = static_cast<std::size_t>(l) * static_cast<std::size_t>(l);
  const Eigen::Index width = 2 * l + 1;
  Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(width, width);
  // The order's span of a block (its bases' channels interleaved), as floats.
  const std::size_t span = (static_cast<std::size_t>(width) - 1) * kChannels * kBlock + kBlock;
  std::vector<float> floats(span);
  for (std::size_t b = 0; b < block_count(vertex_count); ++b) {
    const std::size_t rows = std::min(kBlock, vertex_count - b * kBlock);
    blocks.copy_to(((b * k_count + first) * kChannels + channel) * kBlock, floats);
    const BlockColumns t(floats.data(), static_cast<Eigen::Index>(rows), width,
                         Eigen::OuterStride<Eigen::Dynamic>(kChannels * kBlock));
    gram.noalias() += (t.transpose() * t).cast<double>();
  }
  return gram / static_cast<double>(vertex_count);
}

}  // namespace

std::vector<ShOrderEnergy> portal_sh_energy(const PortalTransferView& portal,
                                            std::size_t vertex_count, std::size_t receivers,
                                            int sh_order) {
  if (sh_order < 1 || vertex_count > receivers) {
    throw std::invalid_argument("portal_sh_energy: bad order or vertex count");
  }
  const std::size_t k_count =
      static_cast<std::size_t>(sh_order) * static_cast<std::size_t>(sh_order);
  if (portal.indirect.size() != blocked_floats(receivers, k_count, kChannels)) {
    throw std::invalid_argument("portal_sh_energy: transfer of portal \"" + portal.name +
                                "\" has the wrong size");
  }
  std::vector<ShOrderEnergy> orders(static_cast<std::size_t>(sh_order));
  for (int l = 0; l < sh_order; ++l) {
    ShOrderEnergy& o = orders[static_cast<std::size_t>(l)];
    o.l = l;
    if (vertex_count == 0) continue;
    for (std::size_t c = 0; c < kChannels; ++c) {
      const Eigen::MatrixXd gram = order_gram(portal.indirect, vertex_count, k_count, l, c);
      const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(gram, Eigen::EigenvaluesOnly);
      // Eigenvalues ascend; the Gram matrix is positive semi-definite, so a negative largest
      // one is rounding.
      o.energy[c] = std::max(0.0, solver.eigenvalues()(gram.rows() - 1));
    }
  }
  for (std::size_t c = 0; c < kChannels; ++c) {
    double total = 0;
    for (const ShOrderEnergy& o : orders) total += o.energy[c];
    if (total <= 0) continue;
    double running = 0;  // summed in the same order as total: the last cumulative is 1
    for (ShOrderEnergy& o : orders) {
      running += o.energy[c];
      o.share[c] = o.energy[c] / total;
      o.cumulative[c] = running / total;
    }
  }
  return orders;
}

std::vector<std::array<double, 3>> shell_order_energy(const std::vector<Rgb>& sh, int sh_order) {
  if (sh_order < 1 || sh.size() != static_cast<std::size_t>(sh_order * sh_order)) {
    throw std::invalid_argument("shell_order_energy: sh_order² coefficients needed");
  }
  std::vector<std::array<double, 3>> energy(static_cast<std::size_t>(sh_order));
  for (int l = 0; l < sh_order; ++l) {
    for (int k = l * l; k < (l + 1) * (l + 1); ++k) {  // the 2l + 1 coefficients of order l
      const Rgb c = sh[static_cast<std::size_t>(k)];
      auto& e = energy[static_cast<std::size_t>(l)];
      e[0] += c.r * c.r;
      e[1] += c.g * c.g;
      e[2] += c.b * c.b;
    }
  }
  return energy;
}

}  // namespace relight
