// The report of a real experiment: swarmdesign runs a small protocol (two 10-second missions,
// two conditions, three designs each) and writes its report; the page opens from file:// in
// headless chromium and must draw every plot, table and design the data calls for.
import assert from 'node:assert/strict';
import { mkdirSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { fileURLToPath } from 'node:url';
import { PASSWORD, SCREENSHOTS, cli, launchBrowser } from './helpers.mjs';
import { checkReport } from './report_page.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
const missions = path.join(here, '..', '..', 'missions');

let tmp;
let browser;

/// A catalogue mission shortened to 10 simulated seconds, as a mission file.
function shortMission(name) {
  const text = readFileSync(path.join(missions, `${name}.json`), 'utf8').replace(/"duration": *[0-9.]+/, '"duration": 10');
  const file = path.join(tmp, `${name}-short.json`);
  writeFileSync(file, text);
  return file;
}

before(async () => {
  tmp = mkdtempSync(path.join(os.tmpdir(), 'sd-report-run-'));
  mkdirSync(SCREENSHOTS, { recursive: true });
  browser = await launchBrowser();
});

after(async () => {
  if (browser) await browser.close();
  if (tmp) rmSync(tmp, { recursive: true, force: true });
});

test('the report of a real experiment opens offline with its plots, tables and designs', { timeout: 240000 }, async () => {
  const env = { ...process.env, SWARMDESIGN_HOME: path.join(tmp, 'home') };
  cli(env, ['sign-up', 'carol', '--password-stdin'], `${PASSWORD}\n`);
  cli(env, ['sign-in', 'carol', '--password-stdin'], `${PASSWORD}\n`);
  cli(env, ['new-project', 'thesis']);
  cli(env, ['select-project', 'thesis']);
  const conditions = [
    { name: 'alone', architectures: ['fsm'], flavours: ['chocolate'] },
    { name: 'trees', architectures: ['bt'], flavours: ['chocolate'] },
  ];
  const protocol = {
    name: 'small', designs: 3, assessment_seeds: 4,
    missions: [
      { mission: shortMission('aac'), budget: 1008, conditions },
      { mission: shortMission('foraging'), budget: 1008, conditions },
    ],
  };
  const file = path.join(tmp, 'small.json');
  writeFileSync(file, JSON.stringify(protocol));
  const run = cli(env, ['experiment', '--file', file, '--threads', '2'], '', 300000);
  assert.match(run, /Experiment small finished: 12 designs/);
  const out = path.join(tmp, 'report');
  const printed = cli(env, ['report', 'small', '--out', out, '--web-root', process.env.SWARMDESIGN_WEB_ROOT || path.join(here, '..', '..', 'build', 'web-root')]);
  assert.match(printed, /Friedman across missions/);

  const page = await browser.newPage({ viewport: { width: 1100, height: 900 } });
  try {
    const r = await checkReport(page, path.join(out, 'report.html'), path.join(SCREENSHOTS, 'report.png'));
    assert.deepEqual(r.errors, []);
    assert.deepEqual(r.problems, []);
    assert.deepEqual(r.requests.filter((url) => !/^(file|data|blob):/.test(url)), []);
    // 2 box plots + 1 Friedman mean ranks + 2 heat maps (Chocolate behaviours and conditions)
    // + 1 architecture bars + 2 convergence plots.
    assert.equal(r.plots, 8);
    // missions, conditions, Wilcoxon, Friedman, architectures, cost.
    assert.equal(r.tables, 6);
    // 2 missions x 2 conditions x (best, median).
    assert.equal(r.drawings, 8);
    const boxes = await page.evaluate(() => document.querySelectorAll('.plot-box').length);
    assert.equal(boxes, 2);
  } finally {
    await page.close();
  }
});
