// A project's mission chosen from the page (issue #56), in headless chromium against the real
// server: a mission uploaded into one project becomes another project's mission with Set
// mission, and that project designs with it; a second account cannot name the first's file
// (refused, nothing changed); deleting the project that holds the file names, in its dialog,
// the project that uses it, which then says "its mission file was deleted" and takes a mission
// the user writes in the mission editor.
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { after, before, test } from 'node:test';
import { cli, PASSWORD, screenshotter, signedInPages, startServer } from './helpers.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
let server;
let browser;
let page;
let other;
let file;  // ida's uploaded mission, as the page names it
const errors = [];
const shot = screenshotter('project-mission');

/// The catalogue's AAC as `name`, 2 s long: a design of 1400 runs on it takes seconds.
function mission(name) {
  const text = readFileSync(path.join(here, '..', '..', 'missions', 'aac.json'), 'utf8')
    .split('\n').filter((l) => !l.trim().startsWith('//')).join('\n');
  const doc = JSON.parse(text);
  Object.assign(doc, { name, title: `Corner of ${name}`, duration: 2 });
  delete doc.argos;
  return JSON.stringify(doc, null, 1);
}

before(async () => {
  server = await startServer({ users: [
    { name: 'ida', projects: [{ name: 'holder', mission: 'aac', budget: 1400 }, { name: 'user', mission: 'aac', budget: 1400 }] },
    { name: 'jon', projects: [{ name: 'jons', mission: 'aac', budget: 1400 }] },
  ] });
  ({ browser, pages: [page, other] } = await signedInPages(server, ['ida', 'jon'], errors));
  cli(server.env, ['sign-in', 'ida', '--password-stdin'], `${PASSWORD}\n`);  // the CLI below is ida's
}, { timeout: 60000 });

after(async () => {
  if (browser) await browser.close();
  if (server) await server.close();
});

const projects = (p) => p.evaluate(async () => (await fetch('/api/projects')).json());
const project = async (p, name) => (await projects(p)).find((x) => x.name === name);
const note = () => page.textContent('#project-mission-note');

async function openProject(p, name) {
  await p.click('#tab-designs');
  await p.click(`[data-testid="project-${name}"]`);
  await p.waitForFunction((n) => document.getElementById('monitor-project').textContent === n, name);
  await p.waitForSelector('#project-mission-form:not([hidden])');
}

async function setMission(value) {
  await page.selectOption('#project-set-mission', value);
  await page.click('#project-set-mission-button');
  await page.waitForFunction(() => /^(done|error)$/.test(document.getElementById('project-mission-note').className));
}

test('an uploaded mission becomes another project\'s mission from the page, and it designs with it', { timeout: 180000 }, async () => {
  await page.click('#tab-missions');
  await page.waitForFunction(() => document.getElementById('upload-project').options.length === 2);
  await page.selectOption('#upload-project', 'holder');
  await page.setInputFiles('#upload-file', { name: 'corner.json', mimeType: 'application/json', buffer: Buffer.from(mission('corner')) });
  await page.click('#upload-button');
  await page.waitForSelector('#upload-status.done');
  file = path.join(server.env.SWARMDESIGN_HOME, 'users', 'ida', 'projects', 'holder', 'missions', 'corner.json');

  await openProject(page, 'user');
  assert.equal(await page.inputValue('#project-set-mission'), 'aac', 'the form starts from the project\'s mission');
  const offered = await page.$$eval('#project-set-mission option', (os) => os.map((o) => o.value));
  assert.ok(offered.includes(file) && offered.includes('aac'), offered.join(' '));
  await setMission(file);
  assert.equal(await note(), 'mission set to holder/corner.json');
  await page.waitForFunction(() => document.querySelector('[data-testid="project-user"]').textContent.includes('holder/corner.json'));
  assert.equal((await project(page, 'user')).mission, file);
  // The CLI's project is the page's: set-mission's service made it the active one.
  assert.equal(JSON.parse(cli(server.env, ['active-project', '--json'])).mission, file);
  await shot(page, 'set-to-uploaded');

  // It designs with it: a small design runs to its end on the uploaded mission.
  await page.selectOption('#design-preset', 'chocolate');
  await page.click('#design-start');
  await page.waitForFunction(() => /^finished/.test(document.getElementById('design-state').textContent), null, { timeout: 160000, polling: 500 });
  const designs = await page.evaluate(async () => (await fetch('/api/projects/user/designs')).json());
  assert.equal(designs[0].mission, file);
  assert.match(await page.textContent('#design-info'), /holder\/corner\.json/);
  assert.equal(await page.isDisabled('#project-set-mission-button'), false, 'a finished design leaves the mission free');
  await shot(page, 'designed-with-it');
  assert.deepEqual(errors, []);
});

