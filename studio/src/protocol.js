// Wire format of `relight serve` (docs/studio-protocol.md): decoding of the binary
// geometry ("RLGE"), movable objects ("RLOB"), frame ("RLFR"), glossy view ("RLGV") and window
// views ("RLWV")
// messages, IEEE 754 binary16 → number, and builders for the client's text messages (state,
// pick, distribution, ping, view).

const LITTLE_ENDIAN = new Uint8Array(new Uint16Array([1]).buffer)[0] === 1;
export const NO_SEQ = 0xffffffff;

// ASCII tag of a binary message ("RLGE", "RLFR", …).
export function binaryTag(buffer) {
  if (buffer.byteLength < 4) return '';
  const b = new Uint8Array(buffer, 0, 4);
  return String.fromCharCode(b[0], b[1], b[2], b[3]);
}

// Typed-array view of little-endian data; copies through a DataView on big-endian hosts or
// when the offset is misaligned for the element type.
function view(Type, buffer, byteOffset, length, getter) {
  if (LITTLE_ENDIAN && byteOffset % Type.BYTES_PER_ELEMENT === 0) {
    return new Type(buffer, byteOffset, length);
  }
  const out = new Type(length);
  const dv = new DataView(buffer);
  for (let i = 0; i < length; i++) out[i] = dv[getter](byteOffset + i * Type.BYTES_PER_ELEMENT, true);
  return out;
}

function need(buffer, bytes, what) {
  if (buffer.byteLength < bytes) {
    throw new Error(`${what}: ${buffer.byteLength} bytes, expected ${bytes}`);
  }
}

// RLGE: positions (f32 xyz), albedo (f32 rgb, linear), indices (u32, CCW front) and per
// triangle 0 (opaque) or p + 1 (window glass of portal p).
export function decodeGeometry(buffer) {
  need(buffer, 16, 'RLGE header');
  if (binaryTag(buffer) !== 'RLGE') throw new Error(`expected RLGE, got "${binaryTag(buffer)}"`);
  const dv = new DataView(buffer);
  const version = dv.getUint32(4, true);
  const V = dv.getUint32(8, true);
  const T = dv.getUint32(12, true);
  need(buffer, 16 + 24 * V + 16 * T, 'RLGE');
  return {
    version,
    vertexCount: V,
    triangleCount: T,
    positions: view(Float32Array, buffer, 16, 3 * V, 'getFloat32'),
    albedo: view(Float32Array, buffer, 16 + 12 * V, 3 * V, 'getFloat32'),
    indices: view(Uint32Array, buffer, 16 + 24 * V, 3 * T, 'getUint32'),
    triangleCodes: view(Uint32Array, buffer, 16 + 24 * V + 12 * T, T, 'getUint32'),
  };
}

// RLOB: per movable object (hello.objects order) its mesh as the scene places it: positions
// (f32 xyz), albedo (f32 rgb, linear) and indices local to the object (u32, CCW front).
export function decodeObjects(buffer) {
  need(buffer, 12, 'RLOB header');
  if (binaryTag(buffer) !== 'RLOB') throw new Error(`expected RLOB, got "${binaryTag(buffer)}"`);
  const dv = new DataView(buffer);
  const version = dv.getUint32(4, true);
  const count = dv.getUint32(8, true);
  const objects = [];
  let at = 12;
  for (let i = 0; i < count; i++) {
    need(buffer, at + 8, `RLOB object ${i}`);
    const V = dv.getUint32(at, true);
    const T = dv.getUint32(at + 4, true);
    at += 8;
    need(buffer, at + 24 * V + 12 * T, `RLOB object ${i}`);
    const indices = view(Uint32Array, buffer, at + 24 * V, 3 * T, 'getUint32');
    for (let k = 0; k < indices.length; k++) {
      if (indices[k] >= V) throw new Error(`RLOB object ${i}: index ${indices[k]} of ${V} vertices`);
    }
    objects.push({
      vertexCount: V,
      triangleCount: T,
      positions: view(Float32Array, buffer, at, 3 * V, 'getFloat32'),
      albedo: view(Float32Array, buffer, at + 12 * V, 3 * V, 'getFloat32'),
      indices,
    });
    at += 24 * V + 12 * T;
  }
  if (at !== buffer.byteLength) throw new Error(`RLOB: ${buffer.byteLength} bytes, expected ${at}`);
  return { version, objects };
}

// RLFR: frame number, seq (null for 0xFFFFFFFF), server milliseconds, per vertex four half
// floats (radiance R G B in cd/m², illuminance in lx) kept as raw Uint16 for upload as a
// half-float vertex attribute, the sensor points' illuminance (f32, lx), then the same four
// half floats per movable-object vertex (all objects back to back, hello.objects order; none
// when the scene has no objects).
export function decodeFrame(buffer) {
  need(buffer, 24, 'RLFR header');
  if (binaryTag(buffer) !== 'RLFR') throw new Error(`expected RLFR, got "${binaryTag(buffer)}"`);
  const dv = new DataView(buffer);
  const frame = dv.getUint32(4, true);
  const rawSeq = dv.getUint32(8, true);
  const V = dv.getUint32(12, true);
  const S = dv.getUint32(16, true);
  const base = 24 + 8 * V + 4 * S;
  need(buffer, base, 'RLFR');
  if ((buffer.byteLength - base) % 8 !== 0) {
    throw new Error(`RLFR: ${buffer.byteLength - base} bytes after the sensors, not 8 per object vertex`);
  }
  const Q = (buffer.byteLength - base) / 8;
  return {
    frame,
    seq: rawSeq === NO_SEQ ? null : rawSeq,
    vertexCount: V,
    sensorCount: S,
    serverMs: dv.getFloat32(20, true),
    halfs: view(Uint16Array, buffer, 24, 4 * V, 'getUint16'),
    sensors: view(Float32Array, buffer, 24 + 8 * V, S, 'getFloat32'),
    objectVertexCount: Q,
    objectHalfs: view(Uint16Array, buffer, base, 4 * Q, 'getUint16'),
  };
}

