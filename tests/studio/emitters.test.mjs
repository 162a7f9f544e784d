// Near-field emitters in the studio, in a real browser (Debian's Chromium through
// playwright-core) against a real `relight serve` on a small room of its own: a 3 × 2.5 × 3 m
// room, a table and one downward-facing 0.4 × 0.4 m panel emitter 0.4 m over it, no other
// light. The hello lists the emitter and the page gives it a panel; raising its luminance
// brightens the picture (fixed exposure), switching it off darkens it, a red colour makes the
// picture red; dragging its marker in the view moves the emitter at its height (the state's
// translate follows the pointer) and moves its bright patch on screen in the drag direction.
import test from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';

import * as browser from './browser_support.mjs';
import { connect, relightBinary, startServer, stopServer } from './studio_support.mjs';

const kScene = {
  materials: { wall: { albedo: [0.6, 0.6, 0.6] }, floor: { albedo: [0.4, 0.4, 0.4] },
               table: { albedo: [0.7, 0.7, 0.7] } },
  geometry: [
    { type: 'box', min: [0, 0, 0], max: [3, 2.5, 3], normals: 'inward', material: 'wall' },
    { type: 'quad', corner: [0, 0.001, 0], u: [0, 0, 3], v: [3, 0, 0], material: 'floor' },
    { type: 'box', min: [0.6, 0, 0.9], max: [2.4, 0.75, 2.1], material: 'table' },
  ],
  // Facing down (u × v = −y), its centre at [1.5, 1.15, 1.5]: 0.4 m over the table top.
  emitters: [{ name: 'panel', luminance: 2000,
               geometry: { type: 'quad', corner: [1.3, 1.15, 1.3], u: [0.4, 0, 0], v: [0, 0, 0.4] } }],
  cameras: [{ name: 'above', eye: [1.5, 2.3, 2.9], target: [1.5, 0.6, 1.2], fov_deg: 70 }],
  precompute: { max_edge: 0.3, gather_rays: 32, nearfield_directions: 64 },
};
const kPivot = [1.5, 1.15, 1.5];

let dir, server, studio, page, hello;

test.before(async () => {
  dir = fs.mkdtempSync(path.join(os.tmpdir(), 'relight-emitters-'));
  const scene = path.join(dir, 'emitter-room.json');
  const rlt = path.join(dir, 'emitter-room.rlt');
  fs.writeFileSync(scene, JSON.stringify(kScene, null, 2));
  execFileSync(relightBinary, ['precompute', scene, '-o', rlt, '--no-progress'], { stdio: 'pipe' });
  server = await startServer([], { scene: rlt });
  const probe = await connect(server.ws);
  hello = await probe.nextJson('hello');
  probe.close();
  studio = await browser.openStudio(server.url);
  page = studio.page;
  // A fixed exposure, so that images compare pixel by pixel.
  await page.locator('#auto-exposure').uncheck();
  await page.locator('#exposure').fill('8');
});

test.after(async () => {
  await studio?.close();
  if (server) assert.equal(await stopServer(server), 0, server.stderr());
  if (dir) fs.rmSync(dir, { recursive: true, force: true });
});

const pixels = () => browser.pixels(page);
const testid = (id) => page.locator(`[data-testid="${id}"]`);
const emitterState = () => page.evaluate(() => window.relightStudio.state().emitters?.panel ?? {});

// Pixels of the room alone: the emitter's marker (drawn in the view) hidden meanwhile.
async function roomPixels(keepAs) {
  await page.locator('#show-emitters').uncheck();
  const p = await pixels();
  if (keepAs) await browser.keepPixels(page, keepAs);
  await page.locator('#show-emitters').check();
  return p;
}

// Drags the emitter's marker to where the world point `to` is on screen, in `steps` moves.
async function dragEmitterTo(to, steps = 12) {
  const box = await page.locator('#viewport').boundingBox();
  const from = await page.evaluate(() => window.relightStudio.emitterOnScreen(0));
  const target = await page.evaluate((p) => window.relightStudio.project(p), to);
  assert.ok(from && target, `marker ${JSON.stringify(from)}, target ${JSON.stringify(target)}`);
  await page.mouse.move(box.x + from.x, box.y + from.y);
  await page.mouse.down();
  await page.mouse.move(box.x + target.x, box.y + target.y, { steps });
  await page.mouse.up();
  await browser.settled(page);
  return { from, to: target };
}

test('the hello lists the emitter and the page gives it a panel', async () => {
  assert.equal(hello.emitters.length, 1);
  const e = hello.emitters[0];
  assert.equal(e.name, 'panel');
  assert.equal(e.luminance, 2000);
  assert.deepEqual(e.color.map((c) => Number(c.toFixed(9))), [1, 1, 1]);
  e.pivot.forEach((v, k) => assert.ok(Math.abs(v - kPivot[k]) < 1e-9, `pivot ${e.pivot}`));
  assert.ok(Math.abs(e.size - 0.2 * Math.SQRT2) < 1e-9, `size ${e.size}`);
  assert.equal(await page.locator('details.emitter').count(), 1);
  assert.equal(await testid('emitter-luminance-0').getAttribute('max'), '4000');
  assert.equal(await testid('emitter-on-0').isChecked(), true);
  const p = await roomPixels();
  assert.ok(p.mean > 3, `the emitter lights the room: mean display value ${p.mean}`);
});

