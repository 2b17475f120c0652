// The mission editor, in headless chromium against the real server: a mission started from the
// catalogue's AAC, changed in the form (walls, a patch, a light, the robots, the objective's
// kind), drawn live as the server checks it, refused with the upload's one line when its walls
// leave no room, saved into a project as JSON the CLI reads and scores the same; a second
// account cannot preview into or save into the project.
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { cli, screenshotter, signedInPages, startServer } from './helpers.mjs';

let server;
let browser;
let page;
let other;
const errors = [];
const shot = screenshotter('mission-editor');
const FSM = '--fsm-config --nstates 1 --s0 10 --rwm0 50';

before(async () => {
  server = await startServer({ users: [
    { name: 'liv', projects: [{ name: 'lab', mission: 'aac', budget: 2000 }] },
    { name: 'max', projects: [{ name: 'lab', mission: 'aac', budget: 2000 }] },
  ] });
  ({ browser, pages: [page, other] } = await signedInPages(server, ['liv', 'max'], errors));
}, { timeout: 60000 });

after(async () => {
  if (browser) await browser.close();
  if (server) await server.close();
});

const status = () => page.textContent('#me-status');
const settled = () => page.waitForFunction(() => {
  const s = document.getElementById('me-status');
  return s.classList.contains('done') || s.classList.contains('error');
});
/// Does `action`, then waits for the drawing (or the refusal) it brings.
async function after_(action) {
  await page.evaluate(() => { document.getElementById('me-status').className = 'small'; });
  await action();
  await settled();
}
const edit = (testid, value) => after_(() => page.fill(`input[data-testid="${testid}"]`, String(value)));

test('a mission from AAC, changed in the form, is drawn live and saved as JSON the CLI reads', { timeout: 60000 }, async () => {
  await page.click('#tab-missions');
  await page.click('#me-details summary');
  await page.waitForFunction(() => document.querySelectorAll('#me-template option').length > 10);
  await page.waitForFunction(() => document.getElementById('me-project').value === 'lab');
  await after_(() => page.selectOption('#me-template', 'aac'));
  assert.match(await status(), /^Aggregation with ambient cues \(copy\): 20 robots, 120 s/);
  assert.equal(await page.inputValue('[data-testid="me-file-name"]'), 'my-aac');
  const drawn = await page.innerHTML('#me-drawing');
  assert.match(drawn, /^<svg/);

  await edit('me-robots', 12);
  await edit('me-duration', 30);
  await after_(() => page.selectOption('[data-testid="me-walls"]', 'rectangle'));
  await edit('me-width', 2);
  assert.match(await status(), /start: reaches outside the walls/, 'a start region wider than the arena is named');
  await after_(() => page.fill('[data-testid="me-start"] label:has-text("radius") input', '0.9'));
  assert.match(await status(), /12 robots, 30 s/);
  await after_(() => page.click('[data-testid="me-add-patch"]'));
  await after_(() => page.click('[data-testid="me-add-light"]'));
  await after_(() => page.selectOption('[data-testid="me-objective"]', 'best_region_fraction_at_end'));
  assert.match(await status(), /12 robots, 30 s, best_region_fraction_at_end/);
  assert.notEqual(await page.innerHTML('#me-drawing'), drawn, 'the drawing follows the form');
  const doc = JSON.parse(await page.inputValue('#me-json'));
  assert.equal(doc.arena.walls.length, 4);
  assert.equal(doc.arena.floor.patches.length, 3);
  assert.equal(doc.arena.lights.length, 2);
  assert.equal(doc.objective.type, 'best_region_fraction_at_end');
  // Scored on this floor's black patches (AAC's and the one added), not the example's regions.
  assert.deepEqual(doc.objective.regions, doc.arena.floor.patches.filter((p) => p.color === 'black').map((p) => p.region));
  assert.equal(doc.objective.regions.length, 2);
  await shot(page, 'edited');

  await page.click('#me-save');
  await page.waitForFunction(() => /^saved as lab\/missions\/my-aac\.json/.test(document.getElementById('me-status').textContent));
  const file = path.join(server.env.SWARMDESIGN_HOME, 'users', 'liv', 'projects', 'lab', 'missions', 'my-aac.json');
  assert.deepEqual(JSON.parse(readFileSync(file, 'utf8')), doc);
  // The CLI reads the file and scores it; the page lists it with the catalogue.
  const shown = JSON.parse(cli(server.env, ['mission', 'show', file, '--json']));
  assert.equal(shown.robots, 12);
  cli(server.env, ['evaluate', '--mission', file, '--seed', '1', ...FSM.split(' ')]);
  await page.waitForSelector('.mission-card >> text=my-aac');
});

test('walls that leave no room, or broken JSON, get one line and cannot be saved', { timeout: 30000 }, async () => {
  await edit('me-width', 0.05);
  assert.match(await status(), /^mission 'my-aac': start: reaches outside the walls|cannot place robot/);
  assert.ok(!(await status()).includes('\n'));
  assert.equal(await page.isDisabled('#me-save'), true);
  await shot(page, 'no-room');
  await page.fill('#me-json', '{"name": ');
  await page.waitForFunction(() => /^not valid JSON/.test(document.getElementById('me-status').textContent));
  assert.equal(await page.isDisabled('#me-save'), true);
});

test('a second account can neither draw into nor save into the project', { timeout: 30000 }, async () => {
  const text = JSON.stringify({ name: 'x' });
  const answers = await other.evaluate(async (body) => {
    const post = (r) => fetch(r, { method: 'POST', headers: { 'Content-Type': 'application/json', 'X-CSRF-Token': window.__sdCsrf }, body }).then((x) => x.status);
    return [await post('/api/projects/lab/missions/preview'), await post('/api/projects/lab/missions')];
  }, JSON.stringify({ name: 'x', text }));
  // max's own lab exists: his requests reach his project, never liv's; liv's file stays hers.
  assert.deepEqual(answers, [400, 400]);
  const file = path.join(server.env.SWARMDESIGN_HOME, 'users', 'liv', 'projects', 'lab', 'missions', 'my-aac.json');
  const status2 = await other.evaluate(async (f) => (await fetch('/api/missions/text?name=' + encodeURIComponent(f))).status, file);
  assert.equal(status2, 404);
  assert.deepEqual(errors, []);
});
