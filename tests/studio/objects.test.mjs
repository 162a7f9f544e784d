// Movable objects in the studio (issue 12), in a real browser (Debian's Chromium through
// playwright-core) against a real `relight serve` on a small room of its own: a 4 × 2.8 × 4 m
// grey room lit by one cosine downlight at the ceiling's centre, and a tall red box "cabinet"
// (0.3 × 1.8 × 0.8 m) standing on the floor left of the light. A node WebSocket client on the
// same server sees what every client sees (the state is shared): the hello lists the object,
// RLOB carries its box as the scene places it, and each frame carries its vertices' light
// (L = ρ·E/π) after the sensors. In the page: the Objects panel; dragging the box across the
// floor moves it (the state's translate follows the pointer), frames keep arriving during the
// drag, and its shadow on the floor moves with it (the frames' floor vertices: dark where it
// now stands in the light's way, bright again where it was); a click on it reads its surface;
// hiding it removes it and its shadow; R, Shift+R and the slider turn it, and the server's
// picks see it turned.
import test from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';

import * as browser from './browser_support.mjs';
import { connect, decodeFrame, decodeObjects, geometryPositions, relightBinary, startServer,
         stopServer } from './studio_support.mjs';

const kBoxMin = [1.05, 0, 1.6], kBoxMax = [1.35, 1.8, 2.4];
const kPivot = kBoxMin.map((v, k) => (v + kBoxMax[k]) / 2); // [1.2, 0.9, 2]
const kAlbedo = [0.8, 0.15, 0.1];
const kScene = {
  materials: { wall: { albedo: [0.5, 0.5, 0.5] }, red: { albedo: kAlbedo } },
  geometry: [{ type: 'box', min: [0, 0, 0], max: [4, 2.8, 4], normals: 'inward', material: 'wall' }],
  luminaires: [{ name: 'down', position: [2, 2.75, 2],
                 distribution: { type: 'cosine_power', candela: 800, exponent: 1 } }],
  objects: [{ name: 'cabinet', geometry: [{ type: 'box', min: kBoxMin, max: kBoxMax, material: 'red' }] }],
  cameras: [{ name: 'above', eye: [2, 2.5, 3.9], target: [2, 0, 1.6], fov_deg: 75 }],
  precompute: { max_edge: 0.2, gather_rays: 32, sh_order: 4 },
};
// Where the drag takes the cabinet: mirrored about the light, x = 2.8.
const kMove = [1.6, 0, 0];
// Floor regions (at z = 2 ± 0.2) the light cannot reach past the cabinet: left of it where the
// scene puts it, right of it where the drag takes it.
const kLeft = [0.15, 0.85], kRight = [3.15, 3.85];

let dir, server, studio, page, hello, watcher, floor;
let latest = null; // the watcher's latest decoded frame

test.before(async () => {
  dir = fs.mkdtempSync(path.join(os.tmpdir(), 'relight-objects-'));
  const scene = path.join(dir, 'object-room.json');
  const rlt = path.join(dir, 'object-room.rlt');
  fs.writeFileSync(scene, JSON.stringify(kScene, null, 2));
  execFileSync(relightBinary, ['precompute', scene, '-o', rlt, '--no-progress'], { stdio: 'pipe' });
  server = await startServer([], { scene: rlt });
  studio = await browser.openStudio(server.url);
  page = studio.page;
  // A fixed exposure, so that the red box's pixels compare before and after.
  await page.locator('#auto-exposure').uncheck();
  await page.locator('#exposure').fill('6.5');
});

test.after(async () => {
  watcher?.close();
  await studio?.close();
  if (server) assert.equal(await stopServer(server), 0, server.stderr());
  if (dir) fs.rmSync(dir, { recursive: true, force: true });
});

const testid = (id) => page.locator(`[data-testid="${id}"]`);
const objectState = () => page.evaluate(() => window.relightStudio.state().objects?.cabinet ?? {});
const luminance = (c) => 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
const mean = (v) => v.reduce((a, b) => a + b, 0) / v.length;

