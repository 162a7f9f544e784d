// False colour and tone mapping constants and the false-colour value scale, ported from the
// CLI so that the studio's pictures read like `relight render` ones:
//  * the 7-colour ramp (src/render/false_color.h: deep blue → white, equally spaced in the
//    scale position t, linear between the 8-bit sRGB values; no surface is grey 128);
//  * the scale rules (src/render/false_color_scale.{h,cpp}): 1st/99th percentiles of the
//    lit values, logarithmic when MAX/MIN > 20, ends rounded to 1-2-5 × 10^k (log) or to the
//    tick step (linear), at most 8 ticks, labels like "%.6g";
//  * exposure (src/render/tone_map.h): L_max = 1.2 · 2^EV100, automatic EV100 puts the
//    log-average luminance at the key 0.18 (Reinhard et al. 2002, Eq. 1–2).
// The per-pixel parts (roll-off, sRGB, ramp lookup) run in the fragment shader
// (display_shader.js); this module does the CPU side: statistics and the legend's ticks.

export const RAMP = [
  [24, 32, 128], // deep blue (MIN)
  [0, 96, 230], // blue
  [0, 200, 230], // cyan
  [40, 190, 60], // green
  [240, 225, 30], // yellow
  [235, 60, 25], // red
  [255, 255, 255], // white (MAX)
];
export const NO_SURFACE = [128, 128, 128];

export const SATURATION_FACTOR = 1.2; // 78 / (q · S), q = 0.65, S = 100
export const AUTO_EXPOSURE_KEY = 0.18;
export const SHOULDER_START = 0.6;

export const exposureScale = (ev100) => 1 / (SATURATION_FACTOR * 2 ** ev100);

// EV100 that maps the log-average luminance to the key (0 when nothing is lit).
export function autoExposureEv100(logAverage) {
  if (!(logAverage > 0)) return 0;
  return Math.log2(logAverage / (SATURATION_FACTOR * AUTO_EXPOSURE_KEY));
}

// Ramp colour (8-bit sRGB) at scale position t; grey for NaN.
export function rampColor(t) {
  if (Number.isNaN(t)) return NO_SURFACE;
  const p = Math.min(Math.max(t, 0), 1) * (RAMP.length - 1);
  const i = Math.min(Math.floor(p), RAMP.length - 2);
  const f = p - i;
  return RAMP[i].map((a, k) => Math.round(a + (RAMP[i + 1][k] - a) * f));
}

export const rampCss = (t) => `rgb(${rampColor(t).join(',')})`;

const LOG_RATIO = 20;
const MAX_TICKS = 8;
const MIN_LOG_TICKS = 4;
const TOL = 1e-9;
const decade = (e) => 10 ** e;

function percentile(sorted, p) {
  return sorted[Math.round(p * (sorted.length - 1))];
}

function intervals(lo, hi, step) {
  return Math.ceil(hi / step - TOL) - Math.floor(lo / step + TOL);
}

function linearStep(lo, hi) {
  const span = hi - lo;
  for (let e = Math.floor(Math.log10(span / (MAX_TICKS - 1))) - 1; e < 400; e++) {
    for (const m of [1, 2, 2.5, 5]) {
      const step = m * decade(e);
      if (intervals(lo, hi, step) <= MAX_TICKS - 1) return step;
    }
  }
  return span;
}

function linearTicks(lo, hi) {
  const step = linearStep(lo, hi);
  const ticks = [];
  const first = Math.ceil(lo / step - TOL), last = Math.floor(hi / step + TOL);
  for (let k = first; k <= last; k++) ticks.push(k === 0 ? 0 : k * step);
  return ticks;
}

const inRange = (v, lo, hi) => v >= lo * (1 - TOL) && v <= hi * (1 + TOL);

function logTicks(lo, hi, mantissas, every) {
  const ticks = [];
  const first = Math.floor(Math.log10(lo)) - 1, last = Math.ceil(Math.log10(hi)) + 1;
  for (let e = first; e <= last; e++) {
    if (e % every !== 0) continue;
    for (const m of mantissas) {
      const v = m * decade(e);
      if (inRange(v, lo, hi)) ticks.push(v);
    }
  }
  return ticks;
}

export function niceFloor125(v) {
  const e = Math.floor(Math.log10(v));
  const m = v / decade(e);
  for (const k of [5, 2, 1]) if (m >= k * (1 - TOL)) return k * decade(e);
  return decade(e);
}

