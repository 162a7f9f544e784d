// `relight report` (issue 17) opened in a real browser (Debian's Chromium through
// playwright-core): the demo room's report is one self-contained page — it loads with no
// console error and no request beyond its own file, shows the illuminance table, a plan per
// sensor set with its legend and a polar plot per luminaire; its screenshot is checked for size
// and kept for a look where STUDIO_SHOTS names a folder, as the other browser tests' are.
import test from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

import { kChromiumArgs } from './browser_support.mjs';
import { relightBinary, requireStudio, studioScene } from './studio_support.mjs';

const { chromium } = requireStudio('playwright-core');

test('the report opens in Chromium with no console error and no request of its own', async () => {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'relight-report-'));
  const report = path.join(dir, 'report.html');
  execFileSync(relightBinary, ['report', studioScene, '-o', report]);
  const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'relight-chromium-'));
  const context = await chromium.launchPersistentContext(profile, {
    executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
    headless: true,
    args: kChromiumArgs,
    viewport: { width: 1000, height: 1400 },
  });
  try {
    const page = await context.newPage();
    const problems = [], requests = [];
    page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
    page.on('console', (m) => { if (m.type() === 'error') problems.push(`console: ${m.text()}`); });
    page.on('request', (r) => requests.push(r.url()));
    await page.goto(pathToFileURL(report).href);
    const shown = await page.evaluate(() => ({
      title: document.title,
      headings: [...document.querySelectorAll('h2')].map((h) => h.textContent),
      plans: document.querySelectorAll('svg.plan').length,
      cells: document.querySelectorAll('svg.plan rect').length,
      polars: document.querySelectorAll('svg.polar').length,
      rows: document.querySelectorAll('table tr').length,
    }));
    const shot = path.join(process.env.STUDIO_SHOTS ?? dir, 'report.png');
    await page.screenshot({ path: shot, fullPage: true });
    console.log(`report: ${JSON.stringify(shown)}; screenshot ${shot} (${fs.statSync(shot).size} bytes)`);
    assert.deepEqual(problems, []);
    assert.deepEqual(requests, [pathToFileURL(report).href]);
    assert.match(shown.title, /relight report/);
    assert.ok(shown.headings.includes('Illuminance'), shown.headings.join(', '));
    assert.ok(shown.headings.includes('Luminaires'), shown.headings.join(', '));
    assert.ok(shown.plans >= 1);
    assert.ok(shown.cells > 100, `${shown.cells} cells`);  // the work plane's points and the legend
    assert.ok(shown.polars >= 1);
    assert.ok(fs.statSync(shot).size > 20000);
  } finally {
    await context.close();
    fs.rmSync(profile, { recursive: true, force: true });
    fs.rmSync(dir, { recursive: true, force: true });
  }
});
