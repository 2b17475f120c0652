// The web app as the user sees it, in Debian's headless chromium: time from pressing Exec to
// the first frame on the page (AAC), and frames drawn per second at each playback speed.
// Run (after a build): node bench/web_viewer.mjs   (server-side figures: build/bench/web_bench)
import { launchBrowser, newPage, signIn, startServer } from '../frontend/e2e/helpers.mjs';

const FSM = '--fsm-config --nstates 2 --s0 0 --rwm0 50 --n0 1 --n0x0 0 --c0x0 0 --p0x0 0.5 --s1 1 --n1 1 --n1x0 0 --c1x0 1 --p1x0 0.5';
const server = await startServer({ users: [{ name: 'alice' }] });
const browser = await launchBrowser();
try {
  const page = await newPage(browser);
  await signIn(page, server.url, 'alice');
  await page.click('#tab-exec');
  await page.waitForSelector('#exec-mission option[value="aac"]', { state: 'attached' });
  await page.selectOption('#exec-mission', 'aac');
  await page.fill('#exec-text', FSM);

  const firstFrame = [], delivered = [];
  for (let seed = 1; seed <= 10; seed++) {
    await page.fill('#exec-seed', String(seed));
    await page.click('#exec-run');
    await page.waitForFunction(() => window.__sdFirstFrameMs > 0, null, { timeout: 10000 });
    firstFrame.push(await page.evaluate(() => window.__sdFirstFrameMs));
    await page.waitForFunction(() => document.querySelector('#final-score').textContent !== '', null, { timeout: 30000 });
    // Placement and 1200 ticks reach the page between the first frame and the end.
    delivered.push(await page.evaluate(() => 1201 / ((window.__sdEndMs - window.__sdFirstFrameMs) / 1000)));
  }
  delivered.sort((a, b) => a - b);
  firstFrame.sort((a, b) => a - b);
  console.log(`Exec -> first frame (AAC, 10 runs): median ${firstFrame[5].toFixed(1)} ms, max ${firstFrame[9].toFixed(1)} ms`);
  console.log(`frames delivered to the page at full speed: median ${delivered[5].toFixed(0)} frames/s`);

  for (const [label, value] of [['real time', '1'], ['10x', '10'], ['every frame', 'frame']]) {
    await page.selectOption('#speed', value);
    await page.click('#exec-run');
    await page.waitForFunction(() => document.querySelector('#final-score').textContent !== '', null, { timeout: 30000 });
    // Replay the recorded run from tick 0 for 3 s and count what the page draws.
    await page.evaluate(() => { const t = document.querySelector('#timeline'); t.value = '0'; t.dispatchEvent(new Event('input')); });
    const before = await page.evaluate(() => [window.__sdFramesDrawn || 0, performance.now()]);
    await page.evaluate(() => { const b = document.querySelector('#play'); if (b && /play/i.test(b.textContent)) b.click(); });
    await page.waitForTimeout(3000);
    const after = await page.evaluate(() => [window.__sdFramesDrawn || 0, performance.now()]);
    const fps = (after[0] - before[0]) / ((after[1] - before[1]) / 1000);
    console.log(`playback at ${label}: ${fps.toFixed(1)} frames drawn per second`);
  }
} finally {
  await browser.close();
  await server.close();
}
