// The offline report page (swarmdesign report's report.html) built from report_fixture.json: the
// bundle is built as for the server, the page assembled as the C++ side does, opened from
// file:// in headless chromium. It must draw every plot, table and design, log no error and ask
// for nothing but files. Also: an unfinished experiment shows its banner and says why there is no
// Friedman test; a Friedman test that rejects shows its critical difference.
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdirSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { fileURLToPath } from 'node:url';
import { SCREENSHOTS, launchBrowser } from './helpers.mjs';
import { assembleReportHtml, checkReport } from './report_page.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
const fixture = JSON.parse(readFileSync(path.join(here, 'report_fixture.json'), 'utf8'));

let tmp;
let webRoot;
let browser;

before(async () => {
  tmp = mkdtempSync(path.join(os.tmpdir(), 'sd-report-'));
  webRoot = process.env.SWARMDESIGN_WEB_ROOT || path.join(tmp, 'web-root');
  if (!process.env.SWARMDESIGN_WEB_ROOT) {
    execFileSync(process.execPath, [path.join(here, '..', 'build.mjs'), '--outdir', webRoot], { stdio: 'ignore', timeout: 60000 });
  }
  mkdirSync(SCREENSHOTS, { recursive: true });
  browser = await launchBrowser();
});

after(async () => {
  if (browser) await browser.close();
  if (tmp) rmSync(tmp, { recursive: true, force: true });
});

async function open(data, name) {
  const html = path.join(tmp, `${name}.html`);
  writeFileSync(html, assembleReportHtml(webRoot, data));
  const page = await browser.newPage({ viewport: { width: 1100, height: 900 } });
  try {
    const result = await checkReport(page, html, path.join(SCREENSHOTS, `${name}.png`));
    const texts = await page.evaluate(() => ({
      banner: document.querySelector('[data-testid="state-banner"]')?.textContent ?? null,
      friedmanMissing: document.querySelector('[data-testid="friedman-missing"]')?.textContent ?? null,
      wilcoxon: document.querySelector('[data-testid="wilcoxon"]')?.textContent ?? '',
      friedman: document.querySelector('[data-testid="friedman"]')?.textContent ?? '',
      ranksCaption: document.querySelector('.plot-ranks')?.closest('figure')?.querySelector('figcaption')?.textContent ?? '',
      title: document.title,
    }));
    return { ...result, ...texts };
  } finally {
    await page.close();
  }
}

/// Offline: every request is the page itself or data the page made (data:, blob:).
function assertOffline(requests) {
  const away = requests.filter((url) => !/^(file|data|blob):/.test(url));
  assert.deepEqual(away, [], `the report asked the network for ${away.join(', ')}`);
}

test('the fixture report draws every plot, table and design, offline and without errors', { timeout: 120000 }, async () => {
  const r = await open(fixture, 'report-fixture');
  assert.deepEqual(r.errors, []);
  assert.deepEqual(r.problems, []);
  assertOffline(r.requests);
  // 2 box plots (one per mission) + 1 Friedman mean ranks + 10 heat maps (five flavours used by the
  // combined condition, behaviours and conditions each) + 1 architecture bars + 2 convergence plots.
  assert.equal(r.plots, 16);
  // missions, conditions, Wilcoxon, Friedman, architectures, cost.
  assert.equal(r.tables, 6);
  // 2 missions × 2 conditions × (best, median): all FSMs or behaviour trees.
  assert.equal(r.drawings, 8);
  assert.equal(r.banner, null, 'a finished experiment has no banner');
  assert.equal(r.friedmanMissing, null);
  assert.match(r.title, /validation/);
});

test('an unfinished experiment shows its banner; without Friedman the page says why', { timeout: 120000 }, async () => {
  // The experiment as it was after the aac designs: one mission, so no Friedman test yet.
  const data = structuredClone(fixture);
  data.experiment = { ...data.experiment, state: 'interrupted', designs_done: 6, finished_at: null };
  const onAac = (row) => row.mission === 'aac';
  for (const key of ['designs', 'boxes', 'wilcoxon', 'architectures', 'wall_time', 'typical']) data[key] = data[key].filter(onAac);
  data.module_frequency = data.module_frequency.filter((row) => row.mission === 'aac');
  data.friedman = null;
  // A significant difference, to see it marked (3 designs against 3 cannot give one).
  Object.assign(data.wilcoxon[0], { p_value: 0.012, better: 'b' });
  // A mission description that would end the data's <script> were "</" not escaped.
  data.missions[0].description = 'aggregation </script><script>window.__broken = true</script>';
  const r = await open(data, 'report-unfinished');
  assert.deepEqual(r.errors, []);
  assertOffline(r.requests);
  assert.match(r.banner, /interrupted — 6 of 12 designs done/);
  assert.match(r.friedmanMissing, /at least two missions/);
  assert.match(r.wilcoxon, /0\.012 \*/);
  assert.equal(r.drawings, 4);
  // 2 box plots (foraging's empty, saying so) + 10 heat maps (aac's combined designs used all five
  // flavours) + 1 architecture bars + 2 convergence plots; no Friedman ranks.
  assert.equal(r.plots, 15);
  assert.equal(r.tables, 5);
});

test('a Friedman test that rejects shows the critical difference around the mean ranks', { timeout: 120000 }, async () => {
  const data = structuredClone(fixture);
  Object.assign(data.friedman, {
    statistic: 6.5, p_value: 0.011, critical_difference: 0.42,
    expected_ranks: [{ condition: 'alone', rank: 1.8 }, { condition: 'combined', rank: 1.2 }],
  });
  const r = await open(data, 'report-friedman');
  assert.deepEqual(r.errors, []);
  assert.equal(r.plots, 16);
  assert.match(r.friedman, /0\.011 \*/);
  assert.match(r.ranksCaption, /half the critical difference \(0\.42\)/);
});