// The watcher's frame that shows the page's latest state (the page has drawn it), or the
// first frame before any state was sent.
async function shownFrame() {
  const sent = await page.evaluate(() => window.relightStudio.store.latestSeq !== null);
  if (sent) await browser.settled(page);
  const number = await page.evaluate(() => window.relightStudio.lastState?.frame ?? window.relightStudio.lastFrameNumber);
  if (latest?.frame >= number) return latest;
  const m = await watcher.next((x) => x.binary && x.tag === 'RLFR' && x.data.readUInt32LE(4) >= number);
  latest = decodeFrame(m.data);
  return latest;
}

// Mean illuminance (lx) of the floor vertices at z = 2 ± 0.2 with x in [lo, hi].
function floorLux(frame, [lo, hi]) {
  const values = floor.filter((f) => f.x >= lo && f.x <= hi).map((f) => frame.illuminance[f.v]);
  assert.ok(values.length >= 4, `${values.length} floor vertices in x ∈ [${lo}, ${hi}]`);
  return mean(values);
}

// Centroid and count of the viewport's red pixels (the cabinet: R > 1.6 G + 8, R > 40; the grey
// room has R = G).
const redPixels = () => browser.pixels(page).then(() => page.evaluate(() => {
  const canvas = document.getElementById('viewport');
  const copy = document.createElement('canvas');
  copy.width = canvas.width;
  copy.height = canvas.height;
  const ctx = copy.getContext('2d');
  ctx.drawImage(canvas, 0, 0);
  const { data } = ctx.getImageData(0, 0, copy.width, copy.height);
  const scale = canvas.width / canvas.clientWidth;
  let x = 0, y = 0, n = 0;
  for (let i = 0; i < data.length / 4; ++i) {
    if (data[4 * i] > 40 && data[4 * i] > 1.6 * data[4 * i + 1] + 8) {
      x += i % copy.width;
      y += Math.floor(i / copy.width);
      ++n;
    }
  }
  return { x: x / n / scale, y: y / n / scale, pixels: n };
}));

test('the hello, RLOB and the frames carry the object', async () => {
  watcher = await connect(server.ws);
  hello = await watcher.nextJson('hello');
  assert.equal(hello.objects.length, 1);
  const o = hello.objects[0];
  assert.equal(o.name, 'cabinet');
  o.pivot.forEach((v, k) => assert.ok(Math.abs(v - kPivot[k]) < 1e-6, `pivot ${o.pivot}`));
  const size = 0.5 * Math.hypot(...kBoxMax.map((v, k) => v - kBoxMin[k]));
  assert.ok(Math.abs(o.size - size) < 1e-6, `size ${o.size} vs ${size}`);
  const geometry = await watcher.next();
  assert.equal(geometry.tag, 'RLGE');
  const positions = geometryPositions(geometry.data);
  floor = [];
  for (let v = 0; v < positions.length / 3; ++v) {
    const [x, y, z] = positions.slice(3 * v, 3 * v + 3);
    if (y < 0.01 && Math.abs(z - 2) <= 0.2) floor.push({ v, x });
  }
  // The box as the scene places it: every vertex on its surface, its 8 corners among them.
  const rlobMessage = await watcher.next();
  assert.equal(rlobMessage.tag, 'RLOB');
  const rlob = decodeObjects(rlobMessage.data);
  assert.equal(rlob.version, 1);
  assert.equal(rlob.objects.length, 1);
  const box = rlob.objects[0];
  assert.equal(box.vertices, o.vertices);
  assert.equal(box.triangles, o.triangles);
  const f32 = (x) => Math.fround(x);
  const corners = new Set();
  for (let v = 0; v < box.vertices; ++v) {
    const p = box.positions.slice(3 * v, 3 * v + 3);
    let extremes = 0;
    p.forEach((x, k) => {
      assert.ok(x >= f32(kBoxMin[k]) && x <= f32(kBoxMax[k]), `vertex ${v} at ${p}`);
      extremes += x === f32(kBoxMin[k]) || x === f32(kBoxMax[k]) ? 1 : 0;
    });
    assert.ok(extremes >= 1, `vertex ${v} at ${p} is inside the box`);
    if (extremes === 3) corners.add(p.join(','));
    box.albedo.slice(3 * v, 3 * v + 3).forEach((a, k) => assert.equal(a, f32(kAlbedo[k])));
  }
  assert.equal(corners.size, 8);
  assert.ok(box.indices.every((i) => i < box.vertices));
  // The first frame: the object's vertices after the sensors, L = ρ·E/π per channel (the
  // frame's illuminance is Y of E = π·L/ρ).
  const frameMessage = await watcher.next();
  assert.equal(frameMessage.tag, 'RLFR');
  const frame = decodeFrame(frameMessage.data);
  latest = frame;
  assert.equal(frameMessage.data.length, 24 + 8 * hello.vertices + 8 * o.vertices);
  assert.equal(frame.objectVertices, o.vertices);
  let top = 0;
  for (let v = 0; v < o.vertices; ++v) {
    const L = [0, 1, 2].map((c) => frame.objectRadiance[3 * v + c]);
    const E = frame.objectIlluminance[v];
    const fromL = luminance(L.map((l, c) => (Math.PI * l) / kAlbedo[c]));
    assert.ok(Math.abs(fromL - E) <= 2e-3 * E + 1e-3, `vertex ${v}: Y(πL/ρ) = ${fromL}, E = ${E}`);
    if (box.positions[3 * v + 1] === f32(kBoxMax[1])) top = Math.max(top, E);
  }
  // The top is 0.95 m under the 800 cd downlight: well over 100 lx.
  assert.ok(top > 100, `the cabinet's top gets ${top} lx`);
  // A pick straight down onto the top reads the cabinet, with the frame's light there.
  watcher.send({ type: 'pick', seq: 1, origin: [kPivot[0], 2.7, kPivot[2]], direction: [0, -1, 0] });
  const pick = await watcher.nextJson('pick');
  assert.equal(pick.object, 'cabinet');
  assert.equal(pick.material, null);
  assert.ok(Math.abs(pick.point[1] - kBoxMax[1]) < 1e-4, `pick at ${pick.point}`);
  assert.ok(pick.normal[1] > 0.999);
  assert.ok(pick.illuminance > 100 && pick.illuminance <= top * 1.001, `pick ${pick.illuminance} lx, top ${top}`);
  // The page lists it with its controls.
  assert.equal(await page.locator('details.object').count(), 1);
  assert.equal(await testid('object-visible-0').isChecked(), true);
  assert.equal(await testid('object-rotate-0').getAttribute('max'), '180');
  assert.equal(await testid('object-x-0').inputValue(), '0');
});

