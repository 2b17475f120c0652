// The report of a real experiment: swarmdesign runs a small protocol (two 10-second missions,
// two conditions, three designs each) while run-exp serves the same home, and writes its
// report; the page opens from file:// in headless chromium and must draw every plot, table and
// design the data calls for. The Designs tab lists the experiment and links the same page,
// which the server serves under its own content security policy, with the data files it links.
import assert from 'node:assert/strict';
import { existsSync, readFileSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { fileURLToPath } from 'node:url';
import { SCREENSHOTS, cli, launchBrowser, newPage, signIn, startServer } from './helpers.mjs';
import { checkReport } from './report_page.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
const missions = path.join(here, '..', '..', 'missions');
const webRoot = process.env.SWARMDESIGN_WEB_ROOT || path.join(here, '..', '..', 'build', 'web-root');

let server;
let browser;

/// A catalogue mission shortened to 10 simulated seconds, as a mission file.
function shortMission(name) {
  const text = readFileSync(path.join(missions, `${name}.json`), 'utf8').replace(/"duration": *[0-9.]+/, '"duration": 10');
  const file = path.join(server.tmp, `${name}-short.json`);
  writeFileSync(file, text);
  return file;
}

/// Every table, plot and drawing the small protocol's data calls for.
function assertComplete(r) {
  assert.deepEqual(r.errors, []);
  assert.deepEqual(r.problems, []);
  // 2 box plots + 1 Friedman mean ranks + 2 heat maps (Chocolate behaviours and conditions)
  // + 1 architecture bars + 2 convergence plots.
  assert.equal(r.plots, 8);
  // missions, conditions, Wilcoxon, Friedman, architectures, cost.
  assert.equal(r.tables, 6);
  // 2 missions x 2 conditions x (best, median).
  assert.equal(r.drawings, 8);
}

before(async () => {
  server = await startServer({ users: [{ name: 'carol', projects: [{ name: 'thesis' }] }] });
  browser = await launchBrowser();
});

after(async () => {
  if (browser) await browser.close();
  if (server) await server.close();
});

test('the report of a real experiment opens offline and in the web app', { timeout: 300000 }, async () => {
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
  const file = path.join(server.tmp, 'small.json');
  writeFileSync(file, JSON.stringify(protocol));
  const run = cli(server.env, ['experiment', '--file', file, '--threads', '2'], '', 300000);
  assert.match(run, /Experiment small finished: 12 designs/);
  const out = path.join(server.tmp, 'report');
  const printed = cli(server.env, ['report', 'small', '--out', out, '--web-root', webRoot]);
  assert.match(printed, /Friedman across missions/);

  const offline = await newPage(browser);
  try {
    const r = await checkReport(offline, path.join(out, 'report.html'), path.join(SCREENSHOTS, 'report.png'));
    assertComplete(r);
    assert.deepEqual(r.requests.filter((url) => !/^(file|data|blob):/.test(url)), [], 'the file asks nothing of the network');
    // Its data links name the files written next to it.
    const linked = await offline.$$eval('a[data-file]', (as) => as.map((a) => a.getAttribute('href')));
    assert.equal(linked.length, 10);
    for (const name of linked) assert.ok(existsSync(path.join(out, name)), name);
  } finally {
    await offline.close();
  }

  const context = await browser.newContext({ viewport: { width: 1400, height: 900 } });
  const page = await context.newPage();
  try {
    await signIn(page, server.url, 'carol');
    await page.click('#tab-designs');
    await page.click('[data-testid="project-thesis"]');
    const item = page.locator('[data-testid="experiment-small"]');
    await item.waitFor();
    assert.match(await page.textContent('[data-testid="exp-state-small"]'), /^finished$/);
    assert.match(await page.textContent('[data-testid="exp-progress-small"]'), /^12 \/ 12 designs done$/);
    await page.screenshot({ path: path.join(SCREENSHOTS, 'report-in-app-designs.png') });
    const href = await page.getAttribute('[data-testid="report-small"]', 'href');
    assert.equal(href, '/api/projects/thesis/experiments/small/report');

    const served = await context.newPage();
    const r = await checkReport(served, new URL(href, server.url).href, path.join(SCREENSHOTS, 'report-in-app.png'));
    assertComplete(r);  // the server's policy lets the inline page run and load nothing
    assert.deepEqual(r.requests.filter((url) => !url.startsWith(new URL(href, server.url).href) && !/^(data|blob):/.test(url)), []);
    // The data files the page links download from the server, equal to those the CLI wrote.
    assert.equal(await served.locator('a[data-file]').count(), 10);
    for (const name of ['boxes.csv', 'designs.csv', 'wilcoxon.csv']) {
      const [download] = await Promise.all([served.waitForEvent('download'), served.click(`a[data-file="${name}"]`)]);
      assert.equal(readFileSync(await download.path(), 'utf8'), readFileSync(path.join(out, name), 'utf8'), name);
    }
    await served.close();
  } finally {
    await context.close();
  }
});
