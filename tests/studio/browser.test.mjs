// The studio in a real browser (issue: browser tests in `make test`): Debian's Chromium
// driven by playwright-core against a real `relight serve` on the demo room. The page loads
// and draws; moving the dimmers brightens the pixels; aiming the wall washer by clicking two
// wall points moves its bright spot towards each point; the false-colour view shows its
// legend with units; a malformed message gets an error and the server still answers. The
// median latency from a state change to the new frame on screen is measured and printed.
import test from 'node:test';
import assert from 'node:assert/strict';

import * as browser from './browser_support.mjs';
import { connect, startServer, stopServer } from './studio_support.mjs';

let server, studio, page, hello;

test.before(async () => {
  server = await startServer();
  const probe = await connect(server.ws);  // the scene's names, as the page gets them
  hello = await probe.nextJson('hello');
  probe.close();
  studio = await browser.openStudio(server.url);
  page = studio.page;
});

test.after(async () => {
  await studio?.close();
  if (server) assert.equal(await stopServer(server), 0, server.stderr());
});

// The shared measurements (browser_support.mjs) on this page.
const pixels = () => browser.pixels(page);
const keepPixels = (name) => browser.keepPixels(page, name);
const brighterCentroid = (a, b) => browser.brighterCentroid(page, a, b);
const afterNewFrame = (action) => browser.afterNewFrame(page, action);

async function setRange(testId, value) {
  await afterNewFrame(() => page.locator(`[data-testid="${testId}"]`).fill(String(value)));
}


test('the page loads the demo room and draws it', async () => {
  const p = await pixels();
  assert.ok(p.mean > 5, `mean pixel value ${p.mean}`);
  assert.ok(await page.locator('#camera-preset option').count() >= 2);
});

test('moving the dimmers brightens the pixels; latency is measured', async () => {
  await page.locator('#auto-exposure').uncheck();
  const count = hello.luminaires.length;
  assert.ok(count >= 1);
  // Daylight off by state, so only the luminaires light the room.
  await afterNewFrame(() => page.evaluate((portals) => {
    const s = window.relightStudio.state();
    s.portals = Object.fromEntries(portals.map(
      (p) => [p.name, { environment: { type: 'uniform', luminance: 0 } }]));
    window.relightStudio.setState(s);
  }, hello.portals));
  for (let i = 0; i < count; ++i) await setRange(`dimmer-${i}`, 10);
  const dim = await pixels();
  for (let i = 0; i < count; ++i) await setRange(`dimmer-${i}`, 100);
  const bright = await pixels();
  assert.ok(bright.mean > dim.mean * 1.5, `mean ${dim.mean} → ${bright.mean}`);
  // Latency: 20 more dimmer moves, each waiting for its frame on screen.
  const start = await page.evaluate(() => window.relightStudio.latencies.length);
  for (let k = 0; k < 20; ++k) await setRange('dimmer-0', k % 2 ? 100 : 50);
  const latencies = (await page.evaluate(() => window.relightStudio.latencies)).slice(start);
  const sorted = [...latencies].sort((a, b) => a - b);
  const median = sorted[Math.floor(sorted.length / 2)];
  console.log(`latency: state change → frame on screen, ${sorted.length} changes: median ` +
              `${median.toFixed(1)} ms, min ${sorted[0].toFixed(1)} ms, max ${sorted.at(-1).toFixed(1)} ms ` +
              `(pixels: mean display value ${dim.mean.toFixed(1)} at dimmer 10 %, ` +
              `${bright.mean.toFixed(1)} at 100 %)`);
  assert.ok(sorted.length >= 10);
  assert.ok(median < 1000, `median latency ${median} ms`);
});

