// Linear Rec.709 RGB, the one colour space of relight. Y = 0.2126 r + 0.7152 g + 0.0722 b is the
// photometric quantity: lux for illuminance, cd/m² for luminance.
#pragma once

namespace relight {

struct Rgb {
  double r = 0, g = 0, b = 0;
  bool operator==(const Rgb&) const = default;
};

constexpr Rgb operator+(Rgb a, Rgb c) {
  return {a.r + c.r, a.g + c.g, a.b + c.b};
}
constexpr Rgb operator-(Rgb a, Rgb c) {
  return {a.r - c.r, a.g - c.g, a.b - c.b};
}
constexpr Rgb operator*(Rgb a, Rgb c) {
  return {a.r * c.r, a.g * c.g, a.b * c.b};
}
constexpr Rgb operator*(Rgb a, double s) {
  return {a.r * s, a.g * s, a.b * s};
}
constexpr Rgb operator*(double s, Rgb a) {
  return a * s;
}
constexpr Rgb operator/(Rgb a, double s) {
  return {a.r / s, a.g / s, a.b / s};
}
constexpr Rgb& operator+=(Rgb& a, Rgb c) {
  return a = a + c;
}
constexpr Rgb& operator*=(Rgb& a, double s) {
  return a = a * s;
}

inline constexpr double kLumaR = 0.2126, kLumaG = 0.7152, kLumaB = 0.0722;
constexpr double luminance(Rgb c) {
  return kLumaR * c.r + kLumaG * c.g + kLumaB * c.b;
}
constexpr double max_component(Rgb c) {
  return c.r > c.g ? (c.r > c.b ? c.r : c.b) : (c.g > c.b ? c.g : c.b);
}
// c into out[0 … 2] in single precision (the engine's arrays of 3 floats per receiver).
constexpr void store_rgb(Rgb c, float* out) {
  out[0] = static_cast<float>(c.r);
  out[1] = static_cast<float>(c.g);
  out[2] = static_cast<float>(c.b);
}
// out[0 … 2] as an Rgb.
constexpr Rgb load_rgb(const float* in) {
  return {in[0], in[1], in[2]};
}

}  // namespace relight
