// Starting a design from the page's form, as a researcher would, in headless chromium against
// the real server: the Chocolate preset (--fsm --chocolate), seed 7 and a budget typed in; the
// design card says what it was started with and the best design uses only Chocolate modules in
// an FSM; the elites table's means and runs are those of `swarmdesign status --json`; the
// convergence plot's iterations are whole numbers; after the server is killed with the design
// running and started again, the design list and the state box both say "interrupted".
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';
import { cli, launchBrowser, newPage, openSignedIn, screenshotter, signIn, startServer } from './helpers.mjs';

let server;
let browser;
let page;
const errors = [];
const shot = screenshotter('design-form');

before(async () => {
  server = await startServer({ users: [{ name: 'carol', projects: [{ name: 'choc', mission: 'aac', budget: 5000 }] }] });
  browser = await launchBrowser();
  page = await newPage(browser, errors, { width: 1280, height: 800 });
  await signIn(page, server.url, 'carol');
}, { timeout: 60000 });

after(async () => {
  if (page) await page.evaluate(() => fetch('/api/projects/choc/designs/stop', { method: 'POST', headers: { 'Content-Type': 'application/json', 'X-CSRF-Token': window.__sdCsrf || '' }, body: '{}' })).catch(() => {});
  if (browser) await browser.close();
  if (server) await server.close();
});

const statusJson = () => {
  cli(server.env, ['select-project', 'choc']);
  return JSON.parse(cli(server.env, ['status', '--json', '--complete']));
};

let budget = 0;

