// Windows show the outside (docs/studio-protocol.md "Window views RLWV"; display_shader.js): in
// Chromium on the demo room, looking at its window under the CIE overcast sky, the glass shows
// the sky above the horizon and the ground below it, as the shell the server sends (the sky at
// the horizon is L_z / 3 = 0.136 E_h, the ground ρ E_h / π = 0.064 E_h for ρ = 0.2: half as
// bright), not one mean over the pane; and the server sends the views again when the sky
// changes, not when a dimmer does.
import test from 'node:test';
import assert from 'node:assert/strict';

import { afterNewFrame, openSession, pixels, sceneHello } from './browser_support.mjs';

let session, page, hello;

test.before(async () => {
  session = await openSession();
  page = session.page;
  hello = await sceneHello(session.server);
});

test.after(async () => {
  await session?.close();
});

const overcast = (lux) => ({
  luminaires: Object.fromEntries(hello.luminaires.map((l) => [l.name, { on: false }])),
  portals: Object.fromEntries(hello.portals.map((p) => [p.name, {
    environment: { type: 'cie_sky', sky_type: 'overcast', horizontal_illuminance: lux } }])),
});

// The mean display value of the glass pixels whose line of sight rises (above) and falls
// (below) more than `slope`, over a grid of canvas points.
async function glassBrightness(slope) {
  await pixels(page);  // keeps each pixel's display value (browser_support.mjs)
  return page.evaluate((slope) => {
    const api = window.relightStudio;
    const canvas = document.getElementById('viewport');
    const y8 = window.__studioTestLuminance.last;
    const scale = canvas.width / canvas.clientWidth;
    const sums = { above: [0, 0], below: [0, 0] };
    for (let y = 4; y < canvas.clientHeight; y += 8) {
      for (let x = 4; x < canvas.clientWidth; x += 8) {
        if (api.portalAt(x, y) < 0) continue;
        const ndcY = -(y / canvas.clientHeight) * 2 + 1, ndcX = (x / canvas.clientWidth) * 2 - 1;
        const dir = new api.camera.position.constructor(ndcX, ndcY, 0.5).unproject(api.camera).sub(api.camera.position).normalize();
        const side = dir.y > slope ? 'above' : dir.y < -slope ? 'below' : null;
        if (!side) continue;
        sums[side][0] += y8[Math.round(y * scale) * canvas.width + Math.round(x * scale)];
        sums[side][1] += 1;
      }
    }
    return { above: sums.above[0] / sums.above[1], below: sums.below[0] / sums.below[1],
             counts: [sums.above[1], sums.below[1]] };
  }, slope);
}

test('the window shows the overcast sky above the horizon and the darker ground below', async () => {
  await page.waitForFunction((n) => window.relightStudio.windowViews?.portals === n, hello.portals.length);
  await page.locator('#camera-preset').selectOption({ label: 'window' });
  await page.locator('#auto-exposure').uncheck();
  await page.locator('#exposure').fill('11');
  await afterNewFrame(page, () => page.evaluate((s) => window.relightStudio.setState(s), overcast(10000)));
  await page.waitForFunction(() => window.relightStudio.windowViews && window.relightStudio.lastState?.final);
  const b = await glassBrightness(0.05);
  console.log(`window glass: mean display value ${b.above.toFixed(1)} above the horizon, ` +
              `${b.below.toFixed(1)} below (${b.counts[0]} and ${b.counts[1]} points)`);
  assert.ok(b.counts[0] > 10 && b.counts[1] > 10, `glass seen above and below: ${b.counts}`);
  assert.ok(b.above > 1.3 * b.below, `sky brighter than the ground: ${b.above} vs ${b.below}`);
});

test('the views come again when the sky changes, not when a dimmer does', async () => {
  const views = () => page.evaluate(() => window.relightStudio.windowViews.frame);
  const before = await views();
  const name = hello.luminaires[0].name;
  await afterNewFrame(page, () => page.evaluate((n) => {
    const s = window.relightStudio.state();
    s.luminaires[n] = { on: true, dimmer: 0.5 };
    window.relightStudio.setState(s);
  }, name));
  assert.equal(await views(), before, 'a dimmer leaves the windows as they were');
  await afterNewFrame(page, () => page.evaluate((s) => window.relightStudio.setState(s), overcast(20000)));
  await page.waitForFunction((f) => window.relightStudio.windowViews.frame > f, before);
});

test('no page errors or console errors', () => {
  assert.deepEqual(session.studio.problems.filter((p) => !/Server: /.test(p)), []);
});
