// What the studio's browser tests share: Debian's Chromium through playwright-core (the flags
// a closed network needs), the studio page opened on a server, and measurements of the
// viewport's pixels (mean display value, centroids of the brightest pixels and of where one
// image is much brighter than another).
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';

import { connect, requireStudio, startServer, stopServer } from './studio_support.mjs';

const { chromium } = requireStudio('playwright-core');

// The flags a closed network needs (the machine's env notes): no background connections.
export const kChromiumArgs = ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic',
  '--no-first-run', '--disable-background-networking', '--disable-component-update',
  '--disable-sync'];

// Opens the studio at `url` in a fresh Chromium profile and waits until it has drawn its first
// frame. Returns {context, page, problems (page errors and console errors, collected), close}.
export async function openStudio(url, { viewport = { width: 1100, height: 700 } } = {}) {
  const profileDir = fs.mkdtempSync(path.join(os.tmpdir(), 'relight-chromium-'));
  const problems = [];
  const context = await chromium.launchPersistentContext(profileDir, {
    executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
    headless: true,
    args: kChromiumArgs,
    viewport,
  });
  const close = async () => {
    await context.close();
    fs.rmSync(profileDir, { recursive: true, force: true });
  };
  try {
    const page = await context.newPage();
    page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
    page.on('console', (m) => { if (m.type() === 'error') problems.push(`console: ${m.text()}`); });
    await page.goto(url);
    await page.evaluate(() => window.relightStudio.ready);
    return { context, page, problems, close };
  } catch (e) {
    await close();
    throw e;
  }
}

// The hello a new connection to `server` gets: the scene's names, as the page has them.
export async function sceneHello(server) {
  const c = await connect(server.ws);
  try {
    return await c.nextJson('hello');
  } finally {
    c.close();
  }
}

// A real `relight serve` (startServer's arguments), a WebSocket watcher on it and the studio in
// Chromium. Returns {server, watcher, studio, page, close}; close() takes down what was opened,
// in reverse order, and asserts that the server exits cleanly.
export async function openSession(serverArgs = [], serverOptions = {}) {
  const session = {};
  session.close = async () => {
    session.watcher?.close();
    await session.studio?.close();
    if (session.server) assert.equal(await stopServer(session.server), 0, session.server.stderr());
  };
  session.server = await startServer(serverArgs, serverOptions);
  session.watcher = await connect(session.server.ws);
  session.studio = await openStudio(session.server.url);
  session.page = session.studio.page;
  return session;
}

// Mean display value of the viewport's pixels (luminance of the 8-bit sRGB values, and per
// channel), and the centroid of its brightest 2 %. Keeps the pixels' luminance for
// keepPixels().
export async function pixels(page) {
  // Two animation frames: whatever changed has been drawn (the client renders on demand).
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  return page.evaluate(() => {
    const canvas = document.getElementById('viewport');
    const copy = document.createElement('canvas');
    copy.width = canvas.width;
    copy.height = canvas.height;
    const ctx = copy.getContext('2d');
    ctx.drawImage(canvas, 0, 0);
    const { data } = ctx.getImageData(0, 0, copy.width, copy.height);
    const n = copy.width * copy.height;
    const y = new Float32Array(n);
    let sum = 0;
    const channel = [0, 0, 0];
    for (let i = 0; i < n; ++i) {
      y[i] = 0.2126 * data[4 * i] + 0.7152 * data[4 * i + 1] + 0.0722 * data[4 * i + 2];
      sum += y[i];
      for (let c = 0; c < 3; ++c) channel[c] += data[4 * i + c];
    }
    window.__studioTestLuminance = window.__studioTestLuminance ?? {};
    window.__studioTestLuminance.last = y;
    const sorted = Float32Array.from(y).sort();
    const threshold = sorted[Math.floor(0.98 * n)];
    let cx = 0, cy = 0, count = 0;
    for (let i = 0; i < n; ++i) {
      if (y[i] >= threshold && y[i] > 0) {
        cx += i % copy.width;
        cy += Math.floor(i / copy.width);
        ++count;
      }
    }
    return { mean: sum / n, red: channel[0] / n, green: channel[1] / n, blue: channel[2] / n,
             cx: cx / count, cy: cy / count, width: copy.width,
             height: copy.height, cssWidth: canvas.clientWidth, cssHeight: canvas.clientHeight };
  });
}

// Keeps the last pixels() under `name`.
export const keepPixels = (page, name) => page.evaluate((n) => {
  window.__studioTestLuminance[n] = window.__studioTestLuminance.last;
}, name);

// Centroid (CSS pixels) of where image `a` is more than twice as bright as image `b` (and
// visibly so): where the light went when it moved from b to a.
export const brighterCentroid = (page, a, b) => page.evaluate(([a, b]) => {
  const ya = window.__studioTestLuminance[a], yb = window.__studioTestLuminance[b];
  const canvas = document.getElementById('viewport');
  const w = canvas.width, scale = canvas.width / canvas.clientWidth;
  let cx = 0, cy = 0, n = 0;
  for (let i = 0; i < ya.length; ++i) {
    if (ya[i] > 2 * yb[i] + 8) {
      cx += i % w;
      cy += Math.floor(i / w);
      ++n;
    }
  }
  return { x: cx / n / scale, y: cy / n / scale, pixels: n };
}, [a, b]);

// Runs `action` and waits until a frame newer than the current one is on screen.
export async function afterNewFrame(page, action) {
  const before = await page.evaluate(() => window.relightStudio.frames);
  await action();
  await page.waitForFunction((n) => window.relightStudio.frames > n, before, { timeout: 30000 });
}

// Waits until the state this page sent last is the one shown: the server has echoed it and
// the frame that shows it is on screen.
export async function settled(page, timeout = 30000) {
  await page.waitForFunction(() => {
    const api = window.relightStudio;
    const s = api.lastState;
    return !api.store._scheduled && s !== null && s.seq === api.store.latestSeq &&
           api.lastFrameNumber !== null && api.lastFrameNumber >= s.frame;
  }, null, { timeout });
}