test('clicking a wall aims the wall washer there and its bright spot moves', async () => {
  const names = hello.luminaires.map((l) => l.name);
  const washer = names.findIndex((n) => /wall washer/.test(n));
  assert.ok(washer >= 0, names.join(', '));
  // Only the wall washer on, at full output, daylight off.
  await afterNewFrame(() => page.evaluate(([w, names, portals]) => {
    const api = window.relightStudio;
    const s = api.state();
    s.luminaires = Object.fromEntries(names.map(
      (name, i) => [name, i === w ? { on: true, dimmer: 1 } : { on: false }]));
    s.portals = Object.fromEntries(portals.map(
      (p) => [p.name, { environment: { type: 'uniform', luminance: 0 } }]));
    api.setState(s);
  }, [washer, names, hello.portals]));
  // A fixed exposure, so that two images compare pixel by pixel.
  await page.locator('#auto-exposure').uncheck();
  await page.locator('#exposure').fill('5');
  const p0 = await pixels();
  // Wall points: canvas pixels whose pick hits a vertical surface at mid height.
  const walls = [];
  for (const fx of [0.1, 0.25, 0.4, 0.55, 0.7, 0.85]) {
    const x = Math.round(fx * p0.cssWidth), y = Math.round(0.4 * p0.cssHeight);
    const hit = await page.evaluate(([x, y]) => window.relightStudio.pick(x, y), [x, y]);
    if (hit.hit && Math.abs(hit.normal[1]) < 0.1 && hit.point[1] > 0.5 && hit.point[1] < 2.2) {
      walls.push({ x, y, point: hit.point });
    }
  }
  assert.ok(walls.length >= 2, `wall points found: ${JSON.stringify(walls)}`);
  const targets = [walls[0], walls.at(-1)];
  for (const [k, t] of targets.entries()) {
    await page.locator(`[data-testid="aim-${washer}"]`).click();
    const box = await page.locator('#viewport').boundingBox();  // pick() takes canvas pixels
    await afterNewFrame(() => page.mouse.click(box.x + t.x, box.y + t.y));
    const target = await page.evaluate((n) => window.relightStudio.state().luminaires[n].target, names[washer]);
    for (let c = 0; c < 3; ++c) assert.ok(Math.abs(target[c] - t.point[c]) < 0.05, `target ${target} vs ${t.point}`);
    await pixels();
    if (process.env.STUDIO_SHOTS) await page.screenshot({ path: `${process.env.STUDIO_SHOTS}/aim-${k}.png` });
    await keepPixels(`aim${k}`);
  }
  // Where the light arrived (aim 1 brighter than aim 0) and where it left.
  const arrived = await brighterCentroid('aim1', 'aim0');
  const left = await brighterCentroid('aim0', 'aim1');
  console.log(`aim: clicks at (${targets.map((t) => `${t.x}, ${t.y}`).join('), (')}); the light ` +
              `left (${left.x.toFixed(0)}, ${left.y.toFixed(0)}) [${left.pixels} px] and arrived at ` +
              `(${arrived.x.toFixed(0)}, ${arrived.y.toFixed(0)}) [${arrived.pixels} px]`);
  const dist = (p, t) => Math.hypot(p.x - t.x, p.y - t.y);
  assert.ok(arrived.pixels > 100 && left.pixels > 100);
  assert.ok(dist(arrived, targets[1]) < dist(arrived, targets[0]), 'the spot arrived at the second click');
  assert.ok(dist(left, targets[0]) < dist(left, targets[1]), 'the spot left the first click');
});

test('false colour shows a legend with units, tone-mapped view hides it', async () => {
  await page.locator('#view-mode').selectOption('false-lux');
  await page.waitForFunction(() => getComputedStyle(document.getElementById('legend')).display !== 'none');
  const legend = await page.locator('#legend').innerText();
  assert.match(legend, /lx/);
  assert.ok((legend.match(/\d/g) || []).length >= 3, legend);
  await page.locator('#view-mode').selectOption('false-luminance');
  assert.match(await page.locator('#legend').innerText(), /cd\/m²|cd\/m2/);
  await page.locator('#view-mode').selectOption('tonemapped');
  await page.waitForFunction(() => getComputedStyle(document.getElementById('legend')).display === 'none');
});

test('a malformed message gets an error reply and the server still answers', async () => {
  const before = await page.evaluate(() => ({ errors: window.relightStudio.errors.length,
                                              pongs: window.relightStudio.pongs }));
  await page.evaluate(() => window.relightStudio.sendRaw('{"type":"state","state":{"luminaires":'));
  await page.waitForFunction((n) => window.relightStudio.errors.length > n, before.errors);
  await page.evaluate(() => window.relightStudio.send({ type: 'ping', seq: 1 }));
  await page.waitForFunction((n) => window.relightStudio.pongs > n, before.pongs);
  await setRange('dimmer-0', 42);  // and still relights
});

test('no page errors or console errors', () => {
  assert.deepEqual(studio.problems.filter((p) => !/Server: /.test(p)), []);
});
