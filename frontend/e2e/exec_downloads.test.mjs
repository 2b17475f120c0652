// Exec's downloads, in headless chromium against the real server: after a run, "Download
// video" gives a WebM that ffprobe (Debian's ffmpeg) decodes, with frames and a duration of the
// run's length over the chosen speed, at the chosen height; "Frame PNG" gives a PNG of that
// height; "Frame SVG" the arena with every robot.
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { copyFileSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { SCREENSHOTS, launchBrowser, newPage, screenshotter, signIn, startServer } from './helpers.mjs';

const FSM = '--fsm-config --nstates 2 --s0 10 --rwm0 50 --n0 1 --n0x0 0 --c0x0 10 --p0x0 0.5 --s1 14 --att1 3 --n1 1 --n1x0 0 --c1x0 12 --p1x0 0.5';
let server;
let browser;
let page;
const errors = [];
const shot = screenshotter('exec-downloads');

before(async () => {
  server = await startServer({ users: [{ name: 'erin' }] });
  browser = await launchBrowser();
  page = await newPage(browser, errors, { width: 1280, height: 800 });
  await signIn(page, server.url, 'erin');
  await page.click('#tab-exec');
  await page.fill('#exec-text', FSM);
  await page.selectOption('#exec-mission', 'aac');
  await page.fill('#exec-seed', '4');
  await page.check('#show-trails');
  await page.click('#exec-run');
  await page.waitForFunction(() => document.getElementById('final-score').textContent !== '', null, { timeout: 60000 });
}, { timeout: 90000 });

after(async () => {
  if (browser) await browser.close();
  if (server) await server.close();
});

async function downloaded(button) {
  const [download] = await Promise.all([page.waitForEvent('download', { timeout: 60000 }), page.click(button)]);
  const file = path.join(server.tmp, download.suggestedFilename());
  await download.saveAs(file);
  return file;
}

test('the video decodes: frames, a duration, the chosen height', { timeout: 90000 }, async () => {
  await page.selectOption('#video-speed', '30');
  await page.selectOption('#video-height', '480');
  const file = await downloaded('#download-video');
  assert.match(path.basename(file), /^aac-seed4-30x\.webm$/);
  const probe = JSON.parse(execFileSync('ffprobe', ['-v', 'error', '-count_frames', '-select_streams', 'v:0',
    '-show_entries', 'stream=codec_name,width,height,nb_read_frames:format=duration,format_name', '-of', 'json', file], { encoding: 'utf8' }));
  const stream = probe.streams[0];
  assert.equal(stream.height, 480);
  assert.ok(['vp8', 'vp9'].includes(stream.codec_name), stream.codec_name);
  assert.match(probe.format.format_name, /webm/);
  // 1200 ticks of 0.1 s at 30x: 4 s at 30 frames a second (pacing may add a little).
  const duration = Number(probe.format.duration);
  assert.ok(duration >= 3.5 && duration <= 8, `duration ${probe.format.duration}`);
  assert.ok(Number(stream.nb_read_frames) >= 60, `frames ${stream.nb_read_frames}`);
  // A frame from the middle of the video, to look at beside the screenshots.
  execFileSync('ffmpeg', ['-v', 'error', '-y', '-ss', '2', '-i', file, '-frames:v', '1', path.join(SCREENSHOTS, 'exec-downloads-video-frame.png')]);
  await shot(page, 'video-saved');
});

test('the frame downloads as PNG at the chosen height and as SVG with every robot', { timeout: 30000 }, async () => {
  await page.evaluate(() => window.__sd.exec.seek(600));
  await page.selectOption('#video-height', '720');
  const pngFile = await downloaded('#download-png');
  const png = readFileSync(pngFile);
  assert.deepEqual([...png.subarray(0, 8)], [0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]);
  assert.equal(png.readUInt32BE(20), 720);  // IHDR height
  copyFileSync(pngFile, path.join(SCREENSHOTS, 'exec-downloads-frame.png'));
  const svgFile = await downloaded('#download-svg');
  assert.match(path.basename(svgFile), /^aac-seed4-tick600\.svg$/);
  const svg = readFileSync(svgFile, 'utf8');
  const robots = svg.slice(svg.indexOf('class="robots"'));
  assert.equal((robots.match(/<circle /g) || []).length, 20);
  assert.match(svg, /tick 600 \/ 1200/);
});

test('at 1280×800 the arena, the timeline and the whole objective plot fit in the window', { timeout: 30000 }, async () => {
  await page.waitForSelector('#objective-plot svg, #objective-plot canvas');
  for (const id of ['#viewer', '#timeline', '#objective-plot']) {
    const box = await page.locator(id).boundingBox();
    assert.ok(box && box.height > 0, id);
    assert.ok(box.y + box.height <= 800, `${id} ends at ${box.y + box.height} px, below the window`);
  }
  assert.ok((await page.locator('#viewer').boundingBox()).width >= 360, 'the arena stays large enough to read');
  await shot(page, 'exec-1280x800');
});

test('the page raised no uncaught error', () => {
  assert.deepEqual(errors, []);
});
