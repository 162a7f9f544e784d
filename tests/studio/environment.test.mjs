// The top-level environment in the studio (issue 15), in a real browser (Debian's Chromium
// through playwright-core) against a real `relight serve` on a small showroom of its own: a
// 4 × 4 m floor under a clear CIE sky whose sun stands 40° high in the south-west, and a movable
// grey crate on it, lit through the visibility cuts. A node WebSocket client on the same server
// sees every frame. The hello carries the scene's environment; the Windows & environment panel
// shows it first; turning the sun round to the north-east from the page puts the crate's shadow
// on the other side; moving the crate moves its shadow; a uniform sky from the panel's type menu
// leaves no side darker than the other; no page or console error on the way.
import test from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';

import * as browser from './browser_support.mjs';
import { geometryPositions, mean, nextStateAndFrame, relightBinary } from './studio_support.mjs';

const sky = (azimuth) => ({ type: 'cie_sky', sky_type: 12, horizontal_illuminance: 3000,
                           sun: { azimuth_deg: azimuth, altitude_deg: 40 }, sun_illuminance: 10000 });
const kScene = {
  materials: { floor: { albedo: [0.5, 0.5, 0.5] }, grey: { albedo: [0.6, 0.6, 0.6] } },
  geometry: [{ type: 'quad', corner: [-2, 0, -2], u: [0, 0, 4], v: [4, 0, 0], material: 'floor' }],
  objects: [{ name: 'crate', geometry: [{ type: 'box', min: [-0.4, 0, -0.4], max: [0.4, 0.6, 0.4], material: 'grey' }] }],
  environment: sky(225),
  cameras: [{ name: 'above', eye: [2, 2.5, -2], target: [0, 0, 0], fov_deg: 60 }],
  precompute: { max_edge: 0.1, gather_rays: 32, sh_order: 2,
                cuts: { directions: 4096, sphere_count: 8, sphere_points: 8 } },
};

let dir, session, studio, page, watcher, floor;

test.before(async () => {
  dir = fs.mkdtempSync(path.join(os.tmpdir(), 'relight-environment-'));
  const scene = path.join(dir, 'showroom.json');
  const rlt = path.join(dir, 'showroom.rlt');
  fs.writeFileSync(scene, JSON.stringify(kScene, null, 2));
  execFileSync(relightBinary, ['precompute', scene, '-o', rlt, '--no-progress'], { stdio: 'pipe' });
  session = await browser.openSession([], { scene: rlt });
  ({ watcher, studio, page } = session);
});

test.after(async () => {
  await session?.close();
  if (dir) fs.rmSync(dir, { recursive: true, force: true });
});

const testid = (id) => page.locator(`[data-testid="${id}"]`);

// Mean illuminance of the floor vertices with x in [lo, hi] and |z| ≤ 0.2 (beside the crate).
function floorLux(frame, [lo, hi], dz = 0) {
  const v = floor.filter((f) => f.x >= lo && f.x <= hi && Math.abs(f.z - dz) <= 0.2).map((f) => frame.illuminance[f.v]);
  assert.ok(v.length >= 4, `${v.length} floor vertices in x ∈ [${lo}, ${hi}]`);
  return mean(v);
}

// The first frame after the page's state satisfies `done`.
async function frameWhen(done) {
  for (;;) {
    const { state, frame } = await nextStateAndFrame(watcher);
    if (done(state.state)) return frame;
  }
}

const kEast = [0.5, 0.9], kWest = [-0.9, -0.5];

test('the environment, its sun and the crate from the page', async () => {
  const hello = await watcher.nextJson('hello');
  assert.deepEqual(hello.environment, kScene.environment);
  const positions = geometryPositions((await watcher.next((m) => m.binary && m.tag === 'RLGE')).data);
  floor = [];
  for (let v = 0; v < positions.length / 3; ++v) {
    if (positions[3 * v + 1] < 0.01) floor.push({ v, x: positions[3 * v], z: positions[3 * v + 2] });
  }
  // The panel shows the scene's environment first.
  assert.equal(await testid('env-type-env').inputValue(), 'cie_sky');
  assert.ok(await page.locator('[data-environment="top"]').isVisible());

  // The sun in the south-west: the crate's shadow falls east of it. Turned round to the
  // north-east through the page's state: west.
  const setEnvironment = (env) => page.evaluate((e) => {
    const s = window.relightStudio.state();
    s.environment = e;
    window.relightStudio.setState(s);
  }, env);
  await page.evaluate(() => {
    const s = window.relightStudio.state();
    s.objects = { crate: { translate: [0, 0, 0] } };
    window.relightStudio.setState(s);
  });
  let frame = await frameWhen((s) => s.objects?.crate !== undefined);
  const before = { east: floorLux(frame, kEast), west: floorLux(frame, kWest) };
  await setEnvironment(sky(45));
  frame = await frameWhen((s) => s.environment?.sun?.azimuth_deg === 45);
  const after = { east: floorLux(frame, kEast), west: floorLux(frame, kWest) };
  console.log(`sun SW: east ${before.east.toFixed(0)}, west ${before.west.toFixed(0)} lx; ` +
              `sun NE: east ${after.east.toFixed(0)}, west ${after.west.toFixed(0)} lx`);
  assert.ok(before.east < 0.5 * before.west, JSON.stringify(before));
  assert.ok(after.west < 0.5 * after.east, JSON.stringify(after));

  // The crate moved 1.2 m south (+z): its shadow goes with it.
  await page.evaluate(() => {
    const s = window.relightStudio.state();
    s.objects = { crate: { translate: [0, 0, 1.2] } };
    window.relightStudio.setState(s);
  });
  frame = await frameWhen((s) => s.objects?.crate?.translate?.[2] === 1.2);
  const moved = { westHere: floorLux(frame, kWest), westThere: floorLux(frame, kWest, 1.2) };
  console.log(`crate moved: west of where it stood ${moved.westHere.toFixed(0)}, west of it now ` +
              `${moved.westThere.toFixed(0)} lx`);
  assert.ok(moved.westHere > 1.5 * after.west, JSON.stringify(moved));
  assert.ok(moved.westThere < 0.5 * moved.westHere, JSON.stringify(moved));

  // A uniform sky from the panel: no side much darker than the other.
  await testid('env-type-env').selectOption('uniform');
  frame = await frameWhen((s) => s.environment?.type === 'uniform');
  const east = floorLux(frame, kEast, 1.2), west = floorLux(frame, kWest, 1.2);
  console.log(`uniform sky: east ${east.toFixed(0)}, west ${west.toFixed(0)} lx`);
  assert.ok(Math.abs(east - west) < 0.2 * Math.max(east, west), `${east} vs ${west}`);
  assert.deepEqual(studio.problems, []);
});
