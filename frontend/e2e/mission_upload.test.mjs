// A user's own mission, brought in from the page: uploaded into a project from the Missions
// tab, in headless chromium against the real server. Bad files get the server's one line and
// nothing is stored; a good one is drawn, offered to new projects and to Exec, runs, and a
// project on it designs to the end (shown as finished, budget spent, not as an error) and its
// best is tested on fresh seeds from the page. A
// second account sees none of it and cannot read, draw, run or overwrite it.
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { after, before, test } from 'node:test';
import { cli, screenshotter, signedInPages, startServer } from './helpers.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
let server;
let browser;
let page;
let other;
const errors = [];
const shot = screenshotter('mission-upload');

/// The catalogue's AAC, named `name`, 10 s long, with `change` applied.
function mission(name, change = () => {}) {
  const text = readFileSync(path.join(here, '..', '..', 'missions', 'aac.json'), 'utf8')
    .split('\n').filter((l) => !l.trim().startsWith('//')).join('\n');
  const doc = JSON.parse(text);
  Object.assign(doc, { name, title: `Corner of ${name}`, duration: 10 });
  delete doc.argos;
  change(doc);
  return JSON.stringify(doc, null, 1);
}

const upload = async (name, text) => {
  await page.fill('#upload-name', '');
  await page.setInputFiles('#upload-file', { name: `${name}.json`, mimeType: 'application/json', buffer: Buffer.from(text) });
  await page.fill('#upload-name', name);
  await page.click('#upload-button');
  await page.waitForFunction(() => {
    const s = document.getElementById('upload-status');
    return s.classList.contains('error') || s.classList.contains('done');
  });
  return page.evaluate(() => ({ text: document.getElementById('upload-status').textContent,
    ok: document.getElementById('upload-status').classList.contains('done') }));
};

before(async () => {
  server = await startServer({ users: [
    { name: 'fay', projects: [{ name: 'lab', mission: 'aac', budget: 1400 }] },
    { name: 'gus', projects: [{ name: 'lab', mission: 'aac', budget: 1400 }] },
  ] });
  ({ browser, pages: [page, other] } = await signedInPages(server, ['fay', 'gus'], errors));
}, { timeout: 60000 });

after(async () => {
  if (browser) await browser.close();
  if (server) await server.close();
});

test('bad mission files get one line naming the problem and add nothing', { timeout: 30000 }, async () => {
  await page.click('#tab-missions');
  await page.waitForFunction(() => document.getElementById('upload-project').value === 'lab');
  const cards = await page.locator('.mission-card').count();

  const broken = await upload('broken', '{"name": "broken",');
  assert.equal(broken.ok, false);
  assert.match(broken.text, /^mission 'broken': not valid JSON/);
  await shot(page, 'malformed');

  const noRobots = await upload('nobody', mission('nobody', (d) => { d.robots = 0; }));
  assert.match(noRobots.text, /robots/);
  const blocked = await upload('blocked', mission('blocked', (d) => {
    d.arena.walls.push({ box: { center: [0, 0], size: [2.4, 2.4] } });
  }));
  assert.match(blocked.text, /cannot place robot/);
  await shot(page, 'no-room');
  for (const t of [broken.text, noRobots.text, blocked.text]) assert.ok(!t.includes('\n'), t);

  assert.equal(await page.locator('.mission-card').count(), cards);
  const stored = await page.evaluate(async () => (await fetch('/api/projects/lab/missions')).json());
  assert.deepEqual(stored, []);
});

test('a good mission is drawn, offered to new projects and Exec, and runs', { timeout: 60000 }, async () => {
  const done = await upload('corner', mission('corner'));
  assert.ok(done.ok, done.text);
  assert.match(done.text, /added Corner of corner to lab/);
  const card = page.locator('.mission-card', { hasText: 'Corner of corner' });
  await card.waitFor();
  // The long path is shortened to project/file, the whole path on hover.
  assert.equal((await card.locator('.name').textContent()).split(' · ')[0], 'lab/corner.json');
  const file = await card.locator('.name').getAttribute('title');
  assert.match(file, /\/users\/fay\/projects\/lab\/missions\/corner\.json$/);
  await page.waitForFunction((f) => {
    const img = [...document.querySelectorAll('.mission-card img')].find((i) => i.alt === `arena of ${f}`);
    return img && img.complete && img.naturalWidth > 0;
  }, file);
  await card.scrollIntoViewIfNeeded();
  await shot(page, 'uploaded');

  // Offered where missions are chosen: a new project, and Exec.
  const offered = await page.evaluate((f) => ({
    project: [...document.querySelectorAll('#project-mission option')].some((o) => o.value === f),
    exec: [...document.querySelectorAll('#exec-mission option')].some((o) => o.value === f),
  }), file);
  assert.deepEqual(offered, { project: true, exec: true });

  // Try in Exec runs it to its end (10 s: 100 ticks).
  await card.locator('button', { hasText: 'Try in Exec' }).click();
  await page.waitForFunction((f) => document.getElementById('exec-mission').value === f, file);
  await page.click('#exec-run');
  await page.waitForFunction(() => document.getElementById('final-score').textContent !== '', null, { timeout: 30000 });
  assert.match(await page.textContent('#exec-status'), /complete: 100 ticks/);
  // The score is the one `swarmdesign evaluate` gives on the stored file.
  const text = await page.inputValue('#exec-text');
  const expected = JSON.parse(cli(server.env, ['evaluate', '--mission', file, '--seed', await page.inputValue('#exec-seed'),
    '--json', ...text.trim().split(/\s+/)])).runs[0].score;
  assert.equal(Number(await page.textContent('#final-score')), expected);
  await shot(page, 'ran-in-exec');
  assert.deepEqual(errors, []);
});

