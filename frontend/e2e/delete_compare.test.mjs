// Earlier designs opened, two designs compared, and deleting (a design, saved software, a whole
// project) from the page, in headless chromium against the real server. Every delete asks first
// and touches only what it names; a second account sees none of it and its requests to delete
// it are answered as for something that does not exist.
import assert from 'node:assert/strict';
import { existsSync, mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { after, before, test } from 'node:test';
import { cli, PASSWORD, screenshotter, signedInPages, startServer } from './helpers.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
let server;
let browser;
let page;
let other;
const errors = [];
const shot = screenshotter('delete-compare');
const FSM = '--fsm-config --nstates 1 --s0 0 --rwm0 50';
let projectFolder;

before(async () => {
  server = await startServer({ users: [
    { name: 'gus', projects: [{ name: 'lab', mission: 'aac', budget: 1400 }] },
    { name: 'hal', projects: [{ name: 'kept', mission: 'aac', budget: 1400 }, { name: 'lab', mission: 'aac', budget: 1100 }] },
  ] });
  // Two finished designs of hal's lab on a 10 s AAC, made by the CLI (the page shows any design).
  projectFolder = path.join(server.env.SWARMDESIGN_HOME, 'users', 'hal', 'projects', 'lab');
  const doc = JSON.parse(readFileSync(path.join(here, '..', '..', 'missions', 'aac.json'), 'utf8')
    .split('\n').filter((l) => !l.trim().startsWith('//')).join('\n'));
  Object.assign(doc, { name: 'short-aac', duration: 10 });
  delete doc.argos;
  mkdirSync(path.join(projectFolder, 'missions'), { recursive: true });
  const file = path.join(projectFolder, 'missions', 'short-aac.json');
  writeFileSync(file, JSON.stringify(doc));
  cli(server.env, ['sign-in', 'hal', '--password-stdin'], `${PASSWORD}\n`);
  cli(server.env, ['select-project', 'lab']);
  cli(server.env, ['set-mission', file]);
  for (const seed of ['3', '4']) cli(server.env, ['run-design', '--fsm', '--chocolate', '--seed', seed, '--threads', '2'], '', 120000);
  ({ browser, pages: [page, other] } = await signedInPages(server, ['hal', 'gus'], errors));
}, { timeout: 180000 });

after(async () => {
  if (browser) await browser.close();
  if (server) await server.close();
});

const post = (p, route, body) => p.evaluate(async ([r, b]) => {
  const res = await fetch(r, { method: 'POST', headers: { 'Content-Type': 'application/json', 'X-CSRF-Token': window.__sdCsrf }, body: JSON.stringify(b) });
  return res.status;
}, [route, body]);

async function openLab() {
  await page.click('#tab-designs');
  await page.click('[data-testid="project-lab"]');
  await page.waitForFunction(() => document.getElementById('monitor-project').textContent === 'lab');
  await page.waitForSelector('#design-list .design-row');
  await page.waitForSelector('[data-testid="best-mean"]');
}

test('an earlier design opens with its own best, and the latest comes back', { timeout: 60000 }, async () => {
  await openLab();
  assert.match(await page.textContent('#design-info'), /Design #2:.*seed 4/);
  await page.click('[data-testid="design-1"] .design-head');
  await page.waitForSelector('[data-testid="opened-note"]');
  assert.match(await page.textContent('#design-info'), /Showing earlier design #1\..*Design #1:.*seed 3/);
  const best1 = JSON.parse(cli(server.env, ['status', '--design', '1', '--json'])).progress.best;
  // The best shown is design 1's, as status --design 1 reads it.
  await page.waitForFunction((m) => Number(document.querySelector('[data-testid="best-mean"]')?.dataset.full) === m, best1.mean_score);
  assert.equal(await page.getAttribute('[data-testid="design-1"]', 'class'), 'design-row opened');
  assert.equal(await page.isDisabled('#design-start'), false, 'Start still acts on the latest design');
  await shot(page, 'earlier-design-opened');
  // Its best is what Test on seeds tests.
  await page.fill('#test-seeds', '1-3');
  await page.click('#test-run');
  await page.waitForSelector('[data-testid="test-summary"]', { timeout: 30000 });
  const file = JSON.parse(cli(server.env, ['active-project', '--json'])).mission;
  const evaluated = JSON.parse(cli(server.env, ['evaluate', '--mission', file, '--seeds', '1-3', '--json', ...best1.configuration.split(' ')]));
  assert.equal(Number(await page.getAttribute('[data-testid="test-summary"]', 'data-mean')), evaluated.mean);
  await page.click('[data-testid="show-latest"]');
  await page.waitForFunction(() => !document.querySelector('[data-testid="opened-note"]') && /Design #2:/.test(document.getElementById('design-info').textContent));
});

test('two ticked designs are compared on the same seeds with a paired test', { timeout: 60000 }, async () => {
  await openLab();
  assert.equal(await page.isDisabled('#compare-run'), true);
  await page.check('[data-testid="compare-1"]');
  await page.check('[data-testid="compare-2"]');
  assert.equal(await page.textContent('#compare-run'), 'Compare #1 and #2');
  await page.fill('#compare-seeds', '1-10');
  await page.click('#compare-run');
  await page.waitForSelector('[data-testid="compare-verdict"]', { timeout: 30000 });
  assert.match(await page.textContent('[data-testid="compare-verdict"]'), /(paired Wilcoxon p = |every seed scores the same).*\(seeds 1-10\)/);
  for (const id of [1, 2]) {
    const side = await page.textContent(`[data-testid="compare-side-${id}"]`);
    const best = JSON.parse(cli(server.env, ['status', '--design', String(id), '--json'])).progress.best.configuration;
    const file = JSON.parse(cli(server.env, ['active-project', '--json'])).mission;
    const evaluated = JSON.parse(cli(server.env, ['evaluate', '--mission', file, '--seeds', '1-10', '--json', ...best.split(' ')]));
    assert.match(side, new RegExp(`^#${id}: mean `));
    const shown = Number(side.match(/mean (\S+)/)[1]);
    assert.ok(Math.abs(shown - evaluated.mean) <= Math.abs(evaluated.mean) * 1e-3 + 1e-9, `${side} vs ${evaluated.mean}`);
  }
  assert.equal(await page.locator('#compare-result svg.box-plot').count(), 2);
  await shot(page, 'two-designs-compared');
});

test('the best shown goes to ARGoS: the design\'s file as export-argos writes it, the string as export --argos', { timeout: 60000 }, async () => {
  await openLab();
  await page.waitForFunction(() => !document.getElementById('argos-best').disabled);
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#argos-best')]);
  assert.equal(download.suggestedFilename(), 'short-aac.argos');
  const saved = readFileSync(await download.path(), 'utf8');
  const written = path.join(server.tmp, 'cli.argos');
  cli(server.env, ['export-argos', '--out', written]);
  assert.equal(saved, readFileSync(written, 'utf8'));
  const best = JSON.parse(cli(server.env, ['status', '--json'])).progress.best.configuration;
  const legacy = JSON.parse(cli(server.env, ['export', '--argos', '--json', ...best.split(' ')]));
  // The design's FSM is the file's default: automode_main runs it when given none.
  assert.ok(saved.includes(`fsm-config="${legacy.config.replace(/^--fsm-config /, '')}"`), saved);
  await page.waitForSelector('[data-testid="argos-command"]');
  assert.equal(await page.textContent('[data-testid="argos-command"]'), `automode_main -n -c short-aac.argos --seed 1 ${legacy.config}`);
  await shot(page, 'argos-files');
});

test('a second account sees none of it and cannot delete any of it', { timeout: 30000 }, async () => {
  await other.click('#tab-designs');
  await other.waitForSelector('[data-testid="project-lab"]');
  assert.equal(await other.locator('[data-testid="project-kept"]').count(), 0);
  await other.click('[data-testid="project-lab"]');
  await other.waitForFunction(() => document.getElementById('monitor-project').textContent === 'lab');
  await other.waitForSelector('#design-list li');
  assert.match(await other.textContent('#design-list'), /no design yet/, 'gus sees his own lab, not hal\'s');
  // Gus's own "lab" is not hal's: requests naming hal's things answer as missing, or act on gus's.
  assert.equal(await post(other, '/api/projects/kept/delete', { confirm: 'kept' }), 404);
  assert.equal(await post(other, '/api/projects/lab/designs/1/delete', {}), 404);
  assert.equal(await post(other, '/api/projects/kept/software/walker/delete', {}), 404);
  assert.ok(existsSync(path.join(projectFolder, 'designs', '1')));
  await shot(other, 'second-account-sees-nothing');
});

test('a design is deleted only once confirmed, and only it', { timeout: 60000 }, async () => {
  await openLab();
  await page.click('[data-testid="design-delete-1"]');
  await page.waitForSelector('[data-testid="confirm-dialog"]');
  assert.match(await page.textContent('[data-testid="confirm-dialog"]'), /Delete design #1\?/);
  await shot(page, 'design-delete-asked');
  await page.click('[data-testid="confirm-cancel"]');
  await page.waitForSelector('[data-testid="confirm-dialog"]', { state: 'detached' });
  assert.ok(existsSync(path.join(projectFolder, 'designs', '1')), 'cancel deletes nothing');

  await page.click('[data-testid="design-delete-1"]');
  await page.click('[data-testid="confirm-ok"]');
  await page.waitForSelector('[data-testid="design-1"]', { state: 'detached' });
  assert.ok(!existsSync(path.join(projectFolder, 'designs', '1')));
  assert.ok(existsSync(path.join(projectFolder, 'designs', '2')));
  assert.equal(await page.locator('#design-list .design-row').count(), 1);
  await shot(page, 'design-deleted');
});

test('saved software is deleted from the editor after asking', { timeout: 30000 }, async () => {
  for (const name of ['walker', 'spare']) assert.equal(await post(page, '/api/projects/lab/software', { name, text: FSM }), 200);
  await page.click('#tab-editor');
  await page.selectOption('#software-project', 'lab');
  await page.waitForSelector('[data-testid="software-walker"]');
  await page.click('[data-testid="software-delete-walker"]');
  await page.click('[data-testid="confirm-ok"]');
  await page.waitForSelector('[data-testid="software-walker"]', { state: 'detached' });
  assert.equal(await page.locator('[data-testid="software-spare"]').count(), 1);
  assert.ok(!existsSync(path.join(projectFolder, 'software', 'walker.txt')));
  assert.ok(existsSync(path.join(projectFolder, 'software', 'spare.txt')));
});

test('a project is deleted only when its name is typed, with all it holds', { timeout: 60000 }, async () => {
  await openLab();
  await page.click('#project-delete');
  await page.waitForSelector('[data-testid="confirm-name"]');
  assert.equal(await page.isDisabled('[data-testid="confirm-ok"]'), true);
  await page.fill('[data-testid="confirm-name"]', 'kept');
  assert.equal(await page.isDisabled('[data-testid="confirm-ok"]'), true, 'another project\'s name does not confirm');
  await page.fill('[data-testid="confirm-name"]', 'lab');
  await shot(page, 'project-delete-asked');
  await page.click('[data-testid="confirm-ok"]');
  await page.waitForSelector('[data-testid="project-lab"]', { state: 'detached' });
  assert.ok(!existsSync(projectFolder));
  await page.waitForSelector('[data-testid="project-kept"]');
  // Its uploaded mission is gone from every list; hal's other project and gus's lab stay.
  await page.click('#tab-missions');
  await page.waitForSelector('.mission-card');
  await page.waitForFunction(() => ![...document.querySelectorAll('.mission-card')].some((c) => c.textContent.includes('short-aac')));
  assert.ok(existsSync(path.join(server.env.SWARMDESIGN_HOME, 'users', 'gus', 'projects', 'lab')));
  await page.click('#tab-designs');
  await shot(page, 'project-deleted');
  assert.deepEqual(errors, []);
});
