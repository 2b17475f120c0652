// Sign-up on the page by the server's policy (issue #56), in headless chromium against the real
// server run with `--sign-up invite`: the administrator (the first account) makes an invitation
// on the Admin tab and sees its link once; someone else opens the link in another browser
// context (or pastes it into a sign-in page already open), finds the sign-up form with the code
// filled in (and gone from the address bar), signs up and lands signed in, not an administrator;
// the same link again is refused in one line; a password against the rule is refused naming it
// and leaves the invitation unused; a revoked invitation is refused; and a server with the
// default policy (closed) shows no sign-up at all.
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';
import { cli, launchBrowser, newPage, screenshotter, signIn, startServer } from './helpers.mjs';

const INVALID = 'this invitation is not valid (used, expired or revoked): ask for another';
let server;
let browser;
let boss;
let link;  // the invitation made on the Admin tab
const errors = [];
const shot = screenshotter('sign-up');

before(async () => {
  // boss signs up first, at the terminal: the home's administrator; the CLI stays signed in as boss.
  server = await startServer({ users: [{ name: 'boss' }], serverArgs: ['--sign-up', 'invite'] });
  browser = await launchBrowser();
  boss = await newPage(browser, errors, { width: 1280, height: 800 });
  await signIn(boss, server.url, 'boss');
}, { timeout: 60000 });

after(async () => {
  if (browser) await browser.close();
  if (server) await server.close();
});

const getJson = (page, url) => page.evaluate(async (u) => (await fetch(u)).json(), url);
const listed = () => JSON.parse(cli(server.env, ['admin', 'invitations', '--json']));

async function openAdmin() {
  await boss.click('#tab-admin');
  await boss.waitForSelector('#admin-invitations tr');
}

/// A fresh browser context (no cookie) at `url`, its sign-up form open.
async function signUpPage(url) {
  const page = await newPage(browser, errors, { width: 1000, height: 720 });
  await page.goto(url);
  await page.waitForSelector('#signup-form', { state: 'visible' });
  return page;
}

async function fillSignUp(page, name, password, again = password) {
  await page.fill('#signup-name', name);
  await page.fill('#signup-password', password);
  await page.fill('#signup-again', again);
}

/// The one-line error of a refused sign-up.
async function refusal(page) {
  await page.evaluate(() => { document.getElementById('signup-error').hidden = true; });
  await page.click('#signup-submit');
  await page.waitForSelector('#signup-error', { state: 'visible' });
  return page.textContent('#signup-error');
}

test('the administrator makes an invitation on the Admin tab and sees its link once', { timeout: 30000 }, async () => {
  assert.deepEqual(await getJson(boss, '/api/sign-up'), { policy: 'invite' });
  await openAdmin();
  await boss.waitForSelector('[data-testid="invitations-none"]');
  assert.match(await boss.textContent('#invite-policy'), /sign-ups by invitation/);
  await boss.click('[data-testid="invite-button"]');
  await boss.waitForSelector('[data-testid="invite-dialog"]');
  assert.equal(await boss.inputValue('[data-testid="invite-days"]'), '7');
  await shot(boss, 'invite-dialog');
  const asked = Math.floor(Date.now() / 1000);
  await boss.click('[data-testid="invite-ok"]');
  await boss.waitForSelector('[data-testid="invite-link"]');
  link = await boss.inputValue('[data-testid="invite-link"]');
  const origin = new URL(server.url).origin;
  const code = await boss.textContent('[data-testid="invite-code"]');
  assert.match(code, /^[A-Za-z2-9]{24}$/);
  assert.equal(link, `${origin}/#invite=${code}`);
  assert.match(await boss.textContent('[data-testid="invite-once"]'), /^Shown only now/);
  await boss.click('[data-testid="invite-copy"]');
  await boss.waitForFunction(() => document.querySelector('[data-testid="invite-copied"]').textContent !== '');
  await shot(boss, 'invitation-shown-once');
  await boss.click('[data-testid="invite-close"]');
  await boss.waitForSelector('[data-testid="invite-dialog"]', { state: 'detached' });
  assert.equal(await boss.isVisible(`text=${code}`), false, 'the code is gone from the page');

  // The table: open, made by boss, valid a week; the server's list has no code.
  const [made] = await getJson(boss, '/api/admin/invitations');
  assert.equal(made.code, undefined);
  assert.deepEqual([made.state, made.created_by, made.used_by], ['open', 'boss', null]);
  assert.ok(Math.abs(made.expires_at - (asked + 7 * 86400)) < 60, `expires ${made.expires_at}`);
  const row = await boss.$$eval(`[data-testid="invitation-row-${made.id}"] td`, (tds) => tds.map((td) => td.textContent));
  assert.equal(row[0], String(made.id));
  assert.deepEqual(row.slice(1, 3), ['open', 'boss']);
  assert.match(row[3], /^\d{4}-\d\d-\d\d \d\d:\d\d UTC$/);
  assert.deepEqual(row.slice(4), ['', 'Revoke']);
});

