// The project's site in a real browser (Debian's Chromium through playwright-core) against a
// real `relight serve` on the demo room, whose scene stands in Munich: the hello carries the
// site and the Site panel shows it; a CIE clear sky "by the sun's altitude" from the Windows
// panel puts a sun by date and time alone (at the site) into the state; moving its time from
// noon to 23:30 leaves the work plane lit by the luminaires alone (the same as the window
// tinted black), and dawn lies between; turning north by 90° from the Site panel puts the
// state's site into the next frame and changes the noon reading; no page or console error.
import test from 'node:test';
import assert from 'node:assert/strict';

import * as browser from './browser_support.mjs';
import { frameWhen, mean } from './studio_support.mjs';

let session, studio, page, watcher;

test.before(async () => {
  session = await browser.openSession();
  ({ watcher, studio, page } = session);
});

test.after(async () => {
  await session?.close();
});

const testid = (id) => page.locator(`[data-testid="${id}"]`);

// The work plane's mean once a frame shows a state for which `done(state)` holds.
const readingWhen = async (done) => mean((await frameWhen(watcher, done)).sensors);

async function setState(edit) {
  await page.evaluate((code) => {
    const s = window.relightStudio.state();
    new Function('s', code)(s);
    window.relightStudio.setState(s);
  }, edit);
}

test('the site places the suns, the sky follows the hour, north turns the sun', async () => {
  const hello = await watcher.nextJson('hello');
  assert.equal(hello.site?.latitude, 48.14, JSON.stringify(hello.site));
  const name = hello.portals[0].name;
  await page.locator('#section-site summary').click();
  assert.equal(await testid('site-latitude').inputValue(), '48.14');
  assert.equal(await testid('site-north_deg').inputValue(), '0');

  // A clear sky by the sun's altitude from the Windows panel (the demo's window shows a CIE
  // overcast sky of 10 klx).
  assert.equal(hello.portals[0].environment.type, 'cie_sky');
  await testid('sky-type-0').selectOption('12');
  await testid('sky-brightness-0').selectOption('s');
  const env = () => window.relightStudio.state();
  await readingWhen((s) => {
    const e = s.portals?.[name]?.environment;
    return e?.sky_type === 12 && e.horizontal_illuminance === undefined && e.sun?.datetime !== undefined;
  });
  const sun = (await page.evaluate(env)).portals[name].environment.sun;
  assert.equal(sun.latitude, undefined, JSON.stringify(sun)); // at the site

  const at = async (time) => {
    await setState(`s.portals['${name}'].environment.sun = { datetime: '2026-06-21T${time}' };`);
    return readingWhen((s) => s.portals[name].environment.sun?.datetime === `2026-06-21T${time}`);
  };
  const noon = await at('13:00');
  const dawn = await at('05:30');
  const night = await at('23:30');
  await setState(`s.portals['${name}'].tint = [0, 0, 0];`);
  const dark = await readingWhen((s) => s.portals[name].tint?.[0] === 0);
  await setState(`delete s.portals['${name}'].tint;`);
  await readingWhen((s) => s.portals[name].tint === undefined);
  console.log(`work plane: 13:00 ${noon.toFixed(0)} lx, 05:30 ${dawn.toFixed(0)} lx, 23:30 ${night.toFixed(1)} lx, window black ${dark.toFixed(1)} lx`);
  assert.ok(Math.abs(night - dark) <= 1e-3 * dark + 0.01, `${night} vs ${dark}`);
  assert.ok(dawn > night * 1.05 && noon > dawn * 3, `${night} ${dawn} ${noon}`);

  // North 90° from the Site panel: the state carries the whole site, and the noon sun, now in
  // the scene's west, lights the room through the south window differently.
  const noonAgain = await at('13:00');
  await testid('site-north_deg').fill('90');
  await testid('site-north_deg').press('Enter');
  await testid('site-north_deg').dispatchEvent('change');
  const turned = await readingWhen((s) => s.site?.north_deg === 90 && s.site.latitude === 48.14);
  console.log(`noon work plane: north 0° ${noonAgain.toFixed(0)} lx, north 90° ${turned.toFixed(0)} lx`);
  assert.ok(Math.abs(turned - noonAgain) > 0.05 * noonAgain, `${noonAgain} -> ${turned}`);
  assert.deepEqual(studio.problems, []);
});
