// A captured map in the Windows panel (issue 14), in a real browser against a real `relight
// serve` on the demo room: node writes two fisheye brackets of a uniform 2000 cd/m²
// surround as 8-bit PNGs (equidistant 190°, three exposures two stops apart, a 1/2.2 gamma),
// `relight capture` turns them into a map calibrated by the surround's horizontal illuminance
// (π · 2000 lx), and typing its path into the window's map form lights the work plane as the
// uniform 2000 cd/m² environment does (within 3 %); no page or console error on the way.
import test from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import zlib from 'node:zlib';

import * as browser from './browser_support.mjs';
import { mean, nextStateAndFrame, relightBinary } from './studio_support.mjs';

const kLuminance = 2000;

// An 8-bit RGB PNG (filter 0 on every row).
function png(width, height, rgb) {
  const chunk = (type, data) => {
    const length = Buffer.alloc(4);
    length.writeUInt32BE(data.length);
    const body = Buffer.concat([Buffer.from(type, 'latin1'), data]);
    const crc = Buffer.alloc(4);
    crc.writeUInt32BE(zlib.crc32(body));
    return Buffer.concat([length, body, crc]);
  };
  const header = Buffer.alloc(13);
  header.writeUInt32BE(width, 0);
  header.writeUInt32BE(height, 4);
  header.set([8, 2, 0, 0, 0], 8);
  const raw = Buffer.alloc((3 * width + 1) * height);
  for (let y = 0; y < height; ++y) {
    raw[y * (3 * width + 1)] = 0;
    rgb.copy(raw, y * (3 * width + 1) + 1, 3 * width * y, 3 * width * (y + 1));
  }
  return Buffer.concat([Buffer.from([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]),
    chunk('IHDR', header), chunk('IDAT', zlib.deflateSync(raw)), chunk('IEND', Buffer.alloc(0))]);
}

// One shot of a view: the lit disc of radius r at (cx, cy), black outside, value
// 255 · (x)^(1/2.2) for exposure x (the surround's luminance × gain × time).
function shot(width, height, x) {
  const cx = width / 2 + 7.5, cy = height / 2 - 4.5, r = 0.45 * height;
  const z = Math.round(255 * Math.min(1, x) ** (1 / 2.2));
  const rgb = Buffer.alloc(3 * width * height);
  for (let py = 0; py < height; ++py) {
    for (let px = 0; px < width; ++px) {
      if (Math.hypot(px + 0.5 - cx, py + 0.5 - cy) <= r) rgb.fill(z, 3 * (py * width + px), 3 * (py * width + px) + 3);
    }
  }
  return png(width, height, rgb);
}

let session, studio, page, watcher, dir;

test.before(async () => {
  session = await browser.openSession();
  ({ watcher, studio, page } = session);
  dir = fs.mkdtempSync(path.join(os.tmpdir(), 'relight-capture-'));
});

test.after(async () => {
  await session?.close();
  if (dir) fs.rmSync(dir, { recursive: true, force: true });
});

const testid = (id) => page.locator(`[data-testid="${id}"]`);

const nextFrame = () => nextStateAndFrame(watcher);

test('a captured map typed into the Windows panel lights the room like the surround it shows', async () => {
  const times = [1 / 1000, 1 / 250, 1 / 62.5];
  const gain = 0.5 / (kLuminance * times[1]);
  const files = { front: [], back: [] };
  for (const view of ['front', 'back']) {
    times.forEach((t, k) => {
      const file = path.join(dir, `${view}_${k}.png`);
      fs.writeFileSync(file, shot(480, 360, kLuminance * gain * t));
      files[view].push(file);
    });
  }
  const map = path.join(dir, 'room.exr');
  const run = spawnSync(relightBinary, ['capture', '--front', ...files.front, '--back', ...files.back,
    '-o', map, '--width', '256', '--exposure-times', [...times, ...times].join(','),
    '--illuminance', String(Math.PI * kLuminance)], { encoding: 'utf8' });
  assert.equal(run.status, 0, run.stderr);

  const hello = await watcher.nextJson('hello');
  const name = hello.portals[0].name;
  const lit = async (change, done) => {
    await change();
    for (;;) {
      const next = await nextFrame();
      if (done(next.state.state.portals?.[name]?.environment)) return mean(Array.from(next.frame.sensors));
    }
  };
  const uniform = await lit(
    () => page.evaluate(([n, l]) => {
      const s = window.relightStudio.state();
      s.portals = { ...(s.portals ?? {}), [n]: { ...(s.portals?.[n] ?? {}), environment: { type: 'uniform', luminance: l } } };
      window.relightStudio.setState(s);
    }, [name, kLuminance]),
    (env) => env?.type === 'uniform' && env.luminance === kLuminance);
  await testid('env-type-0').selectOption('map');
  const captured = await lit(async () => {
    await testid('env-file-0').fill(map);
    await testid('env-file-0').press('Enter');
  }, (env) => env?.type === 'map' && env.file === map);
  console.log(`work plane mean: uniform ${uniform.toFixed(1)} lx, captured map ${captured.toFixed(1)} lx`);
  assert.ok(Math.abs(captured / uniform - 1) < 0.03, `${captured} vs ${uniform}`);
  assert.deepEqual(studio.problems, []);
});
