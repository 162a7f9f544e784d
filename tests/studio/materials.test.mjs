// Live material edits in the studio (issue 13), in a real browser (Debian's Chromium through
// playwright-core) against a real `relight serve` on a small room of its own: a 4 × 2.8 × 4 m
// grey room, a light panel "panel" (albedo 0.8) on its back wall, one downlight, and floor
// sensors in front of the panel. A node WebSocket client on the same server sees what every
// client sees. A click on the panel opens its Material panel; picking a dark blue there edits
// the state's materials.panel live: the server answers with an approximate frame ("final":
// false, the edit's light reflected once) and then the final one, and the floor in front of the
// panel gets darker (less light bounced off it), the final frame darker still than the first;
// roughness from the panel reaches the state; Reset returns the scene's light. Made metal, the
// panel is shaded toward the eye (RLGV after the studio's `view`): its vertices show their own
// luminance, not ρ/π E, and it changes when the camera moves.
import test from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';

import * as browser from './browser_support.mjs';
import { decodeFrame, mean, relightBinary } from './studio_support.mjs';

const kScene = {
  materials: { room: { albedo: [0.5, 0.5, 0.5] }, panel: { albedo: [0.8, 0.8, 0.8] } },
  geometry: [
    { type: 'box', min: [0, 0, 0], max: [4, 2.8, 4], normals: 'inward', material: 'room' },
    { type: 'quad', corner: [0.5, 0.3, 0.01], u: [3, 0, 0], v: [0, 2.2, 0], material: 'panel' },
  ],
  luminaires: [{ name: 'down', position: [2, 2.75, 1.2],
                 distribution: { type: 'cosine_power', candela: 800, exponent: 1 } }],
  sensors: [{ name: 'near panel', grid: { corner: [0.8, 0.01, 0.1], u: [2.4, 0, 0], v: [0, 0, 0.8],
                                          nu: 4, nv: 2 } }],
  cameras: [{ name: 'facing the panel', eye: [2, 1.4, 3.9], target: [2, 1.4, 0], fov_deg: 50 }],
  precompute: { max_edge: 0.3, gather_rays: 64, sensor_gather_rays: 256, sh_order: 4 },
};

let dir, session, studio, page, watcher;

