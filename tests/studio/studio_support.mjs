// What the studio's node tests share: start `relight serve` on a free port, talk to it over
// WebSocket (the `ws` package from studio/node_modules), decode its binary messages
// (docs/studio-protocol.md) and read the server's memory.
import assert from 'node:assert/strict';
import { spawn, spawnSync } from 'node:child_process';
import { createRequire } from 'node:module';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const here = path.dirname(fileURLToPath(import.meta.url));
export const studioDir = path.resolve(here, '../../studio');
export const requireStudio = createRequire(path.join(studioDir, 'package.json'));
const WebSocket = requireStudio('ws');

export const relightBinary = process.env.RELIGHT_BINARY;
export const studioScene = process.env.STUDIO_SCENE;

// Under a sanitizer (scripts/test-sanitize.sh sets RELIGHT_SANITIZER) the server's resident
// memory holds the sanitizer's shadow and allocator caches, so bounds on its growth are reported,
// not asserted; everything else is asserted as always.
export const sanitizer = process.env.RELIGHT_SANITIZER ?? '';
export function assertMemory(ok, message) {
  if (!sanitizer) {
    assert.ok(ok, message);
  } else if (!ok) {
    console.log(`# memory bound not asserted under ${sanitizer}: ${message}`);
  }
}
if (!relightBinary || !studioScene) {
  throw new Error('set RELIGHT_BINARY and STUDIO_SCENE (ctest does: tests/studio/CMakeLists)');
}

// Starts `relight serve SCENE --port 0` (SCENE: STUDIO_SCENE, the demo room, unless `scene`
// names another .rlt) and resolves when it prints its URL.
export function startServer(extraArgs = [], { scene = studioScene } = {}) {
  return new Promise((resolve, reject) => {
    const proc = spawn(relightBinary, ['serve', scene, '--port', '0', ...extraArgs], {
      stdio: ['ignore', 'pipe', 'pipe'],
    });
    let out = '', err = '';
    const timer = setTimeout(() => reject(new Error(`no URL after 60 s: ${out} ${err}`)), 60000);
    proc.stdout.on('data', (d) => {
      out += d;
      const m = out.match(/relight studio: (http:\/\/[^\s]+)/);
      if (m) {
        clearTimeout(timer);
        const url = new URL(m[1]);
        resolve({ proc, url: m[1], ws: `ws://${url.host}/ws`, port: Number(url.port),
                  stderr: () => err });
      }
    });
    proc.stderr.on('data', (d) => { err += d; });
    proc.on('exit', (code) => { clearTimeout(timer); reject(new Error(`serve exited ${code}: ${err}`)); });
  });
}

export async function stopServer(server) {
  if (server.proc.exitCode !== null) return server.proc.exitCode;
  const exited = new Promise((resolve) => server.proc.once('exit', (code, signal) => resolve(code ?? signal)));
  server.proc.kill('SIGTERM');
  return exited;
}

// Resident memory of a process in KiB (VmRSS of /proc/PID/status).
export function residentKiB(pid) {
  const status = fs.readFileSync(`/proc/${pid}/status`, 'utf8');
  return Number(status.match(/VmRSS:\s+(\d+)/)[1]);
}

// A WebSocket client that queues what it receives: text as parsed JSON, binary as Buffers,
// each with the time it arrived (`at`, performance.now()).
export class Client {
  constructor(url, options = {}) {
    this.ws = new WebSocket(url, options);
    this.queue = [];
    this.waiters = [];
    this.closed = null;
    this.ws.on('message', (data, isBinary) => {
      const at = performance.now();
      const m = isBinary ? { binary: true, tag: data.subarray(0, 4).toString('latin1'), data, at }
                         : { binary: false, json: JSON.parse(data.toString()), at };
      this.queue.push(m);
      this.wake();
    });
    this.ws.on('close', (code) => { this.closed = code; this.wake(); });
    this.ws.on('error', () => {});
    this.opened = new Promise((resolve, reject) => {
      this.ws.once('open', resolve);
      this.ws.once('error', reject);
    });
  }
  wake() { for (const w of this.waiters.splice(0)) w(); }
  // The next message matching `predicate` (earlier ones are dropped).
  async next(predicate = () => true, timeoutMs = 30000) {
    const deadline = Date.now() + timeoutMs;
    for (;;) {
      while (this.queue.length) {
        const m = this.queue.shift();
        if (predicate(m)) return m;
      }
      if (this.closed !== null) throw new Error(`connection closed (${this.closed})`);
      const left = deadline - Date.now();
      if (left <= 0) throw new Error('timed out waiting for a message');
      await new Promise((resolve) => {
        const t = setTimeout(resolve, left);
        this.waiters.push(() => { clearTimeout(t); resolve(); });
      });
    }
  }
  nextJson(type, timeoutMs) {
    return this.next((m) => !m.binary && m.json.type === type, timeoutMs).then((m) => m.json);
  }
  nextFrame(timeoutMs) {
    return this.next((m) => m.binary && m.tag === 'RLFR', timeoutMs).then((m) => decodeFrame(m.data));
  }
  send(value) { this.ws.send(typeof value === 'string' || Buffer.isBuffer(value) ? value : JSON.stringify(value)); }
  close() { this.ws.close(); }
}

