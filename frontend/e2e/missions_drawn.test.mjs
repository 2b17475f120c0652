// Every mission's drawing follows its geometry, checked on pixels in headless chromium against
// the real server: the drawing is rasterised, the arena's outline is computed here from the wall
// rectangles the drawing holds (not from its clip path), and no pixel farther than 2 px outside
// that outline has a floor colour (the floor background or a patch's); the arena fills the
// drawing (fitted to its bounding box); a grid objective's grid is drawn.
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';
import { launchBrowser, newPage, screenshotter, signIn, startServer } from './helpers.mjs';

let server;
let browser;
let page;
const errors = [];
const shot = screenshotter('missions');

before(async () => {
  server = await startServer({ users: [{ name: 'fay' }] });
  browser = await launchBrowser();
  page = await newPage(browser, errors, { width: 1280, height: 800 });
  await signIn(page, server.url, 'fay');
}, { timeout: 60000 });

after(async () => {
  if (browser) await browser.close();
  if (server) await server.close();
});

/// In the page: {walls, outside, fill, floorColours, size} for one mission's drawing.
const inspect = (name) => page.evaluate(async (name) => {
  const text = await (await fetch(`/api/missions/svg?name=${encodeURIComponent(name)}`)).text();
  const doc = new DOMParser().parseFromString(text, 'image/svg+xml');
  const [bx, by, bw, bh] = doc.documentElement.getAttribute('viewBox').split(/[\s,]+/).map(Number);
  const width = Number(doc.documentElement.getAttribute('width'));
  const height = Number(doc.documentElement.getAttribute('height'));
  const hex = (c) => [1, 3, 5].map((i) => parseInt(c.slice(i, i + 2), 16));
  const floorColours = [...doc.querySelectorAll('g.floor > rect:not(.zone), .patch')].map((e) => hex(e.getAttribute('fill')));
  // Wall corners in world metres, from each rectangle's translate and rotate.
  const corners = [];
  for (const w of doc.querySelectorAll('rect.wall')) {
    const [, tx, ty, angle] = /translate\(([-\d.e]+) ([-\d.e]+)\) rotate\(([-\d.e]+)\)/.exec(w.getAttribute('transform')).map(Number);
    const x = Number(w.getAttribute('x')), y = Number(w.getAttribute('y'));
    const ww = Number(w.getAttribute('width')), wh = Number(w.getAttribute('height'));
    const a = (angle * Math.PI) / 180;
    for (const [px, py] of [[x, y], [x + ww, y], [x, y + wh], [x + ww, y + wh]])
      corners.push([tx + px * Math.cos(a) - py * Math.sin(a), ty + px * Math.sin(a) + py * Math.cos(a)]);
  }
  // Convex hull (monotone chain), counter-clockwise.
  corners.sort((p, q) => p[0] - q[0] || p[1] - q[1]);
  const cross = (o, p, q) => (p[0] - o[0]) * (q[1] - o[1]) - (p[1] - o[1]) * (q[0] - o[0]);
  const half = (pts) => { const h = []; for (const p of pts) { while (h.length >= 2 && cross(h[h.length - 2], h[h.length - 1], p) <= 0) h.pop(); h.push(p); } h.pop(); return h; };
  const hull = corners.length >= 3 ? [...half(corners), ...half([...corners].reverse())] : [];
  // Rasterise the drawing as the browser shows it.
  // Without the captions under the arena: their anti-aliased greys are not floor.
  for (const t of doc.querySelectorAll('text')) t.remove();
  const image = new Image();
  image.src = URL.createObjectURL(new Blob([new XMLSerializer().serializeToString(doc)], { type: 'image/svg+xml' }));
  await image.decode();
  const canvas = document.createElement('canvas');
  canvas.width = width;
  canvas.height = height;
  const ctx = canvas.getContext('2d');
  ctx.drawImage(image, 0, 0, width, height);
  const pixels = ctx.getImageData(0, 0, width, height).data;
  const k = width / bw;  // pixels per metre
  const toPixel = ([x, y]) => [(x - bx) * k, (-y - by) * k];
  const poly = hull.map(toPixel);  // clockwise on screen (y flipped)
  /// Signed distance outside the convex polygon (positive outside), in pixels.
  const outsideBy = (px, py) => {
    let worst = -Infinity;
    for (let i = 0; i < poly.length; i++) {
      const [x1, y1] = poly[i];
      const [x2, y2] = poly[(i + 1) % poly.length];
      const len = Math.hypot(x2 - x1, y2 - y1) || 1;
      // Counter-clockwise in the world is clockwise on screen (y down): outside is to the left.
      worst = Math.max(worst, ((x2 - x1) * (py - y1) - (y2 - y1) * (px - x1)) / len);
    }
    return worst;
  };
  let outside = 0;
  const samples = [];
  if (poly.length) {
    for (let py = 0; py < height; py++) {
      for (let px = 0; px < width; px++) {
        if (outsideBy(px + 0.5, py + 0.5) <= 2) continue;
        const i = (py * width + px) * 4;
        const c = [pixels[i], pixels[i + 1], pixels[i + 2]];
        if (floorColours.some((f) => Math.abs(f[0] - c[0]) <= 2 && Math.abs(f[1] - c[1]) <= 2 && Math.abs(f[2] - c[2]) <= 2)) {
          outside++;
          if (samples.length < 3) samples.push([px, py, c]);
        }
      }
    }
  }
  const xs = poly.map((p) => p[0]);
  const ys = poly.map((p) => p[1]);
  const fill = poly.length ? Math.max((Math.max(...xs) - Math.min(...xs)) / width, (Math.max(...ys) - Math.min(...ys)) / (bh * k)) : 1;
  return { walls: hull.length, outside, samples, fill, floorColours: floorColours.length, grid: doc.querySelectorAll('g.grid line').length };
}, name);

