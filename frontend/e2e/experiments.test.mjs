// Experiments from the page, in headless chromium against the real server: a thesis protocol
// planned with the CLI's choices; the user's own protocol file started, followed (its design's
// race as it goes), stopped, resumed and finished, with its report and data downloadable; one
// started by the CLI shows up live; a second account sees and touches none of it.
import assert from 'node:assert/strict';
import { spawn } from 'node:child_process';
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { after, before, test } from 'node:test';
import { BIN, cli, PASSWORD, screenshotter, signedInPages, startServer } from './helpers.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
let server;
let browser;
let page;
let other;
const errors = [];
const shot = screenshotter('experiments');
let missionFile;

/// One short mission, two conditions, one design each, three assessment seeds.
const protocol = (name, budget) => JSON.stringify({ name, designs: 1, assessment_seeds: 3, missions: [{ mission: missionFile, budget,
  conditions: [{ name: 'fsm', architectures: ['fsm'], flavours: ['chocolate'] }, { name: 'bt', architectures: ['bt'], flavours: ['maple'] }] }] });

before(async () => {
  server = await startServer({ users: [
    { name: 'jan', projects: [{ name: 'lab', mission: 'aac', budget: 2000 }] },
    { name: 'kim', projects: [{ name: 'lab', mission: 'aac', budget: 2000 }] },
  ] });
  const folder = path.join(server.env.SWARMDESIGN_HOME, 'users', 'jan', 'projects', 'lab', 'missions');
  mkdirSync(folder, { recursive: true });
  const doc = JSON.parse(readFileSync(path.join(here, '..', '..', 'missions', 'aac.json'), 'utf8')
    .split('\n').filter((l) => !l.trim().startsWith('//')).join('\n'));
  Object.assign(doc, { name: 'short-aac', duration: 10 });
  delete doc.argos;
  missionFile = path.join(folder, 'short-aac.json');
  writeFileSync(missionFile, JSON.stringify(doc));
  ({ browser, pages: [page, other] } = await signedInPages(server, ['jan', 'kim'], errors));
}, { timeout: 60000 });

after(async () => {
  if (browser) await browser.close();
  if (server) await server.close();
});

async function openForm() {
  await page.click('#tab-designs');
  await page.click('[data-testid="project-lab"]');
  await page.waitForFunction(() => document.getElementById('monitor-project').textContent === 'lab');
  if (!await page.evaluate(() => document.getElementById('exp-new').open)) await page.click('#exp-new summary');
  await page.waitForFunction(() => document.querySelectorAll('#exp-protocol option').length === 5);
}

