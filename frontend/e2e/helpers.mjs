// Shared set-up of the end-to-end tests: a fresh SwarmDesign home with users and projects, the
// real server (swarmdesign run-exp) on a free loopback port, Debian's chromium via playwright-core.
import { execFileSync, spawn } from 'node:child_process';
import { mkdirSync, mkdtempSync, readdirSync, rmSync } from 'node:fs';
import net from 'node:net';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';

const here = path.dirname(fileURLToPath(import.meta.url));
export const BIN = process.env.SWARMDESIGN_BIN || path.join(here, '..', '..', 'build', 'swarmdesign');
export const SCREENSHOTS = process.env.SWARMDESIGN_SCREENSHOTS || path.join(here, '..', '..', 'build', 'screenshots');
export const CHROMIUM = process.env.CHROMIUM || '/usr/bin/chromium';
export const PASSWORD = 'correct-horse-1';

export function freePort() {
  return new Promise((resolve, reject) => {
    const server = net.createServer();
    server.once('error', reject);
    server.listen(0, '127.0.0.1', () => {
      const { port } = server.address();
      server.close(() => resolve(port));
    });
  });
}

export function cli(env, args, input, timeout = 60000) {
  return execFileSync(BIN, args, { env, input, encoding: 'utf8', stdio: ['pipe', 'pipe', 'pipe'], timeout });
}

/// The front end as the tests see it: SWARMDESIGN_WEB_ROOT, or a fresh build of this folder.
function webRoot(tmp) {
  if (process.env.SWARMDESIGN_WEB_ROOT) return process.env.SWARMDESIGN_WEB_ROOT;
  const out = path.join(tmp, 'web-root');
  execFileSync(process.execPath, [path.join(here, '..', 'build.mjs'), '--outdir', out], { stdio: 'ignore', timeout: 60000 });
  return out;
}

/// Starts a server in a fresh home. users: [{name, projects: [{name, mission, budget}]}];
/// serverArgs: more arguments of run-exp (e.g. ['--sign-up', 'invite']).
export async function startServer({ users = [], serverArgs = [] } = {}) {
  const tmp = mkdtempSync(path.join(os.tmpdir(), 'sd-e2e-'));
  const env = { ...process.env, SWARMDESIGN_HOME: path.join(tmp, 'home') };
  for (const user of users) {
    cli(env, ['sign-up', user.name, '--password-stdin'], `${PASSWORD}\n`);
    cli(env, ['sign-in', user.name, '--password-stdin'], `${PASSWORD}\n`);
    for (const p of user.projects || []) {
      cli(env, ['new-project', p.name]);
      cli(env, ['select-project', p.name]);
      if (p.mission) cli(env, ['set-mission', p.mission]);
      if (p.budget) cli(env, ['set-budget', String(p.budget)]);
    }
  }
  const root = webRoot(tmp);
  let run = await launchServer(env, root, serverArgs);
  process.once('exit', () => run.stop());
  return {
    get url() { return run.url; }, env, tmp, output: () => run.output(),
    /// Kills the server as a crash would (SIGKILL) and starts another on the same home.
    async crashAndRestart() {
      await run.kill('SIGKILL');
      run = await launchServer(env, root, serverArgs);
      return run.url;
    },
    async close() {
      await run.kill('SIGTERM');
      rmSync(tmp, { recursive: true, force: true });
    },
  };
}

/// swarmdesign run-exp on a free port, once it answers.
async function launchServer(env, root, serverArgs = []) {
  const port = await freePort();
  const child = spawn(BIN, ['run-exp', '--port', String(port), '--web-root', root, ...serverArgs], { env, stdio: ['ignore', 'pipe', 'pipe'] });
  let output = '';
  child.stdout.on('data', (d) => { output += d; });
  child.stderr.on('data', (d) => { output += d; });
  const url = `http://127.0.0.1:${port}/`;
  const deadline = Date.now() + 20000;
  for (;;) {
    if (child.exitCode !== null) throw new Error(`run-exp exited (${child.exitCode}): ${output}`);
    try {
      const r = await fetch(url);
      if (r.status < 500) break;
    } catch { /* not yet */ }
    if (Date.now() > deadline) { child.kill(); throw new Error(`run-exp did not answer on ${url}: ${output}`); }
    await new Promise((r) => setTimeout(r, 100));
  }
  return {
    url,
    output: () => output,
    stop() { if (child.exitCode === null && child.signalCode === null) child.kill('SIGTERM'); },
    async kill(signal) {
      if (child.exitCode !== null || child.signalCode !== null) return;
      const exited = new Promise((r) => child.once('exit', r));
      child.kill(signal);
      const timer = setTimeout(() => child.kill('SIGKILL'), 5000);
      await exited;
      clearTimeout(timer);
    },
  };
}

export async function launchBrowser() {
  return chromium.launch({
    executablePath: CHROMIUM,
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
      '--disable-background-networking', '--disable-component-update', '--disable-sync'],
    timeout: 30000,
  });
}

export async function newPage(browser, errors = [], viewport = { width: 1400, height: 900 }) {
  const page = await browser.newPage({ viewport, acceptDownloads: true });
  page.setDefaultTimeout(15000);
  page.on('pageerror', (e) => errors.push(e.message));
  return page;
}

/// A browser with a page signed in for each user name, in that order, page errors collected.
export async function signedInPages(server, names, errors, viewport = { width: 1280, height: 800 }) {
  const browser = await launchBrowser();
  const pages = [];
  for (const name of names) {
    const page = await newPage(browser, errors, viewport);
    await signIn(page, server.url, name);
    pages.push(page);
  }
  return { browser, pages };
}

export function screenshotter(prefix) {
  mkdirSync(SCREENSHOTS, { recursive: true });
  for (const f of readdirSync(SCREENSHOTS)) if (f.startsWith(`${prefix}-`)) rmSync(path.join(SCREENSHOTS, f));
  let n = 0;
  return (page, step) => page.screenshot({ path: path.join(SCREENSHOTS, `${prefix}-${String(++n).padStart(2, '0')}-${step}.png`) });
}

export async function signIn(page, url, name) {
  await page.goto(url);
  await page.waitForSelector('#signin-form', { state: 'visible' });
  await page.fill('#signin-name', name);
  await page.fill('#signin-password', PASSWORD);
  await page.click('#signin-submit');
  await page.waitForSelector('body[data-ready="true"]');
}

/// Opens the app at url, signing in only if the page asks (a session cookie may still hold).
export async function openSignedIn(page, url, name) {
  await page.goto(url);
  await page.waitForSelector('body[data-ready="true"], #signin-form:visible');
  if (await page.isVisible('#signin-form')) await signIn(page, url, name);
}
