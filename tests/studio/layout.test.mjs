// Laying out luminaires in the studio, in a real browser (Debian's Chromium through
// playwright-core) against a real `relight serve --photometry DIR` on a small room of its own: a
// 4 × 2.8 × 4 m grey room with one downlight, a work-plane grid, and a catalogue folder holding a
// rotationally symmetric IES downlight and an asymmetric one (brighter toward C0). Two
// luminaires are dragged from the catalogue onto the ceiling, a 3 × 2 array is placed with the
// array tool, one luminaire is dragged along the ceiling, one is deleted and the deletion undone;
// "Save layout" downloads the state, and `relight probe --state` of that file gives the studio's
// sensor readings (within 0.1 %). The server's catalogue lists both files with their summary;
// bad uploads (truncated, oversized, binary, a path as the name) are refused with the parser's or
// the limit's message and the server keeps serving; a good upload joins every client's
// catalogue; "Export scene" returns the layout as ordinary luminaires; a movable object's drag
// stops at a wall.
import test from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';

import * as browser from './browser_support.mjs';
import { connect, relightBinary, startServer, stopServer } from './studio_support.mjs';

const kScene = {
  materials: { wall: { albedo: [0.5, 0.5, 0.5] }, oak: { albedo: [0.4, 0.3, 0.2] } },
  geometry: [{ type: 'box', min: [0, 0, 0], max: [4, 2.8, 4], normals: 'inward', material: 'wall' }],
  luminaires: [{ name: 'down', position: [2, 2.75, 2],
                 distribution: { type: 'cosine_power', candela: 300, exponent: 1 } }],
  objects: [{ name: 'chest', geometry: [{ type: 'box', min: [0.5, 0, 3.0], max: [1.1, 0.8, 3.6], material: 'oak' }] }],
  sensors: [{ name: 'work plane', grid: { corner: [0.5, 0.8, 0.5], u: [3, 0, 0], v: [0, 0, 3], nu: 4, nv: 4 } }],
  cameras: [{ name: 'up', eye: [2, 1.0, 3.8], target: [2, 2.8, 1.2], fov_deg: 80 },
            { name: 'chest', eye: [2.2, 2.6, 2.2], target: [0.8, 0, 3.4], fov_deg: 80 }],
  precompute: { max_edge: 0.3, gather_rays: 32, sh_order: 4 },
};

// IES LM-63-2002 text: `cd(c, g)` candela at horizontal angle c and vertical angle g (degrees),
// on γ 0…90 every 10° and the given C planes.
function iesText(name, cPlanes, cd) {
  const gammas = Array.from({ length: 10 }, (_, k) => 10 * k);
  const lines = ['IESNA:LM-63-2002', '[MANUFAC] relight test', `[LUMINAIRE] ${name}`, 'TILT=NONE',
    `1 -1 1 ${gammas.length} ${cPlanes.length} 1 2 0.15 0.15 0`, '1 1 18',
    gammas.join(' '), cPlanes.join(' ')];
  for (const c of cPlanes) lines.push(gammas.map((g) => cd(c, g).toFixed(2)).join(' '));
  return lines.join('\n') + '\n';
}
const kSymmetric = iesText('round downlight', [0], (c, g) => 900 * Math.cos((g * Math.PI) / 180));
const kAsymmetric = iesText('wall washer', [0, 90, 180, 270, 360],
  (c, g) => (c === 0 || c === 360 ? 1500 : c === 180 ? 300 : 700) * Math.cos((g * Math.PI) / 180));

let dir, server, studio, page, watcher;