test('dragging the cabinet moves it and its shadow; frames keep coming meanwhile', async () => {
  const before = await shownFrame();
  const leftBefore = floorLux(before, kLeft), rightBefore = floorLux(before, kRight);
  const redBefore = await redPixels();
  if (process.env.STUDIO_SHOTS) await page.screenshot({ path: `${process.env.STUDIO_SHOTS}/object-start.png` });
  const camera = () => page.evaluate(() => window.relightStudio.camera.position.toArray());
  const eye = await camera();
  const box = await page.locator('#viewport').boundingBox();
  const from = await page.evaluate(() => window.relightStudio.objectOnScreen(0));
  const to = await page.evaluate((p) => window.relightStudio.project(p), [kPivot[0] + kMove[0], 0, kPivot[2]]);
  assert.ok(from && to, `from ${JSON.stringify(from)} to ${JSON.stringify(to)}`);
  const received0 = await page.evaluate(() => window.relightStudio.framesReceived);
  const down = performance.now();
  await page.mouse.move(box.x + from.x, box.y + from.y);
  await page.mouse.down();
  const steps = 30;
  for (let k = 1; k <= steps; ++k) {
    const t = k / steps;
    await page.mouse.move(box.x + from.x + t * (to.x - from.x), box.y + from.y + t * (to.y - from.y));
    await new Promise((r) => setTimeout(r, 40));
  }
  const up = performance.now();
  await page.mouse.up();
  await browser.settled(page);
  // What the watcher saw during the drag: states with the cabinet further and further right,
  // and their frames.
  const seen = watcher.queue.filter((m) => m.at >= down && m.at <= up);
  const after = await shownFrame();
  const received = (await page.evaluate(() => window.relightStudio.framesReceived)) - received0;
  const translate = (await objectState()).translate;
  const framesDuring = seen.filter((m) => m.binary && m.tag === 'RLFR').length;
  const xs = seen.filter((m) => !m.binary && m.json.type === 'state').map((m) => m.json.state.objects?.cabinet?.translate?.[0] ?? 0);
  const leftAfter = floorLux(after, kLeft), rightAfter = floorLux(after, kRight);
  const redAfter = await redPixels();
  if (process.env.STUDIO_SHOTS) await page.screenshot({ path: `${process.env.STUDIO_SHOTS}/object-moved.png` });
  const drag = { x: to.x - from.x, y: to.y - from.y };
  const length = Math.hypot(drag.x, drag.y);
  const redMoved = ((redAfter.x - redBefore.x) * drag.x + (redAfter.y - redBefore.y) * drag.y) / length;
  console.log(`object drag: (${from.x.toFixed(0)}, ${from.y.toFixed(0)}) → (${to.x.toFixed(0)}, ` +
              `${to.y.toFixed(0)}) px in ${(up - down).toFixed(0)} ms; translate ${JSON.stringify(translate)}; ` +
              `${framesDuring} frames and ${xs.length} states reached another client during the drag, ` +
              `${received} frames this page; floor left of the start ${leftBefore.toFixed(1)} → ` +
              `${leftAfter.toFixed(1)} lx, right of the end ${rightBefore.toFixed(1)} → ${rightAfter.toFixed(1)} lx; ` +
              `red pixels ${redBefore.pixels} at (${redBefore.x.toFixed(0)}, ${redBefore.y.toFixed(0)}) → ` +
              `${redAfter.pixels} at (${redAfter.x.toFixed(0)}, ${redAfter.y.toFixed(0)}): ${redMoved.toFixed(0)} px along the drag`);
  // The state follows the pointer in the plane of the cabinet's base.
  assert.ok(translate && translate.every((v, k) => Math.abs(v - kMove[k]) < 0.05), `translate ${translate}`);
  // The panel shows the move.
  assert.equal(Number(await testid('object-x-0').inputValue()), translate[0]);
  assert.equal(Number(await testid('object-z-0').inputValue()), translate[2]);
  // The press was the cabinet's: the camera stayed and nothing was probed.
  assert.deepEqual(await camera(), eye);
  assert.equal(await page.locator('#probe').isHidden(), true);
  // Frames kept coming while the pointer moved, for states moving right.
  assert.ok(framesDuring >= 3, `${framesDuring} frames during the drag`);
  assert.ok(xs.length >= 3 && xs.every((x, k) => k === 0 || x >= xs[k - 1]), `states' x ${xs}`);
  // The shadow moved: bright again where the cabinet was in the way, dark where it now is.
  assert.ok(leftAfter > 1.5 * leftBefore, `left of the start: ${leftBefore} → ${leftAfter} lx`);
  assert.ok(rightAfter < rightBefore / 1.5, `right of the end: ${rightBefore} → ${rightAfter} lx`);
  // The cabinet is drawn where it went.
  assert.ok(redBefore.pixels > 500 && redAfter.pixels > 500, `${redBefore.pixels}, ${redAfter.pixels} red px`);
  assert.ok(redMoved > 0.5 * length, `the red box moved ${redMoved} px along a ${length} px drag`);
});

