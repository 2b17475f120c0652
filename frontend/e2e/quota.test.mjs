// Quotas from the page (issue #56), in headless chromium against the real server: the
// administrator (the first account) sets the server's default and a second account's own disk
// limit in the Admin tab; that account sees its limits in the top bar; a mission saved from the
// editor or uploaded past its disk limit is refused with the one-line toast and no file is
// written (the CLI's `quota` sees the same bytes), and is saved once the limit is the default
// again; a design start past the day's runs is refused the same way and no design starts.
import assert from 'node:assert/strict';
import { existsSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { after, before, test } from 'node:test';
import { bytesText } from '../src/numbers.js';
import { cli, screenshotter, signedInPages, startServer } from './helpers.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
let server;
let browser;
let boss;
let ann;
let annUsed;   // ann's disk use before the refused writes, in bytes
let annLimit;  // ann's own disk limit, in bytes
const errors = [];
const shot = screenshotter('quota');

before(async () => {
  // boss signs up first: the home's administrator. ann is the CLI's signed-in account after set-up.
  server = await startServer({ users: [
    { name: 'boss', projects: [{ name: 'lab', mission: 'aac', budget: 1400 }] },
    { name: 'ann', projects: [{ name: 'first', mission: 'aac', budget: 1400 }, { name: 'second', mission: 'aac', budget: 1400 }] },
  ] });
  ({ browser, pages: [boss, ann] } = await signedInPages(server, ['boss', 'ann'], errors));
}, { timeout: 60000 });

after(async () => {
  if (ann) {
    // Stop a design still running so that the server ends quickly.
    await ann.evaluate(() => fetch('/api/projects/first/designs/stop', { method: 'POST', headers: { 'Content-Type': 'application/json', 'X-CSRF-Token': window.__sdCsrf || '' }, body: '{}' })).catch(() => {});
  }
  if (browser) await browser.close();
  if (server) await server.close();
});

const text = (page, testid) => page.textContent(`[data-testid="${testid}"]`);
const textIs = (page, testid, wanted) => page.waitForFunction(([id, w]) => {
  const e = document.querySelector(`[data-testid="${id}"]`);
  return e && (w instanceof RegExp ? w.test(e.textContent) : e.textContent === w);
}, [testid, wanted]);
const getJson = (page, url) => page.evaluate(async (u) => (await fetch(u)).json(), url);
const annUse = () => JSON.parse(cli(server.env, ['quota', '--json']));
const accounts = async () => Object.fromEntries((await getJson(boss, '/api/admin/users')).map((a) => [a.name, a]));

/// The toast `action` brings (an earlier one is hidden first).
async function toastOf(page, action) {
  await page.evaluate(() => { document.getElementById('toast').hidden = true; });
  await action();
  await page.waitForSelector('[data-testid="error-toast"]', { state: 'visible' });
  return page.textContent('[data-testid="error-toast"]');
}

async function openAdmin() {
  await boss.click('#tab-admin');
  await boss.waitForSelector('[data-testid="admin-row-ann"]');
}

/// The quota dialog of `name`: `disk` in MB ('' no limit) or 'default'; runs left as they are.
async function setDisk(name, disk) {
  await boss.click(`[data-testid="admin-quota-${name}"]`);
  await boss.waitForSelector('[data-testid="quota-dialog"]');
  await boss.setChecked('[data-testid="quota-disk-default"]', disk === 'default');
  if (disk !== 'default') await boss.fill('[data-testid="quota-disk"]', disk);
}

// A size as the page and the server write it: "0 B", "840 B", "2.1 kB", "100.0 MB".
const SIZE = String.raw`(\d+ B|\d+\.\d [kMG]B)`;
const DISK_REFUSAL = new RegExp(`^disk quota: this needs ${SIZE} more, and ann uses ${SIZE} of \\d+\\.\\d kB; delete designs or files, or ask an administrator$`);

test('the administrator sets the server default and an account\'s own disk limit', { timeout: 30000 }, async () => {
  await openAdmin();
  const heads = await boss.$$eval('[data-testid="admin-table"] th', (ths) => ths.map((th) => th.textContent));
  assert.deepEqual(heads, ['account', 'role', 'state', 'disk', 'runs today', 'running', 'last sign-in', '']);
  assert.match(await text(boss, 'admin-disk-boss'), new RegExp(`^${SIZE}, no limit \\(default\\)$`));
  assert.equal(await text(boss, 'admin-runs-ann'), '0, no limit (default)');

  await boss.fill('[data-testid="admin-default-disk"]', '100');
  await boss.fill('[data-testid="admin-default-runs"]', '2000');
  await boss.click('[data-testid="admin-default-save"]');
  await textIs(boss, 'admin-note', 'server default: disk 100.0 MB, runs per day 2,000');
  assert.deepEqual(await getJson(boss, '/api/admin/quota'), { disk_limit: 100000000, runs_per_day: 2000 });
  await textIs(boss, 'admin-runs-ann', '0 of 2,000 (default)');
  assert.match(await text(boss, 'admin-disk-ann'), new RegExp(`^${SIZE} of 100\\.0 MB \\(default\\)$`));

  // ann's own limit: 1 kB above what she uses (her projects are database rows: 0 B), less than any mission file.
  annUsed = (await accounts()).ann.disk_bytes;
  annLimit = Math.ceil(annUsed / 1000) * 1000 + 1000;
  await setDisk('ann', String(annLimit / 1e6));
  assert.equal(await boss.isDisabled('[data-testid="quota-runs"]'), true, 'runs follow the default');
  assert.equal(await boss.getAttribute('[data-testid="quota-runs"]', 'placeholder'), '2000');
  await shot(boss, 'quota-dialog');
  await boss.click('[data-testid="quota-ok"]');
  await boss.waitForSelector('[data-testid="quota-dialog"]', { state: 'detached' });
  await textIs(boss, 'admin-note', 'ann: quota set');
  await textIs(boss, 'admin-disk-ann', `${bytesText(annUsed)} of ${bytesText(annLimit)}`);
  assert.equal(await text(boss, 'admin-runs-ann'), '0 of 2,000 (default)');
  const { quota } = (await accounts()).ann;
  assert.deepEqual([quota.disk_limit, quota.disk_from_default, quota.runs_per_day, quota.runs_from_default, quota.runs_today],
    [annLimit, false, 2000, true, 0]);
  await shot(boss, 'accounts');
});

test('the account sees its limits in the top bar', { timeout: 20000 }, async () => {
  await ann.click('#tab-missions');  // a tab shown reads the quota again
  await textIs(ann, 'quota-line', `Disk ${bytesText(annUsed)} of ${bytesText(annLimit)} · runs today 0 of 2,000`);
  const own = await getJson(ann, '/api/quota');
  assert.deepEqual([own.disk_limit, own.runs_per_day, own.runs_today], [annLimit, 2000, 0]);
  await textIs(boss, 'quota-line', new RegExp(`^Disk ${SIZE} of 100\\.0 MB · runs today 0 of 2,000$`));
  await shot(ann, 'own-line');
});

test('a mission past the disk limit is refused with the toast and not written; saved once the limit is lifted', { timeout: 60000 }, async () => {
  const usedBefore = annUse().disk_bytes;
  assert.equal(usedBefore, annUsed);
  const file = path.join(server.env.SWARMDESIGN_HOME, 'users', 'ann', 'projects', 'first', 'missions', 'my-aac.json');
  await ann.click('#me-details summary');
  await ann.waitForFunction(() => document.querySelectorAll('#me-template option').length > 10);
  await ann.waitForFunction(() => document.getElementById('me-project').value === 'first');
  await ann.selectOption('#me-template', 'aac');
  await ann.waitForFunction(() => !document.getElementById('me-save').disabled);
  const saved = await toastOf(ann, () => ann.click('#me-save'));
  assert.match(saved, DISK_REFUSAL);
  assert.equal(await ann.textContent('#me-status'), saved, 'the editor says it too');
  await shot(ann, 'mission-save-refused');

  await ann.selectOption('#upload-project', 'first');
  await ann.setInputFiles('#upload-file', { name: 'corner.json', mimeType: 'application/json', buffer: readFileSync(path.join(here, '..', '..', 'missions', 'aac.json')) });
  await ann.fill('#upload-name', 'corner');
  const uploaded = await toastOf(ann, () => ann.click('#upload-button'));
  assert.match(uploaded, DISK_REFUSAL);
  await textIs(ann, 'upload-status', uploaded);
  await shot(ann, 'upload-refused');
  for (const t of [saved, uploaded]) assert.ok(!t.includes('\n'), t);

  assert.equal(existsSync(file), false);
  assert.deepEqual(await getJson(ann, '/api/projects/first/missions'), []);
  assert.equal(annUse().disk_bytes, usedBefore, 'not a byte written');

  // The administrator puts ann back on the server's default (100 MB): the same save goes through.
  await openAdmin();
  await setDisk('ann', 'default');
  await boss.click('[data-testid="quota-ok"]');
  await textIs(boss, 'admin-disk-ann', /of 100\.0 MB \(default\)$/);
  const line = await text(ann, 'quota-line');
  await ann.click('#me-save');
  await textIs(ann, 'me-status', /^saved as first\/missions\/my-aac\.json/);
  assert.equal(await ann.isVisible('[data-testid="error-toast"]'), false);
  assert.equal(existsSync(file), true);
  await ann.waitForFunction((was) => document.querySelector('[data-testid="quota-line"]').textContent !== was, line);
  assert.match(await text(ann, 'quota-line'), new RegExp(`^Disk ${SIZE} of 100\\.0 MB · runs today 0 of 2,000$`));
  assert.ok(annUse().disk_bytes > usedBefore);
  await shot(ann, 'mission-saved');
});

test('a design start past the day\'s runs is refused with the toast and no design starts', { timeout: 60000 }, async () => {
  await ann.click('#tab-designs');
  await ann.click('[data-testid="project-first"]');
  await ann.waitForFunction(() => document.getElementById('monitor-project').textContent === 'first');
  await ann.waitForFunction(() => document.getElementById('design-budget').value === '1400');
  await ann.click('#design-start');
  await textIs(ann, 'quota-line', /· runs today 1,400 of 2,000$/);

  await ann.click('[data-testid="project-second"]');
  await ann.waitForFunction(() => document.getElementById('monitor-project').textContent === 'second');
  await ann.waitForFunction(() => document.getElementById('design-budget').value === '1400');
  const refused = await toastOf(ann, () => ann.click('#design-start'));
  assert.match(refused, /^runs quota: this design needs 1400 runs, and ann has 600 of 2000 runs left today \(UTC\); [^\n]+$/);
  await shot(ann, 'design-refused');
  assert.deepEqual(await getJson(ann, '/api/projects/second/designs'), []);
  await textIs(ann, 'design-list', 'no design yet');
  assert.match(await text(ann, 'quota-line'), /· runs today 1,400 of 2,000$/, 'a refused start counts nothing');
  assert.equal(annUse().runs_today, 1400);
  assert.equal((await getJson(ann, '/api/projects/first/designs')).length, 1);
  await ann.evaluate(() => fetch('/api/projects/first/designs/stop', { method: 'POST', headers: { 'Content-Type': 'application/json', 'X-CSRF-Token': window.__sdCsrf || '' }, body: '{}' }));

  await openAdmin();
  await textIs(boss, 'admin-runs-ann', '1,400 of 2,000 (default)');
  await shot(boss, 'accounts-runs');
  assert.deepEqual(errors, []);
});