test.before(async () => {
  dir = fs.mkdtempSync(path.join(os.tmpdir(), 'relight-layout-'));
  fs.mkdirSync(path.join(dir, 'photometry'));
  fs.writeFileSync(path.join(dir, 'photometry', 'round.ies'), kSymmetric);
  fs.writeFileSync(path.join(dir, 'photometry', 'washer.ies'), kAsymmetric);
  const scene = path.join(dir, 'layout-room.json');
  fs.writeFileSync(scene, JSON.stringify(kScene, null, 2));
  execFileSync(relightBinary, ['precompute', scene, '-o', path.join(dir, 'layout-room.rlt'), '--no-progress'], { stdio: 'pipe' });
  server = await startServer(['--photometry', path.join(dir, 'photometry')], { scene: path.join(dir, 'layout-room.rlt') });
  studio = await browser.openStudio(server.url);
  page = studio.page;
});

test.after(async () => {
  watcher?.close();
  await studio?.close();
  if (server) assert.equal(await stopServer(server), 0, server.stderr());
  if (dir) fs.rmSync(dir, { recursive: true, force: true });
});

const testid = (id) => page.locator(`[data-testid="${id}"]`);
const doc = () => page.evaluate(() => window.relightStudio.state());

// The page point of world point p (the viewport's offset added).
async function onPage(p) {
  const s = await page.evaluate((q) => window.relightStudio.project(q), p);
  assert.ok(s, `${p} is in view`);
  const box = await page.locator('#viewport').boundingBox();
  return { x: box.x + s.x, y: box.y + s.y };
}

// Waits until the page's latest state is shown in its converged frame.
async function converged() {
  await browser.settled(page);
  await page.waitForFunction(() => window.relightStudio.lastState?.final === true, null, { timeout: 30000 });
  await browser.settled(page);
}

test('the catalogue lists both files with their summary and a polar plot', async () => {
  await page.waitForFunction(() => window.relightStudio.catalogue !== null);
  const entries = await page.evaluate(() => window.relightStudio.catalogue.entries);
  assert.deepEqual(entries.map((e) => e.id), ['round.ies', 'washer.ies']);
  const washer = entries[1].summary;
  assert.equal(washer.luminaire, 'wall washer');
  assert.equal(washer.watts, 18);
  assert.ok(Math.abs(entries[1].polar.c0[0] - 1500) < 1e-6 && Math.abs(entries[1].polar.c180[0] - 300) < 1e-6);
  await page.locator('#camera-preset').selectOption({ label: 'up' });
  assert.equal(await testid('catalogue-round.ies').isVisible(), true);
});