test('a click on the cabinet reads its surface', async () => {
  const box = await page.locator('#viewport').boundingBox();
  const at = await page.evaluate(() => window.relightStudio.objectOnScreen(0));
  await page.mouse.click(box.x + at.x, box.y + at.y);
  await page.locator('#probe').waitFor({ state: 'visible' });
  assert.match(await page.locator('#probe').innerText(), /object “cabinet”/);
  assert.equal(await page.locator('details.object.selected').count(), 1);
  await page.keyboard.press('Escape');
});

test('hiding the cabinet removes it and its shadow', async () => {
  const shown = await shownFrame();
  await browser.afterNewFrame(page, () => testid('object-visible-0').uncheck());
  const hidden = await shownFrame();
  assert.equal((await objectState()).visible, false);
  const red = await redPixels();
  const right = [floorLux(shown, kRight), floorLux(hidden, kRight)];
  console.log(`object hidden: floor right of it ${right[0].toFixed(1)} → ${right[1].toFixed(1)} lx, ` +
              `${red.pixels} red pixels left`);
  assert.ok(right[1] > 1.5 * right[0], `right of the cabinet: ${right}`);
  assert.ok(hidden.objectIlluminance.every((e) => e === 0), 'a hidden object is dark');
  assert.ok(red.pixels < 50, `${red.pixels} red pixels`);
  await browser.afterNewFrame(page, () => testid('object-visible-0').check());
  await browser.settled(page);
  assert.equal((await objectState()).visible, undefined);
});

