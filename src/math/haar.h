// 2D Haar wavelets on one N×N cubemap face (N a power of two), for the per-receiver
// compression of the direct (portal) component: Yue et al. 2009
// (Yue et al. 2009 §3.4, §4.1.2) encodes each vertex's cubemap either with pulse
// functions or with "a Haar wavelet decomposition for each cubemap face", after [NRH03] (Ng,
// Ramamoorthi, Hanrahan 2003), whose run time is a sparse dot product in the wavelet domain.
//
// Transform: the non-standard decomposition (Stollnitz, DeRose, Salesin, "Wavelets for
// computer graphics: a primer", 1995, §3.2; also NRH03): for h = N, N/2, …, 2, one 1D step
// on rows 0..h−1 (first h entries of each), then one on columns 0..h−1. A 1D step on h values
// writes the h/2 averages first and the h/2 details after them:
//   a_k = (x_{2k} + x_{2k+1}) / √2,   d_k = (x_{2k} − x_{2k+1}) / √2.
// Normalisation: each step is orthonormal, so the whole transform is an orthogonal matrix on
// R^{N²} (plain dot product of cell values): Parseval Σ x·y = Σ X·Y holds for any two faces,
// and the inverse is the transpose. In cell units, coefficient (r, c) (index r·N + c, the
// Mallat layout) multiplies a basis function that is constant ±1/S on an S×S square of cells
// and 0 elsewhere, S = haar2d_support(N, r, c): the scaling coefficient (0, 0) has S = N and
// equals Σ x / N (N × the face mean); the three details (horizontal, vertical, diagonal) of a
// square of side S take two + and two − quadrants. Every cell lies in the support of exactly
// 1 + 3·log2 N basis functions (the scaling function and three details per level).
#pragma once

#include <cstddef>
#include <span>

#include "math/rgb.h"

namespace relight {

// True for N = 1, 2, 4, …
constexpr bool is_power_of_two(int n) {
  return n > 0 && (n & (n - 1)) == 0;
}

// Side S of the support square of coefficient (r, c) of an N×N face: the basis function is
// ±1/S on S×S cells. N for the scaling coefficient (0, 0) and the coarsest details
// (max(r, c) = 1); 2 for the finest (max(r, c) ≥ N/2).
constexpr int haar2d_support(int n, int r, int c) {
  int m = r > c ? r : c;
  int level = 0;  // floor(log2 m)
  while (m > 1) {
    m >>= 1;
    ++level;
  }
  return n >> level;
}

// In place: face holds N×N values, index r·N + c (r = row, c = column); scratch holds at least
// N values (no allocation). std::invalid_argument unless N is a power of two and the sizes fit.
void haar2d_forward(std::span<double> face, int n, std::span<double> scratch);
void haar2d_inverse(std::span<double> face, int n, std::span<double> scratch);
void haar2d_forward(std::span<Rgb> face, int n, std::span<Rgb> scratch);
void haar2d_inverse(std::span<Rgb> face, int n, std::span<Rgb> scratch);

// Every face of a buffer of consecutive N×N faces (e.g. a cubemap's 6·N² cells in the layout
// of math/cubemap.h, where face f starts at f·N²); data.size() must be a multiple of N².
void haar2d_forward_faces(std::span<double> data, int n, std::span<double> scratch);
void haar2d_inverse_faces(std::span<double> data, int n, std::span<double> scratch);
void haar2d_forward_faces(std::span<Rgb> data, int n, std::span<Rgb> scratch);
void haar2d_inverse_faces(std::span<Rgb> data, int n, std::span<Rgb> scratch);

}  // namespace relight