export function niceCeil125(v) {
  const e = Math.floor(Math.log10(v));
  const m = v / decade(e);
  for (const k of [1, 2, 5]) if (m <= k * (1 + TOL)) return k * decade(e);
  return decade(e + 1);
}

// The scale actually drawn, from the lit values (finite, > 0; any order) and the user's
// request {min, max (null: automatic), scale: 'auto' | 'linear' | 'log'}. Returns
// {min, max, logarithmic} or {error} when a given range is unusable.
export function resolveScale(values, request = {}) {
  const reqMin = request.min ?? null, reqMax = request.max ?? null;
  if (reqMin !== null && reqMax !== null && !(reqMin < reqMax)) return { error: 'MIN must be below MAX' };
  const lit = Array.from(values).filter((v) => Number.isFinite(v) && v > 0).sort((a, b) => a - b);
  const dataLo = lit.length ? percentile(lit, 0.01) : 0;
  const dataHi = lit.length ? percentile(lit, 0.99) : 0;
  let lo = reqMin ?? dataLo, hi = reqMax ?? dataHi;
  if (!(hi > lo)) {
    if (reqMax === null) {
      hi = reqMin !== null ? (lo > 0 ? 10 * lo : 1) : (hi > 0 ? 2 * hi : 1);
      if (reqMin === null) lo = 0;
    } else {
      lo = 0;
    }
  }
  const kind = request.scale || 'auto';
  const logarithmic = kind === 'log' || (kind === 'auto' && lo > 0 && hi / lo > LOG_RATIO);
  if (logarithmic) {
    if (lo <= 0) {
      if (reqMin !== null) return { error: 'a logarithmic scale needs MIN > 0' };
      lo = hi / 100;
    }
    if (reqMin === null) lo = niceFloor125(lo);
    if (reqMax === null) hi = niceCeil125(hi);
  } else {
    const step = linearStep(lo, hi);
    if (reqMin === null) lo = Math.floor(lo / step + TOL) * step;
    if (reqMax === null) hi = Math.ceil(hi / step - TOL) * step;
  }
  return { min: lo, max: hi, logarithmic };
}

// Position of value on the scale in [0, 1]; NaN for a non-finite value.
export function scalePosition(scale, value) {
  if (!Number.isFinite(value)) return NaN;
  let t;
  if (scale.logarithmic) t = value > 0 ? Math.log(value / scale.min) / Math.log(scale.max / scale.min) : 0;
  else t = (value - scale.min) / (scale.max - scale.min);
  return Math.min(Math.max(t, 0), 1);
}

export function scaleTicks(scale) {
  if (!scale.logarithmic) return linearTicks(scale.min, scale.max);
  let best = logTicks(scale.min, scale.max, [1, 2, 5], 1);
  if (best.length > MAX_TICKS) best = logTicks(scale.min, scale.max, [1, 3], 1);
  for (const every of [1, 2, 3, 5, 10, 20, 50, 100]) {
    if (best.length <= MAX_TICKS) break;
    best = logTicks(scale.min, scale.max, [1], every);
  }
  if (best.length < MIN_LOG_TICKS) return linearTicks(scale.min, scale.max);
  return best;
}

// printf "%.Ng" without trailing zeros.
function formatG(v, digits) {
  const s = v.toPrecision(digits);
  if (s.includes('e')) {
    const [m, e] = s.split('e');
    return `${m.includes('.') ? m.replace(/\.?0+$/, '') : m}e${Number(e)}`;
  }
  return s.includes('.') ? s.replace(/\.?0+$/, '') : s;
}

// Tick label as the CLI writes it: "0", "0.5", "250", "20000", "1.5e6".
export function formatTick(v) {
  if (v === 0) return '0';
  const a = Math.abs(v);
  if (a >= 1e-3 && a < 1e6) return formatG(v, 6);
  const e = Math.floor(Math.log10(a));
  return `${formatG(v / decade(e), 3)}e${e}`;
}

// Short reading of a photometric value for labels and tables: 3 significant digits.
export function formatValue(v) {
  if (!Number.isFinite(v)) return '–';
  const a = Math.abs(v);
  if (a === 0) return '0';
  if (a >= 1000) return String(Math.round(v));
  if (a >= 100) return v.toFixed(0);
  if (a >= 10) return v.toFixed(1);
  if (a >= 0.01) return v.toFixed(2);
  return v.toExponential(1);
}