test('R, Shift+R and the slider turn the cabinet; the server places it turned', async () => {
  // Selected from its panel block (a press there), then the keys go to the view.
  await page.locator('details.object p.hint').last().click();
  assert.equal(await page.locator('details.object.selected').count(), 1);
  await page.locator('#viewport').focus();
  await page.keyboard.press('r');
  await browser.settled(page);
  assert.equal((await objectState()).rotate_deg, 15);
  await page.keyboard.press('Shift+R');
  await browser.settled(page);
  assert.equal((await objectState()).rotate_deg, undefined);
  await browser.afterNewFrame(page, () => testid('object-rotate-0').fill('90'));
  await browser.settled(page);
  assert.equal((await objectState()).rotate_deg, 90);
  // Turned a quarter: the 0.3 × 0.8 m footprint now lies along x, in the view and at the server.
  const extent = await page.evaluate(() => {
    const mesh = window.relightStudio.objects.items[0].mesh;
    const b = mesh.geometry.boundingBox.clone().applyMatrix4(mesh.matrixWorld);
    return [b.max.x - b.min.x, b.max.z - b.min.z];
  });
  assert.ok(Math.abs(extent[0] - 0.8) < 1e-3 && Math.abs(extent[1] - 0.3) < 1e-3, `extent ${extent}`);
  const centre = [kPivot[0] + kMove[0], kPivot[2] + kMove[2]];
  watcher.send({ type: 'pick', seq: 2, origin: [centre[0] + 0.3, 2.7, centre[1]], direction: [0, -1, 0] });
  const pick = await watcher.nextJson('pick');
  assert.equal(pick.object, 'cabinet', JSON.stringify(pick));
  assert.ok(Math.abs(pick.point[1] - kBoxMax[1]) < 1e-4);
  await browser.afterNewFrame(page, () => page.locator('details.object button', { hasText: 'Reset' }).click());
  await browser.settled(page);
  assert.deepEqual(await objectState(), {});
});

test('the cabinet made metal is shaded toward the eye: RLGV lists its vertices after the room vertices', async () => {
  await page.evaluate((a) => window.relightStudio.setState({
    materials: { red: { albedo: a, metallic: 1, roughness: 0.3 } } }), kAlbedo);
  await page.waitForFunction(() => {
    const api = window.relightStudio;
    return api.lastState?.final === true && api.state().materials?.red?.metallic === 1 &&
           api.lastGlossyView?.frame === api.lastState.frame && api.lastGlossyView.count > 0;
  });
  const seen = await page.evaluate(() => {
    const api = window.relightStudio;
    const V = api.viewer.geometry.vertexCount;
    const g = api.lastGlossyView;
    const mine = g.vertices.filter((v) => v >= V);
    return { count: g.count, objectVertices: mine.length, total: api.objects.items[0].o.vertices,
             shown: mine.map((v) => api.objectRadiance(v - V)),
             frame: mine.map((v) => api.objectRadiance(v - V, true)) };
  });
  assert.equal(seen.count, seen.objectVertices, 'only the cabinet is glossy');
  assert.ok(seen.objectVertices > 0.3 * seen.total, `${seen.objectVertices} of ${seen.total} cabinet vertices face the eye`);
  const apart = mean(seen.shown.map((s, i) => Math.abs(luminance(s) - luminance(seen.frame[i])) /
                                         Math.max(luminance(s), luminance(seen.frame[i]), 1e-6)));
  console.log(`metal cabinet: ${seen.objectVertices} of ${seen.total} vertices shaded toward the eye; ` +
              `${(100 * apart).toFixed(0)} % apart from the frame's diffuse radiance per vertex`);
  assert.ok(apart > 0.05, `the view's radiance replaced the frame's: ${apart}`);
  assert.ok(seen.shown.every((s) => s.every(Number.isFinite)));
  await browser.afterNewFrame(page, () => page.evaluate(() => window.relightStudio.setState({})));
  await browser.settled(page);
});

test('no page errors or console errors', () => {
  assert.deepEqual(studio.problems, []);
});