export async function connect(url, options) {
  const c = new Client(url, options);
  await c.opened;
  return c;
}

function halfToFloat(h) {
  const sign = h & 0x8000 ? -1 : 1;
  const e = (h >> 10) & 0x1f, m = h & 0x3ff;
  if (e === 0) return sign * m * 2 ** -24;
  if (e === 31) return m ? NaN : sign * Infinity;
  return sign * (1 + m / 1024) * 2 ** (e - 15);
}

// An RLFR frame: per vertex radiance (3) and illuminance, the sensors, and the same per
// movable-object vertex (the bytes after the sensors, 8 per object vertex).
export function decodeFrame(buf) {
  const frame = buf.readUInt32LE(4), seq = buf.readUInt32LE(8);
  const v = buf.readUInt32LE(12), s = buf.readUInt32LE(16);
  const ms = buf.readFloatLE(20);
  const halfs = (at, n) => {
    const radiance = new Float32Array(3 * n), illuminance = new Float32Array(n);
    for (let i = 0; i < n; ++i) {
      for (let c = 0; c < 3; ++c) radiance[3 * i + c] = halfToFloat(buf.readUInt16LE(at + 8 * i + 2 * c));
      illuminance[i] = halfToFloat(buf.readUInt16LE(at + 8 * i + 6));
    }
    return { radiance, illuminance };
  };
  const { radiance, illuminance } = halfs(24, v);
  const sensors = new Float32Array(s);
  for (let k = 0; k < s; ++k) sensors[k] = buf.readFloatLE(24 + 8 * v + 4 * k);
  const base = 24 + 8 * v + 4 * s;
  if ((buf.length - base) % 8 !== 0) throw new Error(`RLFR: ${buf.length - base} bytes after the sensors`);
  const objects = halfs(base, (buf.length - base) / 8);
  return { frame, seq: seq === 0xffffffff ? null : seq, vertices: v, ms, radiance, illuminance, sensors,
           objectVertices: objects.illuminance.length, objectRadiance: objects.radiance,
           objectIlluminance: objects.illuminance };
}

// RLGE's positions (3 floats per vertex).
export function geometryPositions(buf) {
  const v = buf.readUInt32LE(8);
  return Array.from({ length: 3 * v }, (_, k) => buf.readFloatLE(16 + 4 * k));
}

// RLOB: per object {vertices, triangles, positions (3 per vertex), albedo (3 per vertex),
// indices (3 per triangle)}; throws unless the bytes are exactly that.
export function decodeObjects(buf) {
  if (buf.subarray(0, 4).toString('latin1') !== 'RLOB') throw new Error('not RLOB');
  const version = buf.readUInt32LE(4), count = buf.readUInt32LE(8);
  const objects = [];
  let at = 12;
  const floats = (n) => Array.from({ length: n }, (_, k) => buf.readFloatLE(at + 4 * k));
  for (let i = 0; i < count; ++i) {
    const vertices = buf.readUInt32LE(at), triangles = buf.readUInt32LE(at + 4);
    at += 8;
    const positions = floats(3 * vertices);
    at += 12 * vertices;
    const albedo = floats(3 * vertices);
    at += 12 * vertices;
    const indices = Array.from({ length: 3 * triangles }, (_, k) => buf.readUInt32LE(at + 4 * k));
    at += 12 * triangles;
    objects.push({ vertices, triangles, positions, albedo, indices });
  }
  if (at !== buf.length) throw new Error(`RLOB: ${buf.length} bytes, the layout gives ${at}`);
  return { version, objects };
}

// The sensors' lux that `relight probe RLT --state STATE_FILE` writes (into `csv`).
export function probeSensors(rlt, stateFile, csv) {
  const r = spawnSync(relightBinary, ['probe', rlt, '--state', stateFile, '-o', csv], { encoding: 'utf8' });
  if (r.status !== 0) throw new Error(`relight probe exited ${r.status}: ${r.stderr}`);
  const [header, ...rows] = fs.readFileSync(csv, 'utf8').trim().split('\n');
  const lux = header.split(',').indexOf('lux');
  return rows.map((l) => Number(l.split(',')[lux]));
}

export const mean = (values) => values.reduce((a, b) => a + b, 0) / values.length;

// The next state message a client gets and the frame after it: what a change produced.
export async function nextStateAndFrame(client) {
  const state = await client.nextJson('state');
  const frame = decodeFrame((await client.next((m) => m.binary && m.tag === 'RLFR')).data);
  return { state, frame };
}

// The lighting state and the sensors' lux of the first frame a client gets that shows a state
// for which `done(state)` holds.
export async function frameWhen(client, done) {
  for (;;) {
    const { state, frame } = await nextStateAndFrame(client);
    if (done(state.state)) return { state: state.state, sensors: Array.from(frame.sensors) };
  }
}