test('no floor colour lies outside the walls, and the arena fills its drawing', { timeout: 120000 }, async () => {
  const missions = await page.evaluate(async () => (await (await fetch('/api/missions')).json()).map((m) => m.name));
  assert.ok(missions.length >= 15);
  for (const name of missions) {
    const r = await inspect(name);
    if (!r.walls) continue;  // an unbounded workspace has no walls to stay inside
    assert.ok(r.floorColours >= 1, `${name}: its floor is drawn`);
    assert.equal(r.outside, 0, `${name}: ${r.outside} floor pixels outside the walls, e.g. ${JSON.stringify(r.samples)}`);
    assert.ok(r.fill >= 0.85, `${name}: the arena fills ${Math.round(r.fill * 100)} % of its drawing`);
  }
});

test("grid-exploration draws its objective's 10 x 10 grid", { timeout: 20000 }, async () => {
  const r = await inspect('grid-exploration');
  assert.equal(r.grid, 22);
});

test('the Missions tab at 1280 and 1920 px', { timeout: 30000 }, async () => {
  await page.click('#tab-missions');
  await page.waitForFunction(() => [...document.querySelectorAll('.mission-card img')].slice(0, 8).every((i) => i.complete && i.naturalWidth > 0));
  await shot(page, 'tab-1280');
  await page.setViewportSize({ width: 1920, height: 1080 });
  await page.waitForFunction(() => [...document.querySelectorAll('.mission-card img')].slice(0, 12).every((i) => i.complete && i.naturalWidth > 0));
  await shot(page, 'tab-1920');
  // The last row (TuttiFrutti's arenas, with their captions) as well.
  await page.evaluate(() => { const g = document.getElementById('mission-grid'); g.scrollTop = g.scrollHeight; });
  await page.waitForFunction(() => [...document.querySelectorAll('.mission-card img')].every((i) => i.complete && i.naturalWidth > 0));
  await shot(page, 'tab-1920-end');
});

test('the page raised no uncaught error', () => {
  assert.deepEqual(errors, []);
});
