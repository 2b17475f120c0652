// The design monitor, driven in headless chromium against the real server: a project made on
// the command line (aac, budget 1400, the least Iterated F-Race accepts is 1350) is listed; a project made in the page too; a design started
// from the page makes the runs-used figure grow; it is stopped from the page. Missions are drawn.
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';
import { launchBrowser, newPage, screenshotter, signIn, startServer } from './helpers.mjs';

let server;
let browser;
let page;
const errors = [];
const shot = screenshotter('designs');

before(async () => {
  server = await startServer({ users: [{ name: 'bob', projects: [{ name: 'small', mission: 'aac', budget: 1400 }] }] });
  browser = await launchBrowser();
  page = await newPage(browser, errors);
  await signIn(page, server.url, 'bob');
}, { timeout: 60000 });

after(async () => {
  if (page) {
    // Stop a design still running so that the server ends quickly.
    await page.evaluate(() => fetch('/api/projects/small/designs/stop', { method: 'POST', headers: { 'Content-Type': 'application/json', 'X-CSRF-Token': window.__sdCsrf || '' }, body: '{}' })).catch(() => {});
  }
  if (browser) await browser.close();
  if (server) await server.close();
});

const runsUsed = async () => {
  const text = await page.textContent('#runs-used');
  const m = /^(\d+) \/ (\d+)$/.exec(text.trim());
  return m ? { used: Number(m[1]), budget: Number(m[2]) } : null;
};

test('projects are listed and one can be created in the page', { timeout: 20000 }, async () => {
  await page.click('#tab-designs');
  await page.waitForSelector('[data-testid="project-small"]');
  await page.fill('#project-name', 'fromweb');
  await page.selectOption('#project-mission', 'aac');
  await page.fill('#project-budget', '500');
  await page.click('#project-create');
  await page.waitForSelector('[data-testid="project-fromweb"]');
  await page.waitForFunction(() => document.getElementById('monitor-project').textContent === 'fromweb');
  await shot(page, 'projects');
});

test('a design started from the page makes runs used grow; stop stops it', { timeout: 90000 }, async () => {
  await page.click('[data-testid="project-small"]');
  await page.waitForFunction(() => document.getElementById('monitor-project').textContent === 'small');
  await page.click('#design-start');
  await page.waitForFunction(() => /^\d+ \/ 1400$/.test(document.getElementById('runs-used').textContent.trim()), null, { timeout: 20000 });
  const first = await runsUsed();
  assert.equal(first.budget, 1400);
  await shot(page, 'design-started');
  await page.waitForFunction((before) => {
    const m = /^(\d+) \//.exec(document.getElementById('runs-used').textContent.trim());
    return m && Number(m[1]) > before;
  }, first.used, { timeout: 60000, polling: 250 });
  const later = await runsUsed();
  assert.ok(later.used > first.used, `runs used grew: ${first.used} -> ${later.used}`);
  await shot(page, 'design-progress');
  const state = await page.textContent('#design-state');
  if (/running/.test(state)) {
    await page.click('#design-stop');
    await page.waitForFunction(() => !/^running/.test(document.getElementById('design-state').textContent), null, { timeout: 30000 });
  }
  await shot(page, 'design-stopped');
});

test('the missions are drawn with their description', { timeout: 20000 }, async () => {
  await page.click('#tab-missions');
  await page.waitForSelector('[data-testid="mission-aac"] img');
  await page.waitForFunction(() => {
    const img = document.querySelector('[data-testid="mission-aac"] img');
    return img.complete && img.naturalWidth > 0;
  });
  const cards = await page.$$('.mission-card');
  assert.ok(cards.length >= 10);
  await shot(page, 'missions');
});

test('the page raised no uncaught error', () => {
  assert.deepEqual(errors, []);
});
