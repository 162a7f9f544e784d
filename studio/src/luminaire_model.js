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
  let aim = normalize(scene.aim || [0, -1, 0]);
  if (entry.target) aim = normalize(sub(entry.target, scene.position));
  else if (entry.aim) aim = normalize(entry.aim);
  return {
    name: scene.name,
    position: scene.position,
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
