// Colour helpers: sRGB ↔ linear Rec.709 (IEC 61966-2-1), hex strings for <input type=color>,
// the luminance Y of linear Rec.709 (ARCHITECTURE §4.4), and the colour of a black body
// from its correlated colour temperature (Kang et al. 2002 cubic fits, the same formulas as
// src/light/color_temperature.cpp), for swatches of `cct_kelvin`.

export const luminance = (c) => 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];

export function srgbToLinear(v) {
  return v <= 0.04045 ? v / 12.92 : ((v + 0.055) / 1.055) ** 2.4;
}

export function linearToSrgb(v) {
  if (!(v > 0)) return 0;
  return v <= 0.0031308 ? 12.92 * v : 1.055 * v ** (1 / 2.4) - 0.055;
}

// '#rrggbb' → linear RGB in 0..1.
export function hexToLinear(hex) {
  const n = parseInt(hex.replace('#', ''), 16);
  return [(n >> 16) & 255, (n >> 8) & 255, n & 255].map((b) => srgbToLinear(b / 255));
}

// Linear RGB (any scale) → '#rrggbb'; with normalize the brightest channel becomes 1, so a
// chromaticity (the luminaires' `color`) shows as its brightest displayable colour.
export function linearToHex(rgb, normalize = false) {
  let c = rgb.map((x) => Math.max(0, Number(x) || 0));
  if (normalize) {
    const m = Math.max(...c);
    c = m > 0 ? c.map((x) => x / m) : [1, 1, 1];
  }
  return '#' + c.map((x) => Math.round(255 * Math.min(1, linearToSrgb(x))).toString(16).padStart(2, '0')).join('');
}

// Black body of temperature t (1667..25000 K) → linear Rec.709, luminance 1.
export function cctToRgb(t) {
  const t2 = t * t, t3 = t2 * t;
  const x = t <= 4000
    ? -0.2661239e9 / t3 - 0.2343589e6 / t2 + 0.8776956e3 / t + 0.179910
    : -3.0258469e9 / t3 + 2.1070379e6 / t2 + 0.2226347e3 / t + 0.240390;
  const x2 = x * x, x3 = x2 * x;
  let y;
  if (t <= 2222) y = -1.1063814 * x3 - 1.34811020 * x2 + 2.18555832 * x - 0.20219683;
  else if (t <= 4000) y = -0.9549476 * x3 - 1.37418593 * x2 + 2.09137015 * x - 0.16748867;
  else y = 3.0817580 * x3 - 5.87338670 * x2 + 3.75112997 * x - 0.37001483;
  const X = x / y, Y = 1, Z = (1 - x - y) / y;
  const c = [
    3.2404542 * X - 1.5371385 * Y - 0.4985314 * Z,
    -0.9692660 * X + 1.8760108 * Y + 0.0415560 * Z,
    0.0556434 * X - 0.2040259 * Y + 1.0572252 * Z,
  ].map((v) => Math.max(v, 0));
  const l = luminance(c);
  return c.map((v) => v / l);
}