test('the form offers the presets, every flavour with what it brings, and the minimum budget', { timeout: 30000 }, async () => {
  await page.click('#tab-designs');
  await page.waitForSelector('[data-testid="project-choc"]');
  await page.click('[data-testid="project-choc"]');
  for (const f of ['chocolate', 'tuttifrutti', 'coconut', 'maple', 'arlequin'])
    assert.ok((await page.textContent(`label:has([data-testid="flavour-${f}"])`)).length > 30, `${f} says what it brings`);
  const presets = await page.$$eval('#design-preset option', (os) => os.map((o) => o.value));
  assert.deepEqual(presets, ['all', 'chocolate', 'maple', 'tuttifrutti', 'coconut', 'arlequin', 'custom']);
  await page.waitForFunction(() => /at least \d+ runs/.test(document.getElementById('design-minimum').textContent));
  const everything = Number(/at least (\d+)/.exec(await page.textContent('#design-minimum'))[1]);
  await page.selectOption('#design-preset', 'chocolate');
  assert.equal(await page.isChecked('[data-testid="arch-fsm"]'), true);
  assert.equal(await page.isChecked('[data-testid="flavour-chocolate"]'), true);
  assert.equal(await page.isChecked('[data-testid="flavour-maple"]'), false);
  await page.waitForFunction((e) => {
    const m = /at least (\d+)/.exec(document.getElementById('design-minimum').textContent);
    return m && Number(m[1]) !== e;
  }, everything);
  const minimum = Number(/at least (\d+)/.exec(await page.textContent('#design-minimum'))[1]);
  assert.ok(minimum < everything, `a smaller space needs less: ${minimum} < ${everything}`);
  // Ticking a flavour by hand leaves the preset for "custom".
  await page.check('[data-testid="flavour-coconut"]');
  assert.equal(await page.inputValue('#design-preset'), 'custom');
  await page.uncheck('[data-testid="flavour-coconut"]');
  assert.equal(await page.inputValue('#design-preset'), 'chocolate');
  // The methods, each with its line; the minimum follows the chosen one. Back to automode.
  const methods = await page.$$eval('#design-method option', (os) => os.map((o) => o.value));
  assert.deepEqual(methods, ['automode', 'random-search', 'local-search']);
  await page.selectOption('#design-method', 'local-search');
  await page.waitForFunction(() => /local-search's minimum/.test(document.getElementById('design-minimum').textContent));
  assert.match(await page.textContent('#design-method-summary'), /local search/);
  await page.selectOption('#design-method', 'automode');
  await page.waitForFunction(() => /automode's minimum/.test(document.getElementById('design-minimum').textContent));
  budget = minimum + 100;
  await page.fill('#design-seed', '7');
  await page.fill('#design-budget', String(budget));
  await shot(page, 'form-1280');
});

test('the design runs with the chosen flavours, architecture, seed and budget', { timeout: 240000 }, async () => {
  await page.click('#design-start');
  await page.waitForFunction(() => /^Design #1:/.test(document.getElementById('design-info').textContent), null, { timeout: 20000 });
  assert.equal(await page.textContent('#design-info'), `Design #1: fsm · chocolate · seed 7 · budget ${budget} · aac`);
  assert.match(await page.textContent('[data-testid="design-1"]'), new RegExp(`fsm · chocolate · seed 7 · budget ${budget}`));
  // The first iteration's elites (the race takes a while on a shared machine).
  await page.waitForSelector('#elites tbody tr[data-testid^="elite-"]', { timeout: 200000 });
  await shot(page, 'elites-1280');
  await page.click('#design-stop');
  await page.waitForFunction(() => !/^running/.test(document.getElementById('design-state').textContent), null, { timeout: 60000 });
  const status = statusJson();
  assert.equal(status.design.seed, 7);
  assert.equal(status.design.architectures, 'fsm');
  assert.equal(status.design.flavours, 'chocolate');
  const best = status.progress.best.configuration;
  assert.match(best, /^--fsm-config /);
  const behaviours = [...best.matchAll(/--s\d+ (\d+)/g)].map((m) => Number(m[1]));
  const conditions = [...best.matchAll(/--c\d+x\d+ (\d+)/g)].map((m) => Number(m[1]));
  assert.ok(behaviours.length >= 1);
  for (const id of [...behaviours, ...conditions]) assert.ok(id >= 10 && id <= 15, `module ${id} is a Chocolate module (10-15) in ${best}`);
});

test("the elites' means and runs are those of status --json, over all their runs", { timeout: 30000 }, async () => {
  const status = statusJson();
  const expected = status.progress.elites.map((e) => ({ id: String(e.id), mean: String(e.mean_score), runs: String(e.runs) }));
  assert.ok(expected.length > 0);
  assert.ok(expected.some((e) => Number(e.runs) > 1) || status.race_log.length === 1, 'elites carry their runs across races');
  // The page polls; wait until it shows the stopped design's figures, then compare them all.
  const rows = () => page.$$eval('#elites tbody tr[data-testid^="elite-"]', (trs) => trs.map((tr) => ({
    id: tr.children[0].textContent, mean: tr.querySelector('[data-full]').dataset.full, runs: tr.children[2].textContent,
  })));
  await page.waitForFunction((n) => document.querySelectorAll('#elites tbody tr[data-testid^="elite-"]').length === n, expected.length);
  assert.deepEqual(await rows(), expected);
  // The best elite's mean is the one "Current best" shows, with its runs.
  assert.equal(await page.getAttribute('[data-testid="best-mean"]', 'data-full'), String(status.progress.best.mean_score));
  assert.match(await page.textContent('#best-score'), new RegExp(`over ${status.progress.best.runs} runs`));
  // Rounded for reading: at most 3 decimals shown, the full value on hover.
  const shown = await page.textContent('#elites tbody tr .score-value');
  assert.match(shown, /^-?\d+(\.\d{1,3})?$/);
});

test('the convergence plot has whole iterations on its x axis', { timeout: 30000 }, async () => {
  const status = statusJson();
  const convergence = await page.evaluate(() => window.__sd.monitor.convergence());
  assert.deepEqual(convergence.xs, status.convergence.map((p) => p.iteration));
  for (const x of [...convergence.xs, ...convergence.ticks]) assert.ok(Number.isInteger(x), `x ${x} is an iteration`);
  assert.ok(convergence.ticks.length >= 1);
  await page.setViewportSize({ width: 1920, height: 1080 });
  await shot(page, 'monitor-1920');
  await page.setViewportSize({ width: 1280, height: 800 });
});

test('the best design opens in the editor, drawn full size', { timeout: 30000 }, async () => {
  await page.click('#edit-best');
  await page.waitForFunction(() => !document.getElementById('page-editor').hidden);
  const best = statusJson().progress.best.configuration;
  await page.waitForFunction((b) => window.__sd.editor.current.text === b, best);
  await shot(page, 'best-in-editor-1280');
  await page.click('#tab-designs');
});

test('after a crash and a restart the design list and the state box agree: interrupted', { timeout: 120000 }, async () => {
  await page.waitForFunction(() => !document.getElementById('design-start').disabled);
  // The stopped design resumes as it was started, and the page says so: the form's choices are
  // greyed out (never painted invalid) until the user gives the design up to start afresh.
  assert.equal(await page.textContent('#design-start'), 'Resume design #1');
  assert.ok(await page.isDisabled('#design-preset'));
  assert.ok(await page.isDisabled('#design-budget'));
  // A budget below the minimum is not painted red while it is not used, and is once it would be.
  const typeBudget = (value) => page.$eval('#design-budget', (input, v) => { input.value = v; input.dispatchEvent(new Event('input')); }, value);
  const background = (id) => page.$eval(id, (input) => getComputedStyle(input).backgroundColor);
  await typeBudget('1');
  assert.equal(await background('#design-budget'), await background('#design-seed'), 'the unused budget is not painted invalid');
  await page.check('#design-fresh');
  assert.equal(await page.textContent('#design-start'), 'Start design');
  assert.ok(await page.isEnabled('#design-preset'));
  assert.notEqual(await background('#design-budget'), await background('#design-seed'), 'a budget that would be used is painted invalid');
  await shot(page, 'resume-fresh-1280');
  await page.uncheck('#design-fresh');
  await typeBudget(String(budget));
  assert.ok(await page.isDisabled('#design-budget'));
  await shot(page, 'resume-offered-1280');
  assert.equal(await page.textContent('#design-start'), 'Resume design #1');
  assert.match(await page.textContent('#design-resume'), /Design #1 is interrupted: Start resumes it as it was started \(fsm · chocolate · seed 7/);
  await page.click('#design-start');
  await page.waitForFunction(() => /^running/.test(document.getElementById('design-state').textContent), null, { timeout: 20000 });
  await page.waitForFunction(() => /#1 running/.test(document.querySelector('[data-testid="design-1"]')?.textContent || ''));
  const url = await server.crashAndRestart();
  await openSignedIn(page, url, 'carol');
  await page.click('#tab-designs');
  await page.click('[data-testid="project-choc"]');
  await page.waitForFunction(() => /^interrupted/.test(document.getElementById('design-state').textContent), null, { timeout: 30000 });
  await page.waitForSelector('[data-testid="design-1"]');
  assert.match(await page.textContent('[data-testid="design-1"] .design-head'), /^#1 interrupted$/);
  await shot(page, 'after-restart-1280');
});

test('the page raised no uncaught error', () => {
  assert.deepEqual(errors, []);
});
