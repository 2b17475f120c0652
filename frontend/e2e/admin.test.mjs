// A lab's server administered from the page (issue #56), in headless chromium against the real
// server: the first account sees the Admin tab with every account's use, disables one (its open
// page is signed out, it cannot sign in), gives one a new password shown once, makes one an
// administrator and deletes one with its files; a second account sees no Admin tab and the
// server refuses it anyway; and a user changes their own password on the page.
import assert from 'node:assert/strict';
import { existsSync } from 'node:fs';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { cli, PASSWORD, screenshotter, signedInPages, startServer, newPage } from './helpers.mjs';

let server;
let browser;
let boss;
let ann;
const errors = [];
const shot = screenshotter('admin');

before(async () => {
  // boss signs up first: the home's administrator.
  server = await startServer({ users: [
    { name: 'boss', projects: [{ name: 'lab', mission: 'aac', budget: 1400 }] },
    { name: 'ann', projects: [{ name: 'ann-work', mission: 'aac', budget: 1400 }] },
    { name: 'cid', projects: [{ name: 'cid-work', mission: 'aac', budget: 1400 }] },
  ] });
  ({ browser, pages: [boss, ann] } = await signedInPages(server, ['boss', 'ann'], errors));
}, { timeout: 60000 });

after(async () => {
  if (browser) await browser.close();
  if (server) await server.close();
});

const state = (page, name) => page.textContent(`[data-testid="admin-state-${name}"]`);

async function openAdmin(page) {
  await page.click('#tab-admin');
  await page.waitForSelector('[data-testid="admin-row-cid"]');
}

test('only the administrator has the Admin tab, and the server refuses anyone else', { timeout: 60000 }, async () => {
  assert.equal(await boss.isVisible('#tab-admin'), true);
  assert.equal(await ann.isVisible('#tab-admin'), false);
  await openAdmin(boss);
  const rows = await boss.$$eval('#admin-accounts tr', (trs) => trs.map((tr) => tr.dataset.testid));
  assert.deepEqual(rows, ['admin-row-ann', 'admin-row-boss', 'admin-row-cid']);
  assert.match(await boss.textContent('[data-testid="admin-row-boss"]'), /bossadminactive.*you/);
  await shot(boss, 'accounts');
  // Ann, asking anyway with her own session and CSRF token, is refused.
  const status = await ann.evaluate(async () => {
    const session = await (await fetch('/api/session')).json();
    const list = await fetch('/api/admin/users');
    const disable = await fetch('/api/admin/users/cid/disable', { method: 'POST', headers: { 'Content-Type': 'application/json', 'X-CSRF-Token': session.csrf }, body: '{}' });
    return [session.admin, list.status, disable.status];
  });
  assert.deepEqual(status, [false, 403, 403]);
  assert.equal(await state(boss, 'cid'), 'active');
});

test('a disabled account is signed out and cannot sign in; enabled, it can again', { timeout: 60000 }, async () => {
  await openAdmin(boss);
  await boss.click('[data-testid="admin-disable-ann"]');
  await boss.waitForFunction(() => document.querySelector('[data-testid="admin-state-ann"]').textContent === 'disabled');
  await shot(boss, 'disabled');
  // Ann's open page: its next request finds no session.
  assert.equal(await ann.evaluate(async () => (await fetch('/api/projects')).status), 401);
  const fresh = await newPage(browser, errors);
  await fresh.goto(server.url);
  await fresh.fill('#signin-name', 'ann');
  await fresh.fill('#signin-password', PASSWORD);
  await fresh.click('#signin-submit');
  await fresh.waitForSelector('#signin-error', { state: 'visible' });
  assert.match(await fresh.textContent('#signin-error'), /account 'ann' is disabled; ask the server's administrator/);
  await shot(fresh, 'disabled-sign-in');
  await boss.click('[data-testid="admin-enable-ann"]');
  await boss.waitForFunction(() => document.querySelector('[data-testid="admin-state-ann"]').textContent === 'active');
  await fresh.click('#signin-submit');
  await fresh.waitForSelector('body[data-ready="true"]');
  await fresh.close();
});

test('a new password is shown once, the old one stops working, and the user changes it on the page', { timeout: 90000 }, async () => {
  await openAdmin(boss);
  await boss.click('[data-testid="admin-reset-cid"]');
  await boss.waitForSelector('[data-testid="admin-new-password"]');
  const password = await boss.textContent('[data-testid="admin-new-password"]');
  assert.match(password, /^[A-Za-z2-9]{20}$/);
  await shot(boss, 'new-password');
  assert.throws(() => cli(server.env, ['sign-in', 'cid', '--password-stdin'], `${PASSWORD}\n`));
  const cid = await newPage(browser, errors);
  await cid.goto(server.url);
  await cid.fill('#signin-name', 'cid');
  await cid.fill('#signin-password', password);
  await cid.click('#signin-submit');
  await cid.waitForSelector('body[data-ready="true"]');
  await cid.click('[data-testid="user-name"]');
  await cid.fill('[data-testid="password-current"]', password);
  await cid.fill('[data-testid="password-new"]', 'cid-own-secret');
  await cid.fill('[data-testid="password-again"]', 'cid-own-secret-typo');
  await cid.click('[data-testid="password-ok"]');
  assert.equal(await cid.textContent('[data-testid="password-message"]'), 'The two new passwords differ.');
  await cid.fill('[data-testid="password-again"]', 'cid-own-secret');
  await cid.click('[data-testid="password-ok"]');
  await cid.waitForFunction(() => document.querySelector('[data-testid="password-message"]').textContent === 'Password changed.');
  await shot(cid, 'password-changed');
  await cid.click('[data-testid="password-cancel"]');
  assert.equal(await cid.evaluate(async () => (await fetch('/api/projects')).status), 200, 'this page stays signed in');
  cli(server.env, ['sign-in', 'cid', '--password-stdin'], 'cid-own-secret\n');
  await cid.close();
});

test('an account made administrator sees the tab; a deleted one is gone with its files', { timeout: 60000 }, async () => {
  await openAdmin(boss);
  await boss.click('[data-testid="admin-role-cid"]');
  await boss.waitForFunction(() => document.querySelector('[data-testid="admin-role-cid"]').textContent === 'Make user');
  const folder = path.join(server.env.SWARMDESIGN_HOME, 'users', 'cid');
  assert.equal(existsSync(folder), true);
  await boss.click('[data-testid="admin-delete-cid"]');
  await boss.waitForSelector('[data-testid="confirm-dialog"]');
  await boss.fill('[data-testid="confirm-name"]', 'cid');
  await shot(boss, 'delete-confirm');
  await boss.click('[data-testid="confirm-ok"]');
  await boss.waitForFunction(() => !document.querySelector('[data-testid="admin-row-cid"]'));
  assert.equal(existsSync(folder), false);
  assert.equal(existsSync(path.join(server.env.SWARMDESIGN_HOME, 'users', 'ann', 'projects', 'ann-work')), true);
  await shot(boss, 'deleted');
  assert.deepEqual(errors, []);
});
