// The surface shader: per-vertex radiance (cd/m² per channel, linear Rec.709) and
// illuminance (lx) arrive as one half-float vec4 attribute `lighting` and are interpolated
// over each triangle (Gouraud, as the lighting-design paper's display step, Eq. 18, and
// `relight render`'s vertex path). Per fragment it shows, as the CLI does
// (src/render/tone_map.h, false_color.h):
//  * mode 0, tone-mapped: x = L / L_max with L_max = 1.2 · 2^EV100 per channel, the
//    highlight roll-off above 0.6 (s + (1 − s)·u/(1 + u)), then the sRGB OETF; or the ACES
//    filmic fit (Narkowicz 2015) as an alternative curve;
//  * modes 1 and 2, false colour: illuminance (lx) or luminance Y (cd/m²) placed on the
//    linear or logarithmic scale [MIN, MAX] and looked up in the 7-colour ramp (8-bit sRGB
//    values, output as they are);
//  * mode 3, metering: (Y, E, 0, 1) into a float target, for automatic exposure and the
//    automatic false-colour range.
// Back faces absorb (the CLI shows them as "no surface": black, grey in false colour) unless
// the material is two-sided (window glass, whose illuminance is shown as no surface too).
import * as THREE from 'three';
import { RAMP } from './false_color.js';

const vertexShader = /* glsl */ `
attribute vec4 lighting;
varying vec4 vLighting;
void main() {
  vLighting = lighting;
  gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);
}
`;

const fragmentShader = /* glsl */ `
uniform int uMode;            // 0 tone-mapped, 1 false colour lx, 2 false colour cd/m², 3 metering
uniform int uToneCurve;       // 0 relight roll-off, 1 ACES filmic
uniform float uExposureScale; // 1 / L_max
uniform float uMin, uMax;
uniform bool uLog;
uniform bool uTwoSided;
uniform vec3 uRamp[7];
uniform vec3 uNoSurface;
varying vec4 vLighting;

float rolloff(float x) {
  if (x <= 0.6) return x;
  float u = (x - 0.6) / 0.4;
  return 0.6 + 0.4 * u / (1.0 + u);
}
float oetf(float x) {
  if (!(x > 0.0)) return 0.0;
  return x <= 0.0031308 ? 12.92 * x : 1.055 * pow(x, 1.0 / 2.4) - 0.055;
}
vec3 aces(vec3 x) {
  x *= 0.6;
  return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}
vec3 ramp(float t) {
  float p = clamp(t, 0.0, 1.0) * 6.0;
  int i = int(min(floor(p), 5.0));
  return mix(uRamp[i], uRamp[i + 1], p - float(i)) / 255.0;
}
float scalePosition(float v) {
  if (uLog) return v > 0.0 ? log(v / uMin) / log(uMax / uMin) : 0.0;
  return (v - uMin) / (uMax - uMin);
}

void main() {
  bool front = gl_FrontFacing || uTwoSided;
  vec3 L = max(vLighting.rgb, vec3(0.0));
  float Y = dot(L, vec3(0.2126, 0.7152, 0.0722));
  float E = max(vLighting.a, 0.0);
  if (uMode == 3) {
    if (!front) discard;
    gl_FragColor = vec4(Y, E, 0.0, 1.0);
    return;
  }
  // Back faces show no surface; window glass has no illuminance of its own (the CLI sees
  // the sky through it and leaves its lux undefined): grey in the lux view.
  if (!front || (uTwoSided && uMode == 1)) {
    gl_FragColor = vec4(uMode == 0 ? vec3(0.0) : uNoSurface / 255.0, 1.0);
    return;
  }
  if (uMode == 0) {
    vec3 x = L * uExposureScale;
    vec3 d;
    if (uToneCurve == 1) d = aces(x);
    else d = vec3(rolloff(x.r), rolloff(x.g), rolloff(x.b));
    gl_FragColor = vec4(oetf(d.r), oetf(d.g), oetf(d.b), 1.0);
  } else {
    gl_FragColor = vec4(ramp(scalePosition(uMode == 1 ? E : Y)), 1.0);
  }
}
`;

// One material; twoSided for window glass (its triangles may face either way).
export function createDisplayMaterial(twoSided) {
  return new THREE.ShaderMaterial({
    vertexShader,
    fragmentShader,
    side: THREE.DoubleSide,
    toneMapped: false,
    uniforms: {
      uMode: { value: 0 },
      uToneCurve: { value: 0 },
      uExposureScale: { value: 1 },
      uMin: { value: 0 },
      uMax: { value: 1 },
      uLog: { value: false },
      uTwoSided: { value: twoSided },
      uRamp: { value: RAMP.map((c) => new THREE.Vector3(...c)) },
      uNoSurface: { value: new THREE.Vector3(128, 128, 128) },
    },
  });
}
