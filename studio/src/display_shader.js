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
// Window glass shows, once the server has sent the windows' views (RLWV), what its portal
// sees along the line of sight from the eye: the shell and the sun's disc, per pixel.
import * as THREE from 'three';
import { RAMP } from './false_color.js';

const vertexShader = /* glsl */ `
attribute vec4 lighting;
attribute float portal;      // the portal of a glass vertex (RLGE code − 1), −1 elsewhere
varying vec4 vLighting;
varying vec3 vWorld;
flat varying float vPortal;
void main() {
  vLighting = lighting;
  vPortal = portal;
  vec4 world = modelMatrix * vec4(position, 1.0);
  vWorld = world.xyz;
  gl_Position = projectionMatrix * viewMatrix * world;
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
// Window views (RLWV): per portal a 6N × N strip of its shell's faces (+X −X +Y −Y +Z −Z) and
// a row of its sun: (direction, cos of the disc's radius), (luminance, 0).
uniform bool uViews;
uniform highp sampler2DArray uViewMaps;
uniform highp sampler2D uViewSuns;
uniform float uViewFace;
varying vec4 vLighting;
varying vec3 vWorld;
flat varying float vPortal;

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

// What portal p's glass shows along d: its shell by the OpenGL cube-map convention
// (src/math/cubemap.h), bilinear within a face, and the sun's disc.
vec3 windowView(int p, vec3 d) {
  vec3 a = abs(d);
  float face, sc, tc, ma;
  if (a.x >= a.y && a.x >= a.z) {
    ma = a.x; face = d.x > 0.0 ? 0.0 : 1.0; sc = d.x > 0.0 ? -d.z : d.z; tc = -d.y;
  } else if (a.y >= a.z) {
    ma = a.y; face = d.y > 0.0 ? 2.0 : 3.0; sc = d.x; tc = d.y > 0.0 ? d.z : -d.z;
  } else {
    ma = a.z; face = d.z > 0.0 ? 4.0 : 5.0; sc = d.z > 0.0 ? d.x : -d.x; tc = -d.y;
  }
  // Kept half a texel inside the face: its neighbour in the strip is another face.
  float inset = 0.5 / uViewFace;
  float s = clamp(0.5 * (sc / ma + 1.0), inset, 1.0 - inset);
  float t = clamp(0.5 * (tc / ma + 1.0), inset, 1.0 - inset);
  vec3 L = texture(uViewMaps, vec3((face + s) / 6.0, t, float(p))).rgb;
  vec4 sun = texelFetch(uViewSuns, ivec2(0, p), 0);
  if (dot(d, sun.xyz) >= sun.w) L += texelFetch(uViewSuns, ivec2(1, p), 0).rgb;
  return L;
}

void main() {
  bool front = gl_FrontFacing || uTwoSided;
  vec3 L = max(vLighting.rgb, vec3(0.0));
  if (uTwoSided && uViews && vPortal >= 0.0) L = max(windowView(int(vPortal + 0.5), normalize(vWorld - cameraPosition)), vec3(0.0));
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
      uViews: { value: false },
      uViewMaps: { value: null },
      uViewSuns: { value: null },
      uViewFace: { value: 1 },
    },
  });
}
