// "Open model…" (docs/studio-protocol.md, "open_model"; serve/model_opening.h): a glTF room
// with a skylight chosen in the page's file input in Chromium is sent in pieces, imported and
// precomputed by the server with progress reported to every client, and the page reloads on
// the new scene, whose skylight lights its floor grid. Refusals: a file that is not a model,
// one over 200 MB, pieces nobody announced, more bytes than announced and an IFC file that is
// not one — each a clear message, the server still answering and nothing left in its models
// folder.
import test from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';

import { openSession } from './browser_support.mjs';
import { connect, mean } from './studio_support.mjs';

// A 4 × 3 × 5 m room (y up) with a 1 × 1 m skylight of glass (alphaMode BLEND), as a .gltf
// with its buffer embedded; every face wound to face the room.
function skylightRoomGltf() {
  const positions = [], plaster = [], glass = [];
  const quad = (corners, target) => {
    const base = positions.length / 3;
    for (const c of corners) positions.push(...c);
    const [a, b, c] = corners;
    const u = b.map((v, k) => v - a[k]), w = c.map((v, k) => v - a[k]);
    const n = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]];
    const toCentre = [2 - a[0], 1.5 - a[1], 2.5 - a[2]];
    const inward = n[0] * toCentre[0] + n[1] * toCentre[1] + n[2] * toCentre[2] > 0;
    target.push(...(inward ? [base, base + 1, base + 2, base, base + 2, base + 3]
                           : [base, base + 2, base + 1, base, base + 3, base + 2]));
  };
  quad([[0, 0, 0], [4, 0, 0], [4, 0, 5], [0, 0, 5]], plaster);
  quad([[0, 0, 0], [0, 3, 0], [0, 3, 5], [0, 0, 5]], plaster);
  quad([[4, 0, 0], [4, 0, 5], [4, 3, 5], [4, 3, 0]], plaster);
  quad([[0, 0, 0], [4, 0, 0], [4, 3, 0], [0, 3, 0]], plaster);
  quad([[0, 0, 5], [0, 3, 5], [4, 3, 5], [4, 0, 5]], plaster);
  const ceiling = (x0, z0, x1, z1, target) => quad([[x0, 3, z0], [x1, 3, z0], [x1, 3, z1], [x0, 3, z1]], target);
  ceiling(0, 0, 4, 2, plaster);
  ceiling(0, 3, 4, 5, plaster);
  ceiling(0, 2, 1.5, 3, plaster);
  ceiling(2.5, 2, 4, 3, plaster);
  ceiling(1.5, 2, 2.5, 3, glass);
  const p = Buffer.from(new Float32Array(positions).buffer);
  const i0 = Buffer.from(new Uint32Array(plaster).buffer), i1 = Buffer.from(new Uint32Array(glass).buffer);
  const buffer = Buffer.concat([p, i0, i1]);
  const min = [0, 1, 2].map((k) => Math.min(...positions.filter((_, j) => j % 3 === k)));
  const max = [0, 1, 2].map((k) => Math.max(...positions.filter((_, j) => j % 3 === k)));
  return JSON.stringify({
    asset: { version: '2.0' },
    scene: 0,
    scenes: [{ nodes: [0] }],
    nodes: [{ mesh: 0, name: 'room' }],
    meshes: [{ primitives: [{ attributes: { POSITION: 0 }, indices: 1, material: 0 },
                            { attributes: { POSITION: 0 }, indices: 2, material: 1 }] }],
    materials: [
      { name: 'plaster', pbrMetallicRoughness: { baseColorFactor: [0.7, 0.7, 0.7, 1], metallicFactor: 0 } },
      { name: 'skylight', alphaMode: 'BLEND', pbrMetallicRoughness: { baseColorFactor: [0.9, 0.9, 0.9, 0.2], metallicFactor: 0 } },
    ],
    buffers: [{ byteLength: buffer.length, uri: `data:application/octet-stream;base64,${buffer.toString('base64')}` }],
    bufferViews: [{ buffer: 0, byteOffset: 0, byteLength: p.length, target: 34962 },
                  { buffer: 0, byteOffset: p.length, byteLength: i0.length, target: 34963 },
                  { buffer: 0, byteOffset: p.length + i0.length, byteLength: i1.length, target: 34963 }],
    accessors: [{ bufferView: 0, componentType: 5126, count: positions.length / 3, type: 'VEC3', min, max },
                { bufferView: 1, componentType: 5125, count: plaster.length, type: 'SCALAR' },
                { bufferView: 2, componentType: 5125, count: glass.length, type: 'SCALAR' }],
  });
}

const folder = fs.mkdtempSync(path.join(os.tmpdir(), 'relight-open-model-'));
const models = path.join(folder, 'models');
let session;

test.before(async () => {
  session = await openSession(['--models', models]);
});

test.after(async () => {
  await session?.close();
  fs.rmSync(folder, { recursive: true, force: true });
});

const modelFolders = () => (fs.existsSync(models) ? fs.readdirSync(models) : []);

