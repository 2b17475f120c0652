// Nothing stale stays on screen, in headless chromium against the real server: after a run, an
// Exec the server refuses clears the tick, the objective, the robot panel, the score and the
// robots-per-state counts; a malformed configuration string clears the old drawing (no tree
// beside FSM text) and the drawing comes back when the text parses again.
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';
import { launchBrowser, newPage, screenshotter, signIn, startServer } from './helpers.mjs';

const FSM = '--fsm-config --nstates 1 --s0 10 --rwm0 50';
const TREE = '--bt-config --nroot 3 --nchildroot 1 --n0 0 --nchild0 2 --n00 6 --c00 10 --p00 0.5 --n01 5 --a01 10 --rwm01 50 --p01 0';
let server;
let browser;
let page;
const errors = [];
const shot = screenshotter('stale-state');

before(async () => {
  server = await startServer({ users: [{ name: 'dave' }] });
  browser = await launchBrowser();
  page = await newPage(browser, errors, { width: 1280, height: 800 });
  await signIn(page, server.url, 'dave');
}, { timeout: 60000 });

after(async () => {
  if (browser) await browser.close();
  if (server) await server.close();
});

test('a refused Exec clears what the previous run left', { timeout: 90000 }, async () => {
  await page.click('#tab-exec');
  await page.fill('#exec-text', FSM);
  await page.selectOption('#exec-mission', 'aac');
  await page.fill('#exec-seed', '2');
  await page.click('#exec-run');
  await page.waitForFunction(() => document.getElementById('final-score').textContent !== '', null, { timeout: 60000 });
  await page.evaluate(() => window.__sd.exec.selectRobot(0));
  await page.waitForSelector('#robot-state');
  await page.waitForFunction(() => window.__sd.execCounts() > 0);
  assert.notEqual(await page.textContent('#tick-label'), '');
  assert.notEqual(await page.textContent('#objective-now'), '');

  await page.fill('#exec-text', '--fsm-config --nstates 1 --s0 10 --rwm0 500');
  await page.click('#exec-run');
  await page.waitForFunction(() => /^refused/.test(document.getElementById('exec-status').textContent));
  assert.equal(await page.textContent('#tick-label'), '');
  assert.equal(await page.textContent('#objective-now'), '');
  assert.equal(await page.textContent('#final-score'), '');
  assert.equal(await page.$('#robot-state'), null);
  assert.match(await page.textContent('#robot-info'), /Click a robot/);
  assert.equal(await page.evaluate(() => window.__sd.execCounts()), 0);
  assert.equal(await page.evaluate(() => window.__sd.exec.graph.nodes().length), 0);
  assert.equal(await page.isDisabled('#download-png'), true);
  await shot(page, 'exec-refused');
});

test('a malformed string clears the old drawing; a good one brings a drawing back', { timeout: 30000 }, async () => {
  await page.click('#tab-editor');
  await page.fill('#config-text', TREE);
  await page.waitForFunction(() => window.__sd.editor.current.model?.architecture === 'bt');
  assert.ok(await page.evaluate(() => window.__sd.editor.cy.nodes().length) > 1);
  await page.fill('#config-text', '--fsm-config --nstates 2 --s0 10 --rwm0 50');
  await page.waitForSelector('#config-error', { state: 'visible' });
  await page.waitForFunction(() => window.__sd.editor.cy.nodes().length === 0);
  assert.match(await page.textContent('#properties'), /does not parse/);
  assert.equal(await page.textContent('#flavours-used'), '');
  assert.equal(await page.textContent('#config-description'), '');  // it described the tree
  await shot(page, 'editor-malformed');
  await page.fill('#config-text', FSM);
  await page.waitForFunction(() => window.__sd.editor.current.model?.architecture === 'fsm');
  assert.equal(await page.evaluate(() => window.__sd.editor.cy.nodes().length), 1);
  assert.equal(await page.isVisible('#config-error'), false);
});

test('an error goes once the user moves on; a budget too small for every flavour is warned about', { timeout: 30000 }, async () => {
  await page.click('#tab-designs');
  await page.waitForSelector('label[for="project-budget"]');
  await page.fill('#project-name', 'p1');
  await page.fill('#project-budget', '500');
  await page.waitForFunction(() => /^below \d+, the least Iterated F-Race needs/.test(document.getElementById('project-budget-note').textContent));
  await shot(page, 'low-budget-warned');
  await page.click('#project-create');
  await page.waitForSelector('[data-testid="project-p1"]');
  await page.fill('#project-budget', '200000');
  assert.equal(await page.textContent('#project-budget-note'), '');

  const refuse = async () => {
    await page.fill('#project-name', 'p1');
    await page.click('#project-create');
    await page.waitForSelector('#toast:not([hidden])');
    assert.match(await page.textContent('#toast'), /already have a project named 'p1'/);
  };
  await refuse();
  await shot(page, 'error-shown');
  await page.click('#tab-editor');
  assert.equal(await page.isHidden('#toast'), true, 'another tab: the error spoke of the one left');
  await page.click('#tab-designs');
  await refuse();
  await page.fill('#project-name', 'p2');
  await page.click('#project-create');
  await page.waitForSelector('[data-testid="project-p2"]');
  assert.equal(await page.isHidden('#toast'), true, 'an action that worked clears the earlier error');
});

test('the page raised no uncaught error', () => {
  assert.deepEqual(errors, []);
});