test('the luminance control brightens the room, on/off and colour change it', async () => {
  await browser.afterNewFrame(page, () => testid('emitter-luminance-0').fill('200'));
  await browser.settled(page);
  const low = await roomPixels();
  await browser.afterNewFrame(page, () => testid('emitter-luminance-0').fill('3000'));
  await browser.settled(page);
  const high = await roomPixels();
  assert.equal((await emitterState()).luminance, 3000);
  await browser.afterNewFrame(page, () => testid('emitter-on-0').uncheck());
  await browser.settled(page);
  const off = await roomPixels();
  assert.equal((await emitterState()).on, false);
  await browser.afterNewFrame(page, () => testid('emitter-on-0').check());
  await browser.afterNewFrame(page, () => testid('emitter-color-0').fill('#ff0000'));
  await browser.settled(page);
  const red = await roomPixels();
  const color = (await emitterState()).color;
  console.log(`emitter luminance: mean display value ${low.mean.toFixed(1)} at 200 cd/m², ` +
              `${high.mean.toFixed(1)} at 3000 cd/m², ${off.mean.toFixed(1)} off; red light ` +
              `${JSON.stringify(color)}: mean R ${red.red.toFixed(1)}, G ${red.green.toFixed(1)}, ` +
              `B ${red.blue.toFixed(1)} (white: R ${high.red.toFixed(1)}, G ${high.green.toFixed(1)})`);
  assert.ok(high.mean > 2 * low.mean, `mean ${low.mean} → ${high.mean}`);
  assert.ok(off.mean < 0.25 * low.mean, `off: ${off.mean} vs ${low.mean} at 200 cd/m²`);
  assert.ok(color[0] > 0.99 && color[1] < 0.01 && color[2] < 0.01, JSON.stringify(color));
  assert.ok(red.red > 3 * red.green && red.red > 3 * red.blue, JSON.stringify(red));
  // Back to the scene's emitter.
  await browser.afterNewFrame(page, () => page.evaluate(() => window.relightStudio.setState({})));
  await browser.settled(page);
});

test('dragging the marker moves the emitter and its bright patch', async () => {
  const left = [kPivot[0] - 0.45, kPivot[1], kPivot[2]];
  const right = [kPivot[0] + 0.45, kPivot[1], kPivot[2]];
  const camera = () => page.evaluate(() => window.relightStudio.camera.position.toArray());
  const eye = await camera();
  const first = await dragEmitterTo(left);
  const t0 = (await emitterState()).translate;
  await roomPixels('left');
  if (process.env.STUDIO_SHOTS) await page.screenshot({ path: `${process.env.STUDIO_SHOTS}/emitter-left.png` });
  const second = await dragEmitterTo(right);
  const t1 = (await emitterState()).translate;
  await roomPixels('right');
  if (process.env.STUDIO_SHOTS) await page.screenshot({ path: `${process.env.STUDIO_SHOTS}/emitter-right.png` });
  // The state follows the pointer at the emitter's height.
  const near = (t, want) => t.every((v, k) => Math.abs(v - want[k]) < 0.04);
  assert.ok(near(t0, [-0.45, 0, 0]), `translate after the first drag ${t0}`);
  assert.ok(near(t1, [0.45, 0, 0]), `translate after the second drag ${t1}`);
  // The drags were the emitter's: the camera stayed and no surface was probed.
  assert.deepEqual(await camera(), eye);
  assert.equal(await page.locator('#probe').isHidden(), true);
  // The state panel shows (and would save) the move.
  assert.deepEqual(JSON.parse(await page.locator('#state-json').inputValue()).emitters.panel.translate, t1);
  // Where the light arrived (right brighter than left) and where it left.
  const arrived = await browser.brighterCentroid(page, 'right', 'left');
  const went = await browser.brighterCentroid(page, 'left', 'right');
  const drag = { x: second.to.x - second.from.x, y: second.to.y - second.from.y };
  const length = Math.hypot(drag.x, drag.y);
  const moved = ((arrived.x - went.x) * drag.x + (arrived.y - went.y) * drag.y) / length;
  console.log(`emitter drag: marker (${first.from.x.toFixed(0)}, ${first.from.y.toFixed(0)}) → ` +
              `(${first.to.x.toFixed(0)}, ${first.to.y.toFixed(0)}) → (${second.to.x.toFixed(0)}, ` +
              `${second.to.y.toFixed(0)}) px, translate ${JSON.stringify(t0)} → ${JSON.stringify(t1)}; ` +
              `the light left (${went.x.toFixed(0)}, ${went.y.toFixed(0)}) [${went.pixels} px] and ` +
              `arrived at (${arrived.x.toFixed(0)}, ${arrived.y.toFixed(0)}) [${arrived.pixels} px]: ` +
              `${moved.toFixed(0)} px along the ${length.toFixed(0)} px drag`);
  assert.ok(arrived.pixels > 200 && went.pixels > 200, `${arrived.pixels}, ${went.pixels} px`);
  assert.ok(moved > 0.4 * length, `the patch moved ${moved} px along a ${length} px drag`);
  // Reset puts it back where the scene has it.
  await browser.afterNewFrame(page, () => page.locator('details.emitter button', { hasText: 'Reset' }).click());
  await browser.settled(page);
  assert.deepEqual(await emitterState(), {});
  const back = await page.evaluate(() => window.relightStudio.emitterOnScreen(0));
  assert.ok(Math.hypot(back.x - first.from.x, back.y - first.from.y) < 1, JSON.stringify(back));
});

test('no page errors or console errors', () => {
  assert.deepEqual(studio.problems, []);
});
