// The annual panel (issue 17), in a real browser against a real `relight serve` on the demo room:
// a weather file chosen in the panel and Run give, after progress messages, a table per sensor
// set whose sDA300, ASE and mean DA300 are those `relight annual` prints for the same file (the
// studio runs the same computation on the state shown, daylight alone), per-point DA300 equal to
// the CLI's CSV within 1e-6, sensor points coloured by the DA300 map, and no page or console
// error. A malformed weather file gets the server's error naming the line, and the panel can
// run again. The weather file is written here (none is packaged): ten June days alternating
// clear, intermediate and overcast.
import test from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';

import * as browser from './browser_support.mjs';
import { relightBinary, startServer, stopServer, studioScene } from './studio_support.mjs';

// An EnergyPlus weather file of ten June days at 48.14° N, 11.58° E, UTC+1: the 35 fields of a
// record, the irradiance a function of the day (the sun's height is the server's business;
// hours with the sun down are skipped whatever they say).
function syntheticEpw() {
  const lines = [
    'LOCATION,Testville,ST,Nowhere,synthetic,000000,48.14,11.58,1,520.0',
    'DESIGN CONDITIONS,0',
    'TYPICAL/EXTREME PERIODS,0',
    'GROUND TEMPERATURES,0',
    'HOLIDAYS/DAYLIGHT SAVINGS,No,0,0,0',
    'COMMENTS 1,written by a test',
    'COMMENTS 2,',
    'DATA PERIODS,1,1,Data,Thursday, 6/ 1, 6/10',
  ];
  for (let day = 1; day <= 10; day++) {
    const [direct, diffuse] = [[300, 25], [60, 35], [0, 45]][day % 3];
    for (let hour = 1; hour <= 24; hour++) {
      const daylight = hour >= 6 && hour <= 21;
      const d = daylight ? direct : 0, f = daylight ? diffuse : 0;
      lines.push(`2023,6,${day},${hour},60,?9?9?9?9E0?9?9?9?9?9?9?9?9?9?9?9?9?9?9?9*9*9?9?9?9,18.0,9.0,70,95000,0,0,300,${d + f},${d},${f},0,0,0,0,180,2.0,5,5,20.0,77777,9,999999999,1.5,0.1,0,88,0.2,0,0`);
    }
  }
  return lines.join('\n') + '\n';
}

let server, studio, page, dir;

test.before(async () => {
  dir = fs.mkdtempSync(path.join(os.tmpdir(), 'relight-annual-'));
  server = await startServer();
  studio = await browser.openStudio(server.url);
  page = studio.page;
});

test.after(async () => {
  await studio?.close();
  if (server) assert.equal(await stopServer(server), 0, server.stderr());
  if (dir) fs.rmSync(dir, { recursive: true, force: true });
});

const testid = (id) => page.locator(`[data-testid="${id}"]`);
// Early and late hours too: a dull week's work plane then crosses 300 lx.
const kOccupied = '05:00-21:00';

function cliAnnual(epw) {
  const csv = path.join(dir, 'cli.csv');
  const r = spawnSync(relightBinary, ['annual', studioScene, '--weather', epw, '--occupied', kOccupied, '-o', csv], { encoding: 'utf8' });
  assert.equal(r.status, 0, r.stderr);
  // "work plane: 414 points  sDA300/50% 100.0%  ASE1000,250h 0.0%  mean DA300 94.4%  EN 17037 …"
  const sets = new Map();
  for (const line of r.stdout.split('\n')) {
    const m = line.match(/^(.*): (\d+) points {2}sDA300\/50% ([\d.]+)% {2}ASE1000,250h ([\d.]+)% {2}mean DA300 ([\d.]+)% {2}EN 17037 daylight provision: (\w+)/);
    if (m) sets.set(m[1], { points: +m[2], sda300: +m[3], ase: +m[4], mean: +m[5], en17037: m[6] });
  }
  const rows = fs.readFileSync(csv, 'utf8').trim().split('\n').slice(1).map((l) => l.split(','));
  return { sets, da300: rows.map((r) => +r[5]), stdout: r.stdout };
}

test('a year of daylight from the annual panel equals relight annual', async () => {
  const text = syntheticEpw();
  const epw = path.join(dir, 'june.epw');
  fs.writeFileSync(epw, text);
  const cli = cliAnnual(epw);
  assert.ok(cli.sets.size > 0, cli.stdout);

  await page.locator('#section-annual > summary').click();
  await testid('annual-occupied').fill(kOccupied);
  await testid('annual-weather').setInputFiles({ name: 'june.epw', mimeType: 'text/plain', buffer: Buffer.from(text) });
  assert.equal(await testid('annual-run').isDisabled(), false);
  await testid('annual-run').click();
  await page.waitForFunction(() => window.relightStudio.annual != null, null, { timeout: 300000 });
  const result = await page.evaluate(() => window.relightStudio.annual);
  assert.ok(result.hours > 100, JSON.stringify(result).slice(0, 300));
  assert.equal(result.occupied, kOccupied);
  assert.ok(result.progress_messages > 0, 'no annual_progress before the result');

  const table = testid('annual-table');
  let offset = 0;
  for (const s of result.sets) {
    const expected = cli.sets.get(s.name);
    assert.ok(expected, `the CLI printed no line for ${s.name}`);
    assert.equal(s.points, expected.points);
    assert.ok(Math.abs(100 * s.sda300 - expected.sda300) <= 0.051, `${s.name} sDA ${s.sda300} vs ${expected.sda300}`);
    assert.ok(Math.abs(100 * s.ase - expected.ase) <= 0.051, `${s.name} ASE`);
    assert.ok(Math.abs(100 * s.mean_da300 - expected.mean) <= 0.051, `${s.name} mean DA`);
    assert.equal(s.en17037, expected.en17037);
    const cells = await table.locator(`tr[data-set="${s.name}"] td`).allTextContents();
    assert.equal(cells[1], `${(100 * s.sda300).toFixed(1)}%`);
    assert.equal(cells[4], s.en17037);
    s.da300.forEach((v, i) => assert.ok(Math.abs(v - cli.da300[offset + i]) <= 1e-6, `${s.name}[${i}] DA ${v} vs ${cli.da300[offset + i]}`));
    offset += s.points;
  }
  console.log(`annual panel: ${result.hours} hours in ${result.seconds.toFixed(1)} s; ${JSON.stringify([...cli.sets])}`);

  // The DA300 map colours the points: its legend is shown and the view draws (no errors).
  assert.equal(await testid('annual-map').inputValue(), 'da300');
  await page.locator('.annual-ramp').waitFor();
  await page.screenshot({ path: path.join(dir, 'annual.png') });

  // A malformed file: the server's error names the weather line; the panel can run again.
  await testid('annual-weather').setInputFiles({ name: 'bad.epw', mimeType: 'text/plain', buffer: Buffer.from(text.replace('2023,6,3,12,60', '2023,6,3,twelve,60')) });
  const errors = await page.evaluate(() => window.relightStudio.errors.length);
  await testid('annual-run').click();
  await page.waitForFunction((n) => window.relightStudio.errors.length > n, errors);
  const message = await page.evaluate(() => window.relightStudio.errors.at(-1));
  assert.match(message, /message:\/weather:\d+:/);
  assert.equal(await testid('annual-progress-text').textContent(), 'failed');
  assert.equal(await testid('annual-run').isDisabled(), false);
  assert.deepEqual(studio.problems, []);
});