test.before(async () => {
  dir = fs.mkdtempSync(path.join(os.tmpdir(), 'relight-materials-'));
  const scene = path.join(dir, 'panel-room.json');
  const rlt = path.join(dir, 'panel-room.rlt');
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
const floorLux = (frame) => mean(Array.from(frame.sensors));

// The next state message and the frame after it (the watcher sees every frame).
async function nextStateAndFrame() {
  const state = await watcher.nextJson('state');
  const frame = decodeFrame((await watcher.next((m) => m.binary && m.tag === 'RLFR')).data);
  assert.equal(frame.frame, state.frame);
  return { state, frame };
}

test('the hello lists the materials with their reflectance keys', async () => {
  const hello = await watcher.nextJson('hello');
  const panel = hello.materials.find((m) => m.name === 'panel');
  assert.deepEqual(panel, { name: 'panel', albedo: [0.8, 0.8, 0.8], glossy: false, metallic: 0,
                            roughness: 1, portal: null });
});

test('a click on the panel opens its material; a new colour is live, approximate then final', async () => {
  // The scene's light first (the watcher's first frame).
  const first = decodeFrame((await watcher.next((m) => m.binary && m.tag === 'RLFR')).data);
  const before = floorLux(first);
  const box = await page.locator('#viewport').boundingBox();
  await page.mouse.click(box.x + box.width / 2, box.y + box.height / 2);
  await testid('material-name').waitFor();
  assert.equal(await testid('material-name').innerText(), 'panel');

  await testid('material-color').fill('#102080');  // a dark blue
  const approximate = await nextStateAndFrame();
  assert.equal(approximate.state.final, false);
  const albedo = approximate.state.state.materials.panel.albedo;
  assert.ok(albedo[2] > 0.2 && albedo[0] < 0.01, `albedo ${albedo}`);
  const final = await nextStateAndFrame();
  assert.equal(final.state.final, true);
  assert.deepEqual(final.state.state, approximate.state.state);
  sceneLux = before;
  const [b, a, f] = [before, floorLux(approximate.frame), floorLux(final.frame)];
  console.log(`floor before ${b.toFixed(2)} lx, approximate ${a.toFixed(2)} lx, final ${f.toFixed(2)} lx`);
  assert.ok(a < 0.97 * b, `the first frame shows the darker panel: ${a} vs ${b}`);
  assert.ok(f < a, `bounced further, darker still: ${f} vs ${a}`);
  await page.waitForFunction(() => window.relightStudio.lastState?.final === true);
  assert.equal(await testid('frame-quality').innerText(), '');
});

let sceneLux;  // the floor's light under the scene's own materials

test('roughness from the panel reaches the state; Reset returns the scene', async () => {
  await testid('material-roughness-value').fill('0.3');
  await testid('material-roughness-value').press('Enter');
  await page.waitForFunction(() => window.relightStudio.state().materials?.panel?.roughness === 0.3);
  await testid('material-reset').click();
  await page.waitForFunction(() => window.relightStudio.state().materials === undefined);
  // The reset's final frame is the scene's light again.
  let shown;
  do shown = await nextStateAndFrame(); while (!(shown.state.final && !shown.state.state.materials));
  assert.deepEqual(shown.state.state, {});
  const back = floorLux(shown.frame);
  assert.ok(Math.abs(back - sceneLux) < 1e-4 * sceneLux, `after Reset ${back} lx, the scene ${sceneLux} lx`);
});

// The luminance the page shows at each of the last RLGV's vertices, and that view.
async function glossyShown() {
  return page.evaluate(() => {
    const api = window.relightStudio;
    const g = api.lastGlossyView;
    const y = (rgb) => 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2];
    return { view: g, shown: g.vertices.map((v) => y(api.shownRadiance(v))) };
  });
}

test('a metal panel is shaded toward the eye, and its look follows the camera', async () => {
  // Satin metal: the downlight's highlight spreads over several of the panel's vertices.
  await page.evaluate(() => window.relightStudio.setState({
    materials: { panel: { albedo: [0.9, 0.9, 0.9], metallic: 1, roughness: 0.4 } } }));
  // The final frame of the edit, then the glossy view for it.
  await page.waitForFunction(() => {
    const api = window.relightStudio;
    return api.lastState?.final === true && api.state().materials?.panel?.metallic === 1 &&
           api.lastGlossyView?.frame === api.lastState.frame && api.lastGlossyView.count > 0;
  });
  const facing = await glossyShown();
  const eye = facing.view.eye;
  assert.ok(Math.abs(eye[2] - 3.9) < 1e-3, `shaded for the preset's eye: ${eye}`);
  assert.ok(Math.min(...facing.shown) > 0, 'every glossy vertex shows light');

  // The camera moves up and to the side: a new view, a new look (seen from the preset the
  // downlight's mirror image lies on the panel's upper middle; from the side, above it).
  await page.evaluate(() => {
    const api = window.relightStudio;
    api.camera.position.set(0.6, 2.3, 1.2);
    api.camera.lookAt(2, 1.4, 0);
    api.camera.updateMatrixWorld();
    api.requestRender();
  });
  await page.waitForFunction(() => Math.abs(window.relightStudio.lastGlossyView.eye[0] - 0.6) < 1e-3);
  const side = await glossyShown();
  assert.deepEqual(side.view.vertices, facing.view.vertices);
  const change = mean(facing.shown.map((a, i) => Math.abs(a - side.shown[i]) / Math.max(a, side.shown[i])));
  const brightest = (s) => Math.max(...s.shown);
  console.log(`metal panel: ${facing.view.count} glossy vertices; brightest ${brightest(facing).toFixed(1)} ` +
              `cd/m² facing, ${brightest(side).toFixed(1)} from the side; per vertex ${(100 * change).toFixed(0)} % apart; ` +
              `server ${side.view.serverMs.toFixed(1)} ms`);
  assert.ok(change > 0.1, `the look follows the eye: ${change}`);
  assert.deepEqual(await page.evaluate(() => window.relightStudio.clientErrors), []);
});

test('the reflectance box shows the colour\'s Y in % and scales the colour to a typed one', async () => {
  const albedo = () => page.evaluate(() => window.relightStudio.state().materials?.panel?.albedo);
  const type = async (percent) => {
    await testid('material-reflectance').fill(String(percent));
    await testid('material-reflectance').press('Enter');
  };
  const y = (c) => 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
  await page.evaluate(() => window.relightStudio.setState({ materials: { panel: { albedo: [0.6, 0.3, 0.1] } } }));
  await page.waitForFunction(() => document.querySelector('[data-testid="material-reflectance"]').value === '34.9');
  await type(50);
  await page.waitForFunction(() => {
    const c = window.relightStudio.state().materials?.panel?.albedo;
    return c && Math.abs(0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2] - 0.5) < 1e-3;
  });
  let c = await albedo();
  assert.ok(Math.abs(c[0] / c[1] - 2) < 1e-3 && Math.abs(c[1] / c[2] - 3) < 1e-2, `the hue kept: ${c}`);
  // More than the colour can reflect: as far as its red channel reaches 1.
  await type(90);
  await page.waitForFunction(() => window.relightStudio.state().materials?.panel?.albedo?.[0] === 1);
  c = await albedo();
  assert.ok(Math.abs(y(c) - 0.582) < 2e-3, `capped at Y ${y(c)}`);
  await page.waitForFunction(() => document.querySelector('[data-testid="material-reflectance"]').value === '58.2');
});