test('two dragged from the catalogue, a 3 × 2 array, a move, a delete and its undo', async () => {
  // Two from the catalogue, dropped on the ceiling.
  for (const [id, p] of [['round.ies', [1, 2.8, 1]], ['washer.ies', [3, 2.8, 1.2]]]) {
    const at = await onPage(p);
    const box = await page.locator('#viewport').boundingBox();
    await testid(`catalogue-${id}`).dragTo(page.locator('#viewport'), { targetPosition: { x: at.x - box.x, y: at.y - box.y } });
    await page.waitForFunction((n) => Object.keys(window.relightStudio.state().luminaires ?? {}).length === n, id === 'round.ies' ? 1 : 2);
  }
  let d = await doc();
  assert.deepEqual(Object.keys(d.luminaires).sort(), ['L1', 'L2']);
  assert.deepEqual(d.luminaires.L1.aim, [0, -1, 0]);
  assert.ok(Math.abs(d.luminaires.L1.position[1] - 2.78) < 1e-3, `mounted 2 cm under the ceiling: ${d.luminaires.L1.position}`);
  assert.ok(Math.hypot(d.luminaires.L1.position[0] - 1, d.luminaires.L1.position[2] - 1) < 0.05, `where dropped: ${d.luminaires.L1.position}`);
  assert.equal(d.luminaires.L2.distribution.type, 'ies');
  assert.ok(d.luminaires.L2.distribution.file.endsWith('washer.ies'));
  await converged();

  // A 3 × 2 array of the round downlight centred on the ceiling's middle.
  await testid('catalogue-round.ies').click();
  await testid('array-rows').fill('2');
  await testid('array-cols').fill('3');
  await testid('array-sx').fill('1');
  await testid('array-sz').fill('1.2');
  await testid('array-place').click();
  const centre = await onPage([2, 2.8, 2]);
  await page.mouse.click(centre.x, centre.y);
  await page.waitForFunction(() => Object.keys(window.relightStudio.state().luminaires ?? {}).length === 8);
  d = await doc();
  const array = Object.keys(d.luminaires).filter((n) => n.startsWith('A1-')).sort();
  assert.deepEqual(array, ['A1-r1c1', 'A1-r1c2', 'A1-r1c3', 'A1-r2c1', 'A1-r2c2', 'A1-r2c3']);
  const xs = array.map((n) => d.luminaires[n].position[0]), zs = array.map((n) => d.luminaires[n].position[2]);
  assert.ok(Math.abs(Math.max(...xs) - Math.min(...xs) - 2) < 0.05 && Math.abs(Math.max(...zs) - Math.min(...zs) - 1.2) < 0.05, `spacing: ${xs} ${zs}`);
  await converged();

  // Move L1 along the ceiling by dragging its marker.
  const before = d.luminaires.L1.position;
  const from = await onPage(before);
  const to = await onPage([before[0] + 0.5, before[1], before[2] + 0.3]);
  await page.mouse.move(from.x, from.y);
  await page.mouse.down();
  for (let k = 1; k <= 5; ++k) await page.mouse.move(from.x + ((to.x - from.x) * k) / 5, from.y + ((to.y - from.y) * k) / 5);
  await page.mouse.up();
  d = await doc();
  const moved = d.luminaires.L1.position;
  assert.ok(Math.abs(moved[0] - before[0] - 0.5) < 0.05 && Math.abs(moved[2] - before[2] - 0.3) < 0.05, `moved to ${moved} from ${before}`);
  assert.equal(moved[1], before[1], 'along the ceiling');
  await converged();

  // Delete L2 (a click on its marker selects it), then undo.
  const l2 = await onPage(d.luminaires.L2.position);
  await page.mouse.click(l2.x, l2.y);
  assert.match(await testid('layout-selection').textContent(), /L2/);
  await testid('delete').click();
  d = await doc();
  assert.equal(d.luminaires.L2, undefined);
  await converged();
  await page.keyboard.press('Control+z');
  d = await doc();
  assert.ok(d.luminaires.L2, 'undo brings L2 back');
  await converged();
});

test('the saved layout, probed by the CLI, reads as the studio\'s sensors', async () => {
  const [download] = await Promise.all([page.waitForEvent('download'), testid('save-layout').click()]);
  const saved = path.join(dir, 'saved-layout.json');
  await download.saveAs(saved);
  const state = JSON.parse(fs.readFileSync(saved, 'utf8'));
  assert.equal(Object.keys(state.luminaires).length, 8);
  const csv = path.join(dir, 'probe.csv');
  execFileSync(relightBinary, ['probe', path.join(dir, 'layout-room.rlt'), '--state', saved, '-o', csv], { stdio: 'pipe' });
  const cli = fs.readFileSync(csv, 'utf8').trim().split('\n').slice(1).map((l) => Number(l.split(',')[8]));
  const shown = await page.evaluate(() => window.relightStudio.sensorReadings());
  assert.equal(cli.length, shown.length);
  let worst = 0;
  for (let k = 0; k < cli.length; ++k) {
    assert.ok(Math.abs(shown[k] - cli[k]) <= 1e-3 * cli[k] + 1e-3, `sensor ${k}: studio ${shown[k]} lx, probe ${cli[k]} lx`);
    worst = Math.max(worst, Math.abs(shown[k] - cli[k]) / cli[k]);
  }
  console.log(`studio sensors vs relight probe --state: worst ${(100 * worst).toFixed(4)} % over ${cli.length} sensors`);
  // The layout lights the room: far above the scene's one downlight alone.
  const alone = execFileSync(relightBinary, ['probe', path.join(dir, 'layout-room.rlt')], { encoding: 'utf8' });
  const eavg = (text) => Number(/Eavg ([\d.]+)/.exec(text)[1]);
  const withLayout = execFileSync(relightBinary, ['probe', path.join(dir, 'layout-room.rlt'), '--state', saved], { encoding: 'utf8' });
  assert.ok(eavg(withLayout) > 3 * eavg(alone), `${withLayout} vs ${alone}`);
});

