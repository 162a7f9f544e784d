// The shell's radiance cubemap as the record sums read it (cubemap_encoding.h, paper 000 §5): the
// cells, their per-face Haar transform scaled by each coefficient's support, both as float
// texels, and the cells as three padded planes of floats. Built once per state change.
#include <span>
#include <stdexcept>
#include <vector>

#include "math/haar.h"
#include "sources/portals/cubemap_encoding.h"
#include "sources/portals/cubemap_face.h"

namespace relight {

using cubemap_detail::cell_count;
using cubemap_detail::check_face_size;

namespace {

// `radiance` as floats into `out`, reusing its storage.
void to_texels(const std::vector<Rgb>& radiance, std::vector<ShellTexel>& out) {
  out.resize(radiance.size());
  for (std::size_t k = 0; k < radiance.size(); ++k) {
    out[k].rgb[0] = static_cast<float>(radiance[k].r);
    out[k].rgb[1] = static_cast<float>(radiance[k].g);
    out[k].rgb[2] = static_cast<float>(radiance[k].b);
  }
}

}  // namespace

void prepare_shell_cubemap(int n, std::span<const Rgb> radiance, ShellCubemap& shell) {
  check_face_size(n);
  if (radiance.size() != cell_count(n))
    throw std::invalid_argument("shell cubemap: radiance must hold 6·N² cells");
  shell.n = n;
  shell.cells.assign(radiance.begin(), radiance.end());
  shell.haar.assign(radiance.begin(), radiance.end());
  std::vector<Rgb> row(n);
  haar2d_forward_faces(std::span<Rgb>(shell.haar), n, std::span<Rgb>(row));
  const std::size_t nn = std::size_t(n) * n;
  for (std::size_t start = 0; start < shell.haar.size(); start += nn)
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c)
        shell.haar[start + std::size_t(r) * n + c] *= haar2d_support(n, r, c);
  to_texels(shell.cells, shell.cells_float);
  to_texels(shell.haar, shell.haar_float);
  for (std::vector<float>& plane : shell.planes)
    plane.assign(radiance.size() + ShellCubemap::kPlanePadding, 0.0f);
  for (std::size_t k = 0; k < radiance.size(); ++k) {
    shell.planes[0][k] = static_cast<float>(radiance[k].r);
    shell.planes[1][k] = static_cast<float>(radiance[k].g);
    shell.planes[2][k] = static_cast<float>(radiance[k].b);
  }
}

ShellCubemap prepare_shell_cubemap(int n, std::span<const Rgb> radiance) {
  ShellCubemap shell;
  prepare_shell_cubemap(n, radiance, shell);
  return shell;
}

}  // namespace relight
