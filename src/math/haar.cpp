// 2D non-standard orthonormal Haar transform; see haar.h (paper 000 §4.1.2, NRH03).
#include "math/haar.h"

#include <stdexcept>
#include <string>

namespace relight {
namespace {

constexpr double kInvSqrt2 = 0.70710678118654752440;

void check_sizes(std::size_t data, int n, std::size_t scratch, bool whole_faces) {
  if (!is_power_of_two(n))
    throw std::invalid_argument("haar2d: face size " + std::to_string(n) +
                                " is not a power of two");
  const std::size_t nn = static_cast<std::size_t>(n) * n;
  if (whole_faces ? data % nn != 0 : data != nn)
    throw std::invalid_argument("haar2d: " + std::to_string(data) + " values for " +
                                std::to_string(n) + "x" + std::to_string(n) + " faces");
  if (scratch < static_cast<std::size_t>(n))
    throw std::invalid_argument("haar2d: scratch holds fewer than N values");
}

// One 1D step on h values x[0], x[stride], …: averages to the first h/2, details after.
template <class T>
void step_forward(T* x, std::ptrdiff_t stride, int h, T* tmp) {
  const int half = h / 2;
  for (int k = 0; k < half; ++k) {
    const T a = x[std::ptrdiff_t{2} * k * stride], b = x[(std::ptrdiff_t{2} * k + 1) * stride];
    tmp[k] = (a + b) * kInvSqrt2;
    tmp[half + k] = (a - b) * kInvSqrt2;
  }
  for (int k = 0; k < h; ++k) x[std::ptrdiff_t{k} * stride] = tmp[k];
}

template <class T>
void step_inverse(T* x, std::ptrdiff_t stride, int h, T* tmp) {
  const int half = h / 2;
  for (int k = 0; k < half; ++k) {
    const T a = x[std::ptrdiff_t{k} * stride], d = x[(std::ptrdiff_t{half} + k) * stride];
    tmp[std::ptrdiff_t{2} * k] = (a + d) * kInvSqrt2;
    tmp[std::ptrdiff_t{2} * k + 1] = (a - d) * kInvSqrt2;
  }
  for (int k = 0; k < h; ++k) x[std::ptrdiff_t{k} * stride] = tmp[k];
}

template <class T>
void forward_face(T* face, int n, T* tmp) {
  for (int h = n; h > 1; h /= 2) {
    for (int r = 0; r < h; ++r) step_forward(face + static_cast<std::ptrdiff_t>(r) * n, 1, h, tmp);
    for (int c = 0; c < h; ++c) step_forward(face + c, n, h, tmp);
  }
}

template <class T>
void inverse_face(T* face, int n, T* tmp) {
  for (int h = 2; h <= n; h *= 2) {
    for (int c = 0; c < h; ++c) step_inverse(face + c, n, h, tmp);
    for (int r = 0; r < h; ++r) step_inverse(face + static_cast<std::ptrdiff_t>(r) * n, 1, h, tmp);
  }
}

template <class T>
void faces(std::span<T> data, int n, std::span<T> scratch, bool inverse) {
  check_sizes(data.size(), n, scratch.size(), true);
  const std::size_t nn = static_cast<std::size_t>(n) * n;
  for (std::size_t start = 0; start < data.size(); start += nn) {
    if (inverse)
      inverse_face(data.data() + start, n, scratch.data());
    else
      forward_face(data.data() + start, n, scratch.data());
  }
}

}  // namespace

void haar2d_forward(std::span<double> face, int n, std::span<double> scratch) {
  check_sizes(face.size(), n, scratch.size(), false);
  forward_face(face.data(), n, scratch.data());
}
void haar2d_inverse(std::span<double> face, int n, std::span<double> scratch) {
  check_sizes(face.size(), n, scratch.size(), false);
  inverse_face(face.data(), n, scratch.data());
}
void haar2d_forward(std::span<Rgb> face, int n, std::span<Rgb> scratch) {
  check_sizes(face.size(), n, scratch.size(), false);
  forward_face(face.data(), n, scratch.data());
}
void haar2d_inverse(std::span<Rgb> face, int n, std::span<Rgb> scratch) {
  check_sizes(face.size(), n, scratch.size(), false);
  inverse_face(face.data(), n, scratch.data());
}

void haar2d_forward_faces(std::span<double> data, int n, std::span<double> scratch) {
  faces(data, n, scratch, false);
}
void haar2d_inverse_faces(std::span<double> data, int n, std::span<double> scratch) {
  faces(data, n, scratch, true);
}
void haar2d_forward_faces(std::span<Rgb> data, int n, std::span<Rgb> scratch) {
  faces(data, n, scratch, false);
}
void haar2d_inverse_faces(std::span<Rgb> data, int n, std::span<Rgb> scratch) {
  faces(data, n, scratch, true);
}

}  // namespace relight
