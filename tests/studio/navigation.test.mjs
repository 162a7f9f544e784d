// Navigation and the defaults a designer expects (docs/studio.md, "Moving around"), in Chromium
// on the demo room: orbiting from the overview keeps the eye inside the room (it turns about the
// room's centre, not the wall the camera looks at); a double-click orbits about the point
// clicked (the eye brought in where the turn would take it through a wall); walking keeps the eye at eye height (1.6 m, editable) and stops at walls; the
// readings' labels are off until asked; the dimmer is in %; the colour temperature slider is
// logarithmic over 1800–10000 K and its box takes any value the state allows; the plan view
// looks straight down in false colour, cut 1.2 m over the work plane, with isolines; an
// elevation looks level at a wall with the room's near half cut away.
import test from 'node:test';
import assert from 'node:assert/strict';

import { openSession, sceneHello } from './browser_support.mjs';

let session, page, hello;

test.before(async () => {
  session = await openSession();
  page = session.page;
  hello = await sceneHello(session.server);
});

test.after(async () => {
  await session?.close();
});

const testid = (id) => page.locator(`[data-testid="${id}"]`);
const eye = () => page.evaluate(() => window.relightStudio.camera.position.toArray());
const inside = (p, margin) => [0, 1, 2].every((k) => p[k] > hello.bounds.min[k] + margin && p[k] < hello.bounds.max[k] - margin);

async function drag(dx, dy) {
  const box = await page.locator('#viewport').boundingBox();
  const x = box.x + box.width / 2, y = box.y + box.height / 2;
  await page.mouse.move(x, y);
  await page.mouse.down();
  for (let k = 1; k <= 10; ++k) await page.mouse.move(x + (dx * k) / 10, y + (dy * k) / 10);
  await page.mouse.up();
}

test('orbiting from the overview turns about the room\'s centre and keeps the eye inside', async () => {
  await page.locator('#camera-preset').selectOption({ label: 'overview' });
  assert.ok(inside(await eye(), 0), `the overview's eye is in the room: ${await eye()}`);
  for (const [dx, dy] of [[400, 0], [-800, 0], [0, 150]]) {
    await drag(dx, dy);
    const p = await eye();
    assert.ok(inside(p, 0), `after a drag of (${dx}, ${dy}) px the eye is still in the room: ${p.map((v) => v.toFixed(2))}`);
  }
});

test('a double-click on a surface orbits about that point', async () => {
  await page.locator('#camera-preset').selectOption({ label: 'overview' });
  const box = await page.locator('#viewport').boundingBox();
  await page.mouse.dblclick(box.x + box.width * 0.3, box.y + box.height * 0.75);
  const centre = await page.evaluate(() => window.relightStudio.orbitCentre());
  assert.ok(inside(centre, -0.01), `a point of the room: ${centre}`);
  const before = await eye();
  await drag(200, 0);
  const after = await eye();
  const { looking, centreAfter } = await page.evaluate(() => {
    const api = window.relightStudio;
    const d = api.camera.getWorldDirection(new api.camera.position.constructor());
    return { looking: d.toArray(), centreAfter: api.orbitCentre() };
  });
  assert.deepEqual(centreAfter, centre, 'the drag turned about the point double-clicked');
  const toCentre = centre.map((v, k) => v - after[k]);
  const n = Math.hypot(...toCentre);
  const cos = toCentre.reduce((a, v, k) => a + (v / n) * looking[k], 0);
  assert.ok(cos > 0.9999, `the camera looks at it: cos ${cos}`);
  assert.ok(Math.hypot(...after.map((v, k) => v - before[k])) > 0.2, 'and it moved');
  assert.ok(inside(after, 0), `inside the room: ${after}`);
});

test('walking keeps the eye at eye height and stops at a wall', async () => {
  await page.locator('#camera-preset').selectOption({ label: 'overview' });
  await page.locator('#nav-mode').selectOption('walk');
  const floor = hello.bounds.min[1];
  let p = await eye();
  assert.ok(Math.abs(p[1] - (floor + 1.6)) < 0.01, `eye at 1.6 m above the floor: ${p[1]}`);
  await testid('eye-height').fill('1.2');
  await testid('eye-height').press('Enter');
  p = await eye();
  assert.ok(Math.abs(p[1] - (floor + 1.2)) < 0.01, `eye at 1.2 m: ${p[1]}`);
  // Straight ahead (towards the overview's wall) for 6 s at 1.4 m/s: far more than the room.
  await page.locator('#viewport').focus();
  await page.keyboard.down('KeyW');
  await page.waitForTimeout(6000);
  await page.keyboard.up('KeyW');
  p = await eye();
  assert.ok(inside(p, 0.15), `stopped short of the wall: ${p.map((v) => v.toFixed(2))}`);
  assert.ok(Math.abs(p[1] - (floor + 1.2)) < 0.01, `still at eye height: ${p[1]}`);
  await page.locator('#nav-mode').selectOption('orbit');
});