test('a second account cannot set the first\'s mission file: refused, nothing changed', { timeout: 30000 }, async () => {
  await openProject(other, 'jons');
  const offered = await other.$$eval('#project-set-mission option', (os) => os.map((o) => o.value));
  assert.ok(!offered.includes(file), 'ida\'s file is not offered to jon');
  const answers = await other.evaluate(async (f) => {
    const post = (url, body) => fetch(url, { method: 'POST', headers: { 'Content-Type': 'application/json', 'X-CSRF-Token': window.__sdCsrf }, body: JSON.stringify(body) })
      .then(async (r) => [r.status, (await r.json()).error]);
    return { own: await post('/api/projects/jons/mission', { mission: f }), hers: await post('/api/projects/user/mission', { mission: 'aac' }) };
  }, file);
  assert.equal(answers.own[0], 404);
  assert.match(answers.own[1], /is not a file of your projects/);
  assert.equal(answers.hers[0], 404, 'nor her project');
  assert.equal((await project(other, 'jons')).mission, 'aac');
  assert.equal((await project(page, 'user')).mission, file);
  // The same refusal through jon's own form, a file typed in as a forged option.
  await other.evaluate((f) => {
    const select = document.getElementById('project-set-mission');
    select.append(Object.assign(document.createElement('option'), { value: f, text: 'forged' }));
    select.value = f;
  }, file);
  await other.click('#project-set-mission-button');
  await other.waitForSelector('#project-mission-note.error');
  assert.match(await other.textContent('#project-mission-note'), /is not a file of your projects/);
  assert.equal((await project(other, 'jons')).mission, 'aac');
  await shot(other, 'second-account-refused');
});

test('deleting the project that holds the file names its user, which then says so and takes another mission', { timeout: 90000 }, async () => {
  await openProject(page, 'holder');
  assert.deepEqual((await project(page, 'holder')).mission_used_by, ['user']);
  await page.click('#project-delete');
  await page.waitForSelector('[data-testid="confirm-warning"]');
  const warning = await page.textContent('[data-testid="confirm-warning"]');
  assert.match(warning, /^Project user uses a mission file of holder/);
  assert.match(warning, /its mission file was deleted/);
  await page.fill('[data-testid="confirm-name"]', 'holder');
  await shot(page, 'delete-names-user');
  await page.click('[data-testid="confirm-ok"]');
  await page.waitForSelector('[data-testid="project-holder"]', { state: 'detached' });

  // The page turns to the project left without a mission and offers the choice.
  await page.waitForFunction(() => document.getElementById('monitor-project').textContent === 'user');
  await page.waitForFunction(() => document.getElementById('project-mission-note').className === 'problem');
  assert.equal(await note(), 'holder/corner.json: its mission file was deleted. Choose another mission and Set mission.');
  assert.match(await page.textContent('[data-testid="project-user"]'), /mission file deleted/);
  assert.equal(await page.inputValue('#project-set-mission'), '', 'no mission chosen for it');
  assert.equal((await project(page, 'user')).mission_problem, 'its mission file was deleted');
  assert.match(cli(server.env, ['active-project']), /its mission file was deleted/);
  // Its finished design stays, on the mission it was made with.
  await page.waitForFunction(() => /^finished/.test(document.getElementById('design-state').textContent));
  await shot(page, 'mission-deleted');
  // Start says why in the project's words, not as someone else's file.
  await page.click('#design-start');
  await page.waitForSelector('#toast:not([hidden])');
  assert.match(await page.textContent('#toast'), /^project user: its mission file was deleted; choose another mission/);
  await shot(page, 'start-refused');

  // A mission written in the editor, into this project, then chosen for it.
  await page.click('#tab-missions');
  await page.click('#me-details summary');
  await page.waitForFunction(() => document.querySelectorAll('#me-template option').length > 10);
  await page.selectOption('#me-project', 'user');
  await page.selectOption('#me-template', 'aac');
  await page.waitForFunction(() => document.getElementById('me-status').classList.contains('done'));
  await page.fill('[data-testid="me-file-name"]', 'edited');
  await page.waitForFunction(() => document.getElementById('me-status').classList.contains('done') && !document.getElementById('me-save').disabled);
  await page.click('#me-save');
  await page.waitForFunction(() => /^saved as user\/missions\/edited\.json/.test(document.getElementById('me-status').textContent));
  const edited = path.join(server.env.SWARMDESIGN_HOME, 'users', 'ida', 'projects', 'user', 'missions', 'edited.json');
  await openProject(page, 'user');
  await page.waitForFunction((f) => [...document.querySelectorAll('#project-set-mission option')].some((o) => o.value === f), edited);
  await setMission(edited);
  assert.equal(await note(), 'mission set to user/edited.json');
  const now = await project(page, 'user');
  assert.equal(now.mission, edited);
  assert.equal(now.mission_problem, null);
  await page.waitForFunction(() => !document.querySelector('[data-testid="project-user"]').textContent.includes('deleted'));
  await page.waitForFunction(() => /^finished/.test(document.getElementById('design-state').textContent));
  await page.waitForTimeout(1500);  // only for the picture: the best's drawing is laid out after its parse
  await shot(page, 'another-mission');
  assert.deepEqual(errors, []);
});