test('a project on the uploaded mission designs to its end: finished, budget spent', { timeout: 180000 }, async () => {
  const file = await page.locator('.mission-card', { hasText: 'Corner of corner' }).locator('.name').getAttribute('title');
  await page.click('#tab-designs');
  await page.fill('#project-name', 'own');
  await page.selectOption('#project-mission', file);
  await page.fill('#project-budget', '1400');
  await page.click('#project-create');
  await page.waitForFunction(() => document.getElementById('monitor-project').textContent === 'own');
  await page.click('#design-start');
  await page.waitForFunction(() => /^finished/.test(document.getElementById('design-state').textContent), null, { timeout: 160000, polling: 500 });
  // Iterated F-Race's normal end reads as one, its reason on hover.
  assert.equal(await page.textContent('#design-state'), 'finished: budget spent');
  // Which of irace's two normal ends it is depends on the design's (random) seed.
  assert.match(await page.getAttribute('#design-state', 'title'), /^finished because: (Not enough budget|Budget exhausted)/);
  assert.match(await page.textContent('#alive'), /^\d+( racing of \d+)?$/);
  await shot(page, 'designed-to-the-end');

  // Its best tested on fresh seeds from the page: what evaluate gives on those seeds.
  await page.fill('#test-seeds', '1-8');
  await page.click('#test-run');
  await page.waitForSelector('[data-testid="test-summary"]', { timeout: 30000 });
  assert.match(await page.textContent('[data-testid="test-summary"]'), /^mean .* · sd .* · median .* over 8 seeds \(1-8, maximize\)$/);
  assert.equal(await page.locator('#test-result svg.box-plot circle.seed-point').count(), 8);
  const best = await page.getAttribute('#watch-best', 'data-text');
  const expected = JSON.parse(cli(server.env, ['evaluate', '--mission', file, '--seeds', '1-8', '--json', ...best.split(' ')])).mean;
  assert.equal(Number(await page.getAttribute('[data-testid="test-summary"]', 'data-mean')), expected);
  await page.locator('#test-result').scrollIntoViewIfNeeded();
  await shot(page, 'tested-on-seeds');
  // A bad range gets the server's one line.
  await page.fill('#test-seeds', '1-500');
  await page.click('#test-run');
  await page.waitForSelector('#test-result .error');
  assert.match(await page.textContent('#test-result .error'), /at most 100 seeds/);
});

test('another account sees, reads, runs and overwrites none of it', { timeout: 30000 }, async () => {
  const file = await page.locator('.mission-card', { hasText: 'Corner of corner' }).locator('.name').getAttribute('title');
  await other.click('#tab-missions');
  await other.waitForSelector('.mission-card');
  assert.equal(await other.locator('.mission-card', { hasText: 'Corner of corner' }).count(), 0);
  const seen = await other.evaluate(async (f) => {
    const post = (url, body) => fetch(url, { method: 'POST', headers: { 'Content-Type': 'application/json', 'X-CSRF-Token': window.__sdCsrf }, body: JSON.stringify(body) });
    const mine = await (await fetch('/api/projects/lab/missions')).json();  // gus' own lab: empty
    return {
      mine,
      svg: (await fetch(`/api/missions/svg?name=${encodeURIComponent(f)}`)).status,
      run: (await post('/api/runs', { text: '--fsm-config --nstates 1 --s0 0 --rwm0 50', mission: f, seed: 1 })).status,
      project: (await post('/api/projects', { name: 'stolen', mission: f, budget: 1400 })).status,
    };
  }, file);
  assert.deepEqual(seen, { mine: [], svg: 404, run: 404, project: 404 });
  // Gus' upload lands in his own project, never in Fay's file of the same name.
  await other.setInputFiles('#upload-file', { name: 'corner.json', mimeType: 'application/json', buffer: Buffer.from(mission('corner', (d) => { d.title = 'gus corner'; })) });
  await other.click('#upload-button');
  await other.waitForSelector('#upload-status.done');
  await shot(other, 'second-account');
  const fays = await page.evaluate(async () => (await fetch('/api/missions')).json());
  assert.ok(fays.some((m) => m.title === 'Corner of corner'));
  assert.ok(!fays.some((m) => m.title === 'gus corner'));
});