test('Export scene returns the layout as ordinary luminaires', async () => {
  await testid('export-scene').click();
  await page.waitForFunction(() => window.relightStudio.exports > 0);
  const scene = await page.evaluate(() => window.relightStudio.layout.lastExport);
  assert.equal(scene.luminaires.length, 9);
  assert.ok(scene.luminaires.some((l) => l.name === 'A1-r2c3' && l.distribution.file.endsWith('round.ies')));
  assert.deepEqual(scene.geometry, kScene.geometry);
});

test('bad uploads are refused with their message; a good one joins every catalogue', async () => {
  watcher = await connect(server.ws);
  await watcher.nextJson('hello');
  await watcher.nextJson('catalogue');
  const refusal = async (message) => {
    watcher.send(JSON.stringify({ type: 'upload', seq: 70, ...message }));
    return (await watcher.nextJson('error')).message;
  };
  assert.match(await refusal({ name: 'cut.ies', text: kSymmetric.slice(0, 120) }), /^cut\.ies:\d+: /);
  assert.match(await refusal({ name: 'big.ies', text: kSymmetric + ' '.repeat(5 * 1024 * 1024) }), /over the upload limit of 5 MB/);
  assert.match(await refusal({ name: 'photo.ies', text: '\u0089PNG\r\n\u001a\n\u0000\u0000' }), /binary data at byte/);
  assert.match(await refusal({ name: '../../etc/passwd.ies', text: kSymmetric }), /not a path/);
  watcher.send(JSON.stringify({ type: 'ping', seq: 71 }));
  assert.equal((await watcher.nextJson('pong')).seq, 71, 'the server keeps serving');
  assert.equal(fs.existsSync(path.join(dir, 'photometry', 'uploads')), false, 'nothing stored');
  // A good upload from the page's file input.
  const file = path.join(dir, 'My Lamp.IES');
  fs.writeFileSync(file, kAsymmetric);
  await testid('upload-file').setInputFiles(file);
  await page.waitForFunction(() => window.relightStudio.uploads.length === 1);
  const entry = await page.evaluate(() => window.relightStudio.uploads[0]);
  assert.equal(entry.id, 'uploads/upload-1.ies');
  assert.equal(entry.name, 'My Lamp.IES');
  assert.equal(fs.readFileSync(path.join(dir, 'photometry', 'uploads', 'upload-1.ies'), 'utf8'), kAsymmetric);
  const listed = await watcher.nextJson('catalogue');
  assert.equal(listed.entries.length, 3);
});

test('a movable object dragged toward a wall stops at it', async () => {
  await page.locator('#camera-preset').selectOption({ label: 'chest' });
  const from = await onPage([0.8, 0.8, 3.3]);
  const to = await onPage([0.8, 0.8, 4.6]);
  await page.mouse.move(from.x, from.y);
  await page.mouse.down();
  for (let k = 1; k <= 8; ++k) await page.mouse.move(from.x + ((to.x - from.x) * k) / 8, from.y + ((to.y - from.y) * k) / 8);
  await page.mouse.up();
  const t = (await doc()).objects?.chest?.translate ?? [0, 0, 0];
  // The chest's far side (z = 3.6 + t) stops at the wall at z = 4 (within its 1 mm tolerance), not beyond it.
  assert.ok(3.6 + t[2] <= 4.0015 && 3.6 + t[2] > 3.9, `translate ${t}`);
  assert.deepEqual(studio.problems, []);
});
