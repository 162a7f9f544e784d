// What a luminaire is under the current state: the scene's values (hello.luminaires[i])
// overridden by the state's entry (docs/lighting-state.md, "Keys of a luminaire"), and
// local evaluation of the analytic distributions (scene format: isotropic, cosine_power,
// curve) for defaults when the user switches a luminaire's distribution type.
import { cctToRgb, luminance } from './colors.js';

const sub = (a, b) => a.map((x, i) => x - b[i]);
const normalize = (v) => {
  const l = Math.hypot(...v);
  return l > 0 ? v.map((x) => x / l) : v;
};

// The luminaires the layout shows: the scene's (hello order), then those the state adds (an
// entry whose name the scene lacks, with a position and a distribution; by name, as the
// server orders them). An added one's scene values are its entry's at placing, marked `added`.
export function layoutLuminaires(hello, doc) {
  const names = new Set(hello.luminaires.map((l) => l.name));
  const added = Object.keys(doc?.luminaires ?? {})
    .filter((n) => {
      const e = doc.luminaires[n];
      return !names.has(n) && e && Array.isArray(e.position) && e.distribution;
    })
    .sort()
    .map((name) => {
      const e = doc.luminaires[name];
      return { name, added: true, position: e.position, aim: [0, -1, 0], color: [1, 1, 1], dimmer: 1, size: [0, 0, 0], distribution: e.distribution };
    });
  return [...hello.luminaires, ...added];
}

// The group of an array's luminaire (named GROUP-rRcC by the array tool), or null.
export function groupOf(name) {
  const m = /^(.*)-r\d+c\d+$/.exec(name);
  return m ? m[1] : null;
}

const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];

// C0 as the relighter takes it: the hint (default: world +x, or −z for an aim along x, as the
// scene loader) made perpendicular to the aim.
export function c0Of(hint, aim) {
  const h = hint ?? (Math.abs(aim[0]) > 0.999 ? [0, 0, -1] : [1, 0, 0]);
  const d = dot(h, aim);
  return normalize(h.map((x, k) => x - d * aim[k]));
}

// C0 turned by `deg` about the aim (right-handed), perpendicular to it.
export function turnC0(c0, aim, deg) {
  const a = (deg * Math.PI) / 180, c = Math.cos(a), s = Math.sin(a);
  const x = [aim[1] * c0[2] - aim[2] * c0[1], aim[2] * c0[0] - aim[0] * c0[2], aim[0] * c0[1] - aim[1] * c0[0]];
  return normalize(c0.map((v, k) => c * v + s * x[k]));
}

export function effectiveLuminaire(scene, entry = {}) {
  let colorMode = 'scene';
  let color = scene.color || [1, 1, 1];
  if (entry.cct_kelvin !== undefined) {
    colorMode = 'cct';
    color = cctToRgb(entry.cct_kelvin);
  } else if (entry.color !== undefined) {
    colorMode = 'rgb';
    color = entry.color;
  }
  const l = luminance(color);
  const position = entry.position ?? scene.position;
  let aim = normalize(scene.aim || [0, -1, 0]);
  if (entry.target) aim = normalize(sub(entry.target, position));
  else if (entry.aim) aim = normalize(entry.aim);
  return {
    c0: c0Of(entry.c0 ?? scene.c0, aim),
    name: scene.name,
    added: !!scene.added,
    position,
    moved: entry.position !== undefined && !scene.added,
    on: entry.on ?? true,
    dimmer: entry.dimmer ?? scene.dimmer ?? 1,
    colorMode,
    color: l > 0 ? color.map((x) => x / l) : [1, 1, 1],
    cct: entry.cct_kelvin,
    aim,
    target: entry.target || null,
    aimChanged: !!(entry.target || entry.aim),
    distribution: entry.distribution ?? scene.distribution,
    distributionChanged: entry.distribution !== undefined,
  };
}

// I(γ) in cd of an analytic distribution; null for file-based ones (ies, ldt).
export function analyticIntensity(d, gammaDeg) {
  if (!d) return null;
  if (d.type === 'isotropic') return d.candela;
  if (d.type === 'cosine_power') {
    const c = Math.cos((gammaDeg * Math.PI) / 180);
    return gammaDeg <= (d.cutoff_deg ?? 90) && c > 0 ? d.candela * c ** d.exponent : 0;
  }
  if (d.type === 'curve') {
    const G = d.gamma_deg, C = d.candela;
    if (!G?.length || gammaDeg > G[G.length - 1]) return 0;
    for (let i = 0; i + 1 < G.length; i++) {
      if (gammaDeg <= G[i + 1]) return C[i] + ((C[i + 1] - C[i]) * (gammaDeg - G[i])) / (G[i + 1] - G[i] || 1);
    }
    return C[C.length - 1];
  }
  return null;
}

// Peak intensity (cd) of a distribution, from the server's exact C0 plane when known.
export function peakCandela(d, exact) {
  if (exact?.c0?.length) return Math.max(...exact.c0);
  if (d?.type === 'curve') return Math.max(...d.candela);
  if (d && typeof d.candela === 'number') return d.candela;
  return 100;
}

// Control points sampled from the exact C0 plane every 10° from 0 to 180 (the editor's
// conversion of any distribution to a curve); `exact` is a distribution message's
// {gamma_deg, exact: {c0}}; without it, analytic distributions are evaluated here.
export function sampleCurve(d, message) {
  const gamma = Array.from({ length: 19 }, (_, i) => 10 * i);
  const at = (g) => {
    if (message?.exact?.c0 && message.gamma_deg) {
      const G = message.gamma_deg, C = message.exact.c0;
      for (let i = 0; i + 1 < G.length; i++) {
        if (g <= G[i + 1]) return C[i] + ((C[i + 1] - C[i]) * (g - G[i])) / (G[i + 1] - G[i] || 1);
      }
      return C[C.length - 1];
    }
    return analyticIntensity(d, g) ?? 0;
  };
  return { type: 'curve', gamma_deg: gamma, candela: gamma.map((g) => round6(Math.max(0, at(g)))) };
}

export const round6 = (x) => Number(Number(x).toPrecision(6));