test('readings are off until asked; dimmer in %; colour temperature on a log scale', async () => {
  assert.equal(await page.locator('#show-sensor-values').isChecked(), false);
  const name = hello.luminaires[0].name;
  await testid('dimmer-0-value').fill('50');
  await testid('dimmer-0-value').press('Enter');
  await page.waitForFunction((n) => window.relightStudio.state().luminaires?.[n]?.dimmer === 0.5, name);
  await page.evaluate((n) => window.relightStudio.setState({ luminaires: { [n]: { cct_kelvin: 3000 } } }), name);
  const slider = testid('cct-0');
  await slider.waitFor();
  assert.equal(Number(await slider.getAttribute('min')), Math.log(1800));
  assert.equal(Number(await slider.getAttribute('max')), Math.log(10000));
  await slider.fill(String((Math.log(1800) + Math.log(10000)) / 2));  // the middle: √(1800 · 10000)
  await page.waitForFunction((n) => window.relightStudio.state().luminaires?.[n]?.cct_kelvin === 4243, name);
  await testid('cct-0-value').fill('20000');  // beyond the slider, within the state's range
  await testid('cct-0-value').press('Enter');
  await page.waitForFunction((n) => window.relightStudio.state().luminaires?.[n]?.cct_kelvin === 20000, name);
});

test('the plan view looks down in false colour with the ceiling cut away and isolines drawn; an elevation looks at a wall', async () => {
  await page.locator('#camera-preset').selectOption({ label: 'plan (from above, false colour, isolines)' });
  await page.waitForFunction(() => window.relightStudio.isolineSegments() > 0);
  const view = await page.evaluate(() => {
    const api = window.relightStudio, c = api.camera;
    return { dir: c.getWorldDirection(new c.position.constructor()).toArray(), y: c.position.y, near: c.near,
             mode: document.getElementById('view-mode').value, segments: api.isolineSegments() };
  });
  assert.ok(view.dir[1] < -0.999, `straight down: ${view.dir}`);
  assert.equal(view.mode, 'false-lux');
  // The cut 1.2 m over the work plane: below the ceiling, above the tables.
  const workPlane = Math.min(...hello.sensors.flatMap((s) => s.points.map((p) => p[1])));
  assert.ok(Math.abs(view.y - view.near - (workPlane + 1.2)) < 1e-6, `cut at ${view.y - view.near}`);
  assert.ok(view.y - view.near < hello.bounds.max[1], 'below the ceiling');
  console.log(`plan view: ${view.segments} isoline segments drawn`);
  // An elevation: level towards the north (−z) wall, the room's nearer half cut away.
  await page.locator('#camera-preset').selectOption({ label: 'elevation: north wall' });
  const north = await page.evaluate(() => {
    const c = window.relightStudio.camera;
    return { dir: c.getWorldDirection(new c.position.constructor()).toArray(), z: c.position.z, near: c.near,
             isolines: window.relightStudio.isolineSegments() };
  });
  assert.ok(north.dir[2] < -0.999, `towards −z: ${north.dir}`);
  const centreZ = (hello.bounds.min[2] + hello.bounds.max[2]) / 2;
  assert.ok(Math.abs(north.z - north.near - centreZ) < 1e-6, `cut through the centre: ${north.z - north.near}`);
  // Back to a scene camera: the tone-mapped picture and the perspective's own clipping.
  await page.locator('#camera-preset').selectOption({ label: 'overview' });
  const back = await page.evaluate(() => ({ near: window.relightStudio.camera.near, mode: document.getElementById('view-mode').value }));
  assert.equal(back.mode, 'tonemapped');
  assert.ok(back.near < 0.1, `near ${back.near}`);
});

test('no page errors or console errors', () => {
  assert.deepEqual(session.studio.problems.filter((p) => !/Server: /.test(p)), []);
});