test('a thesis protocol is planned with the CLI\'s choices, and nothing is recorded', { timeout: 60000 }, async () => {
  await openForm();
  await page.selectOption('#exp-protocol', 'architecture');
  const missions = await page.$$eval('#exp-missions input', (els) => els.map((e) => e.value));
  assert.ok(missions.length >= 2, missions.join());
  for (const m of missions.slice(1)) await page.uncheck(`[data-testid="exp-mission-${m}"]`);
  await page.fill('#exp-designs', '2');
  await page.fill('#exp-scale', '0.01');
  // Also in a pseudo-reality: the page sends it as the CLI's flags do (one protocol request).
  await page.fill('#exp-reality', 'sampled-around');
  await page.fill('#exp-reality-samples', '3');
  await page.click('#exp-dry');
  await page.waitForSelector('[data-testid="exp-plan-summary"]');
  const summary = await page.textContent('[data-testid="exp-plan-summary"]');
  const expected = JSON.parse(cli(server.env, ['experiment', 'architecture', '--missions', missions[0], '--designs', '2', '--budget-scale', '0.01',
    '--pseudo-reality', 'sampled-around', '--pseudo-reality-samples', '3', '--dry-run', '--json']));
  assert.match(summary, new RegExp(`^architecture: ${expected.designs.length} designs .*${expected.design_runs.toLocaleString('en')} design runs and ${expected.assessment_runs.toLocaleString('en')} assessment runs`));
  // And how long it would take on the server, as the CLI's --dry-run estimates it.
  const estimate = await page.textContent('[data-testid="exp-plan-estimate"]');
  assert.match(estimate, /^about \d+(\.\d)? (s|min|h|days) on this server \(\d+ threads/);
  for (const m of expected.estimate.missions) assert.ok(estimate.includes(`${m.mission}: ${m.runs.toLocaleString('en')} runs at`), estimate);
  await page.fill('#exp-reality', '');
  await page.fill('#exp-reality-samples', '');
  await page.locator('[data-testid="exp-plan-estimate"]').scrollIntoViewIfNeeded();
  await shot(page, 'planned');
  assert.match(await page.textContent('#experiment-list'), /none yet/);
});

test('an own protocol starts, is followed, stopped, resumed and finished, with its report and data', { timeout: 300000 }, async () => {
  await openForm();
  await page.selectOption('#exp-protocol', 'own');
  await page.setInputFiles('#exp-file', { name: 'quick.json', mimeType: 'application/json', buffer: Buffer.from(protocol('quick', 6000)) });
  await page.fill('#exp-designs', '');
  await page.fill('#exp-scale', '');
  await page.click('#exp-start');
  await page.waitForSelector('[data-testid="exp-started"]');
  await page.waitForFunction(() => /runs \d+ \/ \d+/.test(document.querySelector('[data-testid="exp-progress-quick"]')?.textContent || ''), null, { timeout: 60000, polling: 200 });
  assert.match(await page.textContent('[data-testid="exp-state-quick"]'), /^running \(here\)$/);
  await shot(page, 'running');
  // Its design opens in the monitor, as a design of the project does.
  await page.click('[data-testid="exp-follow-quick"]');
  await page.waitForFunction(() => /^Showing the design experiment quick is making/.test(document.querySelector('[data-testid="opened-note"]')?.textContent || ''));
  await page.waitForFunction(() => document.querySelectorAll('#elites tbody tr[data-testid^="elite-"]').length > 0, null, { timeout: 60000 });
  assert.match(await page.textContent('#runs-used'), /^\d+ \/ 6000$/);
  // Its best is drawn as a design's is.
  await page.waitForFunction(() => window.__sd.monitor.bestDrawing().nodes > 0, null, { timeout: 30000 });
  await shot(page, 'experiment-design-watched');
  assert.match(await page.textContent('[data-testid="exp-started"]'), /^quick started on this server$/);
  await page.click('[data-testid="exp-stop-quick"]');
  await page.waitForFunction(() => document.querySelector('[data-testid="exp-state-quick"]')?.textContent === 'interrupted', null, { timeout: 60000 });
  // "started on this server" went with it: the list says how it stands.
  await page.waitForFunction(() => !document.querySelector('[data-testid="exp-started"]'), null, { timeout: 10000 });
  await shot(page, 'stopped');
  await page.click('[data-testid="exp-resume-quick"]');
  await page.waitForFunction(() => document.querySelector('[data-testid="exp-state-quick"]')?.textContent === 'finished', null, { timeout: 240000, polling: 500 });
  assert.match(await page.textContent('[data-testid="exp-progress-quick"]'), /^2 \/ 2 designs done$/);
  // Its designs all done, the monitor is back on the project, which has no design of its own:
  // nothing is drawn under "no configuration yet" (the experiment's last best stayed there).
  await page.waitForFunction(() => !document.querySelector('[data-testid="opened-note"]'), null, { timeout: 30000 });
  assert.equal(await page.textContent('#design-state'), 'no design yet');
  assert.equal(await page.textContent('#best-score'), 'no configuration yet');
  assert.deepEqual(await page.evaluate(() => window.__sd.monitor.bestDrawing()), { nodes: 0, drawn: null });
  await shot(page, 'finished');
  // Its designs, made, open in the monitor from the experiment's list.
  await page.click('[data-testid="exp-designs-quick"]');
  await page.waitForSelector('[data-testid="exp-designs-dialog"] tr[data-testid^="exp-design-row-"]');
  const rows = await page.$$('[data-testid="exp-designs-dialog"] tr[data-testid^="exp-design-row-"]');
  assert.equal(rows.length, 2);
  await shot(page, 'designs-dialog');
  const first = (await rows[0].getAttribute('data-testid')).replace('exp-design-row-', '');
  await page.click(`[data-testid="exp-open-${first}"]`);
  await page.waitForFunction((id) => document.querySelector('[data-testid="opened-note"]')?.textContent.startsWith(`Showing design #${id} of experiment quick.`), first);
  await page.waitForFunction(() => /^finished/.test(document.getElementById('design-state').textContent));
  assert.match(await page.textContent('#runs-used'), /^\d+ \/ 6000$/);
  await page.waitForFunction(() => window.__sd.monitor.bestDrawing().nodes > 0, null, { timeout: 30000 });
  assert.equal(await page.isDisabled('#test-run'), true, "its report assesses it, not the project's Test");
  await shot(page, 'experiment-design-opened');
  await page.click('[data-testid="show-latest"]');
  await page.waitForFunction(() => !document.querySelector('[data-testid="opened-note"]'));
  // report.json downloads as the server writes it.
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('[data-testid="report-json-quick"]')]);
  const report = JSON.parse(readFileSync(await download.path(), 'utf8'));
  assert.equal(report.experiment.name, 'quick');
  assert.equal(report.experiment.designs_done, 2);
});

test('a second account sees none of it and cannot stop or resume it', { timeout: 30000 }, async () => {
  await other.click('#tab-designs');
  await other.click('[data-testid="project-lab"]');
  await other.waitForSelector('#experiment-list li');
  assert.match(await other.textContent('#experiment-list'), /none yet/);
  const status = await other.evaluate(async () => {
    const post = (r) => fetch(r, { method: 'POST', headers: { 'Content-Type': 'application/json', 'X-CSRF-Token': window.__sdCsrf }, body: '{}' }).then((x) => x.status);
    return [await post('/api/projects/lab/experiments/quick/stop'), await post('/api/projects/lab/experiments/quick/resume'),
      (await fetch('/api/projects/lab/experiments/quick/designs/1')).status];
  });
  assert.deepEqual(status, [404, 404, 404]);
});

test('an experiment the CLI starts shows up live, and the page stops it', { timeout: 120000 }, async () => {
  await openForm();
  const file = path.join(server.tmp, 'cli.json');
  writeFileSync(file, protocol('from-cli', 200000));
  cli(server.env, ['sign-in', 'jan', '--password-stdin'], `${PASSWORD}\n`);
  const child = spawn(BIN, ['experiment', '--file', file, '--project', 'lab'], { env: server.env, stdio: 'ignore' });
  const exited = new Promise((r) => child.once('exit', (code, signal) => r({ code, signal })));
  await page.waitForSelector('[data-testid="exp-state-from-cli"]', { timeout: 30000 });
  await page.waitForFunction(() => document.querySelector('[data-testid="exp-state-from-cli"]')?.textContent === 'running', null, { timeout: 30000 });
  await shot(page, 'cli-experiment-live');
  await page.click('[data-testid="exp-stop-from-cli"]');
  assert.equal((await exited).signal, 'SIGTERM');
  await page.waitForFunction(() => document.querySelector('[data-testid="exp-state-from-cli"]')?.textContent === 'interrupted', null, { timeout: 30000 });
  assert.deepEqual(errors, []);
});
