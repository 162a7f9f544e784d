// A Perez sky from the Windows panel (issue 17), in a real browser against a real `relight
// serve` on the demo room: choosing "Perez sky (weather)" for a window puts a perez environment
// into the state with a sun by place and time (no "no sun": the model needs one); the form has
// its weather rows; an overcast record with three times the diffuse irradiance makes the work
// plane about three times brighter; no page or console error on the way.
import test from 'node:test';
import assert from 'node:assert/strict';

import * as browser from './browser_support.mjs';
import { mean, nextStateAndFrame } from './studio_support.mjs';

let session, studio, page, watcher;

test.before(async () => {
  session = await browser.openSession();
  ({ watcher, studio, page } = session);
});

test.after(async () => {
  await session?.close();
});

const testid = (id) => page.locator(`[data-testid="${id}"]`);

const nextFrame = () => nextStateAndFrame(watcher);

test('a window lit by a Perez sky from the Windows panel', async () => {
  const hello = await watcher.nextJson('hello');
  const name = hello.portals[0].name;
  await testid('env-type-0').selectOption('perez');
  let { state, frame } = await nextFrame();
  while (state.state.portals?.[name]?.environment?.type !== 'perez') ({ state, frame } = await nextFrame());
  const env = state.state.portals[name].environment;
  assert.equal(env.direct_normal_irradiance, 600);
  assert.equal(env.diffuse_horizontal_irradiance, 120);
  assert.ok(env.sun.datetime, JSON.stringify(env));
  const modes = await testid('sun-mode-0').locator('option').allTextContents();
  assert.deepEqual(modes, ['by place and local time', 'by azimuth and altitude']);
  for (const label of ['Direct', 'Diffuse', 'Dew point', 'Albedo']) {
    assert.ok(await page.getByText(label, { exact: true }).first().isVisible(), label);
  }
  // Overcast records through the page's own state API: no beam, then three times the diffuse
  // irradiance — the work plane about three times brighter (the efficacy changes with the sky's
  // brightness Δ, so not exactly).
  const record = async (direct, diffuse) => {
    await page.evaluate(([n, i, d]) => {
      const s = window.relightStudio.state();
      Object.assign(s.portals[n].environment, { direct_normal_irradiance: i, diffuse_horizontal_irradiance: d });
      window.relightStudio.setState(s);
    }, [name, direct, diffuse]);
    for (;;) {
      const next = await nextFrame();
      const e = next.state.state.portals[name].environment;
      if (e.direct_normal_irradiance === direct && e.diffuse_horizontal_irradiance === diffuse) {
        return mean(Array.from(next.frame.sensors));
      }
    }
  };
  const dull = await record(0, 120);
  const bright = await record(0, 360);
  console.log(`work plane mean ${dull.toFixed(1)} -> ${bright.toFixed(1)} lx`);
  assert.ok(bright > 2 * dull && bright < 3.5 * dull, `${dull} -> ${bright}`);
  assert.deepEqual(studio.problems, []);
});