test('what is not a model, or too big, or not announced is refused with a clear message', async () => {
  const c = await connect(session.server.ws);
  try {
    c.send({ type: 'open_model', seq: 1, name: 'notes.txt', bytes: 10 });
    let e = await c.nextJson('error');
    assert.equal(e.seq, 1);
    assert.match(e.message, /"notes\.txt" is not a model .*\.ifc, \.gltf, \.glb or \.obj/);
    c.send({ type: 'open_model', seq: 2, name: 'tower.ifc', bytes: 300 * 1024 * 1024 });
    e = await c.nextJson('error');
    assert.equal(e.seq, 2);
    assert.match(e.message, /tower\.ifc is 300 MB, over the 200 MB limit/);
    c.send(Buffer.from('RLMU0123'));
    e = await c.nextJson('error');
    assert.match(e.message, /no model is being sent on this connection/);
    c.send({ type: 'open_model', seq: 3, name: 'small.obj', bytes: 4 });
    const receiving = await c.nextJson('model');
    assert.deepEqual([receiving.stage, receiving.done, receiving.total], ['receiving', 0, 4]);
    c.send(Buffer.from('RLMU0123456789'));
    e = await c.nextJson('error');
    assert.match(e.message, /more bytes of small\.obj than the 4 announced/);
    assert.deepEqual(modelFolders(), []);
    c.send({ type: 'ping', seq: 4 });
    assert.equal((await c.nextJson('pong')).seq, 4);
  } finally {
    c.close();
  }
});

test('a file that is not IFC fails at the import with its reason, and leaves nothing behind', async () => {
  const c = await connect(session.server.ws);
  try {
    const text = Buffer.from('this is not a building\n');
    c.send({ type: 'open_model', seq: 1, name: 'house.ifc', bytes: text.length });
    assert.equal((await c.nextJson('model')).stage, 'receiving');
    c.send(Buffer.concat([Buffer.from('RLMU'), text]));
    assert.equal((await c.nextJson('model')).stage, 'importing');
    const failed = await c.nextJson('model');
    assert.equal(failed.stage, 'failed');
    assert.match(failed.message, /^house\.ifc: not an IFC file/);
    assert.doesNotMatch(failed.message, /model-\d|\//, 'no server path in the message');
    assert.deepEqual(modelFolders(), []);
  } finally {
    c.close();
  }
});

test('a glTF room opened in the page is imported, precomputed with progress and shown', async () => {
  const { page, watcher } = session;
  const file = path.join(folder, 'skylight room.gltf');
  fs.writeFileSync(file, skylightRoomGltf());
  const seen = [];
  const watched = (async () => {
    for (;;) {
      const m = await watcher.nextJson('model', 300000);
      if (m.name !== 'skylight room.gltf') continue;  // the earlier tests' models
      seen.push(m);
      if (m.stage === 'opening' || m.stage === 'failed') return;
    }
  })();
  await page.evaluate(() => { window.beforeTheModel = true; });
  await page.locator('[data-testid="model-file"]').setInputFiles(file);
  await watched;
  const stages = [...new Set(seen.map((m) => m.stage))];
  // `receiving` goes to the sender (the page) only.
  assert.deepEqual(stages, ['importing', 'imported', 'precomputing', 'opening'],
                   JSON.stringify(seen.at(-1)));
  const imported = seen.find((m) => m.stage === 'imported');
  assert.equal(imported.name, 'skylight room.gltf');
  assert.equal(imported.summary.portals, 1);
  const fractions = seen.filter((m) => m.stage === 'precomputing').map((m) => m.fraction);
  assert.ok(fractions.includes(1), `a phase reported done: ${fractions}`);
  assert.equal(seen.at(-1).scene, 'model-1.rlt');
  assert.ok(fs.existsSync(path.join(models, 'model-1', 'model-1.rlt')));
  assert.ok(fs.existsSync(path.join(models, 'model-1', 'model.gltf')), 'stored under the server\'s name');

  // The page reloads on the new scene once the server is back.
  await page.waitForFunction(
    () => !window.beforeTheModel && document.getElementById('scene-name')?.textContent === 'model-1.rlt',
    null, { timeout: 120000 });
  await page.evaluate(() => window.relightStudio.ready);
  const c = await connect(session.server.ws);
  try {
    const hello = await c.nextJson('hello');
    assert.equal(hello.scene_file, 'model-1.rlt');
    const frame = await c.nextFrame();
    assert.ok(frame.sensors.length > 20, `a floor grid: ${frame.sensors.length} points`);
    // 10 klx of overcast sky through 1 m² of a 20 m² ceiling: tens of lux on the work plane.
    assert.ok(mean(Array.from(frame.sensors)) > 20, `skylight on the grid: ${mean(Array.from(frame.sensors))} lx`);
  } finally {
    c.close();
  }
  assert.deepEqual(session.studio.problems.filter((p) => !/Server: |Open model: |WebSocket connection to .* failed/.test(p)), []);
});
