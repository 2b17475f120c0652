// The reality gap in the page (issue #46), in headless chromium against the real server: Exec
// runs the same control software in a pseudo-reality sample (the run says which robot model it
// used), and a design's best, made on the command line on a 2-second mission in the project,
// is assessed in a pseudo-reality from the Designs tab: the design-model mean, the
// pseudo-reality mean and the drop with its interval and p are shown, and shown again when the
// design is opened later (the assessment is kept with the design).
import assert from 'node:assert/strict';
import { readFileSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { fileURLToPath } from 'node:url';
import { cli, screenshotter, signedInPages, startServer } from './helpers.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
const FSM = '--fsm-config --nstates 1 --s0 0 --rwm0 50';

let server;
let browser;
let page;
const errors = [];
const shot = screenshotter('reality-gap');

before(async () => {
  server = await startServer({ users: [{ name: 'erin', projects: [{ name: 'gap' }] }] });
  // A 2-second AAC inside the project (a server reads only its users' own files), and one design.
  const folder = path.join(server.env.SWARMDESIGN_HOME, 'users', 'erin', 'projects', 'gap');
  const mission = path.join(folder, 'aac-short.json');
  writeFileSync(mission, readFileSync(path.join(here, '..', '..', 'missions', 'aac.json'), 'utf8').replace(/"duration": *[0-9.]+/, '"duration": 2'));
  cli(server.env, ['set-mission', mission]);
  cli(server.env, ['set-budget', '1100']);
  cli(server.env, ['run-design', '--fsm', '--chocolate', '--seed', '3', '--threads', '2'], undefined, 120000);
  ({ browser, pages: [page] } = await signedInPages(server, ['erin'], errors));
}, { timeout: 150000 });

after(async () => {
  if (browser) await browser.close();
  if (server) await server.close();
});

test('Exec runs in a chosen pseudo-reality sample', { timeout: 60000 }, async () => {
  await page.click('#tab-exec');
  await page.waitForFunction(() => [...document.querySelectorAll('#exec-reality option')].some((o) => o.value === 'sampled-around'));
  assert.equal(await page.isDisabled('#exec-sample'), true, 'no sample for the design model');
  await page.fill('#exec-text', FSM);
  await page.selectOption('#exec-mission', 'aac');
  await page.selectOption('#exec-reality', 'sampled-around');
  await page.fill('#exec-sample', '7');
  await page.click('#exec-run');
  await page.waitForFunction(() => document.getElementById('final-score').textContent !== '', null, { timeout: 40000 });
  assert.equal(await page.getAttribute('#exec-status', 'data-world'), 'sampled-around#7');
  await shot(page, 'exec-in-sample-7');
  assert.match(await page.textContent('#exec-status'), /sample 7 of pseudo-reality sampled-around/);
  assert.deepEqual(errors, []);
});

test('a design\'s best is assessed in a pseudo-reality and its drop is shown and kept', { timeout: 90000 }, async () => {
  await page.click('#tab-designs');
  await page.click('[data-testid="project-gap"]');
  await page.waitForFunction(() => document.getElementById('monitor-project').textContent === 'gap');
  await page.waitForFunction(() => !document.getElementById('reality-run').disabled, null, { timeout: 20000 });
  assert.equal(await page.textContent('#reality-result'), '', 'not assessed yet');
  await page.selectOption('#reality-spec', 'sampled-around');
  await page.fill('#reality-samples', '1-5');
  await page.click('#reality-run');
  await page.waitForSelector('[data-testid="reality-drop"]', { timeout: 60000 });
  assert.match(await page.textContent('[data-testid="reality-where"]'), /pseudo-reality sampled-around, samples 1-5, seeds 1-10/);
  assert.match(await page.textContent('[data-testid="reality-drop"]'), /drop .*\[.*, .*\].*Wilcoxon p = /);
  const shown = await page.textContent('[data-testid="reality-mean"]');
  await page.locator('#reality-form').scrollIntoViewIfNeeded();
  await shot(page, 'design-assessed');

  // Opened again (a fresh page), the design shows the assessment it keeps.
  await page.reload();
  await page.waitForSelector('body[data-ready="true"]');
  await page.click('#tab-designs');
  await page.click('[data-testid="project-gap"]');
  await page.waitForSelector('[data-testid="reality-mean"]', { timeout: 20000 });
  assert.equal(await page.textContent('[data-testid="reality-mean"]'), shown);

  // A bad request is refused in one line naming the field.
  await page.fill('#reality-samples', '0');
  await page.click('#reality-run');
  await page.waitForFunction(() => /^refused: samples/.test(document.getElementById('reality-result').textContent), null, { timeout: 10000 });
  await shot(page, 'bad-samples');
  assert.deepEqual(errors, []);
});