// RLGV: the glossy vertices' luminance toward this client's eye (its last `view`) for frame
// `frame`: vertex indices (u32) and per listed vertex three half floats (R G B, cd/m²) that
// replace the frame's radiance there; none when no surface is glossy.
export function decodeGlossyView(buffer) {
  need(buffer, 28, 'RLGV header');
  if (binaryTag(buffer) !== 'RLGV') throw new Error(`expected RLGV, got "${binaryTag(buffer)}"`);
  const dv = new DataView(buffer);
  const G = dv.getUint32(8, true);
  const expected = 28 + 4 * G + 6 * G;
  if (buffer.byteLength !== expected) throw new Error(`RLGV: ${buffer.byteLength} bytes, expected ${expected}`);
  return {
    frame: dv.getUint32(4, true),
    count: G,
    serverMs: dv.getFloat32(12, true),
    eye: [dv.getFloat32(16, true), dv.getFloat32(20, true), dv.getFloat32(24, true)],
    vertices: view(Uint32Array, buffer, 28, G, 'getUint32'),
    halfs: view(Uint16Array, buffer, 28 + 4 * G, 3 * G, 'getUint16'),
  };
}

// RLWV: what each window shows looking out — per portal its centre, the sun disc drawn apart
// (direction, cos of its angular radius, −2 without a sun; luminance R G B) and its shell as
// 6·N² texels of three half floats (cd/m²; faces +X −X +Y −Y +Z −Z, the OpenGL cube-map
// layout), all portals' texels back to back.
export function decodeWindowViews(buffer) {
  need(buffer, 16, 'RLWV header');
  if (binaryTag(buffer) !== 'RLWV') throw new Error(`expected RLWV, got "${binaryTag(buffer)}"`);
  const dv = new DataView(buffer);
  const P = dv.getUint32(8, true), N = dv.getUint32(12, true);
  const expected = 16 + 40 * P + 6 * 6 * N * N * P;
  if (buffer.byteLength !== expected) throw new Error(`RLWV: ${buffer.byteLength} bytes, expected ${expected}`);
  const f = (at) => dv.getFloat32(at, true);
  const portals = [];
  for (let p = 0; p < P; ++p) {
    const at = 16 + 40 * p;
    portals.push({ centre: [f(at), f(at + 4), f(at + 8)], sunDirection: [f(at + 12), f(at + 16), f(at + 20)],
                   sunCos: f(at + 24), sunLuminance: [f(at + 28), f(at + 32), f(at + 36)] });
  }
  return {
    frame: dv.getUint32(4, true),
    faceSize: N,
    portals,
    halfs: view(Uint16Array, buffer, 16 + 40 * P, 3 * 6 * N * N * P, 'getUint16'),
  };
}

// A decoded RLGV in two: the room's vertices (indices below `roomVertices`) and the movable
// objects' (indices from `roomVertices` on, given as object vertex numbers in hello order).
export function splitGlossyView(glossy, roomVertices) {
  const part = (keep, offset) => {
    const at = [];
    glossy.vertices.forEach((v, i) => { if (keep(v)) at.push(i); });
    const halfs = new Uint16Array(3 * at.length);
    at.forEach((i, j) => halfs.set(glossy.halfs.subarray(3 * i, 3 * i + 3), 3 * j));
    return { ...glossy, count: at.length, vertices: Uint32Array.from(at, (i) => glossy.vertices[i] - offset), halfs };
  };
  return { room: part((v) => v < roomVertices, 0), objects: part((v) => v >= roomVertices, roomVertices) };
}

// IEEE 754 binary16 bits → number.
export function halfToFloat(h) {
  const sign = h & 0x8000 ? -1 : 1;
  const exponent = (h >> 10) & 0x1f;
  const mantissa = h & 0x3ff;
  if (exponent === 0) return sign * mantissa * 2 ** -24;
  if (exponent === 31) return mantissa ? NaN : sign * Infinity;
  return sign * (1 + mantissa / 1024) * 2 ** (exponent - 15);
}

// Illuminance (lx) of vertex v from a decoded frame.
export function vertexIlluminance(frame, v) {
  return halfToFloat(frame.halfs[4 * v + 3]);
}

// Text messages of the client (seq: a non-negative integer the server echoes).
export const messages = {
  state: (seq, state) => ({ type: 'state', seq, state }),
  pick: (seq, origin, direction) => ({ type: 'pick', seq, origin, direction }),
  distribution: (seq, luminaire, samples = 181) => ({ type: 'distribution', seq, luminaire, samples }),
  ping: (seq) => ({ type: 'ping', seq }),
  view: (seq, eye) => ({ type: 'view', seq, eye }),
};
