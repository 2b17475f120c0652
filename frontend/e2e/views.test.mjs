// Every view at 1280x800 and 1920x1080, as a new user meets it, in headless chromium against
// the real server (screenshots in <build>/screenshots/views-*): no request of the page is
// answered 404 (the favicon is served); the editor's toolbar stays on one row at 1280 px in
// both modes; the palette and the property panel name each module's flavour, and the page says
// which flavours a drawing uses; a tree's nodes are named as the configuration string names them.
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';
import { launchBrowser, newPage, screenshotter, signIn, startServer } from './helpers.mjs';

const TREE = '--bt-config --nroot 3 --nchildroot 2 --n0 0 --nchild0 2 --n00 6 --c00 10 --p00 0.5 --n01 5 --a01 10 --rwm01 50 --p01 0 --n1 0 --nchild1 2 --n10 6 --c10 27 --l10 2 --p10 0.5 --n11 5 --a11 28 --cle11 4 --clr11 2 --vel11 1 --p11 0';
let server;
let browser;
let page;
const errors = [];
const missing = [];
const shot = screenshotter('views');

before(async () => {
  server = await startServer({ users: [{ name: 'gus', projects: [{ name: 'first', mission: 'foraging', budget: 3000 }] }] });
  browser = await launchBrowser();
  page = await newPage(browser, errors, { width: 1280, height: 800 });
  page.on('response', (r) => { if (r.status() === 404) missing.push(r.url()); });
  await signIn(page, server.url, 'gus');
}, { timeout: 60000 });

after(async () => {
  if (browser) await browser.close();
  if (server) await server.close();
});

/// The toolbar's visible buttons all on one row and none cut off.
const toolbarOnOneRow = () => page.evaluate(() => {
  const bar = document.querySelector('#page-editor .toolbar');
  const buttons = [...bar.querySelectorAll('button')].filter((b) => b.offsetParent !== null);
  const tops = new Set(buttons.map((b) => Math.round(b.getBoundingClientRect().top)));
  const right = Math.max(...buttons.map((b) => b.getBoundingClientRect().right));
  const fits = right <= bar.getBoundingClientRect().right + 0.5;
  return fits ? { rows: tops.size, fits } : { rows: tops.size, fits, right, bar: bar.getBoundingClientRect().right, ids: buttons.map((b) => b.id) };
});

test('the favicon is served and nothing the page asks for is missing', { timeout: 20000 }, async () => {
  const ico = await page.evaluate(async () => { const r = await fetch('/favicon.ico'); return { status: r.status, bytes: (await r.arrayBuffer()).byteLength }; });
  assert.equal(ico.status, 200);
  assert.ok(ico.bytes > 1000);
  assert.equal(await page.evaluate(async () => (await fetch('/favicon.svg')).status), 200);
  assert.deepEqual(missing, []);
});

test('the editor at 1280 px: the toolbar on one row in FSM and tree mode', { timeout: 30000 }, async () => {
  await page.click('#tab-editor');
  assert.deepEqual(await toolbarOnOneRow(), { rows: 1, fits: true });
  await shot(page, 'editor-fsm-1280');
  await page.fill('#config-text', TREE);
  await page.waitForFunction(() => window.__sd.editor.current.model?.architecture === 'bt');
  assert.deepEqual(await toolbarOnOneRow(), { rows: 1, fits: true });
  await shot(page, 'editor-bt-1280');
});

test('flavours: on palette entries, in the property panel, and those the drawing uses', { timeout: 30000 }, async () => {
  assert.equal(await page.textContent('[data-testid="palette-behaviour-28"] .flavour-tag'), 'tuttifrutti');
  assert.equal(await page.textContent('[data-testid="palette-behaviour-10"] .flavour-tag'), 'chocolate');
  assert.equal(await page.textContent('#flavours-used'), 'This drawing uses: chocolate, tuttifrutti');
  // Node n11 (second child of n1) is the 28 GoToColor action.
  const index = await page.evaluate(() => {
    const m = window.__sd.editor.current.model;
    return m.nodes.findIndex((n) => n.module && n.module.id === 28);
  });
  await page.evaluate((i) => { window.__sd.editor.cy.getElementById(`n${i}`).select(); }, index);
  await page.waitForSelector('[data-testid="node-name"]');
  assert.equal(await page.textContent('[data-testid="node-name"]'), 'Node n11: action');
  assert.equal(await page.textContent('[data-testid="module-flavour"]'), 'flavour: tuttifrutti');
  await page.evaluate(() => { window.__sd.editor.cy.getElementById('n0').select(); });
  await page.waitForFunction(() => document.querySelector('[data-testid="node-name"]')?.textContent === 'Node root: sequence*');
  await shot(page, 'editor-bt-selected-1280');
});

test('every view at 1280x800 and 1920x1080', { timeout: 90000 }, async () => {
  for (const [width, height] of [[1280, 800], [1920, 1080]]) {
    await page.setViewportSize({ width, height });
    await page.click('#tab-editor');
    await page.fill('#config-text', '--fsm-config --nstates 2 --s0 10 --rwm0 50 --n0 1 --n0x0 0 --c0x0 10 --p0x0 0.5 --s1 14 --att1 3 --n1 1 --n1x0 0 --c1x0 12 --p1x0 0.5');
    await page.waitForFunction(() => window.__sd.editor.current.model?.architecture === 'fsm');
    await shot(page, `editor-${width}`);
    await page.click('#to-exec');
    await page.selectOption('#exec-mission', 'foraging');
    await page.click('#exec-run');
    await page.waitForFunction(() => document.getElementById('final-score').textContent !== '', null, { timeout: 60000 });
    await page.evaluate(() => { window.__sd.exec.seek(400); window.__sd.exec.selectRobot(3); });
    await page.waitForSelector('#robot-state');
    await shot(page, `exec-${width}`);
    await page.click('#tab-designs');
    await page.waitForFunction(() => document.getElementById('monitor-project').textContent === 'first');
    await page.waitForFunction(() => /at least \d+ runs/.test(document.getElementById('design-minimum').textContent));
    await shot(page, `designs-${width}`);
    await page.click('#tab-missions');
    await page.waitForFunction(() => [...document.querySelectorAll('.mission-card img')].slice(0, 6).every((i) => i.complete && i.naturalWidth > 0));
    await shot(page, `missions-${width}`);
  }
  assert.deepEqual(missing, []);
});

test('the page raised no uncaught error', () => {
  assert.deepEqual(errors, []);
});