test('the link opens the sign-up form; the new account lands signed in and is no administrator', { timeout: 30000 }, async () => {
  const page = await signUpPage(link);
  const code = link.split('#invite=')[1];
  assert.equal(await page.inputValue('#signup-invitation'), code);
  assert.equal(new URL(page.url()).hash, '', 'the code left the address bar');
  assert.equal(await page.isVisible('#signin-form'), false);
  await fillSignUp(page, 'newbie', 'newbie-secret-1', 'newbie-secret-2');
  assert.equal(await refusal(page), 'The two passwords differ.');
  await page.fill('#signup-again', 'newbie-secret-1');
  assert.equal(await page.isVisible('#signup-error'), false, 'typing again clears the error');
  await shot(page, 'form-with-code');
  await page.click('#signup-submit');
  await page.waitForSelector('body[data-ready="true"]');
  assert.equal(await page.textContent('[data-testid="user-name"]'), 'newbie');
  assert.equal(await page.isVisible('#tab-admin'), false);
  const session = await getJson(page, '/api/session');
  assert.deepEqual([session.user, session.admin], ['newbie', false]);
  assert.equal(await page.evaluate(async () => (await fetch('/api/admin/invitations')).status), 403);
  await shot(page, 'signed-in');
  await page.close();
  // The administrator's table says who used the invitation, and lists the new account.
  await openAdmin();
  await boss.waitForSelector('[data-testid="admin-row-newbie"]');
  const [used] = await getJson(boss, '/api/admin/invitations');
  await boss.waitForFunction((id) => document.querySelector(`[data-testid="invitation-state-${id}"]`).textContent === 'used', used.id);
  assert.match(await boss.textContent(`[data-testid="invitation-used-${used.id}"]`), /^newbie, \d{4}-\d\d-\d\d \d\d:\d\d UTC$/);
  assert.equal(await boss.isVisible(`[data-testid="invitation-revoke-${used.id}"]`), false);
});

test('the same link again is refused in one line, and no account is made', { timeout: 30000 }, async () => {
  // This time pasted into a sign-in page already open: only the hash changes.
  const page = await newPage(browser, errors, { width: 1000, height: 720 });
  await page.goto(server.url);
  await page.waitForSelector('#signin[data-sign-up="invite"]');
  await page.goto(link);
  await page.waitForSelector('#signup-form', { state: 'visible' });
  assert.equal(new URL(page.url()).hash, '');
  // Back and forth: the sign-in form offers sign-up on this server; the code stays filled in.
  await page.click('[data-testid="signup-show-signin"]');
  assert.equal(await page.isVisible('#signin-form'), true);
  assert.equal(await page.isVisible('[data-testid="signin-to-signup"]'), true);
  await shot(page, 'sign-in-offers-sign-up');
  await page.click('[data-testid="signin-show-signup"]');
  assert.equal(await page.inputValue('#signup-invitation'), link.split('#invite=')[1]);
  await fillSignUp(page, 'second', 'second-secret-1');
  const text = await refusal(page);
  assert.equal(text, INVALID);
  assert.ok(!text.includes('\n'));
  assert.equal(await page.isVisible('#app'), false);
  await shot(page, 'used-refused');
  await page.close();
  assert.equal((await getJson(boss, '/api/admin/users')).some((a) => a.name === 'second'), false);
});

test('a password against the rule leaves the invitation unused; once revoked, it is refused', { timeout: 30000 }, async () => {
  const made = JSON.parse(cli(server.env, ['admin', 'invite', '--json']));
  const page = await signUpPage(`${server.url}#invite=${made.code}`);
  await fillSignUp(page, 'third', 'short');
  assert.match(await refusal(page), /^password is too short: /);
  assert.equal(listed().find((i) => i.id === made.id).state, 'open');

  await openAdmin();
  await boss.click(`[data-testid="invitation-revoke-${made.id}"]`);
  await boss.waitForSelector('[data-testid="confirm-dialog"]');
  await shot(boss, 'revoke-confirm');
  await boss.click('[data-testid="confirm-ok"]');
  // It stays listed, revoked, with nothing left to do to it.
  await boss.waitForFunction((id) => document.querySelector(`[data-testid="invitation-state-${id}"]`)?.textContent === 'revoked', made.id);
  assert.equal(await boss.textContent('[data-testid="invite-note"]'), `invitation ${made.id} revoked`);
  assert.equal(await boss.$(`[data-testid="invitation-revoke-${made.id}"]`), null);
  assert.equal(listed().find((i) => i.id === made.id).state, 'revoked');
  await shot(boss, 'invitations-table');

  await fillSignUp(page, 'third', 'third-secret-1');
  assert.equal(await refusal(page), INVALID);
  await page.close();
  assert.deepEqual(errors, []);
});

test('a server with the default policy (closed) shows no sign-up at all', { timeout: 30000 }, async () => {
  const closed = await startServer();  // no account needed: closed is refused first
  try {
    const page = await newPage(browser, errors, { width: 1000, height: 720 });
    await page.goto(closed.url);
    await page.waitForSelector('#signin[data-sign-up="closed"]');
    assert.deepEqual(await getJson(page, '/api/sign-up'), { policy: 'closed' });
    assert.equal(await page.isVisible('#signin-form'), true);
    assert.equal(await page.isVisible('#signup-form'), false);
    assert.equal(await page.isVisible('[data-testid="signin-to-signup"]'), false);
    assert.equal(await page.isVisible('#signin-error'), false);
    // An invitation link (for another server, say) opens no sign-up form here: it says why.
    await page.goto(`${closed.url}#invite=abcdefghijkmnpqrstuvwxyz`);
    await page.waitForSelector('#signin-error', { state: 'visible' });
    assert.match(await page.textContent('#signin-error'), /^This invitation link does not work here: sign-up is closed/);
    assert.equal(await page.isVisible('#signup-form'), false);
    assert.equal(new URL(page.url()).hash, '');
    await shot(page, 'closed');
    // Asked anyway, the server refuses.
    const status = await page.evaluate(async () => (await fetch('/api/sign-up', { method: 'POST', headers: { 'Content-Type': 'application/json' },
      body: JSON.stringify({ name: 'x', password: 'x-secret-123', invitation: 'abc' }) })).status);
    assert.equal(status, 403);
    await page.close();
  } finally {
    await closed.close();
  }
  assert.deepEqual(errors, []);
});
